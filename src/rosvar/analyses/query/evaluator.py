"""Queries evaluated over the variational model: each result with the condition it holds under.

A predicate is interpreted over conditional values: every sub-expression evaluates to a
:class:`~rosvar.logic.choice.Choice`, operators apply branch by branch to the jointly possible
combinations of their operands' branches, and a predicate holds where its value is true. So
``self.package == 'kobuki_node'`` on a node whose package depends on an arg holds exactly for
the values of the arg that give that package, and ``len(self.publishers) > 1`` holds where
more than one of the conditional publishers is present.

A branch that Python would fail on (``None.startswith``, ``'a' < 1``) or whose text analysis
cannot know (an ``<other>`` arg value, None) does not satisfy the predicate; ``and``, ``or``
and ``not`` give True or False. Resource guards refuse (:class:`QueryError`), never truncate.
"""

from __future__ import annotations

import ast
import operator
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Final

from rosvar.analyses.feature_model.operations import simplest_trigger
from rosvar.analyses.query.collections import COLLECTIONS, Collection, ElementSet, Queryable
from rosvar.analyses.query.parser import CONSTANTS, Predicate, Query, QueryError, parse
from rosvar.interpreter.safe_eval.limits import MAX_SEQUENCE
from rosvar.interpreter.safe_eval.names import _COMPARE_OPS
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER

MAX_BRANCHES: Final = 1_000_000
"""Operand combinations one query may evaluate (over all elements)."""


class _Failed:
    """The value of a branch where Python would raise: never true, poisons what uses it."""

    def __repr__(self) -> str:
        return "<failed>"


FAILED: Final = _Failed()
_ERRORS: Final = (TypeError, ValueError, AttributeError, IndexError, KeyError, ArithmeticError)
_BINARY: Final[Mapping[type[ast.operator], Callable[[Any, Any], Any]]] = {
    ast.Add: operator.add,
    ast.Sub: operator.sub,
    ast.Mult: operator.mul,
    ast.Div: operator.truediv,
    ast.FloorDiv: operator.floordiv,
    ast.Mod: operator.mod,
}
_FUNCTIONS: Final[Mapping[str, Callable[..., object]]] = {
    "str": str,
    "int": int,
    "float": float,
    "abs": abs,
    "min": min,
    "max": max,
}


@dataclass(frozen=True)
class Result:
    """An element the query selects and the condition under which it does."""

    element: Queryable
    condition: BDD


class QueryEngine:
    """The elements of an analysis' entry files, listed once, and queries over them."""

    def __init__(self, analysis: Analysis, files: Sequence[str] | None = None) -> None:
        self.analysis = analysis
        self.space = analysis.space
        self.models = [
            analysis.model(f) for f in (analysis.workspace.launch_files if files is None else files)
        ]
        self._elements: dict[str, list[Queryable]] = {}
        self._satisfiable: dict[BDD, bool] = {}
        self._examples: dict[BDD, dict[str, str]] = {}

    def elements(self, collection: Collection) -> list[Queryable]:
        found = self._elements.get(collection.name)
        if found is None:
            found = self._elements[collection.name] = [
                element
                for model in self.models
                for element in collection.provider(self.analysis, model)
            ]
        return found

    def restriction(self, args: Mapping[str, str]) -> dict[str, BDD]:
        """Per entry file (label): the condition that its args have the given values."""
        space = self.space
        restricted: dict[str, BDD] = {}
        for model in self.models:
            condition = space.true
            for name, value in args.items():
                input_ = model.inputs.get(name)
                if input_ is not None:
                    slot = value if value in space.domain(input_) else OTHER
                    condition &= space.slot(input_, slot)
            restricted[self.analysis.label(model.file)] = condition
        return restricted

    def run(self, text: str, args: Mapping[str, str] | None = None) -> list[Result]:
        """The elements ``text`` selects (``name:=value`` ``args`` restrict the question)."""
        query = parse(text)
        collection = COLLECTIONS.get(query.collection)
        if collection is None:
            known = ", ".join(sorted(COLLECTIONS))
            raise QueryError(f"unknown collection '{query.collection}' (collections: {known})")
        for predicate in query.predicates:
            _check_attributes(predicate, collection)
        restriction = self.restriction(args or {})
        evaluation = _Evaluation(self.space, query)
        results = []
        false, true = self.space.false, self.space.true
        for element in self.elements(collection):
            restricted = restriction[element.file]
            condition = element.presence if restricted is true else element.presence & restricted
            for predicate in query.predicates:
                if condition == false:
                    break
                condition &= evaluation.truth(predicate, element)
            if condition != false and self.satisfiable(condition):
                results.append(Result(element, condition))
        return results

    def to_json(self, result: Result) -> dict[str, object]:
        """``result`` as ``--json`` shows it (docs/schema/query.schema.json)."""
        element, condition = result.element, result.condition
        example = self._examples.get(condition)
        if example is None:
            example = self._examples[condition] = simplest_trigger(self.space, condition)
        location = element.location
        return {
            "kind": str(element.kind),
            "name": element.name,
            "launch_file": element.file,
            "condition": self.space.describe(condition),
            "example": dict(example),
            **({"file": location.file, "line": location.line} if location is not None else {}),
        }

    def satisfiable(self, condition: BDD) -> bool:
        known = self._satisfiable.get(condition)
        if known is None:
            known = self._satisfiable[condition] = self.space.satisfiable(condition)
        return known


def _check_attributes(predicate: Predicate, collection: Collection) -> None:
    """Attributes read from the element exist in its collection (before any evaluation)."""
    for node in ast.walk(predicate.body):
        if (
            isinstance(node, ast.Attribute)
            and isinstance(node.value, ast.Name)
            and node.value.id == predicate.variable
            and node.attr not in collection.attributes
        ):
            attributes = ", ".join(collection.attributes)
            raise QueryError(
                f"{collection.name} have no attribute '{node.attr}' (they have: {attributes})",
                predicate.offset + node.col_offset,
            )


def _read_attributes(predicate: Predicate) -> tuple[str, ...] | None:
    """The attributes the predicate reads, when that is all it uses the element for."""
    read: list[str] = []
    attribute_bases = set()
    for node in ast.walk(predicate.body):
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
            attribute_bases.add(id(node.value))
            read.append(node.attr)
    for node in ast.walk(predicate.body):
        if (
            isinstance(node, ast.Name)
            and node.id == predicate.variable
            and id(node) not in attribute_bases
        ):
            return None
    return tuple(dict.fromkeys(read))


class _Evaluation:
    """One query's evaluation state: its work budget and the truth of predicates per
    combination of constant attribute values (most elements share a few)."""

    def __init__(self, space: ConditionSpace, query: Query) -> None:
        self.space = space
        self.branches = 0
        self._reads = {id(p): _read_attributes(p) for p in query.predicates}
        self._known: dict[tuple[object, ...], BDD] = {}

    def truth(self, predicate: Predicate, element: Queryable) -> BDD:
        """Where ``predicate`` holds for ``element`` (its presence aside)."""
        key = self._key(predicate, element)
        if key is None:
            return self._truth(predicate, element)
        known = self._known.get(key)
        if known is None:
            known = self._known[key] = self._truth(predicate, element)
        return known

    def _key(self, predicate: Predicate, element: Queryable) -> tuple[object, ...] | None:
        """What the predicate reads: an unconditional hashable value as itself (with its
        type: ``1`` and ``True`` render differently), any other value as the identity of its
        Choice (elements share the Choices of their scope, and outlive the query)."""
        reads = self._reads[id(predicate)]
        if reads is None:
            return None
        key: list[object] = [id(predicate)]
        true = self.space.true
        for name in reads:
            choice = element.attribute(name)
            branches = choice.branches
            if len(branches) == 1 and branches[0][0] == true:
                value = branches[0][1]
                key.append((type(value), value))
            else:
                key.append(id(choice))
        try:
            hash(tuple(key))
        except TypeError:
            return None
        return tuple(key)

    def _truth(self, predicate: Predicate, element: Queryable) -> BDD:
        value = _Interpreter(self, predicate.variable, element).truth(predicate.body)
        return value.where(lambda leaf: leaf is True)

    def spend(self, branches: int) -> None:
        self.branches += branches
        if self.branches > MAX_BRANCHES:
            raise QueryError(f"the query evaluates more than {MAX_BRANCHES:,} value combinations")


class _Interpreter:
    """Evaluates one predicate for one element, over conditional values."""

    def __init__(self, evaluation: _Evaluation, variable: str, element: Queryable) -> None:
        self.evaluation = evaluation
        self.space = evaluation.space
        self.variable = variable
        self.element = element

    def const(self, value: object) -> Choice[object]:
        return Choice(((self.space.true, value),), self.space.false)

    def apply(
        self, operands: Sequence[Choice[object]], function: Callable[..., object]
    ) -> Choice[object]:
        """``function`` on every jointly possible combination of the operands' branches; it
        may return a Choice (a value that itself depends on the configuration)."""
        false = self.space.false
        if not operands:
            try:
                return self.const(function())
            except _ERRORS:
                return self.const(FAILED)
        true = self.space.true
        if all(len(o.branches) == 1 and o.branches[0][0] == true for o in operands):
            constant = self.call_on([o.branches[0][1] for o in operands], function)
            return constant if isinstance(constant, Choice) else self.const(constant)
        out: list[tuple[BDD, object]] = []
        joint = combine(list(operands), tuple)
        self.evaluation.spend(len(joint))
        for condition, leaves in joint:
            result = self.call_on(leaves, function)
            if isinstance(result, Choice):
                for inner, value in result:
                    both = condition & inner
                    if both != false:
                        out.append((both, value))
            else:
                out.append((condition, result))
        return Choice.of(out, false)

    @staticmethod
    def call_on(leaves: Sequence[object], function: Callable[..., object]) -> object:
        """``function(*leaves)``, or FAILED where a leaf failed or Python would raise."""
        if any(leaf is FAILED for leaf in leaves):
            return FAILED
        try:
            return function(*leaves)
        except _ERRORS:
            return FAILED

    def truth(self, node: ast.expr) -> Choice[object]:
        """``node``'s value as True/False (a set is true where it is not empty, a failed
        branch false)."""
        return self.apply([self.value(node).map(_defined)], self._bool)

    def _bool(self, leaf: object) -> object:
        if isinstance(leaf, ElementSet):
            return leaf.counts(self.space).map(bool)
        return bool(leaf)

    def value(self, node: ast.expr) -> Choice[object]:
        if isinstance(node, ast.Constant):
            return self.const(node.value)
        if isinstance(node, ast.Name):
            return self.const(self.element if node.id == self.variable else CONSTANTS[node.id])
        if isinstance(node, ast.Attribute):
            return self.apply([self.value(node.value)], lambda leaf: _attribute(leaf, node.attr))
        if isinstance(node, ast.Call):
            return self.call(node)
        if isinstance(node, ast.BoolOp):
            conjunction = isinstance(node.op, ast.And)
            operands = [self.truth(v) for v in node.values]
            return self.apply(operands, lambda *v: all(v) if conjunction else any(v))
        if isinstance(node, ast.UnaryOp):
            if isinstance(node.op, ast.Not):
                return self.apply([self.truth(node.operand)], operator.not_)
            sign = operator.neg if isinstance(node.op, ast.USub) else operator.pos
            return self.apply([self.value(node.operand)], lambda v: sign(_number(v)))
        if isinstance(node, ast.BinOp):
            function = _BINARY[type(node.op)]
            return self.apply(
                [self.value(node.left), self.value(node.right)],
                lambda a, b: _bounded(function, a, b),
            )
        if isinstance(node, ast.Compare):
            return self.compare(node)
        if isinstance(node, ast.IfExp):
            return self.apply(
                [self.truth(node.test), self.value(node.body), self.value(node.orelse)],
                lambda test, body, orelse: body if test else orelse,
            )
        if isinstance(node, (ast.Tuple, ast.List)):
            build = tuple if isinstance(node, ast.Tuple) else list
            return self.apply([self.value(e) for e in node.elts], lambda *v: build(v))
        if isinstance(node, ast.Subscript):
            return self.subscript(node)
        raise QueryError(f"{type(node).__name__} expressions are not allowed")  # checked before

    def compare(self, node: ast.Compare) -> Choice[object]:
        operands = [self.value(o) for o in (node.left, *node.comparators)]
        tests = [_COMPARE_OPS[type(op)] for op in node.ops]

        def chained(*values: object) -> bool:
            return all(bool(test(values[i], values[i + 1])) for i, test in enumerate(tests))

        return self.apply(operands, chained)

    def subscript(self, node: ast.Subscript) -> Choice[object]:
        index = node.slice
        if isinstance(index, ast.Slice):
            parts = [
                self.const(None) if p is None else self.value(p)
                for p in (index.lower, index.upper, index.step)
            ]
            return self.apply(
                [self.value(node.value), *parts], lambda v, *p: _sequence(v)[slice(*p)]
            )
        return self.apply([self.value(node.value), self.value(index)], lambda v, i: _sequence(v)[i])

    def call(self, node: ast.Call) -> Choice[object]:
        arguments = [self.value(a) for a in node.args]
        function = node.func
        if isinstance(function, ast.Attribute):
            method = function.attr
            return self.apply(
                [self.value(function.value), *arguments],
                lambda receiver, *a: getattr(str, method)(_text(receiver), *a),
            )
        assert isinstance(function, ast.Name)  # the parser allows nothing else
        name = function.id
        if name == "len":
            return self.apply(arguments, self._len)
        if name == "bool":
            return self.apply(arguments, self._bool)
        plain = _FUNCTIONS[name]
        return self.apply(arguments, lambda *a: plain(*(_plain(v) for v in a)))

    def _len(self, leaf: object) -> object:
        if isinstance(leaf, ElementSet):
            return leaf.counts(self.space)
        return len(_sequence(leaf))


def _defined(leaf: object) -> object:
    return False if leaf is FAILED else leaf


def _attribute(leaf: object, name: str) -> object:
    attribute = getattr(leaf, "attribute", None)
    if isinstance(leaf, (str, int, float, list, tuple, dict, ElementSet)) or attribute is None:
        raise AttributeError(name)
    result: object = attribute(name)
    return result


def _plain(value: object) -> object:
    if isinstance(value, ElementSet) or hasattr(value, "attribute"):
        raise TypeError("an element is not a value")
    return value


def _number(value: object) -> float | int:
    if isinstance(value, (int, float)):
        return value
    raise TypeError("not a number")


def _text(value: object) -> str:
    if isinstance(value, str):
        return value
    raise TypeError("not a string")


def _sequence(value: object) -> str | list[object] | tuple[object, ...] | dict[object, object]:
    if isinstance(value, (str, list, tuple, dict)):
        return value
    raise TypeError("not a sequence")


def _bounded(function: Callable[[Any, Any], Any], left: object, right: object) -> object:
    """Arithmetic on plain values; sequences built by ``+`` and ``*`` stay below the bound,
    and ``%`` is arithmetic only (string formatting could render anything)."""
    left, right = _plain(left), _plain(right)
    if function is operator.mod and not isinstance(left, (int, float)):
        raise TypeError("% takes numbers")
    if function in (operator.add, operator.mul):
        size = 1
        for operand, other in ((left, right), (right, left)):
            if isinstance(operand, (str, list, tuple)):
                size = len(operand) * (other if isinstance(other, int) else 1) + (
                    len(other) if isinstance(other, (str, list, tuple)) else 0
                )
        if size > MAX_SEQUENCE:
            raise QueryError(f"the query builds a sequence longer than {MAX_SEQUENCE:,}")
    return function(left, right)


def run_query(analysis: Analysis, text: str, args: Mapping[str, str] | None = None) -> list[Result]:
    """The elements of every entry file of ``analysis`` that ``text`` selects."""
    return QueryEngine(analysis).run(text, args)
