"""What a command that needs the solver says when the feature model is too large to solve:
why, the largest groups of files the constraints link, and a narrower command to run."""

from __future__ import annotations

import os
import shlex
from collections.abc import Sequence

from rosvar.analyses.feature_model.features import ModelTooLarge
from rosvar.outputs.commands.terminal import shown_path


def too_large_text(error: ModelTooLarge, command: str, paths: Sequence[str]) -> str:
    """The lines for stderr: the reason, the largest parts (files and their packages), and
    ``command`` on the largest part's first package with ``paths`` as dependencies."""
    lines = [f"rosvar: the feature model is too large to solve: {error}"]
    if not error.parts:
        return "\n".join(lines)
    lines.append("rosvar: its largest parts (files linked by includes and shared names):")
    for part in error.parts:
        shown = [f"{name or shown_path(path)} ({count})" for name, path, count in part.packages]
        more = ", ..." if part.package_count > len(shown) else ""
        files = _counted(part.files, "file")
        lines.append(
            f"  {files} of {_counted(part.package_count, 'package')}: {', '.join(shown)}{more}"
        )
    _name, folder, _count = error.parts[0].packages[0]
    narrower = [
        "rosvar",
        command,
        shown_path(folder),
        *(word for path in paths for word in ("--deps", shown_path(os.path.abspath(path)))),
    ]
    lines.append(
        "rosvar: configure a package of it, with the rest as dependencies, e.g. "
        + shlex.join(narrower)
    )
    return "\n".join(lines)


def _counted(count: int, noun: str) -> str:
    return f"{count:,} {noun}{'' if count == 1 else 's'}"
