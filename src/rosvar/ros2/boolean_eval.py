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
A value not known yet (a term: an arg's ``<other>`` value) takes part too. Inside its literal
it is a string like any other, so each comparison of it is a predicate of the term (``t ==
'x'`` for an equality, whatever the text around it); an equality of an arg's ``<other>`` value
with one of that arg's listed values is false outright (``<other>`` is none of them). Where a
term may leave its literal (a quote in it rewrites the expression) the predicate "it stays one
plain literal" does not hold, and there the expression's value is one unknown term for the
whole expression, which a configuration computes (:class:`~rosvar.logic.given_up.GivenUp`).
Every other expression, or value, is crossed as before (:mod:`rosvar.ros2.substitutions`).
"""

from __future__ import annotations

import ast
import functools
import warnings
from collections.abc import Callable, Hashable, Iterable, Sequence
from dataclasses import dataclass
from itertools import pairwise
from typing import Any, cast

from rosvar.arithmetic import COMPARISON_SYMBOLS, COMPARISONS
from rosvar.interpreter.model import Raw
from rosvar.interpreter.safe_eval import EvalRefused, referenced_names
from rosvar.logic.atoms import register_predicate
from rosvar.logic.bdd import BDD
from rosvar.logic.cells import Cells, register_cells
from rosvar.logic.choice import Choice, Fail
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import Input
from rosvar.logic.terms import Apply, Hole, Term, concat, register

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
_SYMBOLS = {op: COMPARISON_SYMBOLS[op] for op in COMPARISONS if op not in (ast.Is, ast.IsNot)}
"""The comparisons of two strings whose result follows from their texts (not ``is``), by
their symbol: the name a comparison of a term has in its predicate."""
_COMPARED: dict[str, Callable[[Any, Any], Any]] = {
    symbol: COMPARISONS[op] for op, symbol in _SYMBOLS.items()
}
COMPARED = "python-compare"
"""The term function ``str(left op right)`` of two string operands (one a term)."""
PLAIN_LITERAL = "python-plain-literal"
"""The predicate "this text is one plain string literal" (quote, content, the same quote)."""


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

    def source(self, term: Term) -> str | Term:
        """The literal's source text with ``term`` in it: :data:`PLAIN_LITERAL` of it is
        :meth:`keeps` of the term's string (the text around it has no quote, escape, line
        break nor ``__`` of its own)."""
        return concat([self.quote + self.prefix, term, self.suffix + self.quote])

    def term_text(self, term: Term) -> str | Term:
        """The literal's value with ``term`` in it, where it keeps it."""
        return concat([self.prefix, term, self.suffix])

    def middle(self, text: str) -> str | None:
        """The value whose literal's string is ``text``, if there is one."""
        if len(text) < len(self.prefix) + len(self.suffix):
            return None
        if not text.startswith(self.prefix) or not text.endswith(self.suffix):
            return None
        return text[len(self.prefix) : len(text) - len(self.suffix)]


def _plain_literal(text: str) -> bool:
    """Whether ``text`` is one plain one-line string literal without escapes."""
    if len(text) < 2 or text[0] not in "'\"" or text[-1] != text[0]:
        return False
    return Literal(0, text[0], "", "").keeps(text[1:-1])


register_predicate(PLAIN_LITERAL, _plain_literal, "{} stays one string literal")


Operand = str | Literal


@dataclass(frozen=True)
class Comparison:
    """``operands[0] ops[0] operands[1] ops[1] ...``: a chain, each pair compared."""

    operands: tuple[Operand, ...]
    ops: tuple[str, ...]  # symbols of :data:`_COMPARED`


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
        """Whether every value of every substitution is a term, a failure or a string that
        stays inside its literal."""
        return all(
            literal.keeps(leaf) or isinstance(leaf, Hole | Apply | Fail)
            for literal, value in zip(self.literals, values, strict=True)
            for _condition, leaf in value.branches
        )

    def longest(self, values: Sequence[Choice[Value]]) -> int:
        """The length of the longest text the substitutions can make (a term's: its
        display's)."""
        return self.fixed + sum(max(len(str(leaf)) for leaf in v.values()) for v in values)

    def tested(self, values: Sequence[Choice[Value]]) -> int:
        """How many terms the comparisons test (each a predicate or more): the terms of each
        literal, and for a comparison of two literals, the pairs of their values with one."""
        terms = [sum(isinstance(leaf, Hole | Apply) for leaf in v.values()) for v in values]
        pairs = 0
        for left, right in _literal_pairs(self.root):
            pairs += terms[left] * len(values[right].branches)
            pairs += terms[right] * len(values[left].branches)
        return sum(terms) + pairs

    def escapes(self, space: ConditionSpace, values: Sequence[Choice[Value]]) -> BDD:
        """Where a term may leave its literal (its :data:`PLAIN_LITERAL` does not hold)."""
        result = space.false
        for literal, value in zip(self.literals, values, strict=True):
            for condition, leaf in value.branches:
                if isinstance(leaf, Hole | Apply):
                    kept = space.predicate(PLAIN_LITERAL, cast("Term", literal.source(leaf)))
                    result |= condition & ~kept
        return result

    def condition(self, space: ConditionSpace, values: Sequence[Choice[Value]]) -> BDD:
        """Where the expression is true, wherever every substitution has a value (not a
        failure) and no term leaves its literal (:meth:`escapes`)."""
        return _condition(self.root, space, values)


def _literal_pairs(node: Node) -> list[tuple[int, int]]:
    """The substitutions compared with each other in ``node``."""
    if isinstance(node, bool):
        return []
    if isinstance(node, Negation):
        return _literal_pairs(node.operand)
    if isinstance(node, Junction):
        return [pair for operand in node.operands for pair in _literal_pairs(operand)]
    return [
        (left.hole, right.hole)
        for left, right in pairwise(node.operands)
        if isinstance(left, Literal) and isinstance(right, Literal)
    ]


def _condition(node: Node, space: ConditionSpace, values: Sequence[Choice[Value]]) -> BDD:
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
    left: Operand, op: str, right: Operand, space: ConditionSpace, values: Sequence[Choice[Value]]
) -> BDD:
    """Where ``left op right`` holds: over the branches of the substitutions they hold."""
    if isinstance(left, str) and isinstance(right, str):
        return space.true if _COMPARED[op](left, right) else space.false
    if isinstance(left, str):
        assert isinstance(right, Literal)
        return _over(space, values[right.hole], functools.partial(_against, op, left, right, space))
    if isinstance(right, str):
        return _over(space, values[left.hole], functools.partial(_with, op, left, right, space))
    result = space.false
    for condition, leaf in values[left.hole].branches:
        if isinstance(leaf, Fail):
            continue
        against = functools.partial(_against, op, _Placed(left, leaf), right, space)
        result |= condition & _over(space, values[right.hole], against)
    return result


@dataclass(frozen=True)
class _Placed:
    """A literal with its value: a string's literal text, or a term inside it."""

    literal: Literal
    leaf: Raw

    def text(self) -> str | Term:
        if isinstance(self.leaf, str):
            return self.literal.text(self.leaf)
        return self.literal.term_text(self.leaf)


def _over(space: ConditionSpace, value: Choice[Value], holds: Callable[[Raw], BDD | bool]) -> BDD:
    """Where ``holds`` of ``value``'s leaf is true, a predicate for a term's leaf, wherever
    ``value`` has a leaf that is not a failure: elsewhere it is either (every caller reads it
    there only). It is built from the side with fewer branches, the branches where it holds
    or, negated, those where it does not: the other side's disjunction is never made."""
    sides: tuple[list[BDD], list[BDD]] = ([], [])  # where it holds, where it does not
    terms: list[tuple[BDD, BDD]] = []
    for condition, leaf in value.branches:
        if isinstance(leaf, Fail):
            continue
        where = holds(leaf)
        if isinstance(where, bool):
            sides[not where].append(condition)
        else:
            terms.append((condition, where))
    negated = len(sides[1]) < len(sides[0])
    result = space.false
    for condition in sides[negated]:
        result |= condition
    for condition, where in terms:
        result |= condition & (~where if negated else where)
    return ~result if negated else result


def _with(op: str, left: Literal, right: str, space: ConditionSpace, leaf: Raw) -> BDD | bool:
    """``left op right`` for ``leaf`` in ``left``."""
    if isinstance(leaf, str):
        return bool(_COMPARED[op](left.text(leaf), right))
    return _term_compared(space, op, (left, leaf), right)


def _against(
    op: str, left: str | _Placed, right: Literal, space: ConditionSpace, leaf: Raw
) -> BDD | bool:
    """``left op right`` for ``leaf`` in ``right``."""
    if isinstance(left, _Placed) and not isinstance(left.leaf, str):
        if isinstance(leaf, str):
            return _term_compared(space, op, (left.literal, left.leaf), right.text(leaf))
        return _predicate(space, left.text(), op, right.term_text(leaf))
    text = left if isinstance(left, str) else left.text()
    assert isinstance(text, str)
    if isinstance(leaf, str):
        return bool(_COMPARED[op](text, right.text(leaf)))
    return _term_compared(space, _MIRRORED.get(op, ""), (right, leaf), text, op)


_MIRRORED = {"==": "==", "!=": "!=", "<": ">", "<=": ">=", ">": "<", ">=": "<="}
"""``b op' a`` for ``a op b``, where there is one (``in`` has none)."""


def _term_compared(
    space: ConditionSpace, op: str, placed: tuple[Literal, Raw], text: str, original: str = ""
) -> BDD | bool:
    """``literal(term) op text`` where the term keeps its literal (``original``: the
    comparison as written, ``text`` first, where ``op`` has no mirror)."""
    literal, leaf = placed
    term = cast("Term", leaf)
    if op in ("==", "!="):  # the term's own equality, shared by every literal around it
        middle = literal.middle(text)
        equal: BDD | bool = False if middle is None else _equals(space, term, middle)
        return equal if op == "==" else _negated(equal)
    if not op:
        return _predicate(space, text, original, literal.term_text(term))
    return _predicate(space, literal.term_text(term), op, text)


def _negated(value: BDD | bool) -> BDD | bool:
    return not value if isinstance(value, bool) else ~value


def _equals(space: ConditionSpace, term: Term, text: str) -> BDD | bool:
    """``term == text``: false for an input's ``<other>`` value and one of its listed ones."""
    if isinstance(term, Hole) and text in space.domain(term.input):
        return False
    return _predicate(space, term, "==", text)


def _predicate(space: ConditionSpace, left: str | Term, op: str, right: str | Term) -> BDD:
    shown = " ".join((_shown(left), op, _shown(right)))
    return space.predicate("true", Apply(COMPARED, (left, op, right), shown))


def _shown(operand: str | Term) -> str:
    return repr(operand) if isinstance(operand, str) else f"'{operand}'"


def _compare_term(_host: object, left: str, op: str, right: str) -> str:
    return str(bool(_COMPARED[op](left, right)))


register(COMPARED, _compare_term)


def _compared_constants(term: Apply, input_: Input) -> frozenset[Hashable] | None:
    """What an equality of ``input_``'s own value compares it with (its cells); None for
    anything else."""
    left, op, right = term.operands
    if op not in ("==", "!=") or left != Hole(input_) or not isinstance(right, str):
        return None
    return frozenset((right,))


def _compared_witnesses(constants: Iterable[Hashable]) -> tuple[str, ...]:
    """Each constant, and a string equal to none of them."""
    texts = tuple(sorted(str(c) for c in constants))
    return (*texts, "x" * (1 + max((len(t) for t in texts), default=0)))


register_cells(COMPARED, Cells(_compared_constants, _compared_witnesses))


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
        ops = [_SYMBOLS.get(type(op)) for op in node.ops]
        compared = [_operand(o, text, literals) for o in (node.left, *node.comparators)]
        if any(op is None for op in ops) or any(o is None for o in compared):
            return None
        return Comparison(
            cast("tuple[Operand, ...]", tuple(compared)),
            cast("tuple[str, ...]", tuple(ops)),
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
