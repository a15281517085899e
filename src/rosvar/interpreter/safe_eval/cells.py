"""The values of one arg that an ``$(eval)`` expression cannot tell apart.

When every read of an arg is an operand of a comparison with literals (``arg('dof') == 6``,
``lds_model in ('LDS-01', 'LDS-02')``, ``3 < x <= 7``), the expression's result depends only
on which *cell* of the literals the arg's value (as ``convert_auto`` types it) falls in: each
literal, each open interval between two numbers, below and above them all, any other text.
One value per cell then shows every way such expressions can come out together, so two
``if``s over one arg whose results no value shares exclude each other exactly (the facts of
:mod:`rosvar.logic.cells`), whatever the operators; any other use of the arg gives no cells.
"""

from __future__ import annotations

import ast
import itertools
import math
from collections.abc import Iterable
from decimal import Decimal

from rosvar.interpreter.safe_eval.checking import _checked
from rosvar.interpreter.safe_eval.errors import EvalRefused
from rosvar.interpreter.safe_eval.interpreter import convert_auto
from rosvar.interpreter.safe_eval.names import _BOOL_NAMES, _HOST_FUNCTION_NAMES, _NOT_ARG_NAMES

Literal = bool | int | float | str
_ORDER = (ast.Lt, ast.LtE, ast.Gt, ast.GtE)
_EQUALITY = (ast.Eq, ast.NotEq)
_MEMBERSHIP = (ast.In, ast.NotIn)
_FRESH = "\x00any other text"


def compared_constants(expression: str, arg: str) -> frozenset[Literal] | None:
    """The literals ``arg`` is compared with, when comparisons with literals are its only
    uses in ``expression``; None otherwise (the cells would not decide the result)."""
    try:
        tree = _checked(expression)[0]
    except EvalRefused:
        return None
    parents = {
        id(child): parent for parent in ast.walk(tree) for child in ast.iter_child_nodes(parent)
    }
    constants: set[Literal] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ListComp | ast.SetComp | ast.DictComp | ast.GeneratorExp):
            return None  # a comprehension's own names could shadow the arg
        if _is_arg_call(node) and _call_name(node) is None:
            return None  # a computed arg(x) may read it
        if _host_call(node):
            return None  # find(), env(): what the witnesses give depends on the machine
        if not _reads(node, arg):
            continue
        found = _comparison_literals(parents.get(id(node)), node)
        if found is None:
            return None
        constants |= found
    return frozenset(constants) if all(map(_exact, constants)) else None


def witnesses(constants: Iterable[Literal]) -> tuple[str, ...]:
    """An arg text in every cell of ``constants`` (and perhaps more): each literal, a
    number between each two and beyond them, and a text equal to none."""
    numbers = sorted({float(c) for c in constants if not isinstance(c, str)})
    points = [*numbers, numbers[0] - 1, numbers[-1] + 1] if numbers else [0.0]
    points += [(a + b) / 2 for a, b in itertools.pairwise(numbers)]
    texts = [_number_text(p) for p in points]
    texts += [c for c in constants if isinstance(c, str)]
    return tuple(dict.fromkeys([*texts, _FRESH]))


def _number_text(number: float) -> str:
    """A text ``convert_auto`` reads back as exactly ``number`` (a float needs its dot)."""
    if number.is_integer():
        return str(int(number))
    text = format(Decimal(number), "f")
    assert convert_auto(text) == number
    return text


def _is_arg_call(node: ast.AST) -> bool:
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == "arg"


def _host_call(node: ast.AST) -> bool:
    return (
        isinstance(node, ast.Call)
        and isinstance(node.func, ast.Name)
        and node.func.id in _HOST_FUNCTION_NAMES - {"arg"}
    )


def _call_name(node: ast.AST) -> str | None:
    assert isinstance(node, ast.Call)
    if len(node.args) == 1 and not node.keywords:
        argument = node.args[0]
    elif not node.args and len(node.keywords) == 1 and node.keywords[0].arg == "name":
        argument = node.keywords[0].value
    else:
        return None
    if isinstance(argument, ast.Constant) and isinstance(argument.value, str):
        return argument.value
    return None


def _reads(node: ast.AST, arg: str) -> bool:
    """Whether ``node`` is a read of ``arg`` (a bare name or ``arg('name')``)."""
    if isinstance(node, ast.Name):
        return node.id == arg and node.id not in _NOT_ARG_NAMES
    return _is_arg_call(node) and _call_name(node) == arg


def _comparison_literals(parent: ast.AST | None, read: ast.AST) -> set[Literal] | None:
    """The literals ``read`` is compared with in ``parent``, if that is all it does."""
    if not isinstance(parent, ast.Compare):
        return None
    operands = [parent.left, *parent.comparators]
    index = next(i for i, operand in enumerate(operands) if operand is read)
    found: set[Literal] = set()
    sides = [(parent.ops[index - 1], operands[index - 1], False)] if index > 0 else []
    if index < len(parent.ops):
        sides.append((parent.ops[index], operands[index + 1], True))
    for op, other, read_first in sides:
        if not isinstance(op, _ORDER + _EQUALITY + _MEMBERSHIP):
            return None  # `is` tells apart values that compare equal
        if isinstance(op, _MEMBERSHIP) and not read_first:
            return None  # `'a' in x` is a substring test
        values = _literals(other, isinstance(op, _MEMBERSHIP))
        if values is None:
            return None
        if isinstance(op, _ORDER) and any(isinstance(v, str) for v in values):
            return None  # the order of texts has cells between any two
        found |= values
    return found


def _literals(node: ast.expr, collection: bool) -> set[Literal] | None:
    """A literal's value; a display of literals' when ``collection`` (after ``in``)."""
    if collection:
        if not isinstance(node, ast.Tuple | ast.List | ast.Set):
            return None
        values = [_literal(element) for element in node.elts]
        return None if any(v is None for v in values) else {v for v in values if v is not None}
    value = _literal(node)
    return None if value is None else {value}


def _exact(value: Literal) -> bool:
    """Whether a number keeps its cells as a float (finite, and an int within float's
    exact range): the witnesses are computed in floats."""
    if isinstance(value, str | bool):
        return True
    if isinstance(value, int):
        return abs(value) <= 1 << 53
    return math.isfinite(value)


def _literal(node: ast.expr) -> Literal | None:
    if isinstance(node, ast.Constant) and isinstance(node.value, bool | int | float | str):
        return node.value
    if (
        isinstance(node, ast.UnaryOp)
        and isinstance(node.op, ast.USub | ast.UAdd)
        and isinstance(node.operand, ast.Constant)
        and isinstance(node.operand.value, int | float)
        and not isinstance(node.operand.value, bool)
    ):
        number = node.operand.value
        return -number if isinstance(node.op, ast.USub) else number
    if isinstance(node, ast.Name) and node.id in _BOOL_NAMES:
        return _BOOL_NAMES[node.id]
    return None
