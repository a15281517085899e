"""Queries evaluated over the variational model: each result with the condition it holds under.

A predicate reads attributes of the element, each a :class:`~rosvar.logic.choice.Choice` of
alternatives. It is evaluated once per jointly possible combination of the alternatives of the
attributes it reads, as plain Python values, and holds under the disjunction of the conditions
of the combinations where it is true. So ``self.package == 'kobuki_node'`` on a node whose
package depends on an arg holds exactly for the values of the arg that give that package; a
set-valued attribute (a topic's publishers) is, per condition, the tuple of members present,
so ``len(self.publishers) > 1`` holds where more than one publisher is present.

The predicate is compiled once into closures over the whitelisted syntax (nothing is passed to
``eval``). A combination where Python would raise (``None.startswith``, ``'a' < 1``) does not
satisfy the predicate; text analysis cannot know (an ``<other>`` arg value) is None. Resource
guards refuse (:class:`QueryError`), never truncate. Elements that read the same values share
the answer: it is computed once per query.
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
from rosvar.arithmetic import BINARY, COMPARISONS
from rosvar.interpreter.safe_eval.limits import MAX_SEQUENCE
from rosvar.interpreter.workspace_models import Analysis, collector_paused
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER

MAX_BRANCHES: Final = 1_000_000
"""Combinations of attribute values one query may evaluate (over all elements)."""
MAX_SUBSETS: Final = 4096
"""Distinct member subsets of one set-valued attribute a query may consider."""
_Group = tuple[tuple[Choice[object], ...], list[tuple[int, Queryable]]]
"""The values of the attributes a query reads, and the elements (with their index) having them."""
Compiled = Callable[[Mapping[str, object]], object]
"""A predicate (or part of it) over the values of the attributes it reads."""
_ERRORS: Final = (TypeError, ValueError, AttributeError, IndexError, KeyError, ArithmeticError)
# $(eval)'s arithmetic without ``**`` (a query has no use for powers, and they are costly)
_BINARY: Final[Mapping[type[ast.operator], Callable[[Any, Any], Any]]] = {
    op: function for op, function in BINARY.items() if op is not ast.Pow
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

    def __init__(
        self,
        analysis: Analysis,
        files: Sequence[str] | None = None,
        collections: Mapping[str, Collection] | None = None,
    ) -> None:
        """``collections``: providers that replace the registered ones of their names (the
        communication graph's topics, services and actions)."""
        self.analysis = analysis
        self.collections = {**COLLECTIONS, **(collections or {})}
        self.space = analysis.space
        self.models = [
            analysis.model(f) for f in (analysis.workspace.launch_files if files is None else files)
        ]
        self._elements: dict[str, list[Queryable]] = {}
        self._satisfiable: dict[BDD, bool] = {}
        self._examples: dict[BDD, dict[str, str]] = {}
        self._expanded: dict[int, Choice[object]] = {}  # by id of a Choice of the elements
        self._groups: dict[tuple[str, tuple[str, ...]], list[_Group]] = {}

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
        collection = self.collections.get(query.collection)
        if collection is None:
            known = ", ".join(sorted(self.collections))
            raise QueryError(f"unknown collection '{query.collection}' (collections: {known})")
        restriction = self.restriction(args or {})
        evaluation = _Evaluation(self.space, query, collection, self._expanded)
        selected: list[tuple[int, Result]] = []
        false, true = self.space.false, self.space.true
        with collector_paused():  # the model's heap is large and forms no cycles
            for choices, members in self.groups(collection, evaluation.reads):
                holds = evaluation.truth(choices)
                if holds == false:
                    continue
                for index, element in members:
                    condition = element.presence
                    restricted = restriction[element.file]
                    if restricted is not true:
                        condition &= restricted
                    if holds is not true:
                        condition &= holds
                    if condition != false and self.satisfiable(condition):
                        selected.append((index, Result(element, condition)))
        selected.sort(key=lambda pair: pair[0])
        return [result for _index, result in selected]

    def groups(self, collection: Collection, reads: tuple[str, ...]) -> list[_Group]:
        """The elements of ``collection`` grouped by the values of the attributes ``reads``
        (remembered: queries reading the same attributes evaluate once per distinct values).

        An unconditional hashable value is keyed by itself (with its type: ``1`` and ``True``
        render differently), any other by the identity of its Choice: elements share the
        Choices of their scope, and outlive the engine's queries."""
        key = (collection.name, reads)
        found = self._groups.get(key)
        if found is not None:
            return found
        true = self.space.true
        by_values: dict[object, _Group] = {}
        for index, element in enumerate(self.elements(collection)):
            choices = tuple(element.attribute(name) for name in reads)
            parts: list[object] = []
            for choice in choices:
                branches = choice.branches
                if len(branches) == 1 and branches[0][0] is true:  # constants share the true
                    parts.append((type(branches[0][1]), branches[0][1]))
                else:
                    parts.append(id(choice))
            values: object = tuple(parts)
            try:
                hash(values)
            except TypeError:  # an unhashable value (a list param): a group of its own
                values = ("element", index)
            group = by_values.get(values)
            if group is None:
                group = by_values[values] = (choices, [])
            group[1].append((index, element))
        found = self._groups[key] = list(by_values.values())
        return found

    def example(self, condition: BDD) -> Mapping[str, str]:
        """The simplest configuration in which ``condition`` holds (remembered: a query's
        results share a few conditions)."""
        example = self._examples.get(condition)
        if example is None:
            example = self._examples[condition] = simplest_trigger(self.space, condition)
        return example

    def satisfiable(self, condition: BDD) -> bool:
        known = self._satisfiable.get(condition)
        if known is None:
            known = self._satisfiable[condition] = self.space.satisfiable(condition)
        return known


class _Evaluation:
    """One query's compiled predicates and work budget."""

    def __init__(
        self,
        space: ConditionSpace,
        query: Query,
        collection: Collection,
        expanded: dict[int, Choice[object]],
    ) -> None:
        self.space = space
        self._expanded = expanded
        self.branches = 0
        compiled = [(_read_attributes(p, collection), _compile(p.body)) for p in query.predicates]
        self.reads = tuple(dict.fromkeys(name for reads, _f in compiled for name in reads))
        self._predicates = [
            (reads, tuple(self.reads.index(n) for n in reads), function)
            for reads, function in compiled
        ]

    def truth(self, choices: Sequence[Choice[object]]) -> BDD:
        """Where all predicates hold for an element whose attributes ``reads`` have the
        values ``choices`` (its presence aside)."""
        true, false = self.space.true, self.space.false
        holds = true
        for reads, places, function in self._predicates:
            mine = [choices[place] for place in places]
            constant = all(
                len(c.branches) == 1
                and c.branches[0][0] is true
                and not isinstance(c.branches[0][1], ElementSet)
                for c in mine
            )
            part = self._truth(reads, function, mine, constant)
            if part is false or part == false:
                return false
            if part is not true:
                holds = part if holds is true else holds & part
        return holds

    def _truth(
        self,
        reads: Sequence[str],
        function: Compiled,
        choices: list[Choice[object]],
        constant: bool,
    ) -> BDD:
        space = self.space
        if constant:
            self.spend(1)
            holds = _holds(
                function, {n: c.branches[0][1] for n, c in zip(reads, choices, strict=True)}
            )
            return space.true if holds else space.false
        expanded = [self.expanded(choice) for choice in choices]
        combinations = combine(expanded, tuple) if expanded else Choice.const(space, ())
        self.spend(len(combinations))
        result = space.false
        for condition, values in combinations:
            if _holds(function, dict(zip(reads, values, strict=True))):
                result |= condition
        return result

    def expanded(self, choice: Choice[object]) -> Choice[object]:
        """``choice`` with each set of elements replaced by the tuples of members present
        (remembered by the engine: elements and their values outlive a query)."""
        if not any(isinstance(value, ElementSet) for value in choice.values()):
            return choice
        known = self._expanded.get(id(choice))
        if known is None:
            known = self._expanded[id(choice)] = self._expand(choice)
        return known

    def _expand(self, choice: Choice[object]) -> Choice[object]:
        branches: list[tuple[BDD, object]] = []
        for condition, value in choice:
            if not isinstance(value, ElementSet):
                branches.append((condition, value))
                continue
            subsets = value.subsets(self.space, MAX_SUBSETS)
            if subsets is None:
                raise QueryError(f"a set has more than {MAX_SUBSETS:,} possible member subsets")
            for inner, members in subsets:
                both = condition & inner
                if both != self.space.false:
                    branches.append((both, members))
        return Choice.of(branches, self.space.false)

    def spend(self, branches: int) -> None:
        self.branches += branches
        if self.branches > MAX_BRANCHES:
            raise QueryError(f"the query evaluates more than {MAX_BRANCHES:,} value combinations")


def _holds(function: Compiled, values: Mapping[str, object]) -> bool:
    try:
        return bool(function(values))
    except _ERRORS:
        return False


def _read_attributes(predicate: Predicate, collection: Collection) -> tuple[str, ...]:
    """The attributes the predicate reads, checked to exist before any evaluation."""
    read: list[str] = []
    for node in ast.walk(predicate.body):
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
            if node.attr not in collection.attributes:
                attributes = ", ".join(collection.attributes)
                raise QueryError(
                    f"{collection.name} have no attribute '{node.attr}' (they have: {attributes})",
                    predicate.offset + node.col_offset,
                )
            read.append(node.attr)
    return tuple(dict.fromkeys(read))


def _compile(node: ast.expr) -> Compiled:
    """Closures computing ``node`` from the attribute values (the parser checked it)."""
    if isinstance(node, ast.Constant):
        constant: object = node.value
        return lambda values: constant
    if isinstance(node, ast.Name):
        named = CONSTANTS[node.id]
        return lambda values: named
    if isinstance(node, ast.Attribute):
        attribute = node.attr
        return lambda values: values[attribute]
    if isinstance(node, ast.Call):
        return _compile_call(node)
    if isinstance(node, ast.BoolOp):
        parts = [_compile(v) for v in node.values]
        if isinstance(node.op, ast.And):
            return lambda values: all(part(values) for part in parts)
        return lambda values: any(part(values) for part in parts)
    if isinstance(node, ast.UnaryOp):
        operand = _compile(node.operand)
        if isinstance(node.op, ast.Not):
            return lambda values: not operand(values)
        sign = operator.neg if isinstance(node.op, ast.USub) else operator.pos
        return lambda values: sign(_number(operand(values)))
    if isinstance(node, ast.BinOp):
        function = _BINARY[type(node.op)]
        left, right = _compile(node.left), _compile(node.right)
        return lambda values: _bounded(function, left(values), right(values))
    if isinstance(node, ast.Compare):
        return _compile_compare(node)
    if isinstance(node, ast.IfExp):
        test, body, orelse = _compile(node.test), _compile(node.body), _compile(node.orelse)
        return lambda values: body(values) if test(values) else orelse(values)
    if isinstance(node, (ast.Tuple, ast.List)):
        items = [_compile(e) for e in node.elts]
        build = tuple if isinstance(node, ast.Tuple) else list
        return lambda values: build(item(values) for item in items)
    if isinstance(node, ast.Subscript):
        return _compile_subscript(node)
    raise QueryError(f"{type(node).__name__} expressions are not allowed")  # checked before


def _compile_compare(node: ast.Compare) -> Compiled:
    first = _compile(node.left)
    rest = [
        (COMPARISONS[type(op)], _compile(c))
        for op, c in zip(node.ops, node.comparators, strict=True)
    ]

    def compare(values: Mapping[str, object]) -> bool:
        left = first(values)
        for test, operand in rest:
            right = operand(values)
            if not test(left, right):
                return False
            left = right
        return True

    return compare


def _compile_subscript(node: ast.Subscript) -> Compiled:
    base = _compile(node.value)
    index = node.slice
    if isinstance(index, ast.Slice):
        parts = [
            _compile(p) if p is not None else None for p in (index.lower, index.upper, index.step)
        ]

        def sliced(values: Mapping[str, object]) -> object:
            bounds: list[Any] = [None if p is None else p(values) for p in parts]
            return operator.getitem(_sequence(base(values)), slice(*bounds))

        return sliced
    key = _compile(index)

    def item(values: Mapping[str, object]) -> object:
        sequence: Any = _sequence(base(values))
        return sequence[key(values)]

    return item


def _compile_call(node: ast.Call) -> Compiled:
    arguments = [_compile(a) for a in node.args]
    function = node.func
    if isinstance(function, ast.Attribute):
        receiver = _compile(function.value)
        method = getattr(str, function.attr)
        return lambda values: method(_text(receiver(values)), *(a(values) for a in arguments))
    assert isinstance(function, ast.Name)  # the parser allows nothing else
    if function.id == "len":
        return lambda values: len(_sequence(*(a(values) for a in arguments)))
    if function.id == "bool":
        return lambda values: bool(*(a(values) for a in arguments))
    plain = _FUNCTIONS[function.id]
    return lambda values: plain(*(a(values) for a in arguments))


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
    counted with what they hold (``[[0] * 999999] * 999999`` is refused, not a list of
    999999 references that any later step walks whole), and ``%`` is arithmetic only
    (string formatting could render anything)."""
    if function is operator.mod and not isinstance(left, (int, float)):
        raise TypeError("% takes numbers")
    if function in (operator.add, operator.mul):
        size = 0
        for operand, other in ((left, right), (right, left)):
            if isinstance(operand, (str, list, tuple)):
                if function is operator.mul and isinstance(other, int):
                    size = _weight(operand) * max(other, 0)
                else:
                    size += _weight(operand)
        if size > MAX_SEQUENCE:
            raise QueryError(f"the query builds a sequence longer than {MAX_SEQUENCE:,}")
    return function(left, right)


def _weight(value: object) -> int:
    """How many elements (characters of a string) ``value`` holds, nested ones counted as
    often as they appear; counting stops past ``MAX_SEQUENCE`` (bounded work)."""
    total = 0
    stack: list[object] = [value]
    while stack and total <= MAX_SEQUENCE:
        item = stack.pop()
        if isinstance(item, str):
            total += len(item)
        elif isinstance(item, (list, tuple)):
            total += len(item)
            stack.extend(item[: MAX_SEQUENCE - total + 1])
        elif isinstance(item, dict):
            total += len(item)
            stack.extend(list(item.values())[: MAX_SEQUENCE - total + 1])
    return total
