"""Name clashes under the user's choices: certain, possible, or gone.

A clash is judged on the feature tree and the *requires* constraints only (the exclude
constraints say the clash must not happen, so they would hide it): ``S = tree ∧ requires
∧ user literals``. It is gone when no configuration of ``S`` has both files and the clash
condition, certain when every configuration of ``S`` with both files has it, and possible
otherwise, with its condition simplified under the choices.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import dd.cudd as _cudd

from rosvar.analyses.conflicts import Clash
from rosvar.analyses.features import FeatureModel, conjoin
from rosvar.configuration.derivation import Decisions
from rosvar.configuration.lowering import Bounds, Lowering
from rosvar.logic.conditions import BDD

CERTAIN, POSSIBLE = "certain", "possible"
REQUIRES_LIMIT = 100_000
"""Nodes of a component's formula above which its requires are left out of clash judgements."""


@dataclass(frozen=True)
class Clashing:
    """Two files (the same one twice for a clash inside a file) and where they clash."""

    files: tuple[str, str]  # spelled ids
    names: tuple[str, ...]
    both: BDD  # solver: both files selected
    condition: BDD  # analysis manager, fixed atoms substituted
    bounds: Bounds


@dataclass(frozen=True)
class ConflictState:
    files: tuple[str, str]
    names: tuple[str, ...]
    status: str  # certain | possible
    condition: str | None

    def to_json(self) -> dict[str, object]:
        return {
            "files": list(self.files),
            "names": list(self.names),
            "status": self.status,
            "condition": self.condition,
        }


class Conflicts:
    """Every clashing pair of the model, judged against ``tree ∧ requires``, per component.

    A pair's files are linked by their exclusion, so they share a component of the feature
    model; the pair's status only changes when a choice in that component does.
    """

    def __init__(
        self, model: FeatureModel, lowering: Lowering, file_ids: Mapping[str, str]
    ) -> None:
        solver = model.solver
        self.manager = manager = solver.manager
        self.lowering = lowering
        component_of = {f: i for i, c in enumerate(solver.components) for f in c.files}
        self._quantified = [set(c.variables) for c in solver.components]
        parts: list[list[BDD]] = []
        for component in solver.components:
            others = set(solver.variables) - set(component.variables)
            parts.append([manager.exist(others, solver.tree) if others else solver.tree])
        for constraint, formula in zip(model.constraints, solver.constraints, strict=True):
            if constraint.kind == "requires":
                parts[component_of[constraint.files[0]]].append(formula)
        # Where the whole component is too large a diagram, tree ∧ requires would be as
        # large and slow to build: such a component is judged on its tree alone.
        self.allowed = [
            conjoin(manager, p) if c.formula.dag_size <= REQUIRES_LIMIT else p[0]
            for c, p in zip(solver.components, parts, strict=True)
        ]
        groups: dict[tuple[str, str], list[Clash]] = {}
        for clash in model.clashes:
            if clash.first.file != clash.second.file or clash.kind == "node":
                key = tuple(sorted(clash.files))
                groups.setdefault(key, []).append(clash)  # type: ignore[arg-type]
        features = {f.file: f for f in model.files}
        self.pairs: list[tuple[int, Clashing]] = []
        for (first, second), clashes in sorted(groups.items()):
            condition = model.space.false
            for clash in clashes:
                condition |= clash.condition
            fixed, bounds = lowering.lower(condition)
            if bounds.may == manager.false:
                continue
            a, b = features[first], features[second]
            self.pairs.append(
                (
                    component_of[a.id],
                    Clashing(
                        (file_ids[first], file_ids[second]),
                        tuple(sorted({f"{c.kind} {c.name}" for c in clashes})),
                        solver.var(a.variable) & solver.var(b.variable),
                        fixed,
                        bounds,
                    ),
                )
            )
        self._judged: dict[tuple[int, BDD], ConflictState | None] = {}

    def _satisfiable(self, component: int, cube: BDD) -> bool:
        found = _cudd.and_exists(self.allowed[component], cube, self._quantified[component])
        return bool(found != self.manager.false)

    def judge(
        self, decisions: Decisions, describe: Callable[[BDD, Mapping[str, bool]], str]
    ) -> list[ConflictState]:
        found = []
        for number, (component, pair) in enumerate(self.pairs):
            cube = decisions.cubes[component]
            key = (number, cube)
            if key not in self._judged:
                self._judged[key] = self._status(component, pair, cube, decisions, describe)
            state = self._judged[key]
            if state is not None:
                found.append(state)
        return found

    def _status(
        self,
        component: int,
        pair: Clashing,
        cube: BDD,
        decisions: Decisions,
        describe: Callable[[BDD, Mapping[str, bool]], str],
    ) -> ConflictState | None:
        both = cube & pair.both
        if both == self.manager.false or not self._satisfiable(component, both & pair.bounds.may):
            return None
        if not self._satisfiable(component, both & ~pair.bounds.must):
            return ConflictState(pair.files, pair.names, CERTAIN, None)
        literals = {v: b for v, b in decisions.literals.items() if v in self._quantified[component]}
        return ConflictState(pair.files, pair.names, POSSIBLE, describe(pair.condition, literals))
