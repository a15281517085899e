"""Values of a Python launch file known at launch time only, as Python expressions.

``LaunchConfiguration('x').perform(context)`` is a string the file computes with when launch
runs it; rosvar reads the file before, for every configuration at once. Such a value is a
:class:`~rosvar.ros2.frontends.python.values.Dynamic`: the Python source of an expression over
substitutions (``float('$(var voxel)') * 10.0``) that the ROS 2 interpreter evaluates for each
configuration as it evaluates ``$(eval)``, through the same restricted evaluator. A value used
as text is ``$(eval <source>)`` (``str()`` of the result, as ``PythonExpression`` gives);
a branch on it is a condition ``$(eval 'bool(<source>)')``.

A launch-time string enters the expression as the ``repr`` of its value
(``$(rosvar-python-string ...)``): a value holding quotes or backslashes is the string it is.
"""

from __future__ import annotations

import ast

from rosvar.arithmetic import COMPARISON_SYMBOLS
from rosvar.ros2.frontends.python.text import PYTHON_STRING, Sub, Text
from rosvar.ros2.frontends.python.values import Conditional, Dynamic, Value

Kind = type | None
"""The Python type of a launch-time value where it is known (``None``: not known)."""

OPERATORS: dict[type[ast.AST], str] = {
    ast.Add: "+",
    ast.Sub: "-",
    ast.Mult: "*",
    ast.Div: "/",
    ast.FloorDiv: "//",
    ast.Mod: "%",
    **COMPARISON_SYMBOLS,
}
"""Python operators a launch-time value enters, with their source."""

STRING_METHODS: dict[str, Kind] = {
    "lower": str,
    "upper": str,
    "strip": str,
    "lstrip": str,
    "rstrip": str,
    "replace": str,
    "capitalize": str,
    "title": str,
    "startswith": bool,
    "endswith": bool,
    "isdigit": bool,
    "isnumeric": bool,
    "isalpha": bool,
    "split": list,
    "count": int,
    "find": int,
}
"""Methods of a launch-time string the expression keeps, with the type they return."""

CONVERSIONS: dict[str, Kind] = {"str": str, "int": int, "float": float, "bool": bool, "len": int}
"""Builtins applied to a launch-time value, with the type they return."""


def performed(text: Text) -> Dynamic:
    """The string a substitution gives at launch time (``.perform(context)``)."""
    return Dynamic(quoted(text), str, text)


def performed_value(text: Text) -> Value:
    """:func:`performed`, but a literal text is the string it is (a helper's ``perform``
    read again in one configuration computes with it)."""
    literal = text.literal()
    return performed(text) if literal is None else literal


def quoted(text: Text) -> Text:
    """``text`` as a Python string literal of its launch-time value: its ``repr`` where it is
    literal, else ``$(rosvar-python-string text)``, the ``repr`` of the value it gives."""
    literal = text.literal()
    if literal is not None:
        return Text.of(repr(literal))
    return Text.of(Sub(PYTHON_STRING, (text,)))


def source(value: Value) -> Text | None:
    """The Python source of ``value``; ``None`` when it has none (a launch object)."""
    if isinstance(value, Dynamic):
        return value.source
    if isinstance(value, str | int | float | bool) or value is None:
        return Text.of(repr(value))
    if isinstance(value, list | tuple):
        items = [source(item) for item in value]
        known = [item for item in items if item is not None]
        if len(known) < len(items):
            return None
        opening, closing = ("[", "]") if isinstance(value, list) else ("(", ",)")
        return Text.of(opening, *_arguments(known), closing)
    if isinstance(value, Conditional):  # a list chosen by a launch-time ``if``
        then, otherwise = source(value.then), source(value.otherwise)
        if then is not None and otherwise is not None:
            return chosen(value.test, then, otherwise, None).source
    return None


def kind_of(value: Value) -> Kind:
    if isinstance(value, Dynamic):
        return value.kind
    if isinstance(value, Conditional):
        kinds = {kind_of(value.then), kind_of(value.otherwise)}
        return kinds.pop() if len(kinds) == 1 else None
    if isinstance(value, bool | str | int | float):
        return type(value)
    return None


def as_text(value: Dynamic) -> Text:
    """What ``str(value)`` gives at launch time, as text."""
    if value.text is not None:
        return value.text
    return Text.of(Sub("eval", (value.source,)))


def stringified(value: Dynamic) -> Dynamic:
    if value.kind is str:
        return value
    return Dynamic(Text.of("str(", value.source, ")"), str, as_text(value))


def concatenated(parts: list[Text]) -> Dynamic:
    """Launch-time strings joined (``+``, f-strings, ``join``)."""
    return performed(Text.of(*parts))


def binary(operator: str, left: Text, right: Text, kind: Kind) -> Dynamic:
    return Dynamic(Text.of("(", left, f") {operator} (", right, ")"), kind)


def arithmetic_kind(operator: str, left: Kind, right: Kind) -> Kind:
    """The type of ``left <operator> right`` as Python gives it, where the operands' are known."""
    if operator in ("==", "!=", "<", "<=", ">", ">=", "in", "not in", "is", "is not"):
        return bool
    numbers = (int, float, bool)
    if left in numbers and right in numbers:
        if operator == "/" or float in (left, right):
            return float
        return int
    if operator == "+" and left is right is str:
        return str
    if operator == "*" and {left, right} in ({str, int}, {str, bool}):
        return str
    return None


def _arguments(args: list[Text]) -> list[str | Text]:
    inner: list[str | Text] = []
    for index, arg in enumerate(args):
        inner.extend([", ", arg] if index else [arg])
    return inner


def call(function: str, args: list[Text]) -> Dynamic:
    """``function(args)`` of a builtin in :data:`CONVERSIONS`."""
    return Dynamic(Text.of(f"{function}(", *_arguments(args), ")"), CONVERSIONS[function])


def method(receiver: Dynamic, name: str, args: list[Text]) -> Dynamic:
    """``receiver.name(args)`` of a method in :data:`STRING_METHODS`."""
    parts = ("(", receiver.source, f").{name}(", *_arguments(args), ")")
    return Dynamic(Text.of(*parts), STRING_METHODS[name])


def negated(test: Text) -> Text:
    return Text.of("not (", test, ")")


def truth(test: Text) -> Text:
    return Text.of("bool(", test, ")")


def chosen(test: Text, then: Text, otherwise: Text, kind: Kind) -> Dynamic:
    """``then if test else otherwise``."""
    return Dynamic(Text.of("(", then, ") if (", test, ") else (", otherwise, ")"), kind)


def condition(test: Text) -> Text:
    """The ``if`` attribute text true where the Python ``test`` holds: ``True``/``False``."""
    return Text.of(Sub("eval", (truth(test),)))


def evaluated(attribute: str, text: Text) -> Dynamic:
    """``IfCondition(x).evaluate(context)`` (``UnlessCondition``): launch's truth of the text
    (``true``/``1`` in any case, surrounding blanks ignored; another value, which launch
    refuses, reads as false)."""
    truthy = Text.of("(", quoted(text), ").strip().lower() in ('true', '1')")
    return Dynamic(truthy if attribute == "if" else negated(truthy), bool)
