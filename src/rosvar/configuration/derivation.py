"""Derived feature states: what the solver decides once the user fixed some variables.

A variable is decided true when no valid configuration (formula ∧ user literals) sets it
false, and decided false when none sets it true. The feature model's solver holds one
formula per *component* (files linked by constraints; components share no variable), so
every question is asked of one component, and a choice only changes its own component.
Two kinds of evidence answer the questions:

* *witnesses*: valid configurations of a component, found by a depth-first walk of its BDD
  that follows the user literals. A variable that takes both values among the witnesses is
  open; so is an element whose condition is true in one witness and false in another.
* *refutations*: a satisfiability check ``∃ all. formula ∧ literals ∧ v`` done inside CUDD
  (``and_exists``), which never builds the restricted formula. Only what the witnesses leave
  unsettled is checked; a check that succeeds is followed by a walk that adds a witness.

Literals are added one at a time; each step keeps the witnesses that agree with the new
literal and only looks at the variables still open in the literal's component.
"""

from __future__ import annotations

import random
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import dd.cudd as _cudd

from rosvar.analyses.features import Solver
from rosvar.configuration.lowering import Bounds
from rosvar.logic.conditions import BDD

PRESENT, ABSENT, UNDETERMINED = "present", "absent", "undetermined"
WITNESSES = 24
CACHED_ROOTS = 64  # formulas restricted by a step's literals, shared by that step's walks
"""Witnesses kept per component and step: enough to show most variables open."""


@dataclass(frozen=True)
class Decisions:
    """The solver's view after some user literals."""

    literals: Mapping[str, bool]  # the user literals by variable
    cubes: Mapping[int, BDD]  # the user literals of each component, conjoined
    decided: Mapping[str, bool]  # every variable fixed in all valid configurations
    witnesses: Mapping[int, tuple[int, ...]]  # per component: one bit per variable position

    @property
    def cube(self) -> BDD:
        """All user literals, conjoined."""
        cubes = iter(self.cubes.values())
        result = next(cubes)
        for cube in cubes:
            result &= cube
        return result


class Derivation:
    """Satisfiability questions about the feature model, one component at a time."""

    def __init__(self, solver: Solver) -> None:
        self.solver = solver
        self.manager = manager = solver.manager
        self._all = set(solver.variables)
        self.variables = list(solver.variables)
        self.position = {v: i for i, v in enumerate(self.variables)}
        self.formulas = [c.formula for c in solver.components]
        self.members = [list(c.variables) for c in solver.components]
        self._quantified = [set(c.variables) for c in solver.components]
        self.component_of = {v: i for i, c in enumerate(self.members) for v in c}
        self._supports: dict[BDD, frozenset[str]] = {}
        self._restricted: dict[object, tuple[str | None, BDD, BDD, int | None]] = {}
        self._judged: dict[tuple[BDD, BDD, BDD], str] = {}
        self._roots: dict[tuple[int, frozenset[tuple[str, bool]]], BDD] = {}
        self._random = random.Random(0)  # reproducible witnesses, hence reproducible timings
        components = range(len(self.members))
        empty = Decisions(
            {},
            {i: manager.true for i in components},
            {},
            {i: self._walks(i, {}, WITNESSES) for i in components},
        )
        for i in components:
            if empty.witnesses[i]:  # else the model has no valid configuration at all
                empty = self._settle(empty, i, self.members[i])
        self.initial = empty

    def satisfiable(self, component: int, cube: BDD) -> bool:
        """Some valid configuration of ``component`` satisfies ``cube`` (a small BDD)."""
        found = _cudd.and_exists(self.formulas[component], cube, self._quantified[component])
        return bool(found != self.manager.false)

    def add(self, decisions: Decisions, variable: str, value: bool) -> Decisions | None:
        """``decisions`` plus the user literal ``variable = value``; None when unsatisfiable."""
        component = self.component_of[variable]
        atom = self.manager.var(variable)
        cube = decisions.cubes[component] & (atom if value else ~atom)
        literals = {**decisions.literals, variable: value}
        cubes = {**decisions.cubes, component: cube}
        known = decisions.decided.get(variable)
        if known is not None:
            if known != value:
                return None
            return Decisions(literals, cubes, decisions.decided, decisions.witnesses)
        bit = 1 << self.position[variable]
        kept = tuple(w for w in decisions.witnesses[component] if bool(w & bit) == value)
        if not kept:
            if not self.satisfiable(component, cube):
                return None  # refuted inside CUDD: a walk would have to try every path
            kept = self._walks(component, literals, 1)
        step = Decisions(
            literals,
            cubes,
            {**decisions.decided, variable: value},
            {**decisions.witnesses, component: kept},
        )
        return self._settle(step, component, self.members[component])

    def _settle(self, step: Decisions, component: int, candidates: Sequence[str]) -> Decisions:
        """Decide the open ``candidates``: open where witnesses disagree, else by refutation.

        A new witness prefers, for every candidate the witnesses agree on so far, the value
        not seen yet: one walk then shows many variables open at once.
        """
        witnesses = list(step.witnesses[component])
        cube = step.cubes[component]
        decided = dict(step.decided)
        ones, all_ones = 0, -1
        for witness in witnesses:
            ones, all_ones = ones | witness, all_ones & witness
        for variable in candidates:
            bit = 1 << self.position[variable]
            if variable in decided or (ones & bit and not all_ones & bit):
                continue
            seen = bool(all_ones & bit)
            atom = self.manager.var(variable)
            if not self.satisfiable(component, cube & (~atom if seen else atom)):
                decided[variable] = seen
                continue
            prefer = {
                v: not all_ones >> self.position[v] & 1
                for v in candidates
                if v not in decided and not (ones ^ all_ones) >> self.position[v] & 1
            }
            found = self._walks(component, step.literals, 1, prefer, (variable, not seen))
            for witness in found:
                witnesses.append(witness)
                ones, all_ones = ones | witness, all_ones & witness
        return Decisions(
            step.literals,
            step.cubes,
            decided,
            {**step.witnesses, component: tuple(witnesses[-WITNESSES:])},
        )

    def _walks(
        self,
        component: int,
        literals: Mapping[str, bool],
        count: int,
        prefer: Mapping[str, bool] | None = None,
        extra: tuple[str, bool] | None = None,
    ) -> tuple[int, ...]:
        """Up to ``count`` valid configurations of ``component`` that agree with ``literals``
        (and with the literal ``extra``, applied to the restriction by ``literals``, which is
        remembered: one step's walks share it).

        The formula is first restricted by the literals inside CUDD; in a reduced BDD every
        node but FALSE reaches TRUE, so each walk goes from the root to TRUE without ever
        backing up: where one branch is FALSE it takes the other, elsewhere the branch
        ``prefer`` names, else a random one.
        """
        manager = self.manager
        true, false = manager.true, manager.false
        coin = self._random.getrandbits
        members = self.members[component]
        fixed = {v: literals[v] for v in members if v in literals}
        key = (component, frozenset(fixed.items()))
        root = self._roots.get(key)
        if root is None:
            root = self.formulas[component]
            if fixed:
                root = manager.let(fixed, root)
            if len(self._roots) >= CACHED_ROOTS:
                self._roots.pop(next(iter(self._roots)))
            self._roots[key] = root
        if extra is not None:
            root = manager.let(dict([extra]), root)
            literals = {**literals, extra[0]: extra[1]}
        if root == false:
            return ()
        found: list[int] = []
        for _ in range(count):
            path: dict[str, bool] = {}
            node = root
            while node != true:
                low, high = node.low, node.high
                if node.negated:
                    low, high = ~low, ~high
                name = str(node.var)
                if low == false or high == false:
                    branch = low == false
                else:
                    preferred = prefer.get(name) if prefer else None
                    branch = bool(coin(1)) if preferred is None else preferred
                path[name] = branch
                node = high if branch else low
            bits = 0
            for variable in members:
                value = path.get(variable)
                if value is None:
                    value = literals.get(variable)
                if value is None and prefer:
                    value = prefer.get(variable)
                if value is None:
                    value = bool(coin(1))
                if value:
                    bits |= 1 << self.position[variable]
            found.append(bits)
        return tuple(found)

    def presence(self, bounds: Bounds, decisions: Decisions) -> tuple[str, dict[str, bool]]:
        """Present, absent or undetermined, and the decided variables it was restricted by.

        Restricting by the decided variables settles most conditions; the witnesses show
        most of the rest undetermined; only what is left goes to the solver. Answers are
        remembered: most elements keep theirs from one step to the next.
        """
        support = self._support(bounds.may) | self._support(bounds.must)
        values = {v: decisions.decided[v] for v in support if v in decisions.decided}
        key = (bounds.must, bounds.may, frozenset(values.items()))
        restricted = self._restricted.get(key)
        if restricted is None:
            restricted = self._restrict(bounds, values, support - values.keys())
            self._restricted[key] = restricted
        verdict, must, may, component = restricted
        if verdict is not None:
            return verdict, values
        cube = decisions.cube if component is None else decisions.cubes[component]
        judged = self._judged.get((must, may, cube))
        if judged is None:
            judged = self._judge(must, may, component, decisions)
            self._judged[(must, may, cube)] = judged
        return judged, values

    def _restrict(
        self, bounds: Bounds, values: Mapping[str, bool], open_: frozenset[str]
    ) -> tuple[str | None, BDD, BDD, int | None]:
        """The verdict restriction alone gives, else what the solver must judge."""
        must = self.cofactor(bounds.must, values)
        may = self.cofactor(bounds.may, values)
        if must == self.manager.true:
            return PRESENT, must, may, None
        if may == self.manager.false:
            return ABSENT, must, may, None
        if not open_ or (must == may and len(open_) == 1):
            # only an <other> text decides it, or one open variable (it takes both values)
            return UNDETERMINED, must, may, None
        components = {self.component_of[v] for v in open_}
        # conditions over several components are rare (no constraint links their files)
        return None, must, may, components.pop() if len(components) == 1 else None

    def _judge(self, must: BDD, may: BDD, component: int | None, decisions: Decisions) -> str:
        if component is None:
            everything, cube = self.solver.formula, decisions.cube
            if _cudd.and_exists(everything, cube & ~must, self._all) == self.manager.false:
                return PRESENT
            if _cudd.and_exists(everything, cube & may, self._all) == self.manager.false:
                return ABSENT
            return UNDETERMINED
        sometimes_not = sometimes = False
        for witness in decisions.witnesses[component]:
            sometimes_not |= not self._holds(must, witness)
            sometimes |= self._holds(may, witness)
            if sometimes and sometimes_not:
                return UNDETERMINED
        cube = decisions.cubes[component]
        if not sometimes_not and not self.satisfiable(component, cube & ~must):
            return PRESENT
        if not sometimes and not self.satisfiable(component, cube & may):
            return ABSENT
        return UNDETERMINED

    def _holds(self, u: BDD, witness: int) -> bool:
        """The truth of ``u`` in a witness: one path from the root down."""
        flipped = False
        while (name := u.var) is not None:
            flipped ^= bool(u.negated)  # the children are those of the regular node
            u = u.high if witness >> self.position[name] & 1 else u.low
        return bool(u == self.manager.true) != flipped

    def cofactor(self, u: BDD, values: Mapping[str, bool]) -> BDD:
        """``u`` with ``values`` fixed, one variable at a time (dd's ``let`` with Booleans
        builds a cube over every variable of the manager)."""
        true, false = self.manager.true, self.manager.false
        for name, value in values.items():
            u = self.manager.let({name: true if value else false}, u)
        return u

    def _support(self, u: BDD) -> frozenset[str]:
        found = self._supports.get(u)
        if found is None:
            found = frozenset(self.manager.support(u))
            self._supports[u] = found
        return found
