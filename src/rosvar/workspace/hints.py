"""The hints file: what static analysis cannot see, given by the user.

YAML with three optional mappings (see docs/hints.md)::

    executables:            # package -> extra executable names (values of node types)
      my_pkg: [driver_node]
    args:                   # arg name, or FILE:arg (FILE = launch file name) -> extra values
      robot: [husky, jackal]
      bringup.launch:laser: [lms1xx]
    env:                    # environment variable -> values it may take
      TURTLEBOT_3D_SENSOR: [kinect, astra]
"""

from __future__ import annotations

from dataclasses import dataclass, field

import yaml

from rosvar.diagnostics import Diagnostic, Location, Severity

SECTIONS = ("executables", "args", "env")


@dataclass
class Hints:
    executables: dict[str, list[str]] = field(default_factory=dict)
    args: dict[str, list[str]] = field(default_factory=dict)
    env: dict[str, list[str]] = field(default_factory=dict)
    diagnostics: list[Diagnostic] = field(default_factory=list)


def load_hints(path: str | None) -> Hints:
    """Read a hints file; problems are diagnostics, never exceptions."""
    hints = Hints()
    if path is None:
        return hints

    def problem(message: str, line: int = 1) -> Hints:
        hints.diagnostics.append(
            Diagnostic("hints-invalid", Severity.ERROR, message, Location(path, line, 1))
        )
        return hints

    try:
        with open(path, encoding="utf-8") as handle:
            data = yaml.safe_load(handle)
    except OSError as error:
        return problem(f"cannot read hints file: {error.strerror}")
    except yaml.YAMLError as error:
        mark = getattr(error, "problem_mark", None)
        return problem(f"invalid YAML: {error}", mark.line + 1 if mark else 1)
    if data is None:
        return hints
    if not isinstance(data, dict):
        return problem("the hints file must be a mapping")
    for key, value in data.items():
        if key not in SECTIONS:
            problem(f"unknown section '{key}' (expected one of {', '.join(SECTIONS)})")
            continue
        if not isinstance(value, dict):
            problem(f"section '{key}' must map names to lists of values")
            continue
        target: dict[str, list[str]] = getattr(hints, key)
        for name, values in value.items():
            items = values if isinstance(values, list) else [values]
            target[str(name)] = [str(v).lower() if isinstance(v, bool) else str(v) for v in items]
    return hints
