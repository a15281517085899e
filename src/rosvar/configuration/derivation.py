"""Derived feature states: what the solver decides once the user fixed some variables.

A variable is decided true when no valid configuration (formula ∧ user literals) sets it
false, and decided false when none sets it true. The feature model's solver holds one
formula per *component* (files linked by constraints; components share no variable), so
every question is asked of one component, and a choice only changes its own component.
Two kinds of evidence answer the questions:

* *witnesses*: valid configurations of a component, found by a depth-first walk of its BDD
  that follows the user literals. A variable that takes both values among the witnesses is
  open; so is an element whose condition is true in one witness and false in another.
* *refutations*: satisfiability checks ``∃ all. formula ∧ literals ∧ g`` done inside CUDD
  (``and_exists``), which never build the restricted formula. What the witnesses leave
  unsettled goes to one check (``g``: one of them differs from the witnesses), which
  usually refutes the lot; when it does not, halving finds one that differs and a walk
  adds a witness.

Literals are added one at a time; each step keeps the witnesses that agree with the new
literal and only looks at the variables still open in the literal's component.
"""

from __future__ import annotations

import random
from collections import deque
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from itertools import chain

import dd.cudd as _cudd

from rosvar.analyses.features import Solver
from rosvar.configuration.lowering import Bounds
from rosvar.logic.conditions import BDD

PRESENT, ABSENT, UNDETERMINED = "present", "absent", "undetermined"
WITNESSES = 24
"""Witnesses kept per component and step: enough to show most variables open."""
CACHED_ROOTS = 64  # formulas restricted by a step's literals, shared by that step's walks
EXAMPLES = 64
"""Configurations found for presence judgements, kept to judge other conditions too."""
SMALL_ROOT = 5_000
"""Nodes of a restricted formula up to which a conjunction with it costs less than a check."""


@dataclass(frozen=True)
class Decisions:
    """The solver's view after some user literals."""

    literals: Mapping[str, bool]  # the user literals by variable
    cubes: Mapping[int, BDD]  # the user literals of each component, conjoined
    decided: Mapping[str, bool]  # every variable fixed in all valid configurations
    witnesses: Mapping[int, tuple[int, ...]]  # per component: one bit per variable position
    fixed: Mapping[int, tuple[int, int]]  # per component: the literals' positions and values

    @property
    def cube(self) -> BDD:
        """All user literals, conjoined."""
        cubes = iter(self.cubes.values())
        result = next(cubes)
        for cube in cubes:
            result &= cube
        return result

    def valid(self, component: int, witness: int) -> bool:
        """A valid configuration of ``component`` (found at any step) is still valid here
        when it agrees with the user literals."""
        mask, bits = self.fixed[component]
        return witness & mask == bits


@dataclass(frozen=True)
class Verdict:
    """Presence of a condition at one step, and what it depended on.

    ``values`` are the decided variables of its support. When restriction by them was not
    enough, ``components`` are those whose literals the judgement read; an undetermined
    one keeps ``witnesses`` (a valid configuration without it, one that may have it):
    it stays undetermined while both agree with the user literals.
    """

    presence: str
    values: Mapping[str, bool]
    components: frozenset[int] = frozenset()
    witnesses: tuple[int, int] | None = None


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
        self.component_of = solver.component_of
        self._supports: dict[BDD, frozenset[str]] = {}
        self._restricted: dict[object, tuple[str | None, BDD, BDD, frozenset[int]]] = {}
        self._judged: dict[tuple[BDD, BDD, BDD], tuple[str, tuple[int, int] | None]] = {}
        self._roots: dict[tuple[int, BDD], tuple[BDD, int]] = {}  # with its size
        self._counts: dict[tuple[int, BDD], int] = {}
        components = range(len(self.members))
        self._random = random.Random(0)  # reproducible witnesses, hence reproducible timings
        self._examples: dict[int, deque[int]] = {i: deque(maxlen=EXAMPLES) for i in components}
        empty = Decisions(
            {},
            {i: manager.true for i in components},
            {},
            {},
            {i: (0, 0) for i in components},
        )
        empty = replace(empty, witnesses={i: self._walks(i, empty, WITNESSES) for i in components})
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
        bit = 1 << self.position[variable]
        mask, bits = decisions.fixed[component]
        step = Decisions(
            {**decisions.literals, variable: value},
            {**decisions.cubes, component: decisions.cubes[component] & (atom if value else ~atom)},
            decisions.decided,
            decisions.witnesses,
            {**decisions.fixed, component: (mask | bit, bits | bit if value else bits)},
        )
        known = decisions.decided.get(variable)
        if known is not None:
            return step if known == value else None
        kept = tuple(w for w in decisions.witnesses[component] if bool(w & bit) == value)
        if not kept:
            if not self._possible(component, step, self.manager.true):
                return None  # refuted inside CUDD: a walk would have to try every path
            kept = self._walks(component, step, 1)
        step = replace(
            step,
            decided={**decisions.decided, variable: value},
            witnesses={**decisions.witnesses, component: kept},
        )
        return self._settle(step, component, self.members[component])

    def _settle(self, step: Decisions, component: int, candidates: Sequence[str]) -> Decisions:
        """Decide the open ``candidates``: open where witnesses disagree, else by refutation.

        The *suspects* are the candidates every witness gives the same value. One solver
        question refutes them all at once (no valid configuration differs from the
        witnesses on any of them), which is the common answer; otherwise halving finds
        one that can differ, and a walk that prefers, for every suspect, the value not
        seen yet shows it and usually many others open.
        """
        witnesses = list(step.witnesses[component])
        decided = dict(step.decided)
        ones, all_ones = 0, -1
        for witness in witnesses:
            ones, all_ones = ones | witness, all_ones & witness
        while True:
            suspects = [
                (variable, bool(all_ones >> self.position[variable] & 1))
                for variable in candidates
                if variable not in decided and not (ones ^ all_ones) >> self.position[variable] & 1
            ]
            if not suspects:
                break
            found = self._differing(component, step, suspects, decided)
            if found is None:
                break
            variable, seen = found
            prefer = {v: not s for v, s in suspects}
            for witness in self._walks(component, step, 1, prefer, (variable, not seen)):
                witnesses.append(witness)
                ones, all_ones = ones | witness, all_ones & witness
        return Decisions(
            step.literals,
            step.cubes,
            decided,
            {**step.witnesses, component: tuple(witnesses[-WITNESSES:])},
            step.fixed,
        )

    def _differing(
        self,
        component: int,
        step: Decisions,
        suspects: Sequence[tuple[str, bool]],
        decided: dict[str, bool],
    ) -> tuple[str, bool] | None:
        """A suspect some valid configuration sets to the value not seen (None: none does).

        Suspects refuted on the way, a whole half at a time, go to ``decided``.
        """
        group = list(suspects)
        if not self._possible(component, step, self._differs(group)):
            decided.update(group)
            return None
        while len(group) > 1:
            half = group[: len(group) // 2]
            if self._possible(component, step, self._differs(half)):
                group = half
            else:
                decided.update(half)
                group = group[len(half) :]  # the other half holds one that differs
        return group[0]

    def _differs(self, literals: Sequence[tuple[str, bool]]) -> BDD:
        """Some variable differs from its value in ``literals``."""
        return ~self.manager.cube(dict(literals))

    def root(self, component: int, decisions: Decisions) -> BDD:
        """The component's formula with its user literals fixed (remembered per step)."""
        return self._root(component, decisions)[0]

    def _root(self, component: int, decisions: Decisions) -> tuple[BDD, int]:
        cube = decisions.cubes[component]
        key = (component, cube)
        found = self._roots.get(key)
        if found is None:
            mine = {v: b for v, b in decisions.literals.items() if v in self._quantified[component]}
            root = self.cofactor(self.formulas[component], mine)
            found = (root, root.dag_size)
            if len(self._roots) >= CACHED_ROOTS:
                self._roots.pop(next(iter(self._roots)))
            self._roots[key] = found
        return found

    def _possible(self, component: int, decisions: Decisions, goal: BDD) -> bool:
        """Some valid configuration under the user literals satisfies ``goal``: conjoined
        with the restricted formula where it is small (``and_exists`` first builds a cube
        over every variable of the manager), else checked inside CUDD."""
        root, size = self._root(component, decisions)
        if size > SMALL_ROOT:
            return self.satisfiable(component, decisions.cubes[component] & goal)
        return bool(root & goal != self.manager.false)

    def _example(self, component: int, decisions: Decisions, goal: BDD) -> int | bool:
        """A valid configuration satisfying ``goal`` where the restricted formula is small
        enough to conjoin; else only whether there is one (False: none)."""
        root, size = self._root(component, decisions)
        if size > SMALL_ROOT:
            return self._possible(component, decisions, goal)
        both = root & goal
        if both == self.manager.false:
            return False
        found = self._walk(component, both, decisions.literals)
        self._examples[component].append(found)
        return found

    def count(self, decisions: Decisions) -> int:
        """Valid configurations left: the product of the components' counts (each cached)."""
        total = 1
        for component, cube in decisions.cubes.items():
            found = self._counts.get((component, cube))
            if found is None:
                mask = decisions.fixed[component][0]
                free = len(self.members[component]) - mask.bit_count()
                found = int(self.manager.count(self.root(component, decisions), nvars=free))
                self._counts[(component, cube)] = found
            total *= found
        return total

    def _walks(
        self,
        component: int,
        decisions: Decisions,
        count: int,
        prefer: Mapping[str, bool] | None = None,
        extra: tuple[str, bool] | None = None,
    ) -> tuple[int, ...]:
        """Up to ``count`` valid configurations of ``component`` under the user literals of
        ``decisions`` (and the literal ``extra``).

        In a reduced BDD every node but FALSE reaches TRUE, so each walk of the restricted
        formula goes from the root to TRUE without ever backing up: where one branch is
        FALSE it takes the other, elsewhere the branch ``prefer`` names, else a random one.
        """
        literals = decisions.literals
        root = self.root(component, decisions)
        if extra is not None:
            root = self.manager.let(dict([extra]), root)
            literals = {**literals, extra[0]: extra[1]}
        if root == self.manager.false:
            return ()
        return tuple(self._walk(component, root, literals, prefer) for _ in range(count))

    def _walk(
        self,
        component: int,
        root: BDD,
        literals: Mapping[str, bool],
        prefer: Mapping[str, bool] | None = None,
    ) -> int:
        """One configuration of ``component`` satisfying ``root`` (a restriction of its
        formula by ``literals``, not FALSE), as bits."""
        true, false = self.manager.true, self.manager.false
        coin = self._random.getrandbits
        position = self.position
        bits = 0
        seen: set[str] = set()
        node, flipped = root, False
        while (name := node.var) is not None:
            flipped ^= bool(node.negated)  # the children are those of the regular node
            low, high = node.low, node.high
            dead = true if flipped else false  # the child that is FALSE under the flip
            if low == dead or high == dead:
                branch = low == dead
            else:
                preferred = prefer.get(name) if prefer else None
                branch = bool(coin(1)) if preferred is None else preferred
            seen.add(name)
            if branch:
                bits |= 1 << position[name]
            node = high if branch else low
        for variable in self.members[component]:
            if variable in seen:
                continue
            value = literals.get(variable)
            if value is None and prefer:
                value = prefer.get(variable)
            if value is None:
                value = bool(coin(1))
            if value:
                bits |= 1 << position[variable]
        return bits

    def presence(self, bounds: Bounds, decisions: Decisions) -> Verdict:
        """Present, absent or undetermined, and what the verdict depended on.

        Restricting by the decided variables settles most conditions; the witnesses show
        most of the rest undetermined; only what is left goes to the solver. Answers are
        remembered: most conditions keep theirs from one step to the next.
        """
        support = self._support(bounds.may) | self._support(bounds.must)
        values = {v: decisions.decided[v] for v in support if v in decisions.decided}
        key = (bounds.must, bounds.may, frozenset(values.items()))
        restricted = self._restricted.get(key)
        if restricted is None:
            restricted = self._restrict(bounds, values, support - values.keys())
            self._restricted[key] = restricted
        verdict, must, may, components = restricted
        if verdict is not None:
            return Verdict(verdict, values)
        (component,) = components if len(components) == 1 else (None,)
        cube = decisions.cube if component is None else decisions.cubes[component]
        judged = self._judged.get((must, may, cube))
        if judged is None:
            judged = self._judge(must, may, component, decisions)
            self._judged[(must, may, cube)] = judged
        return Verdict(judged[0], values, components, judged[1])

    def _restrict(
        self, bounds: Bounds, values: Mapping[str, bool], open_: frozenset[str]
    ) -> tuple[str | None, BDD, BDD, frozenset[int]]:
        """The verdict restriction alone gives, else what the solver must judge: the
        restricted bounds and the components of their open variables."""
        must = self.cofactor(bounds.must, values)
        may = self.cofactor(bounds.may, values)
        if must == self.manager.true:
            return PRESENT, must, may, frozenset()
        if may == self.manager.false:
            return ABSENT, must, may, frozenset()
        if not open_ or (must == may and len(open_) == 1):
            # only an <other> text decides it, or one open variable (it takes both values)
            return UNDETERMINED, must, may, frozenset()
        # conditions over several components are rare (no constraint links their files)
        return None, must, may, frozenset(self.component_of[v] for v in open_)

    def _judge(
        self, must: BDD, may: BDD, component: int | None, decisions: Decisions
    ) -> tuple[str, tuple[int, int] | None]:
        """The verdict, with the witnesses that show it undetermined when there are some."""
        if component is None:
            everything, cube = self.solver.formula, decisions.cube
            if _cudd.and_exists(everything, cube & ~must, self._all) == self.manager.false:
                return PRESENT, None
            if _cudd.and_exists(everything, cube & may, self._all) == self.manager.false:
                return ABSENT, None
            return UNDETERMINED, None
        without = within = None
        examples = (w for w in self._examples[component] if decisions.valid(component, w))
        for witness in chain(decisions.witnesses[component], examples):
            if without is None and not self._holds(must, witness):
                without = witness
            if within is None and self._holds(may, witness):
                within = witness
            if without is not None and within is not None:
                return UNDETERMINED, (without, within)
        found_without = self._example(component, decisions, ~must) if without is None else without
        if found_without is False:  # (a witness is an int, never the object False)
            return PRESENT, None
        found_within = self._example(component, decisions, may) if within is None else within
        if found_within is False:
            return ABSENT, None
        if found_without is True or found_within is True:
            return UNDETERMINED, None
        return UNDETERMINED, (found_without, found_within)

    def _holds(self, u: BDD, witness: int) -> bool:
        """The truth of ``u`` in a witness: one path from the root down."""
        flipped = False
        while (name := u.var) is not None:
            flipped ^= bool(u.negated)  # the children are those of the regular node
            u = u.high if witness >> self.position[name] & 1 else u.low
        return bool(u == self.manager.true) != flipped

    def cofactor(self, u: BDD, values: Mapping[str, bool]) -> BDD:
        """``u`` with ``values`` fixed."""
        return self.manager.let(dict(values), u) if values else u

    def _support(self, u: BDD) -> frozenset[str]:
        found = self._supports.get(u)
        if found is None:
            found = frozenset(self.manager.support(u))
            self._supports[u] = found
        return found
