"""Conditional values: a value paired with the condition under which it holds.

``Choice`` is the variational counterpart of a plain value: a list of
``(condition, leaf)`` branches with pairwise-disjoint conditions. Equal leaves
share one branch, so a value that does not really vary stays a single branch.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, Generic, TypeVar, cast

from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.terms import Apply, Hole

T = TypeVar("T", covariant=True)
U = TypeVar("U")
V = TypeVar("V")


@dataclass(frozen=True)
class Fail:
    """A branch where roslaunch would raise: ``message`` is what it would say."""

    message: str
    code: str = "launch-error"


_SELF_KEYED = frozenset({str, Hole, Apply})
"""Leaf types that are their own merge key: equal only to leaves of their own type (terms
compare their class), and the most common leaves."""


def leaf_key(leaf: object) -> object:
    """Merge key: equal *and* of the same type (0, False and 0.0 are different params)."""
    if type(leaf) in _SELF_KEYED:  # other keys are tuples, never equal to these
        return leaf
    try:
        hash(leaf)
    except TypeError:
        return ("unhashable", type(leaf).__name__, repr(leaf))
    if isinstance(leaf, tuple):
        return (tuple, tuple(leaf_key(item) for item in leaf))
    return (type(leaf), leaf)


class Choice(Generic[T]):
    """Disjoint ``(condition, value)`` branches; conditions are BDDs of one space."""

    __slots__ = ("branches", "false")

    def __init__(self, branches: tuple[tuple[BDD, T], ...], false: BDD | None) -> None:
        """Branches already merged and possible; ``Choice.of`` makes any branches so.
        ``false``: the manager's false, None only for the empty combination of no choices."""
        self.branches = branches
        self.false = false

    @staticmethod
    def of(branches: Iterable[tuple[BDD, U]], false: BDD | None = None) -> Choice[U]:
        """Equal leaves merged, impossible branches dropped; ``false`` (the manager's false)
        is needed only when ``branches`` may be empty."""
        if isinstance(branches, list) and len(branches) == 1:  # the common constant case
            condition = branches[0][0]
            if false is None:
                false = condition.bdd.false
            return Choice(() if condition == false else (branches[0],), false)
        merged = _merged(branches)
        if false is None and merged:
            false = merged[0][0].bdd.false
        return Choice(tuple(branch for branch in merged if branch[0] != false), false)

    @staticmethod
    def _of_possible(branches: list[tuple[BDD, U]], false: BDD | None) -> Choice[U]:
        """The constructor for branches whose conditions are known not to be false (taken
        from a choice, or just checked): equal leaves merged, nothing compared again."""
        return Choice(_merged(branches) if len(branches) > 1 else tuple(branches), false)

    @staticmethod
    def const(space: ConditionSpace, leaf: U) -> Choice[U]:
        """``leaf`` in every configuration; one shared object per text (or None) and space."""
        shared = type(leaf) is str or leaf is None
        if shared:
            known: Choice[U] | None = space.constants.get(leaf)
            if known is not None:
                return known
        choice = Choice(((space.true, leaf),), space.false)
        if shared:
            space.constants[leaf] = choice
        return choice

    @staticmethod
    def empty(space: ConditionSpace) -> Choice[U]:
        """No value in any configuration (every branch failed)."""
        return Choice((), space.false)

    def __iter__(self) -> Iterator[tuple[BDD, T]]:
        return iter(self.branches)

    def __len__(self) -> int:
        return len(self.branches)

    def __repr__(self) -> str:
        return f"Choice({[v for _, v in self.branches]!r})"

    def key(self) -> tuple[tuple[BDD, object], ...]:
        """The branches as a dictionary key: equal keys are the same branches (conditions
        and leaves, as :func:`_key` tells leaves apart) in the same order."""
        return tuple((condition, leaf_key(leaf)) for condition, leaf in self.branches)

    def single(self) -> T | None:
        """The value when there is exactly one branch (whatever its condition)."""
        return self.branches[0][1] if len(self.branches) == 1 else None

    def values(self) -> list[T]:
        return [v for _, v in self.branches]

    def map(self, function: Callable[[T], U]) -> Choice[U]:
        """``function`` of each leaf; this choice itself where it changes no leaf."""
        branches = [(c, function(v)) for c, v in self.branches]
        if all(new is old for (_, new), (_, old) in zip(branches, self.branches, strict=True)):
            return cast("Choice[U]", self)
        return Choice._of_possible(branches, self.false)

    def bind(self, function: Callable[[T], Choice[U]]) -> Choice[U]:
        """Apply a conditional function to each branch and flatten."""
        out: list[tuple[BDD, U]] = []
        for condition, leaf in self.branches:
            for inner, value in function(leaf):
                joint = condition & inner
                if joint != self.false:
                    out.append((joint, value))
        return Choice._of_possible(out, self.false)

    def restrict(self, condition: BDD) -> Choice[T]:
        """Only the part of this value that can hold under ``condition``.

        Under true the value is itself: the same object, so that a constant stays
        recognisable as one (its condition the space's own true) downstream.
        """
        if condition.var is None and condition != self.false:
            return self
        return Choice.of([(c & condition, v) for c, v in self.branches], self.false)

    def where(self, predicate: Callable[[T], bool]) -> BDD:
        """The condition under which the value satisfies ``predicate``."""
        result = None
        for condition, leaf in self.branches:
            if predicate(leaf):
                result = condition if result is None else result | condition
        return result if result is not None else _false_of(self)

    def covered(self) -> BDD:
        """Where this value is defined at all."""
        result = _false_of(self)
        for condition, _leaf in self.branches:
            result |= condition
        return result


def _merged(branches: Iterable[tuple[BDD, V]]) -> tuple[tuple[BDD, V], ...]:
    """Branches with equal leaves joined into the first one's place."""
    merged: dict[object, tuple[BDD, V]] = {}
    for branch in branches:
        leaf = branch[1]
        key = leaf if type(leaf) in _SELF_KEYED else leaf_key(leaf)
        known = merged.get(key)
        merged[key] = branch if known is None else (known[0] | branch[0], leaf)
    return tuple(merged.values())


def _false_of(choice: Choice[Any]) -> BDD:
    if choice.false is not None:
        return choice.false
    raise ValueError("empty choice has no condition space")


def ite(space: ConditionSpace, condition: BDD, then: Choice[V], otherwise: Choice[V]) -> Choice[V]:
    """``then`` where ``condition`` holds, else ``otherwise`` (guarded state update)."""
    if condition == space.true:
        return then
    if condition == space.false:
        return otherwise
    # each leaf's conditions on both sides, in the order ``Choice.of`` would merge them: a
    # leaf on both sides (a value kept where it is set again) is one if-then-else, not two
    # conjunctions and their disjunction (the nodes of both halves built for nothing)
    placed: dict[object, list[Any]] = {}
    for c, v in then.branches:
        key = v if type(v) in _SELF_KEYED else leaf_key(v)
        known = placed.get(key)
        placed[key] = [c, None, v] if known is None else [known[0] | c, None, v]
    for c, v in otherwise.branches:
        key = v if type(v) in _SELF_KEYED else leaf_key(v)
        known = placed.get(key)
        if known is None:
            placed[key] = [None, c, v]
        else:
            known[1] = c if known[1] is None else known[1] | c
            known[2] = v
    false = space.false
    branches: list[tuple[BDD, V]] = []
    for where_then, where_else, v in placed.values():
        if where_else is None:
            joint = where_then & condition
        elif where_then is None:
            joint = where_else & ~condition
        else:
            joint = space.bdd.ite(condition, where_then, where_else)
        if joint != false:
            branches.append((joint, v))
    return Choice(tuple(branches), false)


def combine(choices: Sequence[Choice[V]], function: Callable[[list[V]], U]) -> Choice[U]:
    """Cross product of several choices (only jointly possible combinations).

    Most operands have a single branch (a constant, or a value that does not vary):
    they are conjoined once instead of crossed with every combination of the others.
    Combinations come in the order of a nested loop over the operands, first outermost.
    """
    if not choices:
        return Choice((), None)
    return Choice._of_possible(
        [(c, function(leaves)) for c, leaves in crossed(choices)], choices[0].false
    )


def combine_bind(
    choices: Sequence[Choice[V]], function: Callable[[list[V]], Choice[U]]
) -> Choice[U]:
    """``combine(choices, tuple).bind(...)`` without the intermediate choice: the
    combinations of merged operands are distinct, so merging them (by their leaves' keys)
    only cost time."""
    if not choices:
        return Choice((), None)
    false = choices[0].false
    out: list[tuple[BDD, U]] = []
    for condition, leaves in crossed(choices):
        for inner, value in function(leaves):
            if inner.var is None:  # a constant's branch, true (a choice keeps no false one)
                out.append((condition, value))
                continue
            joint = condition & inner
            if joint != false:
                out.append((joint, value))
    return Choice._of_possible(out, false)


def crossed(choices: Sequence[Choice[V]]) -> list[tuple[BDD, list[V]]]:
    """The jointly possible combinations of the (non-empty) ``choices``' leaves, in the
    order of a nested loop over the operands, first outermost."""
    false = choices[0].false
    joint: BDD | None = None  # conjunction of the single branches' conditions; None: true
    varying: list[int] = []
    leaves: list[Any] = []  # the varying operands' places are filled per combination below
    for index, choice in enumerate(choices):
        branches = choice.branches
        if len(branches) != 1:
            varying.append(index)
            leaves.append(None)
            continue
        condition, leaf = branches[0]
        leaves.append(leaf)
        if joint is None:
            joint = condition
        elif condition is not joint:  # constants share the space's true: nothing to do
            joint = joint & condition
    if not varying:  # every operand a single branch: ``joint`` conjoins them all
        assert joint is not None
        return [] if joint == false else [(joint, leaves)]
    if joint is not None and joint.var is None and joint != false:  # true: nothing to conjoin
        joint = None
    partial: list[tuple[BDD | None, list[V]]] = [(joint, leaves)]
    for index in varying:
        nxt: list[tuple[BDD | None, list[V]]] = []
        for c1, vs in partial:
            for c2, v in choices[index].branches:
                both = c2 if c1 is None else c1 & c2
                if c1 is None or both != false:  # a branch alone is never false
                    chosen = list(vs)
                    chosen[index] = v
                    nxt.append((both, chosen))
        partial = nxt
    return cast("list[tuple[BDD, list[V]]]", partial)  # each with a varying one's branch
