"""What the commands write besides their results: progress on a terminal, JSON shaped for
its reader, and paths as people read them."""

from __future__ import annotations

import json
import os
import sys
from dataclasses import replace
from typing import TYPE_CHECKING

from rosvar.diagnostics import Location

if TYPE_CHECKING:
    from rosvar.configuration.engine import Progress


def progress(index: int, total: int, file: str) -> None:
    """The file being analysed, on a terminal and only for a workspace large enough to wait
    for."""
    if total >= 50 and sys.stderr.isatty():
        sys.stderr.write(f"\r[{index + 1}/{total}] {os.path.basename(file)[:50]:<50}")
        if index + 1 == total:
            sys.stderr.write("\n")
        sys.stderr.flush()


def building(tty_only: bool) -> Progress:
    """Shows how far the configuration engine's build is: one line rewritten in place on
    a terminal, else (unless ``tty_only``) a line per phase."""
    tty = sys.stderr.isatty()

    def show(phase: str, done: int, total: int) -> None:
        if tty:
            end = "\n" if phase == "ready" else ""
            counted = f" {done:,}/{total:,}" if total > 1 else ""
            line = f"rosvar: building the configuration engine: {phase}{counted}"
            sys.stderr.write(f"\r{line:<79}{end}")
        elif not tty_only and done == 0:
            sys.stderr.write(f"rosvar: building the configuration engine: {phase} ...\n")
        sys.stderr.flush()

    return show


def print_json(document: object) -> None:
    """``document`` on stdout: indented for a terminal, on one line for a pipe or a file.

    Python's fast JSON encoder only writes without indentation: indented, printing a large
    analysis takes longer than computing it (``jq`` indents it again)."""
    indent = 2 if sys.stdout.isatty() else None
    sys.stdout.write(json.dumps(document, indent=indent, ensure_ascii=False) + "\n")


def shown_path(path: str) -> str:
    """A path for people: relative to the current directory, unless the absolute one is
    shorter (a file far from it); an empty path (a place no file holds) as it is."""
    if not path:
        return path
    relative = os.path.relpath(path)
    absolute = os.path.abspath(path)
    return relative if len(relative) <= len(absolute) else absolute


def relative_location(location: Location) -> Location:
    """``location`` with its file as :func:`shown_path` spells it."""
    return replace(location, file=shown_path(location.file))


def shown_location(location: Location) -> str:
    """``location`` for people: a file's path as :func:`shown_path` spells it, a URL as it
    is."""
    return str(location if "://" in location.file else relative_location(location))
