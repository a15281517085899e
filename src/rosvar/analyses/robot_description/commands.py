"""Command lines of launch files, read as the shell words the launch code passes on.

roslaunch runs a ``<param command=...>`` as ``shlex.split(command)``, ros2/launch's
``Command`` substitution likewise; ``spawn_model`` and friends take their options from a
node's ``args``. rosvar runs nothing: it splits the text as they do, keeping a part that is
only known per configuration (a term) as a part of its word. A xacro command gives the file
and the ``name:=value`` args xacro would read (``xacro``, the old ``xacro.py``, through
``rosrun``/``ros2 run``; ``--inorder`` and the other options are xacro's, not args).
"""

from __future__ import annotations

import os
import re
import shlex
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Final

from rosvar.interpreter.model import Raw
from rosvar.logic.terms import Apply, Term, concat

_PLACEHOLDER: Final = 0xE000  # private-use characters stand for the terms while splitting
_BLANK: Final = "\uf8ff"  # a blank inside a substitution left unresolved: one word
_SUBSTITUTION: Final = re.compile(r"\$\([^)]*\)")
_FIND_EXEC: Final = re.compile(r"\$\(find-exec\s+([^)\s]+)\s*\)")
XACRO_PROGRAMS: Final = frozenset({"xacro", "xacro.py"})
_XACRO_VALUED: Final = frozenset({"-o", "--root-dir", "--verbosity"})
_RUNNERS: Final = (("rosrun", "xacro"), ("ros2", "run", "xacro"))
REMAP: Final = ":="


class CommandError(ValueError):
    """A command line the shell would not split (an unclosed quote)."""


def parts(raw: Raw) -> list[str | Term]:
    """A text as the strings and terms it joins."""
    if isinstance(raw, Apply) and raw.function == "concat":
        found: list[str | Term] = []
        for operand in raw.operands:
            if isinstance(operand, tuple):
                raise CommandError("a command line holds no tuple")
            found.extend(parts(operand))
        return found
    return [raw]


def split(raw: Raw) -> list[Raw]:
    """``shlex.split`` of a text whose terms each stand inside one word."""
    pieces = parts(raw)
    terms: list[Term] = []
    text = ""
    for piece in pieces:
        if isinstance(piece, str):
            text += piece
        else:
            text += chr(_PLACEHOLDER + len(terms))
            terms.append(piece)
    text = _SUBSTITUTION.sub(lambda m: m[0].replace(" ", _BLANK), _FIND_EXEC.sub(r"\1", text))
    try:
        words = shlex.split(text)
    except ValueError as error:
        raise CommandError(str(error)) from None
    return [_restored(word.replace(_BLANK, " "), terms) for word in words]


def _restored(word: str, terms: Sequence[Term]) -> Raw:
    joined: list[str | Term] = []
    start = 0
    for index, character in enumerate(word):
        number = ord(character) - _PLACEHOLDER
        if 0 <= number < len(terms):
            joined.append(word[start:index])
            joined.append(terms[number])
            start = index + 1
    joined.append(word[start:])
    return concat(joined)


@dataclass
class XacroCommand:
    """What ``xacro FILE name:=value...`` reads: the file and the args it is given."""

    file: Raw
    args: dict[str, Raw] = field(default_factory=dict)


def xacro_command(words: Sequence[Raw]) -> XacroCommand | None:
    """The xacro run of a command line, None for another program; ``CommandError`` for a
    xacro command xacro itself refuses (no file, two files, a malformed ``:=``)."""
    rest = _program(words)
    if rest is None:
        return None
    args: dict[str, Raw] = {}
    positional: list[Raw] = []
    skip = False
    for word in rest:
        if skip:
            skip = False
            continue
        if isinstance(word, str) and REMAP not in word and word.startswith("-"):
            skip = word in _XACRO_VALUED
            continue
        mapping = _mapping(word)
        if mapping is None:
            positional.append(word)
        elif mapping:
            name, value = mapping
            args[name] = value
    if len(positional) != 1:
        raise CommandError("xacro expects exactly one input file")
    return XacroCommand(positional[0], args)


def _program(words: Sequence[Raw]) -> Sequence[Raw] | None:
    """The words after the xacro program, None when it runs another one."""
    for runner in _RUNNERS:
        if tuple(words[: len(runner)]) == runner:
            words = words[len(runner) :]
            break
    if not words or not isinstance(words[0], str):
        return None
    if os.path.basename(words[0]) not in XACRO_PROGRAMS:
        return None
    return words[1:]


def _mapping(word: Raw) -> tuple[str, Raw] | tuple[()] | None:
    """A ``name:=value`` word (``()`` for one xacro ignores: a ``_param:=``), else None."""
    pieces = parts(word)
    head = pieces[0]
    if not isinstance(head, str) or REMAP not in head:
        return None
    name, _, first = head.partition(REMAP)
    value = concat([first, *pieces[1:]])
    if any(isinstance(p, str) and REMAP in p for p in pieces[1:]) or (
        isinstance(value, str) and REMAP in value
    ):
        raise CommandError(f"Invalid remapping argument '{word}'")
    name = name.strip()
    value = value.strip() if isinstance(value, str) else value
    if not name or value == "":
        return ()
    if len(name) > 1 and name[0] == "_" and name[1] != "_":
        return ()
    return name, value


def options(words: Sequence[Raw]) -> dict[str, Raw | None]:
    """``-option value`` words (a word after an option that starts with ``-`` is the next
    option): each option's value, None for a flag."""
    found: dict[str, Raw | None] = {}
    current: str | None = None
    for word in words:
        if isinstance(word, str) and word.startswith("-") and not _number(word):
            current = word
            found[current] = None
        elif current is not None:
            found[current] = word
            current = None
    return found


def _number(word: str) -> bool:
    try:
        float(word)
    except ValueError:
        return False
    return True
