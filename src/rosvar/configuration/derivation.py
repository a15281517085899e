"""Derived feature states: what the solver decides once the user fixed some variables.

A variable is decided true when no valid configuration (formula ∧ user literals) sets it
false, and decided false when none sets it true. The feature model's solver holds one
formula per *component* (files linked by constraints; components share no variable), so
a choice only changes what is decided in its own component. Two kinds of evidence answer
the questions:

* *witnesses*: valid configurations, models of the SAT solver (``sat``) under the user
  literals. A variable that takes both values among a component's witnesses is open; so
  is an element whose condition is true in one witness and false in another.
* *refutations*: the same solver finding no model. What the witnesses leave unsettled
  goes to one question (one of them differs from the witnesses), which usually refutes
  the lot; when it does not, its model is a new witness, which prefers the values not
  seen yet and so shows many open at once.

Witnesses are kept as a cover (``_cover``: enough to show every open variable open).
Literals are added one at a time; each step keeps the witnesses that agree with the new
literal, *repairs* the others (``repaired``: the files where one disagrees copied from a
witness that agrees) and only looks at the variables still open in the literal's
component. Repairs also carry most undetermined verdicts from one step to the next
without a question to the solver. The BDDs of the components are only restricted to
count configurations.

One module, past the usual length: witnesses, repairs and questions are one algorithm over
one state (each component's witnesses as bit masks), and each part is only correct with
what the others keep true of it (a cover that shows every open variable, repairs that stay
valid configurations).
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, replace

from rosvar.analyses.feature_model.features import FileFeature, name_of
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.configuration.lowering import Bounds
from rosvar.configuration.presence import Presence, PresenceVerdict
from rosvar.configuration.sat import Sat
from rosvar.logic.bdd import (
    BDD,
    Cubes,
    Literals,
    children_first,
    cofactor,
    cofactors,
    evaluate,
    walked_support,
)
from rosvar.memo import Memo

SOURCES = 4  # witnesses tried as the source of a repair
REPAIRED_FILES = 32  # files a repair may copy: beyond, the solver is the cheaper way
CACHED_REPAIRS = 4096  # repaired witnesses by witness and literals, dropped all at once
MUTATED = 4  # the latest candidates a missing example is first sought from (``_mutated``)
EXAMPLES = 64
"""Configurations found for presence judgements, kept to judge other conditions too."""


Crossing = tuple[BDD, int, frozenset[int]]
"""A constraint that links files, the positions of the variables it reads (as bits), and
those files."""


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


class Derivation:
    """Satisfiability questions about the feature model, one component at a time."""

    def __init__(self, model: FeatureModel) -> None:
        solver = model.solver
        self.manager = manager = solver.manager
        self._cubes = Cubes(manager)  # of the decided literals conditions are restricted by
        self.sats = Sat.per_component(model)
        self._model = model
        self._whole_sat: Sat | None = None
        self.variables = list(solver.variables)
        self.position = {v: i for i, v in enumerate(self.variables)}
        self.components = solver.components
        self.members = [list(c.variables) for c in solver.components]
        self._masks = [sum(1 << self.position[v] for v in c.variables) for c in solver.components]
        self._blocks = [sum(1 << self.position[v] for v in f.variable_names()) for f in model.files]
        self._file_at = {
            self.position[v]: n for n, f in enumerate(model.files) for v in f.variable_names()
        }
        # the constraints that leave each file, with the files they link
        self._crossing: list[list[Crossing]] = [[] for _ in model.files]
        # every part of the component formulas that reads a file, and its args' values
        self._parts_of: list[list[BDD]] = [solver.arg_trees(f) for f in model.files]
        self._groups = [_groups(f, self.position) for f in model.files]
        self._file_bit = [1 << self.position[name_of(f.variable)] for f in model.files]
        for constraint in solver.constraints:
            support = [self.position[v] for v in walked_support(constraint)]
            files = frozenset(self._file_at[at] for at in support)
            for file in files:
                self._parts_of[file].append(constraint)
            if len(files) > 1:
                reads = sum(1 << at for at in support)
                for file in files:
                    self._crossing[file].append((constraint, reads, files))
        self._necessary: Memo[BDD, tuple[int, int]] = Memo()
        self._component_sets: dict[frozenset[int], frozenset[int]] = {}
        """Each set of components ``_restricted`` names once (nearly always one component:
        Husky + ``_external`` names 30,000 times a few)."""
        self._implications: Memo[tuple[int, int], tuple[int, int]] = Memo()
        """Each distinct value of ``_necessary`` once: its integers are as wide as the
        positions (Husky + ``_external``: 15,566 values, 5,462 distinct, 600 bytes each)."""
        self._leaving: dict[frozenset[int], tuple[int, tuple[Crossing, ...]]] = {}
        """Files → the constraints that link them to other files, and what those read."""
        self._broke: dict[tuple[frozenset[int], int], frozenset[int]] = {}
        self._repairs: dict[tuple[int, BDD], int | None] = {}
        self._block_of: dict[frozenset[int], int] = {}  # files → their variables' positions
        self.component_of = solver.component_of
        self._supports: Memo[BDD, tuple[str, ...]] = Memo()
        self._masks_of: Memo[BDD, int] = Memo()
        self._restricted: Memo[object, tuple[Presence | None, BDD, BDD, frozenset[int]]] = Memo()
        self._judged: Memo[tuple[BDD, BDD, BDD], tuple[Presence, tuple[int, int] | None]] = Memo()
        self._counts: Memo[tuple[int, BDD], int] = Memo()
        components = range(len(self.members))
        self._examples: dict[int, deque[int]] = {}  # per component: its solver's models
        self._combinations: deque[tuple[frozenset[int], int]] = deque(maxlen=EXAMPLES)
        """Examples over several components (``_combined``) and their components."""
        firsts = [sat.model([]) for sat in self.sats]
        valid = None not in firsts  # else the model has no valid configuration at all
        empty = Decisions(
            {},
            {i: manager.true for i in components},
            {},
            {i: (first,) if valid and first is not None else () for i, first in enumerate(firsts)},
            {i: (0, 0) for i in components},
        )
        if valid:
            for i in components:
                empty = self._settle(empty, i)
        self.initial = empty

    def satisfiable(self, literals: Iterable[tuple[str, bool]]) -> bool:
        """Some valid configuration sets every variable of ``literals`` to its value."""
        own: list[list[int]] = [[] for _ in self.sats]
        for variable, value in literals:
            component = self.component_of[variable]
            own[component].append(self.sats[component].atom(variable, value))
        return all(sat.satisfiable(mine) for sat, mine in zip(self.sats, own, strict=True))

    def _whole(self) -> Sat:
        """A solver for questions about several components at once (rare: no constraint
        links their files), made on first need."""
        if self._whole_sat is None:
            self._whole_sat = Sat.whole(self._model)
        return self._whole_sat

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
        witnesses = decisions.witnesses[component]
        kept = tuple(w for w in witnesses if bool(w & bit) == value)
        if not kept:
            found = self.sats[component].model(self._assumptions(step, component))
            if found is None:
                return None
            kept = (found,)
        step = replace(
            step,
            decided={**decisions.decided, variable: value},
            witnesses={**decisions.witnesses, component: kept},
        )
        repaired = self.repaired(component, (w for w in witnesses if w not in kept), step).values()
        kept += tuple(dict.fromkeys(w for w in repaired if w is not None and w not in kept))
        step = replace(step, witnesses={**decisions.witnesses, component: kept})
        return self._settle(step, component)

    def _assumptions(self, decisions: Decisions, component: int | None) -> list[int]:
        """The user literals on ``component`` (None: all), as its solver's assumptions."""
        if component is None:
            return [self._whole().atom(v, b) for v, b in decisions.literals.items()]
        sat, of = self.sats[component], self.component_of
        return [sat.atom(v, b) for v, b in decisions.literals.items() if of[v] == component]

    def _settle(self, step: Decisions, component: int) -> Decisions:
        """Decide the component's open variables: open where witnesses disagree, else by
        refutation.

        The *suspects* are the undecided variables every witness gives the same value
        (found with masks: one bit per variable). One SAT question asks for a valid
        configuration where one of them differs: none refutes them all at once (the
        common answer), else the model, which prefers the values not seen yet for every
        suspect, is a new witness and usually shows many open.
        """
        witnesses = list(step.witnesses[component])
        decided = dict(step.decided)
        sat = self.sats[component]
        assumptions = self._assumptions(step, component)
        position, variables = self.position, self.variables
        undecided = self._masks[component]
        for variable in decided:
            if self.component_of[variable] == component:
                undecided &= ~(1 << position[variable])
        ones, all_ones = 0, -1
        for witness in witnesses:
            ones, all_ones = ones | witness, all_ones & witness
        while suspected := undecided & ~(ones ^ all_ones):
            suspects = []
            while suspected:
                at = (suspected & -suspected).bit_length() - 1
                suspected &= suspected - 1
                suspects.append((variables[at], bool(all_ones >> at & 1)))
            differ = [sat.atom(v, not seen) for v, seen in suspects]
            found = sat.model(assumptions, some=differ, prefer=differ)
            if found is None:
                decided.update(suspects)
                break
            witnesses.append(found)
            ones, all_ones = ones | found, all_ones & found
        shown = undecided & (ones ^ all_ones)  # the open variables
        return Decisions(
            step.literals,
            step.cubes,
            decided,
            {**step.witnesses, component: _cover(witnesses, shown)},
            step.fixed,
        )

    def count(self, decisions: Decisions) -> int:
        """Valid configurations left: the product of the components' exact counts (each
        cached; CUDD's own count is a double, exact only below 2^53)."""
        total = 1
        for component, cube in decisions.cubes.items():
            found = self._counts.get((component, cube))
            if found is None:
                mine = {
                    v: b for v, b in decisions.literals.items() if self.component_of[v] == component
                }
                found = self.components[component].count(mine)
                self._counts[(component, cube)] = found
            total *= found
        return total

    def prepare_counts(self) -> None:
        """Make every component ready to be counted after any choice (``count``): for a
        server, which would otherwise charge the first count and recount to clicks."""
        for component in self.components:
            component.counted_diagram.prepare()

    def presence(self, bounds: Bounds, decisions: Decisions) -> PresenceVerdict:
        """Present, absent or undetermined, and what the verdict depended on."""
        return self.presences([(bounds, None)], decisions)[0]

    def presences(
        self, conditions: Sequence[tuple[Bounds, PresenceVerdict | None]], decisions: Decisions
    ) -> list[PresenceVerdict]:
        """Each condition's verdict, and what it depended on; with a condition may come
        its verdict under fewer literals (a prefix of these), whose witnesses may be
        repaired (``_carried``).

        Restricting by the decided variables settles most conditions; the witnesses show
        most of the rest undetermined; only what is left goes to the solver. Answers are
        remembered: most conditions keep theirs from one step to the next.
        """
        verdicts = []
        for bounds, earlier in conditions:
            support = self._support(bounds.may)
            if bounds.must != bounds.may:
                support = (*support, *(v for v in self._support(bounds.must) if v not in support))
            values = {v: decisions.decided[v] for v in support if v in decisions.decided}
            literals = frozenset(values.items())
            key = (bounds.must, bounds.may, literals)
            restricted = self._restricted.get(key)
            if restricted is None:
                restricted = self._restrict(bounds, literals, frozenset(support).difference(values))
                self._restricted[key] = restricted
            verdict, must, may, components = restricted
            if verdict is not None:
                verdicts.append(PresenceVerdict(verdict, values))
                continue
            (component,) = components if len(components) == 1 else (None,)
            cube = decisions.cube if component is None else decisions.cubes[component]
            judged = self._judged.get((must, may, cube))
            if judged is None:
                judged = None
                if earlier is not None and component is not None:
                    judged = self._carried(must, may, earlier, decisions)
                if judged is None:
                    judged = self._judge(must, may, component, decisions)
                self._judged[(must, may, cube)] = judged
            verdicts.append(PresenceVerdict(judged[0], values, components, judged[1]))
        return verdicts

    def _restrict(
        self, bounds: Bounds, literals: Literals, open_: frozenset[str]
    ) -> tuple[Presence | None, BDD, BDD, frozenset[int]]:
        """The verdict restriction by the decided ``literals`` alone gives, else what the
        solver must judge: the restricted bounds and the components of their open
        variables."""
        must = self._cubes.cofactor(bounds.must, literals)
        may = must if bounds.may == bounds.must else self._cubes.cofactor(bounds.may, literals)
        if must == self.manager.true:
            return Presence.PRESENT, must, may, frozenset()
        if may == self.manager.false:
            return Presence.ABSENT, must, may, frozenset()
        if not open_ or (must == may and len(open_) == 1):
            # only an <other> text decides it, or one open variable (it takes both values)
            return Presence.UNDETERMINED, must, may, frozenset()
        # conditions over several components are rare (no constraint links their files)
        components = frozenset(self.component_of[v] for v in open_)
        return None, must, may, self._component_sets.setdefault(components, components)

    def carries(self, bounds: Bounds, before: tuple[int, int], after: tuple[int, int]) -> bool:
        """The witnesses ``before`` of an undetermined verdict of ``bounds`` (one without
        ``must``, one with ``may``), repaired into ``after``, still show it undetermined.

        A repair that left the support of a bound alone left its truth as it was."""
        (without, within), (before_without, before_within) = after, before
        if (without ^ before_without) & self._mask(bounds.must) and self._holds(
            bounds.must, without
        ):
            return False
        return not (
            (within ^ before_within) & self._mask(bounds.may)
            and not self._holds(bounds.may, within)
        )

    def _carried(
        self, must: BDD, may: BDD, earlier: PresenceVerdict, decisions: Decisions
    ) -> tuple[Presence, tuple[int, int]] | None:
        """``earlier`` (undetermined under fewer literals) still undetermined for the
        restricted bounds ``must`` and ``may``, shown by its witnesses repaired."""
        repaired = self.repairs(earlier, decisions)
        if repaired is None:
            return None
        without, within = repaired
        if self._holds(must, without) or not self._holds(may, within):
            return None
        return Presence.UNDETERMINED, repaired

    def repairs(self, earlier: PresenceVerdict, decisions: Decisions) -> tuple[int, int] | None:
        """The witnesses of ``earlier`` (an undetermined verdict under fewer literals)
        repaired to agree with the literals of ``decisions`` (``repaired``); None when
        one cannot be."""
        if earlier.witnesses is None:
            return None
        (component,) = earlier.components
        found = self.repaired(component, earlier.witnesses, decisions)
        without, within = (found[w] for w in earlier.witnesses)
        if without is None or within is None:
            return None
        return without, within

    def repaired(
        self, component: int, witnesses: Iterable[int], decisions: Decisions
    ) -> dict[int, int | None]:
        """Each of ``witnesses`` (valid configurations of ``component`` under fewer
        literals) repaired to agree with the literals of ``decisions``: itself when it
        does, None when it cannot be.

        A step adds literals to a few files, and a witness that disagrees with one usually
        shows the condition of a file far from them. Copying the blocks of those files
        from a current witness keeps every constraint inside a block and outside them
        satisfied; only the constraints crossing a block's border are checked, and the
        files of those the copy breaks copied too, until none is broken (``_copied``).
        Most undetermined conditions are carried so, without a question to the solver.
        The witnesses of a step disagree with the same new literals: they share the
        files to copy, and one pass serves them all.
        """
        mask, bits = decisions.fixed[component]
        cube = decisions.cubes[component]
        sources = decisions.witnesses[component][:SOURCES]
        starts: dict[int, frozenset[int]] = {}  # wrong bits → their files
        found: dict[int, int | None] = {}
        for witness in witnesses:
            wrong = (witness ^ bits) & mask
            if not wrong:
                found[witness] = witness
                continue
            key = (witness, cube)
            if key in self._repairs:
                found[witness] = self._repairs[key]
                continue
            start = starts.get(wrong)
            if start is None:
                files, rest = set(), wrong
                while rest:
                    file = self._file_at[(rest & -rest).bit_length() - 1]
                    files.add(file)
                    rest &= ~self._blocks[file]
                start = starts[wrong] = frozenset(files)
            repaired = None
            for source in sources:
                repaired = self._copied(witness, source, start)
                if repaired is not None:
                    break
            if len(self._repairs) >= CACHED_REPAIRS:
                self._repairs.clear()
            self._repairs[key] = found[witness] = repaired
        return found

    def _copied(self, witness: int, source: int, files: frozenset[int]) -> int | None:
        """``witness`` with the blocks of ``files`` copied from ``source``, and then those
        of the files of every constraint the copy breaks; None beyond ``REPAIRED_FILES``."""
        if len(files) > REPAIRED_FILES:
            return None
        while True:
            block = self._block_of.get(files)
            if block is None:
                block = self._block_of[files] = sum(self._blocks[file] for file in files)
            patched = witness & ~block | source & block
            fresh = self._broken(files, patched, witness ^ patched, source ^ patched)
            if not fresh:
                return patched
            files |= fresh
            if len(files) > REPAIRED_FILES:
                return None

    def _broken(
        self, files: frozenset[int], patched: int, from_witness: int, from_source: int
    ) -> frozenset[int]:
        """The files outside ``files`` linked to them by a constraint that ``patched`` breaks,
        remembered for the values of the variables those constraints read: a step repairs
        many witnesses the same way, which differ elsewhere.

        ``from_witness`` and ``from_source`` are the bits where ``patched`` differs from the
        repaired witness and from its source, two valid configurations: a constraint whose
        variables agree with either holds, unevaluated (most do, far from the copy)."""
        leaving = self._leaving.get(files)
        if leaving is None:
            crossing = {
                part[0]: part
                for file in files
                for part in self._crossing[file]
                if not part[2] <= files  # within the copied blocks, it holds as in the source
            }
            reads = 0
            for _constraint, read, _others in crossing.values():
                reads |= read
            leaving = self._leaving[files] = (reads, tuple(crossing.values()))
        reads, constraints = leaving
        key = (files, patched & reads)
        found = self._broke.get(key)
        if found is None:
            if len(self._broke) >= CACHED_REPAIRS:
                self._broke.clear()
            found = self._broke[key] = frozenset(
                linked
                for constraint, read, others in constraints
                if from_witness & read
                and from_source & read
                and not self._holds(constraint, patched)
                for linked in others
                if linked not in files
            )
        return found

    def _judge(
        self, must: BDD, may: BDD, component: int | None, decisions: Decisions
    ) -> tuple[Presence, tuple[int, int] | None]:
        """The verdict, with the witnesses that show it undetermined in one component.

        It needs a valid configuration without ``must`` and one with ``may``: sought among
        the witnesses and earlier examples, else asked of the SAT solver, whose model
        becomes an example for the conditions judged after.
        """
        without = within = None
        if component is not None:
            examples = [
                w for w in self._examples.get(component, ()) if decisions.valid(component, w)
            ]
            candidates = [*decisions.witnesses[component], *examples]
            # the newest examples first: made for the conditions judged just before (the
            # variants of one element), they hold for the next more often than the others
            ordered = [*reversed(examples), *decisions.witnesses[component]]
            exact = must == may  # the usual case: one walk down the diagram answers both
            mask, bits = self._implied(may)  # a witness without these has no ``may``
            for witness in ordered:
                if witness & mask != bits:
                    holds = False
                elif exact:
                    holds = self._holds(must, witness)
                else:
                    holds = None
                if without is None and not (holds if exact else self._holds(must, witness)):
                    without = witness
                if within is None and (holds if holds is not None else self._holds(may, witness)):
                    within = witness
                if without is not None and within is not None:
                    return Presence.UNDETERMINED, (without, within)
            if within is None:
                within = self._mutated(may, component, decisions, candidates)
                if within is not None:
                    self._examples.setdefault(component, deque(maxlen=EXAMPLES)).append(within)
        if without is None:
            without = self._example(decisions, ~must, component)
            if without is None:
                return Presence.PRESENT, None
        if within is None:
            within = self._example(decisions, may, component)
            if within is None:
                return Presence.ABSENT, None
        return Presence.UNDETERMINED, None if component is None else (without, within)

    def _implied(self, u: BDD) -> tuple[int, int]:
        """Literals every model of ``u`` has (positions and values, as bits): those of the
        nodes from its root down while one cofactor is FALSE — a conjunction's top."""
        found = self._necessary.get(u)
        if found is None:
            mask = bits = 0
            false = self.manager.false
            node = u
            while node.var is not None:
                low, high = cofactors(node)
                bit = 1 << self.position[node.var]
                if low == false:
                    mask, bits, node = mask | bit, bits | bit, high
                elif high == false:
                    mask, node = mask | bit, low
                else:
                    break
            found = self._implications.get((mask, bits))
            if found is None:
                found = self._implications[mask, bits] = (mask, bits)
            self._necessary[u] = found
        return found

    def _mutated(
        self, goal: BDD, component: int, decisions: Decisions, candidates: Sequence[int]
    ) -> int | None:
        """A valid configuration where ``goal`` holds, made from one of ``candidates``
        (valid ones) without the solver: the path of ``goal`` to TRUE closest to it taken
        (``_closest``), the values of the args of the files it changed made one per arg
        again, and only the parts of the formula that read the variables it changed checked
        (the others hold as in the candidate).

        Variants of one element differ in the values of a few args, so a configuration
        found for one usually becomes one for the next by setting those values."""
        for witness in candidates[-MUTATED:]:
            mask, bits = self._closest(goal, witness)
            mutated = witness & ~mask | bits
            files = set()
            rest = mutated ^ witness
            while rest:
                file = self._file_at[(rest & -rest).bit_length() - 1]
                files.add(file)
                rest &= ~self._blocks[file]
            for file in files:
                mutated = self._one_value_each(file, mutated, mask)
            changed = mutated ^ witness  # a part that reads none of these holds as in it
            parts = (part for file in files for part in self._parts_of[file])
            if (
                decisions.valid(component, mutated)
                and self._holds(goal, mutated)
                and all(
                    not changed & self._mask(part) or self._holds(part, mutated) for part in parts
                )
            ):
                return mutated
        return None

    def _closest(self, goal: BDD, witness: int) -> tuple[int, int]:
        """The literals of a path of ``goal`` to TRUE that differs from ``witness`` in the
        fewest variables (positions and values, as bits)."""
        false, position = self.manager.false, self.position
        best: dict[BDD, tuple[int, int, int] | None] = {self.manager.true: (0, 0, 0), false: None}
        for node in children_first(goal, cofactors, best):
            assert node.var is not None  # the constants are in ``best`` already
            bit = 1 << position[node.var]
            has = bool(witness & bit)
            found = None
            for value, child in zip((False, True), cofactors(node), strict=True):
                below = best[child]
                if below is None:
                    continue
                cost = below[0] + (value != has)
                if found is None or cost < found[0]:
                    found = (cost, below[1] | bit, below[2] | bit if value else below[2])
            best[node] = found
        path = best[goal]
        return (0, 0) if path is None else (path[1], path[2])

    def _one_value_each(self, file: int, bits: int, fixed: int) -> int:
        """``bits`` with one value for each arg of a selected ``file`` (the one set, else
        its default or first value not cleared by ``fixed``), none for an unselected one."""
        for group, preferred in self._groups[file]:
            if not bits & self._file_bit[file]:
                bits &= ~group
                continue
            chosen = bits & group
            if chosen and not chosen & (chosen - 1):
                continue
            kept = chosen & fixed or group & ~fixed
            if not kept:
                continue  # every value is ruled out: the check of the parts refuses it
            pick = preferred if preferred & kept else kept & -kept
            bits = bits & ~group | pick
        return bits

    def _example(self, decisions: Decisions, goal: BDD, component: int | None) -> int | None:
        """A valid configuration under the user literals where ``goal`` (over ``component``;
        None: over several) holds, kept to judge its component's other conditions too;
        None: there is none."""
        if component is None:
            found = self._combined(decisions, goal)
            if found is not None:
                return found
        sat = self._whole() if component is None else self.sats[component]
        found = sat.model(self._assumptions(decisions, component), goal)
        if found is not None and component is not None:
            self._examples.setdefault(component, deque(maxlen=EXAMPLES)).append(found)
        return found

    def _combined(self, decisions: Decisions, goal: BDD) -> int | None:
        """A valid configuration where ``goal``, over several components, holds, found
        without the solver of the whole workspace; None: not found so (that solver answers).

        Components share no variable and no constraint, so witnesses of all but the largest
        with a model of the largest one's solver are a valid configuration: its question is
        ``goal`` restricted by their values. On Husky + ``_external`` such a question to
        the whole solver (4,228 variables) took 5 ms, its goal translated for it alone; to
        the largest component's (3,274) under 1 ms."""
        support = self._support(goal)
        components = {self.component_of[v] for v in support}
        if not components:  # TRUE (the literals have a valid configuration) or FALSE
            return 0 if goal == self.manager.true else None
        for made, example in reversed(self._combinations):  # the variants of one element
            if (
                components <= made
                and all(decisions.valid(c, example) for c in components)
                and self._holds(goal, example)
            ):
                return example
        largest = max(components, key=lambda c: len(self.members[c]))
        others = [decisions.witnesses[c] for c in sorted(components - {largest})]
        if not all(others):
            return None
        position, false = self.position, self.manager.false
        fixed = [v for v in support if self.component_of[v] != largest]
        tried = set()
        for turn in range(MUTATED):
            bits = 0
            for witnesses in others:
                bits |= witnesses[turn % len(witnesses)]
            if bits in tried:
                break
            tried.add(bits)
            rest = cofactor(goal, {v: bool(bits >> position[v] & 1) for v in fixed})
            if rest == false:
                continue
            found = self.sats[largest].model(self._assumptions(decisions, largest), rest)
            if found is not None:
                self._combinations.append((frozenset(components), bits | found))
                return bits | found
        return None

    def _holds(self, u: BDD, witness: int) -> bool:
        """The truth of ``u`` in a witness: one path from the root down."""
        position = self.position
        return evaluate(u, lambda name: witness >> position[name] & 1)

    def _mask(self, u: BDD) -> int:
        """The positions of ``u``'s support, as bits."""
        found = self._masks_of.get(u)
        if found is None:
            found = self._masks_of[u] = sum(1 << self.position[v] for v in self._support(u))
        return found

    def _support(self, u: BDD) -> tuple[str, ...]:
        """``u``'s variables, as a tuple: a server keeps one per condition, and a frozenset
        of the usual ten names takes six times the memory (Husky + ``_external``: 12 MB)."""
        found = self._supports.get(u)
        if found is None:
            found = tuple(walked_support(u))
            self._supports[u] = found
        return found


def _groups(file: FileFeature, position: Mapping[str, int]) -> list[tuple[int, int]]:
    """Per arg of ``file``: the positions of its values, and its default value's (else its
    first value's), as bits."""
    groups = []
    for arg in file.args:
        bits = [1 << position[name_of(v.variable)] for v in arg.values]
        if bits:
            defaults = [b for b, v in zip(bits, arg.values, strict=True) if v.default]
            groups.append((sum(bits), (defaults or bits)[0]))
    return groups


def _cover(witnesses: Sequence[int], shown: int) -> tuple[int, ...]:
    """The witnesses, newest first, that show a variable of ``shown`` take a value no
    witness kept before gives it: together they show every one of them open, and
    witnesses kept from step to step (and repaired) spare most questions to the solver."""
    ones = zeros = 0
    kept = []
    for witness in reversed(witnesses):
        if shown & (witness & ~ones | ~witness & ~zeros):
            kept.append(witness)
            ones |= witness
            zeros |= ~witness
    return tuple(kept)
