"""Presence of the graph's conditions, carried from one step to the next.

Graph elements share conditions (every element of one branch of a file has the same), so
verdicts are kept per distinct condition. A verdict depends on the decided variables of
the condition's support, on the ``<other>`` texts typed for its file's args (they decide
open predicates) and, when restriction by the decided variables was not enough, on the
user literals of the components the solver judged it in. From an earlier step of the same
list of literals, a condition is judged again only when one of those changed, and even
then not when the solver found it present or absent (more literals cannot undo that) or
when the witnesses that showed it undetermined still agree with the literals.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass

from rosvar.configuration.derivation import UNDETERMINED, Decisions, Derivation, Verdict
from rosvar.configuration.graph import Element
from rosvar.configuration.lowering import Bounds, Lowering
from rosvar.logic.conditions import BDD
from rosvar.logic.inputs import Input

Typed = Mapping[str, Mapping[Input, str]]
"""Entry file → the ``<other>`` texts typed for its args."""
Describe = Callable[[BDD, Mapping[str, bool]], str]
"""A condition simplified under decided variables, for people."""


@dataclass(frozen=True)
class Condition:
    """A presence condition some elements of one entry file's model share."""

    entry: str
    condition: BDD  # analysis manager, fixed atoms substituted
    bounds: Bounds


@dataclass(frozen=True)
class Judged:
    """A condition's verdict at one step, and the condition simplified for people."""

    verdict: Verdict
    description: str | None  # None once present or absent

    @property
    def shown(self) -> tuple[str, str | None]:
        """What elements show of it: presence and condition."""
        return self.verdict.presence, self.description


SEVERAL = -1
"""The key of ``Judgement.open`` for verdicts the solver judged in several components."""


@dataclass(frozen=True)
class Judgement:
    """Every condition's verdict at one step, with the undetermined ones the solver judged
    by component (``SEVERAL``: in more than one): those a step in it may overturn. A step
    visits its component's, not all conditions."""

    verdicts: list[Judged]  # per condition of ``Presences``
    open: Mapping[int, frozenset[int]]

    def moved(self, verdicts: list[Judged], changed: Iterable[int]) -> Judgement:
        """``verdicts``, which differ from these at ``changed`` only."""
        open_ = dict(self.open)
        for index in changed:
            before, after = _open_key(self.verdicts[index]), _open_key(verdicts[index])
            if before != after:
                if before is not None:
                    open_[before] = open_[before] - {index}
                if after is not None:
                    open_[after] = open_.get(after, frozenset()) | {index}
        return Judgement(verdicts, open_)


def _open_key(judged: Judged) -> int | None:
    """The component whose steps may overturn ``judged``, if the solver judged it."""
    verdict = judged.verdict
    if verdict.presence != UNDETERMINED or not verdict.components:
        return None
    if verdict.witnesses is None:
        return SEVERAL
    (component,) = verdict.components
    return component


class Presences:
    """The distinct conditions of the graph's elements, judged step after step."""

    def __init__(
        self,
        elements: Sequence[Element],
        derivation: Derivation,
        lowering: Lowering,
    ) -> None:
        self.derivation = derivation
        self.lowering = lowering
        self.conditions: list[Condition] = []
        self.of_element: list[int] = []
        number: dict[tuple[str, BDD], int] = {}
        for element in elements:
            key = (element.entry, element.condition)
            if key not in number:
                number[key] = len(self.conditions)
                self.conditions.append(Condition(element.entry, element.condition, element.bounds))
            self.of_element.append(number[key])
        self._reading: dict[str, list[int]] = {}  # variable → conditions over it
        self._typed_in: dict[str, list[int]] = {}  # entry → conditions texts can decide
        self._masks: list[int] = []  # per condition: the positions of ``_reading``'s variables
        variables = set(derivation.variables)
        for index, condition in enumerate(self.conditions):
            # the condition's support, not its bounds': typed texts may bring variables back
            reading = lowering.space.support(condition.condition) & variables
            for variable in reading:
                self._reading.setdefault(variable, []).append(index)
            self._masks.append(sum(1 << derivation.position[v] for v in reading))
            if not condition.bounds.exact:
                self._typed_in.setdefault(condition.entry, []).append(index)

    def judge(
        self,
        decisions: Decisions,
        typed: Typed,
        describe: Describe,
        before: tuple[Decisions, Typed, Judgement] | None = None,
    ) -> Judgement:
        """Every condition's verdict; ``before`` is an earlier step of the same list of
        literals (a prefix) with its typed texts and answer, of which most is kept."""
        if before is None:
            verdicts = self._judge(range(len(self.conditions)), decisions, typed, describe, None)
            open_: dict[int, set[int]] = {}
            for index, judged in enumerate(verdicts):
                key = _open_key(judged)
                if key is not None:
                    open_.setdefault(key, set()).add(index)
            return Judgement(verdicts, {k: frozenset(v) for k, v in open_.items()})
        earlier, earlier_typed, answer = before
        # present or absent in every valid configuration stays so under more literals
        again = {
            index
            for index in self._touched(decisions, typed, earlier, earlier_typed)
            if answer.verdicts[index].verdict.presence == UNDETERMINED
        }
        components = {c for c, cube in decisions.cubes.items() if cube != earlier.cubes[c]}
        found = list(answer.verdicts)
        if components:
            self._carry(answer, found, again, components, decisions, typed)
        ordered = sorted(again)
        for index, judged in zip(
            ordered, self._judge(ordered, decisions, typed, describe, answer.verdicts), strict=True
        ):
            found[index] = judged
        return answer.moved(found, ordered)

    def _carry(
        self,
        answer: Judgement,
        found: list[Judged],
        again: set[int],
        components: set[int],
        decisions: Decisions,
        typed: Typed,
    ) -> None:
        """Undetermined verdicts of ``answer`` in ``components`` (whose literals changed)
        whose decided variables did not change, kept in ``found`` where their witnesses
        still agree with the literals or repaired ones still show them undetermined, else
        added to ``again``. The verdicts share witnesses: each is repaired once."""
        verdicts = answer.verdicts
        for index in answer.open.get(SEVERAL, ()):  # judged without witnesses
            if not verdicts[index].verdict.components.isdisjoint(components):
                again.add(index)
        for component in components:
            indices = answer.open.get(component, frozenset()) - again
            witnesses = {w for index in indices for w in verdicts[index].verdict.witnesses or ()}
            repaired = self.derivation.repaired(component, witnesses, decisions)
            for index in indices:
                verdict = verdicts[index].verdict
                assert verdict.witnesses is not None
                without, within = (repaired[w] for w in verdict.witnesses)
                if (without, within) == verdict.witnesses:
                    continue  # they agree with the literals: it stays undetermined
                kept = None
                if without is not None and within is not None:
                    pair = (without, within)
                    before_without, before_within = verdict.witnesses
                    if (without ^ before_without | within ^ before_within) & self._masks[index]:
                        kept = self.derivation.carried(self._bounds(index, typed), verdict, pair)
                    else:  # the repairs left its support alone, so its truth in them
                        kept = Verdict(verdict.presence, verdict.values, verdict.components, pair)
                if kept is None:
                    again.add(index)
                else:
                    found[index] = Judged(kept, verdicts[index].description)

    def _touched(
        self, decisions: Decisions, typed: Typed, earlier: Decisions, earlier_typed: Typed
    ) -> set[int]:
        """Conditions whose decided variables or typed texts changed."""
        changed: Iterable[tuple[str, bool]] = decisions.decided.items() ^ earlier.decided.items()
        touched = {index for v, _ in changed for index in self._reading.get(v, ())}
        for entry in typed.keys() | earlier_typed.keys():
            if typed.get(entry) != earlier_typed.get(entry):
                touched.update(self._typed_in.get(entry, ()))
        return touched

    def _bounds(self, index: int, typed: Typed) -> Bounds:
        """The bounds of a condition, decided further by the texts typed for its file."""
        condition = self.conditions[index]
        if not condition.bounds.exact and condition.entry in typed:
            return self.lowering.decide(condition.condition, typed[condition.entry])
        return condition.bounds

    def _judge(
        self,
        indices: Sequence[int],
        decisions: Decisions,
        typed: Typed,
        describe: Describe,
        answer: Sequence[Judged] | None,
    ) -> list[Judged]:
        """The conditions of ``indices``, judged in one pass (the solver's example for one
        may show the next undetermined), with their verdicts in ``answer`` (an earlier
        step) as hints."""
        bounds = [
            (self._bounds(index, typed), None if answer is None else answer[index].verdict)
            for index in indices
        ]
        judged = []
        for index, verdict in zip(
            indices, self.derivation.presences(bounds, decisions), strict=True
        ):
            description = None
            if verdict.presence == UNDETERMINED:
                description = describe(self.conditions[index].condition, verdict.values)
            judged.append(Judged(verdict, description))
        return judged
