"""Build of rosvar: every module compiled to a C extension by mypyc, or plain Python.

rosvar's sources are strictly typed (``mypy --strict``), which is what mypyc needs to turn
them into native code: the interpreter, the feature model and the configuration engine run
about 1.5 times as fast compiled (docs/performance.md). ``ROSVAR_COMPILE=0`` builds the plain
Python package (for a machine without a C compiler); the code is the same either way.
"""

from __future__ import annotations

import os
from pathlib import Path

from setuptools import setup

PLAIN_PYTHON = ("__main__.py", "lazy.py", "outputs/web/server.py")
"""Modules left as Python: ``python -m rosvar`` runs ``__main__`` as a script, ``lazy`` keeps
``functools.cached_property`` out of mypyc's sight, and the web server subclasses the standard
library's HTTP server classes (which compiled classes cannot)."""


def compiled_modules() -> list[str]:
    """The module files mypyc compiles, as paths relative to the project root (setuptools
    runs this file from there)."""
    package = Path("src", "rosvar")
    return sorted(
        str(path)
        for path in package.rglob("*.py")
        if path.relative_to(package).as_posix() not in PLAIN_PYTHON
    )


def extensions() -> list[object]:
    if os.environ.get("ROSVAR_COMPILE", "1") == "0":
        return []
    from mypyc.build import mypycify

    return list(mypycify(compiled_modules(), opt_level="3", debug_level="1"))


setup(ext_modules=extensions())
