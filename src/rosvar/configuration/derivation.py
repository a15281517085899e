"""Derived feature states: what the solver decides once the user fixed some variables.

A variable is decided true when no valid configuration (formula ∧ user literals) sets it
false, and decided false when none sets it true. Two kinds of evidence answer this:

* *witnesses*: valid configurations found by a depth-first walk of the formula's BDD that
  follows the user literals. A variable that takes both values among the witnesses is open;
  so is an element whose condition is true in one witness and false in another.
* *refutations*: a satisfiability check ``∃ all. formula ∧ literals ∧ v`` done inside CUDD
  (``and_exists``), which never builds the restricted formula. Only what the witnesses leave
  unsettled is checked; a check that succeeds is followed by a walk that adds a witness.

Literals are added one at a time; each step keeps the witnesses that agree with the new
literal and only looks at variables that were still open in the constraint component the
literal belongs to: a variable in another component cannot be affected.
"""

from __future__ import annotations

import random
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import dd.cudd as _cudd

from rosvar.configuration.lowering import Bounds
from rosvar.logic.conditions import BDD

PRESENT, ABSENT, UNDETERMINED = "present", "absent", "undetermined"
WITNESSES = 16
"""Witnesses kept per step: enough to show most variables open, few enough to stay cheap."""


@dataclass(frozen=True)
class Decisions:
    """The solver's view after some user literals."""

    cube: BDD  # the user literals, conjoined
    literals: Mapping[str, bool]  # the user literals by variable
    decided: Mapping[str, bool]  # every variable fixed in all valid configurations
    witnesses: tuple[int, ...]  # valid configurations, one bit per variable (by position)


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
        self.position = {v: i for i, v in enumerate(self.variables)}
        self._quantified = set(variables)
        self.component_of = dict(component_of)
        self.members: dict[int, list[str]] = {}
        for variable in self.variables:
            self.members.setdefault(self.component_of[variable], []).append(variable)
        self._supports: dict[BDD, frozenset[str]] = {}
        self._random = random.Random(0)  # reproducible witnesses, hence reproducible timings
        first = self._witness({})
        empty = Decisions(manager.true, {}, {}, (first,) if first is not None else ())
        self.initial = self._settle(empty, self.variables) if first is not None else empty

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
            return Decisions(cube, literals, decisions.decided, decisions.witnesses)
        bit = 1 << self.position[variable]
        kept = tuple(w for w in decisions.witnesses if bool(w & bit) == value)
        if not kept:
            found = self._witness(literals)
            if found is None:
                return None
            kept = (found,)
        step = Decisions(cube, literals, {**decisions.decided, variable: value}, kept)
        open_ = [v for v in self.members[self.component_of[variable]] if v not in step.decided]
        return self._settle(step, open_)

    def _settle(self, step: Decisions, candidates: Sequence[str]) -> Decisions:
        """Decide ``candidates``: open where the witnesses disagree, else by refutation."""
        witnesses = list(step.witnesses)
        decided = dict(step.decided)
        for variable in candidates:
            bit = 1 << self.position[variable]
            values = {bool(w & bit) for w in witnesses}
            if len(values) == 2:
                continue
            (seen,) = values
            atom = self.manager.var(variable)
            if not self.satisfiable(step.cube & (~atom if seen else atom)):
                decided[variable] = seen
                continue
            found = self._witness({**step.literals, variable: not seen})
            assert found is not None
            witnesses.append(found)
        return Decisions(step.cube, step.literals, decided, tuple(witnesses[-WITNESSES:]))

    def _witness(self, literals: Mapping[str, bool]) -> int | None:
        """A valid configuration with ``literals``: a walk of the formula to TRUE, or None.

        Nodes whose variable is fixed follow the literal; the others try a random branch
        first. Nodes found to lead nowhere under the literals are remembered, so the walk
        never visits a node twice.
        """
        manager = self.manager
        true, false = manager.true, manager.false
        coin = self._random.getrandbits
        dead: set[BDD] = set()
        path: dict[str, bool] = {}
        stack: list[tuple[BDD, str, BDD | None]] = []  # node, its variable, branch left
        node = self.formula
        while node != true:
            if node == false or node in dead:
                while stack:  # back up to the last node with a branch left
                    parent, name, other = stack.pop()
                    if other is not None:
                        stack.append((parent, name, None))
                        path[name] = not path[name]
                        node = other
                        break
                    dead.add(parent)
                    del path[name]
                else:
                    return None
                continue
            low, high = node.low, node.high
            if node.negated:
                low, high = ~low, ~high
            name = str(node.var)
            value = literals.get(name)
            if value is None:
                value = bool(coin(1))
                stack.append((node, name, low if value else high))
            else:
                stack.append((node, name, None))
            path[name] = value
            node = high if value else low
        bits = 0
        for index, variable in enumerate(self.variables):
            value = path.get(variable)
            if value is None:
                value = literals.get(variable)
            if value is None:
                value = self._random.random() < 0.5
            if value:
                bits |= 1 << index
        return bits

    def presence(self, bounds: Bounds, decisions: Decisions) -> tuple[str, dict[str, bool]]:
        """Present, absent or undetermined, and the decided variables it was restricted by.

        Restricting by the decided variables settles most conditions; the witnesses show
        most of the rest undetermined; only what is left goes to the solver.
        """
        support = self._support(bounds.may) | self._support(bounds.must)
        values = {v: decisions.decided[v] for v in support if v in decisions.decided}
        must = self.manager.let(values, bounds.must) if values else bounds.must
        may = self.manager.let(values, bounds.may) if values else bounds.may
        if must == self.manager.true:
            return PRESENT, values
        if may == self.manager.false:
            return ABSENT, values
        open_ = sorted(support - values.keys())
        if not open_ or (must == may and len(open_) == 1):
            # only an <other> text decides it, or one open variable (it takes both values)
            return UNDETERMINED, values
        sometimes_not = sometimes = False
        for witness in decisions.witnesses:
            point = {v: bool(witness >> self.position[v] & 1) for v in open_}
            sometimes_not |= self.manager.let(point, must) == self.manager.false
            sometimes |= self.manager.let(point, may) == self.manager.true
            if sometimes and sometimes_not:
                return UNDETERMINED, values
        if not sometimes_not and not self.satisfiable(decisions.cube & ~bounds.must):
            return PRESENT, values
        if not sometimes and not self.satisfiable(decisions.cube & bounds.may):
            return ABSENT, values
        return UNDETERMINED, values

    def _support(self, u: BDD) -> frozenset[str]:
        found = self._supports.get(u)
        if found is None:
            found = frozenset(self.manager.support(u))
            self._supports[u] = found
        return found
