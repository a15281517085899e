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
from rosvar.analyses.features import FeatureModel
from rosvar.configuration.derivation import Decisions
from rosvar.configuration.lowering import Bounds, Lowering
from rosvar.logic.conditions import BDD

CERTAIN, POSSIBLE = "certain", "possible"


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
    """Every clashing pair of the model, judged against ``tree ∧ requires``."""

    def __init__(
        self, model: FeatureModel, lowering: Lowering, file_ids: Mapping[str, str]
    ) -> None:
        solver = model.solver
        self.manager = solver.manager
        self.lowering = lowering
        self._quantified = set(solver.variables)
        allowed = solver.tree
        for constraint, formula in zip(model.constraints, solver.constraints, strict=True):
            if constraint.kind == "requires":
                allowed &= formula
        self.allowed = allowed
        groups: dict[tuple[str, str], list[Clash]] = {}
        for clash in model.clashes:
            if clash.first.file != clash.second.file or clash.kind == "node":
                key = tuple(sorted(clash.files))
                groups.setdefault(key, []).append(clash)  # type: ignore[arg-type]
        variables = {f.file: solver.var(f.variable) for f in model.files}
        self.pairs: list[Clashing] = []
        for (first, second), clashes in sorted(groups.items()):
            condition = model.space.false
            for clash in clashes:
                condition |= clash.condition
            fixed, bounds = lowering.lower(condition)
            if bounds.may == self.manager.false:
                continue
            self.pairs.append(
                Clashing(
                    (file_ids[first], file_ids[second]),
                    tuple(sorted({f"{c.kind} {c.name}" for c in clashes})),
                    variables[first] & variables[second],
                    fixed,
                    bounds,
                )
            )

    def _satisfiable(self, cube: BDD) -> bool:
        return bool(_cudd.and_exists(self.allowed, cube, self._quantified) != self.manager.false)

    def judge(
        self, decisions: Decisions, describe: Callable[[BDD, Mapping[str, bool]], str]
    ) -> list[ConflictState]:
        found = []
        for pair in self.pairs:
            both = decisions.cube & pair.both
            if both == self.manager.false or not self._satisfiable(both & pair.bounds.may):
                continue
            if not self._satisfiable(both & ~pair.bounds.must):
                found.append(ConflictState(pair.files, pair.names, CERTAIN, None))
                continue
            found.append(
                ConflictState(
                    pair.files, pair.names, POSSIBLE, describe(pair.condition, decisions.literals)
                )
            )
        return found
