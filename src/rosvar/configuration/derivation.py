"""Derived feature states: what the solver decides once the user fixed some variables.

A variable is decided true when no valid configuration (formula ∧ user literals) sets it
false, and decided false when none sets it true. Each question is one satisfiability check
``∃ all. formula ∧ literals ∧ v`` done inside CUDD (``and_exists``), which never builds the
restricted formula. Literals are added one at a time and each step re-asks only about
variables that were still open and lie in the changed constraint component: a variable in
another component cannot be affected.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import dd.cudd as _cudd

from rosvar.configuration.lowering import Bounds
from rosvar.logic.conditions import BDD


@dataclass(frozen=True)
class Decisions:
    """The solver's view after some user literals."""

    cube: BDD  # the user literals, conjoined
    literals: Mapping[str, bool]  # the user literals by variable
    decided: Mapping[str, bool]  # every variable fixed in all valid configurations


class Derivation:
    """Satisfiability questions about one formula, grouped by constraint component."""

    def __init__(
        self,
        manager: _cudd.BDD,
        formula: BDD,
        variables: Sequence[str],
        component_of: Mapping[str, int],
    ) -> None:
        self.manager = manager
        self.formula = formula
        self.variables = list(variables)
        self._quantified = set(variables)
        self.component_of = dict(component_of)
        self.members: dict[int, list[str]] = {}
        for variable in self.variables:
            self.members.setdefault(self.component_of[variable], []).append(variable)
        self._supports: dict[BDD, frozenset[str]] = {}
        self.initial = Decisions(manager.true, {}, self._decide(manager.true, self.variables, {}))

    def satisfiable(self, cube: BDD) -> bool:
        """Some valid configuration satisfies ``cube`` (any small BDD)."""
        return bool(_cudd.and_exists(self.formula, cube, self._quantified) != self.manager.false)

    def add(self, decisions: Decisions, variable: str, value: bool) -> Decisions | None:
        """``decisions`` plus the user literal ``variable = value``; None when unsatisfiable."""
        known = decisions.decided.get(variable)
        literal = self.manager.var(variable) if value else ~self.manager.var(variable)
        cube = decisions.cube & literal
        literals = {**decisions.literals, variable: value}
        if known is not None:
            if known != value:
                return None
            return Decisions(cube, literals, decisions.decided)
        if not self.satisfiable(cube):
            return None
        open_ = [
            v
            for v in self.members[self.component_of[variable]]
            if v not in decisions.decided and v != variable
        ]
        decided = {**decisions.decided, variable: value}
        decided.update(self._decide(cube, open_, decided))
        return Decisions(cube, literals, decided)

    def presence(self, bounds: Bounds, decisions: Decisions) -> tuple[str, dict[str, bool]]:
        """Present, absent or undetermined, and the decided variables it was restricted by.

        Restricting by the decided variables settles most conditions; only one that still
        depends on several open variables needs the solver (they may be correlated).
        """
        support = self._support(bounds.may) | self._support(bounds.must)
        values = {v: decisions.decided[v] for v in support if v in decisions.decided}
        must = self.manager.let(values, bounds.must) if values else bounds.must
        may = self.manager.let(values, bounds.may) if values else bounds.may
        if must == self.manager.true:
            return PRESENT, values
        if may == self.manager.false:
            return ABSENT, values
        if must == may and len(support) - len(values) == 1:
            return UNDETERMINED, values  # one open variable: it takes both values
        if not self.satisfiable(decisions.cube & ~bounds.must):
            return PRESENT, values
        if not self.satisfiable(decisions.cube & bounds.may):
            return ABSENT, values
        return UNDETERMINED, values

    def _support(self, u: BDD) -> frozenset[str]:
        found = self._supports.get(u)
        if found is None:
            found = frozenset(self.manager.support(u))
            self._supports[u] = found
        return found

    def _decide(
        self, cube: BDD, candidates: Sequence[str], known: Mapping[str, bool]
    ) -> dict[str, bool]:
        """Candidates fixed under ``cube`` (the formula ∧ cube is satisfiable)."""
        found: dict[str, bool] = {}
        for variable in candidates:
            if variable in known:
                continue
            atom = self.manager.var(variable)
            if not self.satisfiable(cube & atom):
                found[variable] = False
            elif not self.satisfiable(cube & ~atom):
                found[variable] = True
        return found


PRESENT, ABSENT, UNDETERMINED = "present", "absent", "undetermined"
