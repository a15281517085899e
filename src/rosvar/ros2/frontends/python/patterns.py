"""``re`` as launch helpers use it: a literal pattern matched against a literal name.

moveit's builder picks its configuration files by name (``re.compile("^(.*)_planning.yaml$")
.search(child.name)``, then ``m.groups()``). Python's ``re`` backtracks, so a hostile pattern
(``(a+)+$``) takes time exponential in the string: a pattern is matched only where its work
is bounded by construction, at most :data:`MAX_QUANTIFIERS` quantifiers, none repeating a
group (``(...)?`` is one), over strings of at most :data:`MAX_SUBJECT` characters (a file
name has at most 255); any other stays unknown, reported.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Callable
from typing import Protocol

from rosvar.ros2.frontends.python.values import Match, Pattern, Unknown, Value

MAX_PATTERN = 200
"""Longest pattern followed."""
MAX_QUANTIFIERS = 2
"""Quantifiers (``*``, ``+``, ``?``, ``{m,n}``) of a pattern followed: backtracking over a
string of n characters costs at most n to the power of their number, plus one."""
MAX_SUBJECT = 256
"""Longest string a pattern is matched against."""


class Interpreter(Protocol):
    def not_followed(self, what: str, node: ast.AST) -> Unknown: ...


def _bounded(source: str) -> bool:
    """Whether ``source`` has few quantifiers and none repeats a group (``(...)*``)."""
    quantifiers, index, previous = 0, 0, ""
    while index < len(source):
        char = source[index]
        if char == "\\":
            index, previous = index + 2, "atom"
            continue
        if char == "[":  # a class is one atom: skip to its end
            end = source.find("]", index + 2)
            index, previous = (len(source) if end < 0 else end + 1), "atom"
            continue
        if char in "*+{" or (char == "?" and previous not in ("(", "quantifier")):
            if previous == ")" and char != "?":  # an optional group repeats nothing
                return False
            quantifiers += 1
            previous = "quantifier"
        else:
            previous = char if char in "()" else "atom"
        index += 1
    return quantifiers <= MAX_QUANTIFIERS


def compile_pattern(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``re.compile(pattern)`` of a literal pattern without flags."""
    source = args[0] if len(args) == 1 and not kwargs else None
    if not isinstance(source, str):
        return interpreter.not_followed("re.compile() of a value not known statically", node)
    if len(source) > MAX_PATTERN or not _bounded(source):
        return interpreter.not_followed("a regular expression of unbounded work", node)
    try:
        re.compile(source)
    except re.error as error:
        return interpreter.not_followed(f"re.compile() that fails ({error})", node)
    return Pattern(source)


def _matcher(name: str) -> Callable[[Interpreter, Pattern, list[Value], ast.AST], Value]:
    def match(
        interpreter: Interpreter, pattern: Pattern, args: list[Value], node: ast.AST
    ) -> Value:
        subject = args[0] if len(args) == 1 else None
        if not isinstance(subject, str):
            return interpreter.not_followed(f"{name}() of a value not known statically", node)
        if len(subject) > MAX_SUBJECT:
            return interpreter.not_followed(f"{name}() of a string over {MAX_SUBJECT}", node)
        found = getattr(re.compile(pattern.source), name)(subject)
        return None if found is None else Match(found.group(0), found.groups())

    return match


METHODS = {name: _matcher(name) for name in ("search", "match", "fullmatch")}
"""A pattern's methods the reading follows."""


def module_function(
    name: str,
) -> Callable[[Interpreter, list[Value], dict[str, Value], ast.AST], Value]:
    """``re.search(pattern, string)`` and kin: the pattern compiled, then matched."""

    def call(
        interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
    ) -> Value:
        if len(args) != 2:
            return interpreter.not_followed(f"re.{name}() with flags", node)
        pattern = compile_pattern(interpreter, args[:1], kwargs, node)
        if not isinstance(pattern, Pattern):
            return pattern
        return METHODS[name](interpreter, pattern, args[1:], node)

    return call


def match_method(
    interpreter: Interpreter, found: Match, name: str, args: list[Value], node: ast.AST
) -> Value:
    """``m.groups()``, ``m.group(i)``."""
    if name == "groups" and not args:
        return found.groups
    if name == "group" and len(args) <= 1:
        index = args[0] if args else 0
        if isinstance(index, int) and 0 <= index <= len(found.groups):
            return found.text if index == 0 else found.groups[index - 1]
    return interpreter.not_followed(f"method {name}() of a match", node)
