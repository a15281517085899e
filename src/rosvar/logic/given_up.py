"""Values the variational analysis gave up on, computed again in one configuration.

A value that combines too many operand values across all configurations (the bounds of
:class:`~rosvar.interpreter.substitution_args.ValueBudget`) is left unknown, yet in one
configuration each operand has one value and the combination is a single one. A
:class:`GivenUp` term keeps the operands' choices and the combination; evaluated with a
configuration's :class:`Bindings` (a resolution's), it picks each operand's branch that holds
and combines those leaves once, under the same bounds. Without bindings (a configuration
graph whose inputs are only partly known), it stays unknown as before.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, cast

from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, Fail
from rosvar.logic.inputs import Input
from rosvar.logic.terms import (
    Apply,
    Operand,
    PackageTable,
    TermError,
    evaluate,
    is_term,
    shared,
)

Combination = Callable[[list[Any]], Operand | Fail]
"""The value of one leaf of each operand (a failing one: the launch tool's failure)."""


@dataclass(frozen=True)
class Bindings(PackageTable):
    """A host that knows one configuration: the packages, and which conditions hold."""

    holds: Callable[[BDD], bool]


class GivenUp(Apply):
    """``too_complex(text)``: a value over the work limits, with what computes it in one
    configuration (``choices``, one leaf of each given to ``combination``).

    Hash-consed by its computation: ``GivenUp(...)`` of a text, display, choices (the same
    conditions and leaves, in order) and combination (the same function of the same
    arguments) that a give-up alive already has is that give-up, so that the same value
    given up in every includer's walk, or in both passes of an entry file, is one term with
    one set of predicates (each a BDD variable the condition space keeps for good, with
    its term and the conditions the term holds). Otherwise equal only to itself (two
    give-ups of one text may combine different operands), and hashed as itself: hashed by
    their text, the give-ups of one text piled up in one probe chain of each dict they
    were keys of, every lookup comparing them all.
    """

    __slots__ = ("choices", "combination")

    choices: tuple[Choice[object], ...]
    combination: Combination

    def __new__(
        cls, text: str, display: str, choices: Sequence[Choice[object]], combination: Combination
    ) -> GivenUp:
        choices = tuple(choices)

        def made() -> GivenUp:
            self = cast("GivenUp", cls._made("too_complex", (text,), display))
            self.choices = choices
            self.combination = combination
            return self

        key = _key(text, display, choices, combination)
        return made() if key is None else shared(key, made)

    def __reduce__(self) -> Any:
        raise TypeError("a value given up is not pickled: it holds conditions")

    __eq__ = object.__eq__
    __hash__ = object.__hash__

    def evaluated(self, inputs: Mapping[Input, str], host: object) -> str:
        if not isinstance(host, Bindings):
            return super().evaluated(inputs, host)
        leaves: list[object] = []
        for choice in self.choices:
            leaf = next((leaf for condition, leaf in choice if host.holds(condition)), _NONE)
            if leaf is _NONE:
                raise TermError(f"{self.display} has no value in this configuration")
            leaves.append(leaf)
        value = self.combination(leaves)
        if isinstance(value, Fail):
            raise TermError(value.message, value.code)
        return evaluate(value, inputs, host)


_NONE = object()


def _key(
    text: str, display: str, choices: tuple[Choice[object], ...], combination: Combination
) -> tuple[object, ...] | None:
    """What makes a give-up the same computation, or None where a part cannot be compared
    (a leaf or an argument of the combination not hashable). The manager's identity comes
    before the conditions: conditions of two managers cannot be compared."""
    managers = [choice.false.bdd for choice in choices if choice.false is not None]
    if isinstance(combination, functools.partial):
        function: object = (combination.func, combination.args, tuple(combination.keywords.items()))
    else:
        function = combination
    key = (
        GivenUp,
        id(managers[0]) if managers else None,
        text,
        display,
        function,
        tuple(choice.key() for choice in choices),
    )
    try:
        hash(key)
    except TypeError:
        return None
    return key


def first(leaves: list[Any]) -> Any:
    """The combination of one operand: its leaf (a given-up value that picks, in a
    configuration, the branch of one choice that holds there)."""
    return leaves[0]


def terms_merged(value: Choice[Any], text: str, display: str) -> Choice[Any]:
    """``value`` with its branches of terms as one branch: a :class:`GivenUp` that picks the
    term that holds in a configuration and evaluates it. For values that nothing reads
    before a configuration makes them concrete (a file a helper writes): crossing each term
    with the operands of the texts made of it would multiply branches that all mean "known
    per configuration" (nav2's bringup: 3,792 per server)."""
    terms = [branch for branch in value.branches if is_term(branch[1])]
    if len(terms) < 2:
        return value
    where = terms[0][0]
    for condition, _term in terms[1:]:
        where |= condition
    merged = GivenUp(text, display, [Choice(tuple(terms), value.false)], first)
    kept = tuple(branch for branch in value.branches if not is_term(branch[1]))
    return Choice((*kept, (where, merged)), value.false)
