"""Reading Python 2 scripts with Python 3's ``ast``: the line that fails is rewritten.

Many ROS 1 nodes are Python 2 (``print x``, ``except E, e``); their ROS calls are the same in
both. Each line the parser refuses is rewritten to its Python 3 spelling, or replaced by
``pass`` when no rewrite applies, so line numbers stay those of the file.
"""

from __future__ import annotations

import ast
import re

MAX_REWRITES = 500
_REWRITES: list[tuple[re.Pattern[str], str]] = [
    (re.compile(r"^(\s*)print\s*>>\s*([^,]+),\s*(.*?),?\s*$"), r"\1print(\3, file=\2)"),
    (re.compile(r"^(\s*)print\s*$"), r"\1print()"),
    (re.compile(r"^(\s*)print\b(?!\s*\()\s*(.*?),?\s*$"), r"\1print(\2)"),
    (re.compile(r"^(\s*)except\s+([^,:]+),\s*(\w+)\s*:"), r"\1except \2 as \3:"),
    (re.compile(r"^(\s*)raise\s+([\w.]+)\s*,\s*(.*)$"), r"\1raise \2(\3)"),
    (re.compile(r"\b0(\d+)\b"), r"0o\1"),
    (re.compile(r"`([^`]*)`"), r"repr(\1)"),
    (re.compile(r"\bur(['\"])"), r"u\1"),
]


def parse(source: str, filename: str) -> tuple[ast.Module, int]:
    """The module, and how many lines had to be rewritten (0 for Python 3 sources).

    Raises ``SyntaxError`` when even rewriting does not make the source parse.
    """
    lines = source.split("\n")
    rewritten = 0
    try:
        return ast.parse(source, filename=filename), 0
    except SyntaxError:
        # rewrite every Python 2 statement at once: re-parsing per line costs a parse a line
        for index, line in enumerate(lines):
            changed = _statement(line)
            if changed != line:
                lines[index] = changed
                rewritten += 1
    while True:
        try:
            return ast.parse("\n".join(lines), filename=filename), rewritten
        except SyntaxError as error:
            index = (error.lineno or 0) - 1
            if rewritten >= MAX_REWRITES or not 0 <= index < len(lines):
                raise
            lines[index] = _rewrite(lines[index])
            rewritten += 1


def _statement(line: str) -> str:
    """``line`` with a Python 2 ``print`` or ``except E, e`` statement rewritten, if it is one."""
    for pattern, replacement in _REWRITES[:4]:
        if pattern.match(line) and not re.match(r"\s*print\s*=", line):
            changed = pattern.sub(replacement, line)
            return changed if _parses(changed.strip()) else line
    return line


def _rewrite(line: str) -> str:
    for pattern, replacement in _REWRITES:
        changed = pattern.sub(replacement, line)
        if changed != line and _parses(changed.strip()):
            return changed
    indent = line[: len(line) - len(line.lstrip())]
    return indent + "pass"


def _parses(statement: str) -> bool:
    """Whether ``statement`` is valid alone, or as the header of a block (``except E as e:``)."""
    for candidate in (
        statement,
        f"try:\n    pass\n{statement}\n    pass",
        f"{statement}\n    pass",
    ):
        try:
            ast.parse(candidate)
        except SyntaxError:
            continue
        return True
    return False
