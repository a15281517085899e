"""The presence of the graph's conditions judged at each step, carried from one step to the
next.

Graph elements share conditions (every element of one branch of a file has the same), so
verdicts are kept per distinct condition. A verdict depends on the decided variables of
the condition's support, on the ``<other>`` texts typed (they decide open predicates, of
its file's args or of an includer's, through the condition that its file is launched) and,
when restriction by the decided variables was not enough, on the
user literals of the components the solver judged it in. From an earlier step of the same
list of literals, a condition is judged again only when one of those changed, and even
then not when the solver found it present or absent (more literals cannot undo that) or
when the witnesses that showed it undetermined still agree with the literals, or were
repaired to without changing its support (``Judgement.held``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property

from rosvar.configuration.derivation import Decisions, Derivation
from rosvar.configuration.graph import Element
from rosvar.configuration.lowering import Bounds, Lowering
from rosvar.configuration.presence import Presence, PresenceVerdict
from rosvar.logic.bdd import BDD
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
    """A condition's verdict at one step, and the condition simplified for people.

    The description is made when first shown: a view's summary (how many elements are
    present) needs the verdicts only, and describing is the larger part of judging."""

    verdict: PresenceVerdict
    condition: BDD  # analysis manager: what ``describe`` simplifies
    describe: Describe = field(compare=False)

    @cached_property
    def description(self) -> str | None:
        """None once present or absent."""
        if self.verdict.presence != Presence.UNDETERMINED:
            return None
        return self.describe(self.condition, self.verdict.values)

    @property
    def shown(self) -> tuple[str, str | None]:
        """What elements show of it: presence and condition."""
        return self.verdict.presence, self.description


SEVERAL = -1
"""The key of ``Judgement.open`` for verdicts the solver judged in several components."""

Held = Mapping[int, int]
"""A witness kept in verdicts → the valid configuration it stands for at a step."""


@dataclass(frozen=True)
class Judgement:
    """Every condition's verdict at one step, with the undetermined ones the solver judged
    by component (``SEVERAL``: in more than one): those a step in it may overturn, so a
    step visits its component's, not all conditions.

    An undetermined verdict keeps the witnesses it was judged with; ``held`` maps each of
    them, per component, to what it is repaired to at this step. A step repairs each
    witness once, and visits only the verdicts whose support a repair changed: the others
    stay the same objects, shown by the same witnesses.
    """

    verdicts: list[Judged]  # per condition of ``Presences``
    open: Mapping[int, frozenset[int]]
    held: Mapping[int, Held]
    judged: Sequence[int]  # the verdicts judged at this step: the others are the earlier ones

    def witnesses(self, index: int) -> tuple[int, int] | None:
        """The configurations that show verdict ``index`` undetermined at this step."""
        verdict = self.verdicts[index].verdict
        if verdict.witnesses is None:
            return None
        (component,) = verdict.components
        held = self.held[component]
        without, within = verdict.witnesses
        return held[without], held[within]


def _open_key(judged: Judged) -> int | None:
    """The component whose steps may overturn ``judged``, if the solver judged it."""
    verdict = judged.verdict
    if verdict.presence != Presence.UNDETERMINED or not verdict.components:
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
        self.of_parts: list[tuple[int, ...]] = []  # per element: its parts' conditions
        number: dict[tuple[str, BDD], int] = {}

        def numbered(entry: str, condition: BDD, bounds: Bounds) -> int:
            key = (entry, condition)
            if key not in number:
                number[key] = len(self.conditions)
                self.conditions.append(Condition(entry, condition, bounds))
            return number[key]

        for element in elements:
            self.of_element.append(numbered(element.entry, element.condition, element.bounds))
            self.of_parts.append(
                tuple(numbered(element.entry, p.condition, p.bounds) for p in element.parts)
            )
        self._reading: dict[str, list[int]] = {}  # variable → conditions over it
        self._open: list[int] = []  # conditions typed texts can decide
        self._masks: list[int] = []  # per condition: the positions of ``_reading``'s variables
        variables = set(derivation.variables)
        for index, condition in enumerate(self.conditions):
            # the condition's support, not its bounds': typed texts may bring variables back
            reading = lowering.space.support(condition.condition) & variables
            for variable in reading:
                self._reading.setdefault(variable, []).append(index)
            self._masks.append(sum(1 << derivation.position[v] for v in reading))
            if not condition.bounds.exact:
                self._open.append(index)

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
            indices = range(len(self.conditions))
            verdicts = self._judge(indices, decisions, typed, describe, [None] * len(indices))
            return _judgement(verdicts, indices, {}, {})
        earlier, earlier_typed, answer = before
        # present or absent in every valid configuration stays so under more literals
        again = {
            index
            for index in self._touched(decisions, typed, earlier, earlier_typed)
            if answer.verdicts[index].verdict.presence == Presence.UNDETERMINED
        }
        components = {c for c, cube in decisions.cubes.items() if cube != earlier.cubes[c]}
        held = {**answer.held}
        for index in answer.open.get(SEVERAL, ()):  # judged without witnesses
            if not answer.verdicts[index].verdict.components.isdisjoint(components):
                again.add(index)
        for component in components & held.keys():
            held[component] = self._carry(answer, component, again, decisions, typed)
        ordered = sorted(again)
        hints = [_hint(answer, index) for index in ordered]
        found = list(answer.verdicts)
        for index, judged in zip(
            ordered, self._judge(ordered, decisions, typed, describe, hints), strict=True
        ):
            found[index] = judged
        return _judgement(found, ordered, answer.open, held, answer.verdicts)

    def _carry(
        self,
        answer: Judgement,
        component: int,
        again: set[int],
        decisions: Decisions,
        typed: Typed,
    ) -> Held:
        """The witnesses ``answer`` holds in ``component`` (whose literals changed)
        repaired; the undetermined verdicts they no longer show so (their support changed
        in a repair, or one failed) are added to ``again``."""
        before = answer.held[component]
        repaired = self.derivation.repaired(component, set(before.values()), decisions)
        held: dict[int, int] = {}
        failed: set[int] = set()
        changed = 0  # the positions some repair changed
        for kept, value in before.items():
            found = repaired[value]
            if found is None:
                failed.add(kept)
            else:
                held[kept] = found
                changed |= found ^ value
        if not changed and not failed:
            return before  # every witness agrees with the literals
        masks = self._masks
        for index in answer.open.get(component, frozenset()) - again:
            verdict = answer.verdicts[index].verdict
            assert verdict.witnesses is not None
            without, within = verdict.witnesses
            if (
                without in failed
                or within in failed
                or (
                    masks[index] & changed
                    and not self.derivation.carries(
                        self._bounds(index, typed),
                        (before[without], before[within]),
                        (held[without], held[within]),
                    )
                )
            ):
                again.add(index)
        return held

    def _touched(
        self, decisions: Decisions, typed: Typed, earlier: Decisions, earlier_typed: Typed
    ) -> set[int]:
        """Conditions whose decided variables or typed texts changed."""
        changed: Iterable[tuple[str, bool]] = decisions.decided.items() ^ earlier.decided.items()
        touched = {index for v, _ in changed for index in self._reading.get(v, ())}
        if typed != earlier_typed:
            touched.update(self._open)
        return touched

    def presence(self, index: int, decisions: Decisions, typed: Typed) -> Presence:
        """Condition ``index``'s presence under ``decisions`` and the texts ``typed``, judged
        alone (a refusal's question, outside the steps' judgements)."""
        [verdict] = self.derivation.presences([(self._bounds(index, typed), None)], decisions)
        return verdict.presence

    def _bounds(self, index: int, typed: Typed) -> Bounds:
        """The bounds of a condition, decided further by the texts typed (for any file's
        args: whether a file is launched reads its includers')."""
        condition = self.conditions[index]
        if not condition.bounds.exact and typed:
            texts = {i: text for texts in typed.values() for i, text in texts.items()}
            return self.lowering.decide(condition.condition, texts)
        return condition.bounds

    def _judge(
        self,
        indices: Sequence[int],
        decisions: Decisions,
        typed: Typed,
        describe: Describe,
        hints: Sequence[PresenceVerdict | None],
    ) -> list[Judged]:
        """The conditions of ``indices``, judged in one pass (the solver's example for one
        may show the next undetermined), with their verdicts at an earlier step (if any) as
        ``hints``."""
        bounds = [
            (self._bounds(index, typed), hint) for index, hint in zip(indices, hints, strict=True)
        ]
        return [
            Judged(verdict, self.conditions[index].condition, describe)
            for index, verdict in zip(
                indices, self.derivation.presences(bounds, decisions), strict=True
            )
        ]


def _hint(answer: Judgement, index: int) -> PresenceVerdict:
    """Verdict ``index`` of ``answer``, with the witnesses that show it at that step."""
    verdict = answer.verdicts[index].verdict
    witnesses = answer.witnesses(index)
    if witnesses is None or witnesses == verdict.witnesses:
        return verdict
    return PresenceVerdict(verdict.presence, verdict.values, verdict.components, witnesses)


def _judgement(
    verdicts: list[Judged],
    changed: Sequence[int],
    open_: Mapping[int, frozenset[int]],
    held: Mapping[int, Held],
    before: Sequence[Judged] | None = None,
) -> Judgement:
    """``verdicts``, which differ from ``before`` (with ``open_`` and ``held``) at
    ``changed`` only; their new witnesses stand for themselves. Only what changed is
    copied; a component's witnesses no verdict keeps any more are dropped once they
    outnumber the others."""
    moved: dict[int, set[int]] = {}
    grown: dict[int, dict[int, int]] = {}
    for index in changed:
        old = None if before is None else _open_key(before[index])
        new = _open_key(verdicts[index])
        for key in (old, new):
            if key is not None and key not in moved:
                moved[key] = set(open_.get(key, ()))
        if old is not None:
            moved[old].discard(index)
        if new is None:
            continue
        moved[new].add(index)
        if new == SEVERAL:
            continue
        mine = grown.get(new)
        if mine is None:
            mine = grown[new] = dict(held.get(new, {}))
        mine.update((w, w) for w in verdicts[index].verdict.witnesses or ())
    for component, mine in grown.items():
        kept = moved[component]
        if len(mine) > 4 * len(kept) + 64:
            used = {w for index in kept for w in verdicts[index].verdict.witnesses or ()}
            grown[component] = {w: mine[w] for w in used}
    opened = {**open_, **{key: frozenset(indices) for key, indices in moved.items()}}
    return Judgement(verdicts, opened, {**held, **grown}, changed)
