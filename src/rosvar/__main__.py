"""Allow ``python -m rosvar``."""

from rosvar.outputs.cli import main

raise SystemExit(main())
