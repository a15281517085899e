"""launch's boolean substitutions: ``$(equals a b)``, ``$(not-equals a b)``, ``$(not x)``,
``$(and a b)``, ``$(or a b)`` and ``$(if c a [b])``, with the conditions
``LaunchConfigurationEquals``/``NotEquals`` and the ``AllSubstitution``/``AnySubstitution``
the Python frontend writes with them. ``$(all ...)`` and ``$(any ...)`` fail, as jazzy's XML
and YAML parsers fail on them (they pass ``args=``, which the classes do not take).

Each gives the text launch gives (``true``/``false``, or the chosen branch) as its
``perform`` computes it: ``equals`` compares ``true``/``false``/``1``/``0`` as booleans (any
case) and numbers as floats (``math.isclose``), else the texts; the others read their
operands as launch's typed substitution reads a ``bool`` (``1``/``0``, then YAML's booleans:
``yes``, ``On``, ``TRUE``...), any other text failing the launch. Where an operand is an
argument's ``<other>`` value, the result is a term computed once the value is known, except
an ``equals`` of a text that is neither a boolean nor a number with one of the argument's
foreseen values: ``<other>`` is none of them, so they differ.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import yaml

from rosvar import bounded_yaml
from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.model import Raw
from rosvar.logic.choice import Choice, Fail
from rosvar.logic.inputs import OTHER, ArgInput
from rosvar.logic.terms import Apply, Hole, TermError, is_term, register
from rosvar.ros2.context import Context
from rosvar.ros2.frontends.python.text import CONFIGURATION_EQUALS, EMPTY
from rosvar.ros2.substitutions import (
    EMPTY_ARGUMENT,
    UNSUPPORTED,
    Handler,
    Value,
    configuration,
    substitution,
)

MAX_BOOLEAN_TEXT = 4096
"""Longer texts are no boolean (YAML reads a word, with spaces and a comment at most)."""


class NotBoolean(ValueError):
    """A text launch's typed substitution does not read as a ``bool``."""


def _is_boolean_word(text: str) -> bool:
    return text.lower() in ("true", "false", "1", "0")


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def equals(left: str, right: str) -> str:
    """``EqualsSubstitution.perform``."""
    if _is_boolean_word(left) and _is_boolean_word(right):
        same = (left.lower() in ("true", "1")) == (right.lower() in ("true", "1"))
    elif _is_number(left) and _is_number(right):
        same = math.isclose(float(left), float(right))
    else:
        same = left == right
    return "true" if same else "false"


def typed_bool(text: str) -> bool:
    """``perform_typed_substitution(context, text, bool)``; raises :class:`NotBoolean`."""
    text = {"1": "true", "0": "false"}.get(text, text)
    if not text or len(text) > MAX_BOOLEAN_TEXT:
        raise NotBoolean(f"Cannot convert value '{text[:80]}' to 'bool'")
    try:
        value = bounded_yaml.safe_load(text)
    except yaml.YAMLError:  # a limit too: no YAML that deep or large is a boolean
        raise NotBoolean(f"Failed to convert '{text}' to 'bool'") from None
    if not isinstance(value, bool):
        raise NotBoolean(f"Cannot convert value '{text}' to 'bool'")
    return value


def _text(value: bool) -> str:
    return "true" if value else "false"


Function = Callable[..., str]
"""A substitution's ``perform`` over the operands' texts; raises :class:`NotBoolean`."""

FUNCTIONS: dict[str, Function] = {
    "equals": equals,
    "not-equals": lambda left, right: _text(equals(left, right) == "false"),
    "not": lambda value: _text(not typed_bool(value)),
    "and": lambda left, right: _text(typed_bool(left) and typed_bool(right)),
    "or": lambda left, right: _text(typed_bool(left) or typed_bool(right)),
    "if": lambda condition, if_value, else_value="": (
        if_value if typed_bool(condition) else else_value
    ),
}
ARITY: dict[str, tuple[int, int]] = {
    "equals": (2, 2),
    "not-equals": (2, 2),
    "not": (1, 1),
    "and": (2, 2),
    "or": (2, 2),
    "if": (2, 3),
}
"""How many arguments each takes (launch's ``parse`` refuses others)."""


def _term_function(name: str) -> Callable[..., str]:
    def compute(_host: object, *operands: str) -> str:
        try:
            return FUNCTIONS[name](*operands)
        except NotBoolean as error:
            raise TermError(f"$({name}): {error}") from None

    return compute


def _shown(operand: Raw) -> str:
    """An operand as the ``$(...)`` text would write it."""
    if isinstance(operand, Hole):
        kind = "var" if isinstance(operand.input, ArgInput) else "env"
        return f"$({kind} {operand.input.name})"
    if not isinstance(operand, str):
        return str(operand)
    plain = operand and not any(c.isspace() or c in "'\"()$\\" for c in operand)
    return operand if plain else repr(operand)


def _differs_from_foreseen(
    host: Interpretation[Context], args: Sequence[Raw | None], by_value: bool = True
) -> bool:
    """An ``<other>`` value compared with one of its input's foreseen texts, which is
    neither a boolean nor a number where they compare ``by_value`` (``1.0`` equals ``1``,
    ``TRUE`` equals ``true``)."""
    hole = next((arg for arg in args if isinstance(arg, Hole)), None)
    other = next((arg for arg in args if isinstance(arg, str)), None)
    if hole is None or other is None:
        return False
    if by_value and (_is_boolean_word(other) or _is_number(other)):
        return False
    domain = host.space.domain(hole.input)
    return OTHER in domain and other in domain


def _compute(name: str) -> Handler:
    def handler(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
        least, most = ARITY[name]
        if not least <= len(args) <= most:
            return Choice.const(
                host.space,
                Fail(f"$({name}) takes {least} to {most} arguments", "substitution-invalid"),
            )
        result: Value
        if any(is_term(arg) for arg in args):
            if name in ("equals", "not-equals") and _differs_from_foreseen(host, args):
                result = "false" if name == "equals" else "true"
            else:
                display = " ".join(_shown(arg) for arg in args)
                result = Apply(f"ros2-{name}", tuple(args), f"$({name} {display})")
        else:
            try:
                result = FUNCTIONS[name](*args)
            except NotBoolean as error:
                result = Fail(f"$({name}): {error}", "bool-invalid")
        return Choice.const(host.space, result)

    return handler


for _name in FUNCTIONS:
    substitution(_name)(_compute(_name))
    register(f"ros2-{_name}", _term_function(_name))


def _unparsable(name: str) -> Handler:
    def handler(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
        cls = {"all": "AllSubstitution", "any": "AnySubstitution"}[name]
        message = f"$({name}) fails in jazzy's frontends: {cls}() takes no 'args'"
        return Choice.const(host.space, Fail(message, UNSUPPORTED))

    return handler


for _name in ("all", "any"):
    substitution(_name)(_unparsable(_name))


EMPTY_ARGUMENT.update({"equals": "[]", "not-equals": "[]"})  # str([]): '' is an empty list


@substitution(EMPTY)
def _empty(host: Interpretation[Context], context: Context, args: list[Raw]) -> Choice[Value]:
    return Choice.const(host.space, "")


@substitution(CONFIGURATION_EQUALS)
def _configuration_equals(
    host: Interpretation[Context], context: Context, args: list[Raw]
) -> Choice[Value]:
    """``LaunchConfigurationEquals``' predicate: the configuration is the text (an undefined
    one is only equal to no text)."""
    if len(args) not in (1, 2) or not isinstance(args[0], str):
        return Choice.const(
            host.space, Fail("LaunchConfigurationEquals takes a name", "substitution-invalid")
        )
    expected = args[1] if len(args) == 2 else None

    def compare(value: Raw | None) -> Value:
        if value is None or expected is None:
            return _text(value is None and expected is None)
        if isinstance(value, str) and isinstance(expected, str):
            return _text(value == expected)
        if _differs_from_foreseen(host, (value, expected), by_value=False):
            return "false"
        display = f"$({CONFIGURATION_EQUALS} {_shown(args[0])} {_shown(expected)})"
        return Apply("ros2-text-equals", (value, expected), display)

    return configuration(host, context, args[0]).map(compare)


register("ros2-text-equals", lambda _host, left, right: _text(left == right))
