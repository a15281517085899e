"""Presence conditions: propositional formulas over inputs, kept as BDDs.

One :class:`ConditionSpace` (one ``dd`` BDD manager) per analysis. Its variables
are *atoms*: "input X holds slot s" (exactly one slot per input, enforced by
:attr:`ConditionSpace.valid`) or "predicate p holds for the still-unknown term
t" (decided only when a configuration makes t concrete). Everything that asks
"can this happen?" asks the BDD, never ad-hoc logic.
"""

from __future__ import annotations

from collections.abc import Callable, Container, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, cast

import dd.cudd as _cudd

from rosvar.logic.inputs import OTHER, UNSET, ArgInput, EnvInput, Input, Slot
from rosvar.logic.terms import Term, term_inputs
from rosvar.logic.terms import evaluate as evaluate_term

BDD = Any  # dd.cudd.Function: dd ships no type information

BOOLEAN_WORDS = ("true", "false")
MAX_FULL = 200  # longer formulas over <other> values help nobody
MAX_CUBES = 256  # beyond this many disjuncts a formula is no longer readable
CACHE_ENTRIES = 1 << 16
"""Size of CUDD's computed table, fixed. CUDD's default start (2^18 entries) took more than
10 ms to set up, and CUDD grows the table with the unique table, i.e. with the number of
variables, whether or not it is used: interpretation fills a few percent of 2^16 entries
(Husky: 15,000 lookups in all), and growing it to 2^18 only cost page faults (8 MB, 1,500
faults, a few ms each run). The feature model's quantification in this manager does as many
steps with 2^16 entries as with 2^18 (callgrind on Husky)."""
SUPPORT_WALK_FACTOR = 16  # a node visited in Python costs about as much as 16 variables in dd
MEMORY_PER_FILE = 512 << 10
MIN_MEMORY = 64 << 20
MAX_MEMORY = 1 << 30
"""Bounds of the memory estimate given to CUDD (``memory_estimate``, see
:func:`memory_estimate`); the upper one is ``dd``'s default."""


def memory_estimate(files: int) -> int:
    """What CUDD is told to expect for an analysis of ``files`` launch files.

    CUDD touches a 128th of its estimate when the manager is created (8 MB, 2,000 page
    faults, for ``dd``'s default of 1 GiB) and collects garbage more eagerly once it uses
    90 % of it. Interpretation uses about 40 KB
    per file (Husky 8 MB, 2,000 generated files 80 MB), so half a MB per file keeps a
    wide margin while small systems start small.
    """
    return min(MAX_MEMORY, max(MIN_MEMORY, files * MEMORY_PER_FILE))


def cofactors(u: BDD) -> tuple[BDD, BDD]:
    """The low and high cofactors of ``u`` by its top variable (``dd`` gives the children of
    its regular node, which a complemented ``u`` negates)."""
    low, high = u.low, u.high
    return (~low, ~high) if u.negated else (low, high)


def children_first(
    root: BDD, children: Callable[[BDD], Iterable[BDD]], done: Container[BDD]
) -> Iterator[BDD]:
    """The nodes under ``root`` not in ``done``, each after its ``children``; the caller adds
    each node it is given to ``done``. An explicit stack: no recursion limit."""
    stack = [root]
    while stack:
        node = stack[-1]
        if node in done:
            stack.pop()
            continue
        pending = [child for child in children(node) if child not in done]
        if pending:
            stack.extend(pending)
            continue
        stack.pop()
        yield node


def walked_support(u: BDD) -> set[str]:
    """The variables ``u`` depends on, found by visiting its nodes: linear in ``u``'s size,
    where ``dd``'s ``support`` walks every variable of its manager in Python."""
    names: set[str] = set()
    seen: set[int] = set()
    stack = [u]
    while stack:
        node = stack.pop()
        name = node.var
        if name is None or int(node) in seen:
            continue
        seen.add(int(node))
        names.add(name)
        stack.append(node.low)
        stack.append(node.high)
    return names


class _TooComplex(Exception):
    """The condition has too many disjuncts to print usefully."""


@dataclass(frozen=True)
class SlotAtom:
    """Input ``input`` holds ``slot``."""

    input: Input
    slot: Slot


@dataclass(frozen=True)
class PredicateAtom:
    """``test(term)`` holds; ``test`` names an entry of :data:`PREDICATES`."""

    test: str
    term: Term


@dataclass(frozen=True)
class FileAtom:
    """Launch file ``file`` is part of the product (a feature of the feature model)."""

    file: str
    label: str


Atom = SlotAtom | PredicateAtom | FileAtom
Predicate = Callable[[str], bool]
PREDICATES: dict[str, tuple[Predicate, str]] = {}


def register_predicate(name: str, test: Predicate, display: str) -> None:
    """Register a predicate over strings; ``display`` is a format with ``{}`` for the term."""
    PREDICATES[name] = (test, display)


def exactly_one(manager: Any, variables: Sequence[BDD]) -> BDD:
    """Exactly one of ``variables`` holds (an xor-group), in ``manager``.

    Built in one pass (none so far / exactly one so far), not as the disjunction of one
    term per variable: linear instead of quadratic, and the same function, hence the
    same canonical BDD.
    """
    none = manager.true
    one = manager.false
    for variable in reversed(variables):  # in level order, each step only adds nodes above
        one = (variable & none) | (~variable & one)
        none = ~variable & none
    return one


class ConditionSpace:
    """The BDD manager of one analysis and the meaning of its variables."""

    def __init__(self, files: int = 0) -> None:
        """``files``: how many launch files the analysis holds, to size the manager."""
        self.bdd = _cudd.BDD(memory_estimate(files), CACHE_ENTRIES)
        # Declaration order is already local (one file's inputs together); dynamic
        # reordering would cost more than it saves, quadratically in the variables.
        self.bdd.configure(reordering=False, max_cache_hard=CACHE_ENTRIES)
        self.true: BDD = self.bdd.true
        self.false: BDD = self.bdd.false
        self._constraints: list[BDD] = []
        self._valid: BDD = self.bdd.true
        self._valid_count = 0
        self._atoms: list[Atom] = []
        self._var_of: dict[Atom, str] = {}
        self._atom_of: dict[str, Atom] = {}
        self._domains: dict[Input, tuple[Slot, ...]] = {}
        self._slot_names: dict[Input, dict[Slot, str]] = {}  # `slot` without a SlotAtom
        self._slot_atoms: dict[Input, tuple[tuple[Slot, BDD], ...]] = {}
        self._input_constraints: dict[Input, BDD] = {}
        self._facts_of: dict[str, list[BDD]] = {}
        self._described: dict[tuple[BDD, bool, bool, int], str] = {}
        # Choice.const's constants of this space, by text: choices are immutable, and the
        # same literal is met again in every file that includes the one it is written in.
        self.constants: dict[object, Any] = {}

    # -- declaring atoms -------------------------------------------------------------
    def _new_var(self, atom: Atom, level: int | None = None) -> BDD:
        """A variable for ``atom``, last in the order or inserted at ``level``."""
        name = f"a{len(self._atoms)}"
        if level is None:
            self.bdd.declare(name)
        else:
            self.bdd.insert_var(name, level)
        self._atoms.append(atom)
        self._var_of[atom] = name
        self._atom_of[name] = atom
        return self.bdd.var(name)

    def declare_input(self, input_: Input, domain: Sequence[Slot]) -> None:
        """Create the slot atoms of ``input_``; exactly one of them holds."""
        if input_ in self._domains:
            return
        slots = tuple(dict.fromkeys(domain))
        self._domains[input_] = slots
        variables = [self._new_var(SlotAtom(input_, slot)) for slot in slots]
        self._slot_names[input_] = {
            slot: str(v.var) for slot, v in zip(slots, variables, strict=True)
        }
        self._slot_atoms[input_] = tuple(zip(slots, variables, strict=True))
        exactly_one = self.exactly_one(variables)
        self._input_constraints[input_] = exactly_one
        self._constraints.append(exactly_one)

    def exactly_one(self, variables: Sequence[BDD]) -> BDD:
        return exactly_one(self.bdd, variables)

    def input_constraint(self, input_: Input) -> BDD:
        """The exactly-one constraint of one input."""
        return self._input_constraints[input_]

    def file_atom(self, file: str, label: str) -> BDD:
        """The feature "``file`` is part of the product", created on first use."""
        atom = FileAtom(file, label)
        name = self._var_of.get(atom)
        return self.bdd.var(name) if name is not None else self._new_var(atom)

    def variable_name(self, atom: Atom) -> str:
        return self._var_of[atom]

    def atom_of(self, name: str) -> Atom:
        return self._atom_of[name]

    def domain(self, input_: Input) -> tuple[Slot, ...]:
        return self._domains[input_]

    def inputs(self) -> list[Input]:
        return list(self._domains)

    def slot_atoms(self, input_: Input) -> tuple[tuple[Slot, BDD], ...]:
        """Each slot of a declared input with its atom, in domain order."""
        return self._slot_atoms[input_]

    def slot(self, input_: Input, slot: Slot) -> BDD:
        """The atom "``input_`` holds ``slot``" (false if the slot is not in the domain)."""
        name = self._slot_names.get(input_, {}).get(slot)
        return self.bdd.var(name) if name is not None else self.false

    def predicate(self, test: str, term: Term) -> BDD:
        """The atom "``test`` holds for ``term``", created on first use."""
        atom = PredicateAtom(test, term)
        name = self._var_of.get(atom)
        if name is not None:
            return self.bdd.var(name)
        # Next to the slots of the inputs it reads: a disjunction of (slot ∧ predicate)
        # pairs is linear when each pair is adjacent, exponential when all predicates sit
        # below all slots (one file's 19 `bool-invalid` errors made 700k nodes).
        levels = [
            self.bdd.level_of_var(name)
            for input_ in term_inputs(term)
            for name in self._slot_names.get(input_, {}).values()
        ]
        return self._new_var(atom, max(levels) + 1 if levels else None)

    def support(self, u: BDD) -> set[str]:
        """The variables ``u`` depends on, in time linear in the size of ``u``.

        ``dd``'s own ``support`` walks every variable of the manager in Python; with tens
        of thousands of atoms in a large workspace that made each call cost as much as
        the workspace is large, and analysis quadratic. It stays the faster choice for a
        BDD that is large next to the number of variables.
        """
        if u.dag_size * SUPPORT_WALK_FACTOR > len(self._atoms):
            return cast(set[str], self.bdd.support(u))
        return walked_support(u)

    def constrain(self, constraint: BDD) -> None:
        """Add a fact every configuration satisfies (e.g. two predicates exclude each other)."""
        self._constraints.append(constraint)
        for name in self.support(constraint):
            self._facts_of.setdefault(name, []).append(constraint)

    def care(self, condition: BDD) -> BDD:
        """The facts that can matter for ``condition``: those over its variables.

        Every other fact constrains inputs ``condition`` does not mention and is
        satisfiable on its own, so it changes no answer about ``condition`` — and
        the global conjunction grows with the whole workspace.
        """
        result = self.true
        seen: set[int] = set()
        for name in self.support(condition):
            atom = self._atom_of[name]
            if isinstance(atom, SlotAtom) and id(atom.input) not in seen:
                seen.add(id(atom.input))
                result &= self._input_constraints[atom.input]
            for fact in self._facts_of.get(name, ()):
                result &= fact
        return result

    @property
    def valid(self) -> BDD:
        """All facts together; built lazily because interpretation never needs it."""
        if self._valid_count != len(self._constraints):
            for constraint in self._constraints[self._valid_count :]:
                self._valid &= constraint
            self._valid_count = len(self._constraints)
        return self._valid

    # -- questions ---------------------------------------------------------------------
    def satisfiable(self, condition: BDD) -> bool:
        return bool((condition & self.care(condition)) != self.false)

    def valid_implies(self, condition: BDD) -> bool:
        """True when every valid configuration satisfies ``condition``."""
        return bool((self.care(condition) & ~condition) == self.false)

    def assignment(
        self,
        values: Mapping[Input, str | None],
        host: object = None,
        files: frozenset[str] = frozenset(),
    ) -> dict[str, bool]:
        """Truth of every atom under concrete inputs (``None`` = not given/unset).

        A value outside an input's domain selects its ``OTHER`` slot; predicates are
        decided by evaluating their terms with the concrete strings.
        """
        concrete: dict[Input, str] = {}
        chosen: dict[Input, Slot] = {}
        for input_, slots in self._domains.items():
            value = values.get(input_)
            if value is None:
                chosen[input_] = UNSET
            else:
                concrete[input_] = value
                chosen[input_] = value if value in slots else OTHER
        result: dict[str, bool] = {}
        for atom, name in self._var_of.items():
            if isinstance(atom, SlotAtom):
                result[name] = (
                    chosen.get(atom.input) is atom.slot or chosen.get(atom.input) == atom.slot
                )
            elif isinstance(atom, FileAtom):
                result[name] = atom.file in files
            else:
                result[name] = decide_predicate(atom, concrete, host)
        return result

    def evaluate(self, condition: BDD, assignment: Mapping[str, bool]) -> bool:
        """The truth of ``condition`` under ``assignment``: one path from the root down."""
        flipped = False
        node = condition
        while (name := node.var) is not None:
            flipped ^= bool(node.negated)  # children are those of the regular node
            node = node.high if assignment[name] else node.low
        return bool(node == self.true) != flipped

    def cofactor(self, u: BDD, values: Mapping[str, bool]) -> BDD:
        """``u`` with the variables of ``values`` fixed, in time linear in the size of ``u``.

        ``dd``'s ``let`` with Boolean values builds a cube over every variable of the
        manager first; one composition per variable does not.
        """
        for name, value in values.items():
            u = self.bdd.let({name: self.true if value else self.false}, u)
        return u

    # -- readable form ---------------------------------------------------------------------
    def describe(self, condition: BDD, qualify: bool = False, known_only: bool = True) -> str:
        key = (condition, qualify, known_only, len(self._constraints))
        text = self._described.get(key)
        if text is None:  # elements share conditions: describing is the slow part of --json
            text = self._describe(condition, qualify, known_only)
            self._described[key] = text
        return text

    def _describe(self, condition: BDD, qualify: bool, known_only: bool) -> str:
        """A short readable formula, e.g. ``use_teleop=true ∧ ¬sim``, modulo validity.

        With ``known_only`` (the default) arg inputs are assumed to hold one of the
        values analysis knows, which hides the rarely useful ``<other>`` refinements;
        a condition that this view would show as ``true`` but that fails for some
        other value is shown in full.
        """
        # the facts over the condition and their variables, found once: walking a BDD's
        # support in Python is most of describing an undetermined condition in the engine
        local = self.care(condition)
        if condition == self.false or (condition & local) == self.false:  # unsatisfiable
            return "false"
        variables = self.support(local)
        involved = self._inputs_of(variables)
        if known_only:
            others = {
                name: False
                for name in variables
                if isinstance(atom := self._atom_of[name], SlotAtom)
                and atom.slot is OTHER
                and isinstance(atom.input, ArgInput)
            }
            known = self.cofactor(condition, others)
            care = self.cofactor(local, others)
            if (known & care) == self.false:
                return "only for other values"
            if (care & ~known) == self.false and (local & ~condition) != self.false:
                full = self._describe(condition, qualify, known_only=False)
                return full if len(full) <= MAX_FULL else "true for every known value"
            domains = {
                input_: tuple(
                    s
                    for s in self._domains[input_]
                    if s is not OTHER or isinstance(input_, EnvInput)
                )
                for input_ in involved
            }
        else:
            known, care = condition, local
            domains = {input_: self._domains[input_] for input_ in involved}
        simplified = _cudd.restrict(known, care)
        if simplified == self.true or (care & ~known) == self.false:
            return "true"
        try:
            cubes = self._prime_cubes(simplified, known, care, domains)
        except _TooComplex:
            names = sorted({str(i) for i in self._inputs_of(self.support(simplified))})
            shown = ", ".join(names[:6]) + (", …" if len(names) > 6 else "")
            return f"a condition over {len(names)} inputs ({shown})"
        rendered = [self._render_cube(cube, qualify, domains) for cube in cubes]
        if len(rendered) == 1:
            return rendered[0]
        return " ∨ ".join(f"({r})" if "∧" in r else r for r in sorted(rendered))

    def _inputs_of(self, variables: Iterable[str]) -> set[Input]:
        return {
            atom.input
            for atom in (self._atom_of[name] for name in variables)
            if isinstance(atom, SlotAtom)
        }

    def _prime_cubes(
        self,
        simplified: BDD,
        target: BDD,
        care: BDD,
        domains: Mapping[Input, tuple[Slot, ...]],
    ) -> list[dict[object, frozenset[Slot] | bool]]:
        """Cubes of ``simplified``, each widened while it stays inside ``target`` (mod care)."""
        cubes = _merge_cubes(self._grouped_cubes(simplified, domains), domains)
        widened: list[dict[object, frozenset[Slot] | bool]] = []
        outside = care & ~target
        for cube in cubes:
            for key in sorted(cube, key=_sort_key):
                trial = {k: v for k, v in cube.items() if k != key}
                if (self._cube_bdd(trial) & outside) == self.false:
                    cube = trial
            if cube not in widened:
                widened.append(cube)
        covered = [self._cube_bdd(c) for c in widened]
        result = []
        for index, cube in enumerate(widened):
            others = self.false
            for j, bdd in enumerate(covered):
                if j != index and (j > index or widened[j] in result):
                    others |= bdd
            if ((covered[index] & care) & ~others) != self.false:
                result.append(cube)
        return result or widened

    def _cube_bdd(self, cube: Mapping[object, frozenset[Slot] | bool]) -> BDD:
        result = self.true
        for key, value in cube.items():
            if isinstance(key, PredicateAtom | FileAtom):
                atom = self.bdd.var(self._var_of[key])
                result &= atom if value else ~atom
            else:
                assert isinstance(value, frozenset)
                any_slot = self.false
                for slot in value:
                    any_slot |= self.slot(key, slot)  # type: ignore[arg-type]
                result &= any_slot
        return result

    def _paths(self, u: BDD, budget: list[int] | None = None) -> Iterator[dict[str, bool]]:
        if budget is None:
            budget = [MAX_CUBES]
        if u == self.false:
            return
        if u == self.true:
            budget[0] -= 1
            if budget[0] < 0:
                raise _TooComplex
            yield {}
            return
        var = u.var
        for value, child in zip((False, True), cofactors(u), strict=True):
            for path in self._paths(child, budget):
                yield {var: value, **path}

    def _grouped_cubes(
        self, u: BDD, domains: Mapping[Input, tuple[Slot, ...]]
    ) -> list[dict[object, frozenset[Slot] | bool]]:
        cubes: list[dict[object, frozenset[Slot] | bool]] = []
        for path in self._paths(u):
            cube: dict[object, frozenset[Slot] | bool] = {}
            negated: dict[Input, set[Slot]] = {}
            for name, value in path.items():
                atom = self._atom_of[name]
                if isinstance(atom, PredicateAtom | FileAtom):
                    cube[atom] = value
                elif value:
                    cube[atom.input] = frozenset([atom.slot])
                else:
                    negated.setdefault(atom.input, set()).add(atom.slot)
            for input_, slots in negated.items():
                if input_ not in cube:
                    cube[input_] = frozenset(s for s in domains[input_] if s not in slots)
            cubes.append(cube)
        return cubes

    def _render_cube(
        self,
        cube: Mapping[object, frozenset[Slot] | bool],
        qualify: bool,
        domains: Mapping[Input, tuple[Slot, ...]],
    ) -> str:
        parts = []
        for key, value in sorted(cube.items(), key=lambda kv: _sort_key(kv[0])):
            if isinstance(key, FileAtom):
                parts.append(key.label if value else f"¬{key.label}")
            elif isinstance(key, PredicateAtom):
                _test, display = PREDICATES[key.test]
                text = display.format(key.term)
                parts.append(text if value else f"¬({text})")
            else:
                assert isinstance(value, frozenset)
                input_ = cast(Input, key)
                parts.append(_render_slots(input_, value, domains[input_], qualify))
        return " ∧ ".join(parts)

    def atoms(self) -> Iterable[Atom]:
        return iter(self._atoms)


def decide_predicate(atom: PredicateAtom, concrete: Mapping[Input, str], host: object) -> bool:
    """Truth of a predicate atom under concrete input strings."""
    test, _display = PREDICATES[atom.test]
    try:
        return test(evaluate_term(atom.term, concrete, host))
    except Exception:  # an undecidable term satisfies no predicate
        return False


def _sort_key(key: object) -> tuple[int, str]:
    if isinstance(key, FileAtom):
        return (-1, key.label)
    if isinstance(key, PredicateAtom):
        return (1, str(key.term))
    return (0, str(key))


def _merge_cubes(
    cubes: list[dict[object, frozenset[Slot] | bool]], domains: Mapping[Input, tuple[Slot, ...]]
) -> list[dict[object, frozenset[Slot] | bool]]:
    """Join cubes that differ only in the slots of one input (x=a ∨ x=b → x∈{a,b}).

    Cubes are bucketed by everything but one key, so each round is linear in the
    number of cubes rather than quadratic.
    """
    changed = True
    while changed and len(cubes) > 1:
        changed = False
        keys = {key for cube in cubes for key in cube}
        for key in sorted(keys, key=_sort_key):
            buckets: dict[frozenset[tuple[object, object]], list[int]] = {}
            for index, cube in enumerate(cubes):
                rest = frozenset((k, v) for k, v in cube.items() if k != key)
                buckets.setdefault(rest, []).append(index)
            merged_any = False
            result: list[dict[object, frozenset[Slot] | bool]] = []
            for members in buckets.values():
                current = cubes[members[0]]
                for other_index in members[1:]:
                    joined = _merge_pair(current, cubes[other_index], domains)
                    if joined is None:
                        result.append(cubes[other_index])
                    else:
                        current = joined
                        merged_any = True
                result.append(current)
            if merged_any:
                cubes = result
                changed = True
    return cubes


def _merge_pair(
    a: dict[object, frozenset[Slot] | bool],
    b: dict[object, frozenset[Slot] | bool],
    domains: Mapping[Input, tuple[Slot, ...]],
) -> dict[object, frozenset[Slot] | bool] | None:
    keys = set(a) | set(b)
    differing = [k for k in keys if a.get(k) != b.get(k)]
    if len(differing) != 1:
        return None
    key = differing[0]
    va, vb = a.get(key), b.get(key)
    if isinstance(key, PredicateAtom | FileAtom) or va is None or vb is None:
        # p ∧ rest ∨ ¬p ∧ rest = rest
        if isinstance(va, bool) and isinstance(vb, bool):
            return {k: v for k, v in a.items() if k != key}
        return None
    assert isinstance(va, frozenset) and isinstance(vb, frozenset)
    union = va | vb
    merged = dict(a)
    if len(union) == len(domains[key]):  # type: ignore[index]
        del merged[key]
    else:
        merged[key] = union
    return merged


def _slot_text(slot: Slot) -> str:
    return slot if isinstance(slot, str) else repr(slot)


def _render_slots(
    input_: Input, slots: frozenset[Slot], domain: tuple[Slot, ...], qualify: bool
) -> str:
    name = str(input_)
    if qualify and isinstance(input_, ArgInput):
        name = f"{input_.file}:{input_.name}"
    if len(slots) == 1:
        (slot,) = slots
        if isinstance(slot, str) and slot.lower() in BOOLEAN_WORDS and _is_boolean(domain):
            return name if slot.lower() == "true" else f"¬{name}"
        return f"{name}={_slot_text(slot)}"
    excluded = [s for s in domain if s not in slots]
    if len(excluded) == 1:
        return f"{name}≠{_slot_text(excluded[0])}"
    ordered = [s for s in domain if s in slots]
    return f"{name}∈{{{', '.join(_slot_text(s) for s in ordered)}}}"


def _is_boolean(domain: tuple[Slot, ...]) -> bool:
    words = {s.lower() for s in domain if isinstance(s, str)}
    return bool(words) and words <= {"true", "false"}
