"""An ``$(eval)`` whose value is a boolean function of comparisons of the values it is made
of, computed as a condition over those values instead of by crossing them.

Launch evaluates ``str(eval(text))`` on the text the substitutions inside the expression make.
Where that text is comparisons (``==``, ``!=``, ``<``, ``in`` ...) of string literals joined by
``and``, ``or`` and ``not``, each substituted value inside a literal of its own that it
cannot leave (no quote, backslash or line break in it), the value is ``True`` exactly where
that boolean function of the comparisons holds, and each comparison holds where its
operand's value makes it hold: a disjunction over that operand's branches. The work then
grows with the sum of the operands' branches, not with their product (a ``<let>`` of four
args of three values each was 81 texts evaluated, conjoined and merged, in every includer).
Every other expression, or value, is crossed as before (:mod:`rosvar.ros2.substitutions`).
"""

from __future__ import annotations

import ast
import functools
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from itertools import pairwise
from typing import Any, cast

from rosvar.arithmetic import COMPARISONS
from rosvar.interpreter.model import Raw
from rosvar.interpreter.safe_eval import EvalRefused, referenced_names
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, Fail
from rosvar.logic.conditions import ConditionSpace

Value = Raw | Fail
Template = tuple[object, ...]
"""A substitution argument: text (``str``) and the substitutions in it (anything else)."""

HOLES = 0xE000
"""The first of the private-use characters that stand for the substitutions while the
expression's shape is read (``HOLES + i`` for the ``i``-th); text holding one is crossed."""
MAX_HOLES = 0x1000
_LEAVE = frozenset("\\\n\r\0")
"""Characters that end or change a string literal besides its quote (the parser rejects a
NUL); a value holding one, or a surrogate, is crossed."""
_COMPARED = {op: function for op, function in COMPARISONS.items() if op not in (ast.Is, ast.IsNot)}
"""The comparisons of two strings whose result follows from their texts (not ``is``)."""


@dataclass(frozen=True)
class Literal:
    """A string literal holding one substituted value: ``quote prefix VALUE suffix quote``."""

    hole: int  # which substitution, in the expression's order
    quote: str
    prefix: str
    suffix: str

    def text(self, value: str) -> str:
        """The literal's string (its value in the expression) for ``value``."""
        return self.prefix + value + self.suffix

    def keeps(self, value: object) -> bool:
        """Whether ``value`` substituted stays the literal's content: a string with no quote,
        escape or line break, and no ``__`` made with the text beside it (refused by the
        evaluator wherever it is)."""
        if type(value) is not str or self.quote in value or not _LEAVE.isdisjoint(value):
            return False
        if "__" in self.prefix[-1:] + value + self.suffix[:1]:
            return False
        return all(not 0xD800 <= ord(ch) <= 0xDFFF for ch in value)


Operand = str | Literal


@dataclass(frozen=True)
class Comparison:
    """``operands[0] ops[0] operands[1] ops[1] ...``: a chain, each pair compared."""

    operands: tuple[Operand, ...]
    ops: tuple[Callable[[Any, Any], Any], ...]


@dataclass(frozen=True)
class Junction:
    """``and`` (``conjunctive``) or ``or`` of boolean operands: a boolean."""

    conjunctive: bool
    operands: tuple[Node, ...]


@dataclass(frozen=True)
class Negation:
    operand: Node


Node = bool | Comparison | Junction | Negation


@dataclass(frozen=True)
class BooleanExpression:
    """An expression of the shape above: its tree, its literals with a substitution each (in
    the substitutions' order), and its fixed text's length."""

    root: Node
    literals: tuple[Literal, ...]
    fixed: int

    def accepts(self, values: Sequence[Choice[Value]]) -> bool:
        """Whether every value of every substitution stays inside its literal."""
        return all(
            literal.keeps(leaf)
            for literal, value in zip(self.literals, values, strict=True)
            for _condition, leaf in value.branches
        )

    def longest(self, values: Sequence[Choice[Value]]) -> int:
        """The length of the longest text the substitutions can make."""
        return self.fixed + sum(max(len(cast("str", leaf)) for leaf in v.values()) for v in values)

    def condition(self, space: ConditionSpace, values: Sequence[Choice[str]]) -> BDD:
        """Where the expression is true, wherever every substitution has a value."""
        return _condition(self.root, space, values)


def _condition(node: Node, space: ConditionSpace, values: Sequence[Choice[str]]) -> BDD:
    if isinstance(node, bool):
        return space.true if node else space.false
    if isinstance(node, Negation):
        return ~_condition(node.operand, space, values)
    if isinstance(node, Junction):
        result = space.true if node.conjunctive else space.false
        for operand in node.operands:
            condition = _condition(operand, space, values)
            result = result & condition if node.conjunctive else result | condition
        return result
    result = space.true
    for (left, right), op in zip(pairwise(node.operands), node.ops, strict=True):
        result &= _compared(left, op, right, space, values)
    return result


def _compared(
    left: Operand,
    op: Callable[[Any, Any], Any],
    right: Operand,
    space: ConditionSpace,
    values: Sequence[Choice[str]],
) -> BDD:
    """Where ``left op right`` holds: over the branches of the substitutions they hold."""
    if isinstance(left, str) and isinstance(right, str):
        return space.true if op(left, right) else space.false
    if isinstance(left, str):
        assert isinstance(right, Literal)
        return values[right.hole].where(lambda leaf: bool(op(left, right.text(leaf))))
    if isinstance(right, str):
        return values[left.hole].where(lambda leaf: bool(op(left.text(leaf), right)))
    result = space.false
    for condition, leaf in values[left.hole].branches:
        result |= condition & values[right.hole].where(
            functools.partial(_holds, op, left.text(leaf), right)
        )
    return result


def _holds(op: Callable[[Any, Any], Any], left: str, right: Literal, leaf: str) -> bool:
    return bool(op(left, right.text(leaf)))


@functools.lru_cache(maxsize=4096)
def boolean_expression(template: Template, namespaces: frozenset[str]) -> BooleanExpression | None:
    """The shape of the expression ``template`` makes, if it is one of comparisons of string
    literals, each substitution inside one literal of its own (None otherwise); the
    evaluator reads the members of ``namespaces``."""
    pieces: list[str] = []
    holes = 0
    for part in template:
        if isinstance(part, str):
            if "__" in part or any(HOLES <= ord(ch) < HOLES + MAX_HOLES for ch in part):
                return None
            pieces.append(part)
        else:
            if holes == MAX_HOLES:
                return None
            pieces.append(chr(HOLES + holes))
            holes += 1
    text = "".join(pieces).lstrip(" \t")  # as the evaluator reads it
    try:  # the evaluator's own checks (whitelist, nesting): a text it refuses is crossed
        referenced_names(text, namespaces)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            tree = ast.parse(text, mode="eval")
    except (EvalRefused, SyntaxError, ValueError, RecursionError, MemoryError):
        return None
    literals: dict[int, Literal] = {}
    root = _node(tree.body, text, literals)
    if root is None or sorted(literals) != list(range(holes)):
        return None
    fixed = sum(len(piece) for piece in pieces) - holes
    return BooleanExpression(root, tuple(literals[i] for i in range(holes)), fixed)


def _node(node: ast.expr, text: str, literals: dict[int, Literal]) -> Node | None:
    """The boolean shape of ``node``, recording its literals; None for anything else."""
    if isinstance(node, ast.Constant) and type(node.value) is bool:
        return node.value
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.Not):
        operand = _node(node.operand, text, literals)
        return None if operand is None else Negation(operand)
    if isinstance(node, ast.BoolOp):
        operands = [_node(value, text, literals) for value in node.values]
        if any(operand is None for operand in operands):
            return None
        return Junction(isinstance(node.op, ast.And), cast("tuple[Node, ...]", tuple(operands)))
    if isinstance(node, ast.Compare):
        ops = [_COMPARED.get(type(op)) for op in node.ops]
        compared = [_operand(o, text, literals) for o in (node.left, *node.comparators)]
        if any(op is None for op in ops) or any(o is None for o in compared):
            return None
        return Comparison(
            cast("tuple[Operand, ...]", tuple(compared)),
            cast("tuple[Callable[[Any, Any], Any], ...]", tuple(ops)),
        )
    return None


def _operand(node: ast.expr, text: str, literals: dict[int, Literal]) -> Operand | None:
    """A string literal: its value, or the substitution it holds (its only one, in a plain
    one-line literal without escapes: the value's text is its content)."""
    if not isinstance(node, ast.Constant) or type(node.value) is not str:
        return None
    holes = [ch for ch in node.value if HOLES <= ord(ch) < HOLES + MAX_HOLES]
    if not holes:
        return node.value
    source = ast.get_source_segment(text, node)
    if source is None or len(holes) != 1 or len(source) < 2:
        return None
    quote, body = source[0], source[1:-1]
    if quote not in "'\"" or source[-1] != quote or quote in body or "\\" in body:
        return None  # a prefix, triple quotes, implicit concatenation or escapes
    hole = ord(holes[0]) - HOLES
    prefix, suffix = body.split(holes[0])
    literals[hole] = Literal(hole, quote, prefix, suffix)
    return literals[hole]
