"""What the real launch code (``../shared/ros2-oracle/upstream``) exposes, read from its
sources (never imported): the names of ``@expose_action``/``@expose_substitution`` and what
each package's modules export."""

from __future__ import annotations

import ast
import re
from pathlib import Path

from rosvar.ros2.api.registry import PythonName

UPSTREAM = Path(__file__).resolve().parents[4] / "shared" / "ros2-oracle" / "upstream"
PACKAGES = ("launch", "launch_ros", "launch_xml", "launch_yaml")


def exposed_by_upstream(kind: str) -> set[str]:
    """The frontend names of every ``@expose_<kind>('name')`` of the launch packages."""
    found: set[str] = set()
    for package in PACKAGES:
        for path in (UPSTREAM / package / package).rglob("*.py"):
            text = path.read_text(encoding="utf-8")
            found.update(re.findall(rf"@expose_{kind}\('([^']+)'\)", text))
    return found


def exported_by_upstream(module: str, *packages: str) -> set[PythonName]:
    """The names ``package.module`` exports (its ``__init__``'s imports, aliases included)."""
    found: set[PythonName] = set()
    for package in packages:
        init = UPSTREAM / package / package / module / "__init__.py"
        for node in ast.parse(init.read_text(encoding="utf-8")).body:
            if isinstance(node, ast.ImportFrom):
                found.update((package, alias.asname or alias.name) for alias in node.names)
    return found
