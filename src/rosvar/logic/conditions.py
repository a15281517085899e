"""Presence conditions: propositional formulas over inputs, kept as BDDs.

One :class:`ConditionSpace` (one ``dd`` BDD manager) per analysis. Its variables
are *atoms*: "input X holds slot s" (exactly one slot per input, enforced by
:attr:`ConditionSpace.valid`) or "predicate p holds for the still-unknown term
t" (decided only when a configuration makes t concrete). Everything that asks
"can this happen?" asks the BDD, never ad-hoc logic.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping, Sequence
from typing import Any

from rosvar.logic.atoms import PREDICATES, Atom, FileAtom, PredicateAtom, SlotAtom
from rosvar.logic.bdd import (
    BDD,
    Manager,
    cofactor,
    collect_garbage,
    evaluate,
    new_manager,
    walked_support,
)
from rosvar.logic.cells import CELLS, FRESH, PREDICATE_TEXTS
from rosvar.logic.inputs import OTHER, UNSET, Input, Slot
from rosvar.logic.printer import Printer
from rosvar.logic.terms import Apply, Term, term_inputs
from rosvar.logic.terms import evaluate as evaluate_term
from rosvar.memo import Memo

_Member = tuple[Input, PredicateAtom, str | None, frozenset[Any]]
"""A predicate of a cell group: its input, the atom, its term's function (None: the bare
hole) and the constants the term compares the input with."""
CACHE_ENTRIES = 1 << 16
"""Size of CUDD's computed table, fixed. CUDD's larger default start is slow to set up, and
CUDD grows the table with the unique table, i.e. with the number of variables, whether or not
it is used: interpretation fills a small part of this size, and a larger table only costs
page faults; the feature model's quantification in this manager does as many steps with it
as with a larger one (docs/performance.md)."""
_QUOTED = re.compile(r"'([^']*)'|\"([^\"]*)\"")
MAX_WITNESS_TRIALS = 20_000
"""Predicate evaluations one example's search for unforeseen texts may make (bounded work
for a condition over many inputs)."""
SUPPORT_WALK_FACTOR = 16  # a node visited in Python costs about as much as 16 variables in dd
MAX_CELL_GROUP = 24
"""Predicates over one input related by one fact over all of them (its size grows with
their number times their cells); a later one is related to each earlier one by a fact of
its own (pairs, enough for a clash between two nodes)."""
MEMORY_PER_FILE = 128 << 10
MIN_MEMORY = 16 << 20
MAX_MEMORY = 1 << 30
"""Bounds of the memory estimate given to CUDD (``memory_estimate``, see
:func:`memory_estimate`); the upper one is ``dd``'s default."""


def memory_estimate(files: int) -> int:
    """What CUDD is told to expect for an analysis of ``files`` launch files.

    CUDD touches a 128th of its estimate when the manager is created (page faults, for
    ``dd``'s default of 1 GiB), and collects garbage only once it uses 90 % of it: below,
    dead nodes pile up until they outnumber four times the unique table's slots (256 per
    variable), and CUDD never gives their memory back. Interpretation uses about half of
    this share per file (docs/performance.md), so it keeps a margin, while the web server's
    graph build, which leaves most of its nodes dead, collects them as it goes.
    """
    return min(MAX_MEMORY, max(MIN_MEMORY, files * MEMORY_PER_FILE))


def exactly_one(manager: Manager, variables: Sequence[BDD]) -> BDD:
    """Exactly one of ``variables`` holds (an xor-group), in ``manager``.

    Built in one pass (none so far / exactly one so far), not as the disjunction of one
    term per variable: linear instead of quadratic, and the same function, hence the
    same canonical BDD.
    """
    none = manager.true
    one = false = manager.false
    ite = manager.ite  # one operation in CUDD where the connectives took five
    for variable in reversed(variables):  # in level order, each step only adds nodes above
        one = ite(variable, none, one)
        none = ite(variable, false, none)
    return one


class ConditionSpace:
    """The BDD manager of one analysis and the meaning of its variables."""

    def __init__(self, files: int = 0) -> None:
        """``files``: how many launch files the analysis holds, to size the manager."""
        # declaration order is already local: one file's inputs together
        self.bdd = new_manager(memory_estimate(files), CACHE_ENTRIES, CACHE_ENTRIES)
        self.true: BDD = self.bdd.true
        self.false: BDD = self.bdd.false
        self._constraints: list[BDD] = []
        self._constrained: set[BDD] = set()  # the facts of ``constrain``, each added once
        self._valid: BDD = self.bdd.true
        self._valid_count = 0
        self._atoms: list[Atom] = []
        self._var_of: dict[Atom, str] = {}
        self._atom_of: dict[str, Atom] = {}
        # each predicate's variable by its test and term: found by a plain tuple (a term
        # found by identity, terms being hash-consed), with no atom made to look it up
        self._predicates: dict[tuple[str, Term], BDD] = {}
        self._domains: dict[Input, tuple[Slot, ...]] = {}
        self._slot_names: dict[Input, dict[Slot, str]] = {}  # `slot` without a SlotAtom
        self._slot_atoms: dict[Input, tuple[tuple[Slot, BDD], ...]] = {}
        self._input_constraints: dict[Input, BDD] = {}
        self._facts_of: dict[str, list[BDD]] = {}
        self._fact_inputs: dict[str, set[Input]] = {}  # the inputs of the facts of a variable
        self._described: Memo[tuple[BDD, bool, bool, int], str] = Memo()
        self._satisfiable: Memo[tuple[BDD, int], bool] = Memo()  # by condition and facts
        self._printer: Printer | None = None
        # predicates over one input's hole or terms whose cells are known, by input
        self._cell_groups: dict[Input, list[_Member]] = {}
        self._decisions: Memo[tuple[PredicateAtom, str], bool] = Memo()  # by atom and text
        # the truths a group's members take together, by the members (a bare hole's by test)
        self._relations: dict[tuple[object, ...], frozenset[tuple[bool, ...]]] = {}
        # Choice.const's constants of this space, by text: choices are immutable, and the
        # same literal is met again in every file that includes the one it is written in.
        self.constants: dict[object, Any] = {}

    # -- declaring atoms -------------------------------------------------------------
    def _named(self, atom: Atom) -> str:
        """The name of ``atom``'s variable, which the caller then declares."""
        name = f"a{len(self._atoms)}"
        self._atoms.append(atom)
        self._var_of[atom] = name
        self._atom_of[name] = atom
        return name

    def _new_var(self, atom: Atom, level: int | None = None) -> BDD:
        """A variable for ``atom``, last in the order or inserted at ``level``."""
        name = self._named(atom)
        if level is None:
            self.bdd.declare(name)
        else:
            self.bdd.insert_var(name, level)
        return self.bdd.var(name)

    def declare_input(self, input_: Input, domain: Sequence[Slot]) -> None:
        """Create the slot atoms of ``input_``; exactly one of them holds."""
        if input_ in self._domains:
            return
        slots = tuple(dict.fromkeys(domain))
        self._domains[input_] = slots
        names = [self._named(SlotAtom(input_, slot)) for slot in slots]
        self.bdd.declare(*names)
        variables = list(map(self.bdd.var, names))
        self._slot_names[input_] = dict(zip(slots, names, strict=True))
        self._slot_atoms[input_] = tuple(zip(slots, variables, strict=True))
        exactly_one = self.exactly_one(variables)
        self._input_constraints[input_] = exactly_one
        self._constraints.append(exactly_one)

    def exactly_one(self, variables: Sequence[BDD]) -> BDD:
        return exactly_one(self.bdd, variables)

    def varies(self, key: object) -> bool:
        """Whether ``key`` (tuples of conditions and leaves, as ``Choice.key`` makes them)
        holds a condition other than true and false: a key some input steers, met again
        only where those inputs are."""
        pending = [key]
        constants = (self.true, self.false)
        condition = type(self.true)
        while pending:
            item = pending.pop()
            if isinstance(item, tuple):
                pending.extend(item)
            elif type(item) is condition and item not in constants:
                return True
        return False

    def collect_garbage(self) -> None:
        """Free the BDD nodes no condition holds any more (memos released)."""
        collect_garbage(self.bdd)

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
        known = self._predicates.get((test, term))
        if known is not None:
            return known
        atom = PredicateAtom(test, term)
        # Next to the slots of the inputs it reads: a disjunction of (slot ∧ predicate)
        # pairs is linear when each pair is adjacent, exponential when all predicates sit
        # below all slots (a file testing many predicates blows up).
        levels = [
            self.bdd.level_of_var(name)
            for input_ in term_inputs(term)
            for name in self._slot_names.get(input_, {}).values()
        ]
        variable = self._new_var(atom, max(levels) + 1 if levels else None)
        self._predicates[test, term] = variable
        self._relate(atom)
        return variable

    def _relate(self, atom: PredicateAtom) -> None:
        """Add as a fact which predicates over the input of ``atom``'s term can hold
        together for an unforeseen value: those over its bare hole and over terms of
        registered functions of it (:mod:`rosvar.logic.cells`) are one group, evaluated at
        the group's witnesses."""
        member = self._cell_member(atom)
        if member is None:
            return
        input_ = member[0]
        group = self._cell_groups.setdefault(input_, [])
        group.append(member)
        related = [group] if len(group) <= MAX_CELL_GROUP else [[g, group[-1]] for g in group[:-1]]
        for members in related:
            if len(members) < 2:
                continue
            seen = self._combinations(members, input_)
            if len(seen) == 1 << len(members):
                continue
            variables = [self.bdd.var(self._var_of[m[1]]) for m in members]
            possible = self.false
            for combination in seen:
                cube = self.true
                for variable, holds in zip(variables, combination, strict=True):
                    cube &= variable if holds else ~variable
                possible |= cube
            self.constrain(~self.slot(input_, OTHER) | possible)

    def _combinations(
        self, members: Sequence[_Member], input_: Input
    ) -> frozenset[tuple[bool, ...]]:
        """Which truths of ``members`` hold together at some of their witnesses. A predicate
        over the bare hole is its test of the text, whatever the input: a group of those is
        evaluated once per analysis for all the inputs whose groups have the same tests
        (Husky: 109 groups of ``true`` and ``false``, 2,836 evaluations before)."""
        key = tuple(m[1].test if m[2] is None else m[1] for m in members)
        found = self._relations.get(key)
        if found is None:
            values = _witnesses(members)
            found = frozenset(
                tuple(self._decided(m[1], input_, v) for m in members) for v in values
            )
            self._relations[key] = found
        return found

    def _cell_member(self, atom: PredicateAtom) -> _Member | None:
        """``atom`` as a member of its input's group: a predicate whose texts are registered,
        over the bare hole or over a term of one input whose function's cells know what it
        compares the input with."""
        term = atom.term
        inputs = term_inputs(term)
        if len(inputs) != 1 or atom.test not in PREDICATE_TEXTS:
            return None  # a predicate whose texts are not known could tell others apart
        (input_,) = inputs
        if not isinstance(term, Apply):
            return input_, atom, None, frozenset()
        cells = CELLS.get(term.function)
        constants = None if cells is None else cells.constants(term, input_)
        return None if constants is None else (input_, atom, term.function, constants)

    def _decided(self, atom: PredicateAtom, input_: Input, value: str) -> bool:
        """``atom`` at ``value`` of its one input, remembered: a group is evaluated again
        at each predicate it gains."""
        key = (atom, value)
        found = self._decisions.get(key)
        if found is None:
            found = self._decisions[key] = decide_predicate(atom, {input_: value}, None)
        return found

    def witnesses(
        self, chosen: Mapping[Input, Slot], required: Mapping[PredicateAtom, bool]
    ) -> dict[Input, str] | None:
        """A text outside its domain for each input ``chosen`` gives ``OTHER``, under which
        every atom of ``required`` over those inputs holds as given (a hole stands for an
        unforeseen value only: an atom over another input's hole does not matter where that
        input holds a slot). Each input's candidates are the witnesses of its group and of
        the atoms over it alone, and the literal texts of the atoms it is in; searched in
        order, within :data:`MAX_WITNESS_TRIALS` evaluations. None when none is found."""
        others = sorted((i for i, slot in chosen.items() if slot is OTHER), key=str)
        alone: dict[Input, list[PredicateAtom]] = {input_: [] for input_ in others}
        joint: list[tuple[PredicateAtom, set[Input]]] = []
        for atom in required:
            inputs = term_inputs(atom.term)
            if not inputs or not inputs <= alone.keys():
                continue
            if len(inputs) == 1:
                alone[next(iter(inputs))].append(atom)
            else:
                joint.append((atom, inputs))
        literals = [text for atom, _inputs in joint for text in _literals(atom.term)]
        candidates: list[list[str]] = []
        for input_ in others:
            members = list(self._cell_groups.get(input_, ()))
            members += [m for a in alone[input_] if (m := self._cell_member(a)) is not None]
            domain = self._domains.get(input_, ())
            own = [text for atom in alone[input_] for text in _literals(atom.term)]
            texts = dict.fromkeys([*_witnesses(members), *own, *literals])
            candidates.append(
                [
                    text
                    for text in texts
                    if text not in domain
                    and all(self._decided(a, input_, text) is required[a] for a in alone[input_])
                ]
            )
        trials = [MAX_WITNESS_TRIALS]

        def search(index: int, given: dict[Input, str]) -> dict[Input, str] | None:
            if index == len(others):
                return dict(given)
            for text in candidates[index]:
                given[others[index]] = text
                checked = [a for a, inputs in joint if others[index] in inputs <= given.keys()]
                trials[0] -= len(checked)
                if trials[0] < 0:
                    return None
                if all(decide_predicate(a, given, None) is required[a] for a in checked):
                    found = search(index + 1, given)
                    if found is not None:
                        return found
                del given[others[index]]
                if trials[0] < 0:
                    return None
            return None

        return search(0, {})

    def support(self, u: BDD) -> set[str]:
        """The variables ``u`` depends on, in time linear in the size of ``u``.

        ``dd``'s own ``support`` walks every variable of the manager in Python; with tens
        of thousands of atoms in a large workspace that made each call cost as much as
        the workspace is large, and analysis quadratic. It stays the faster choice for a
        BDD that is large next to the number of variables.
        """
        if u.dag_size * SUPPORT_WALK_FACTOR > len(self._atoms):
            return self.bdd.support(u)
        return walked_support(u)

    def constrain(self, constraint: BDD) -> None:
        """Add a fact every configuration satisfies (e.g. two predicates exclude each other).

        A fact added again changes nothing: every ``if`` testing the same value adds the
        same one, and a new fact makes what was remembered under the facts stale."""
        if constraint in self._constrained:
            return
        self._constrained.add(constraint)
        self._constraints.append(constraint)
        names = self.support(constraint)
        inputs = {a.input for a in map(self._atom_of.__getitem__, names) if isinstance(a, SlotAtom)}
        for name in names:
            self._facts_of.setdefault(name, []).append(constraint)
            self._fact_inputs.setdefault(name, set()).update(inputs)

    def facts_of(self, name: str) -> Sequence[BDD]:
        """The facts added with :meth:`constrain` that mention variable ``name``."""
        return self._facts_of.get(name, ())

    def care(self, condition: BDD) -> BDD:
        """The facts that can matter for ``condition``: those over its variables.

        Every other fact constrains inputs ``condition`` does not mention and is
        satisfiable on its own, so it changes no answer about ``condition`` — and
        the global conjunction grows with the whole workspace.
        """
        return self.care_over(self.support(condition))

    def care_over(self, variables: Iterable[str]) -> BDD:
        """The facts over ``variables``: the exactly-one constraints of their inputs and
        the facts added with :meth:`constrain` that mention them."""
        result = self.true
        seen: set[int] = set()
        for name in variables:
            atom = self._atom_of[name]
            if isinstance(atom, SlotAtom) and id(atom.input) not in seen:
                seen.add(id(atom.input))
                result &= self._input_constraints[atom.input]
            for fact in self._facts_of.get(name, ()):
                result &= fact
        return result

    def care_key(self, variables: Iterable[str]) -> frozenset[object]:
        """What :meth:`care_over` depends on: the inputs of the slot atoms among ``variables``
        and the variables that carry facts. Equal keys, equal care."""
        key: set[object] = set()
        for name in variables:
            atom = self._atom_of[name]
            if isinstance(atom, SlotAtom):
                key.add(atom.input)
            if name in self._facts_of:
                key.add(name)
        return frozenset(key)

    def care_inputs(self, variables: Iterable[str]) -> set[Input]:
        """The inputs :meth:`care_over` involves (perhaps a few more than its support)."""
        inputs: set[Input] = set()
        for name in variables:
            atom = self._atom_of[name]
            if isinstance(atom, SlotAtom):
                inputs.add(atom.input)
            inputs.update(self._fact_inputs.get(name, ()))
        return inputs

    def facts(self) -> int:
        """How many facts the space holds: what depends on them is stale once it grows."""
        return len(self._constraints)

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
        """Remembered: the checks ask again for the conditions their findings share."""
        if condition == self.false:
            return False
        if condition == self.true:
            return True
        key = (condition, len(self._constraints))
        found = self._satisfiable.get(key)
        if found is None:
            found = self._satisfiable[key] = bool((condition & self.care(condition)) != self.false)
        return found

    def valid_implies(self, condition: BDD) -> bool:
        """True when every valid configuration satisfies ``condition``."""
        return bool((self.care(condition) & ~condition) == self.false)

    def held(self, input_: Input, value: str | None) -> Slot:
        """The slot of ``input_`` that ``value`` holds (``None``: unset; a value outside the
        domain: ``OTHER``)."""
        if value is None:
            return UNSET
        return value if value in self._domains[input_] else OTHER

    def assignment(
        self,
        values: Mapping[Input, str | None],
        host: object = None,
        files: frozenset[str] = frozenset(),
        into: dict[str, bool] | None = None,
    ) -> dict[str, bool]:
        """Truth of every atom under concrete inputs (``None`` = not given/unset), filled
        into ``into`` (a new dict by default).

        A value outside an input's domain selects its ``OTHER`` slot; predicates are
        decided by evaluating their terms with the concrete strings, in the order the atoms
        were made: a term over a value given up (:mod:`~rosvar.logic.given_up`) is made
        after the atoms of its operands' conditions, so a ``host`` that reads ``into``
        finds them decided.
        """
        concrete: dict[Input, str] = {}
        chosen: dict[Input, Slot] = {}
        for input_ in self._domains:
            value = values.get(input_)
            if value is not None:
                concrete[input_] = value
            chosen[input_] = self.held(input_, value)
        result: dict[str, bool] = {} if into is None else into
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
        return evaluate(condition, assignment.__getitem__)

    def cofactor(self, u: BDD, values: Mapping[str, bool]) -> BDD:
        """``u`` with the variables of ``values`` fixed (``bdd.cofactor``)."""
        return cofactor(u, values)

    def describe(self, condition: BDD, qualify: bool = False, known_only: bool = True) -> str:
        """``condition`` in readable form (``printer.Printer``), remembered: elements share
        conditions, and describing is the slow part of ``--json``."""
        key = (condition, qualify, known_only, len(self._constraints))
        text = self._described.get(key)
        if text is None:
            if self._printer is None:
                self._printer = Printer(self)
            text = self._described[key] = self._printer.describe(condition, qualify, known_only)
        return text

    def atoms(self) -> Iterable[Atom]:
        return iter(self._atoms)


def _witnesses(members: Iterable[_Member]) -> tuple[str, ...]:
    """The texts that tell the members' predicates apart: per function, the witnesses of
    its members' constants together (cells of two literals meet between them), each
    predicate's texts, and a text equal to none."""
    constants: dict[str, set[Any]] = {}
    texts: list[str] = []
    for _input, atom, function, compared in members:
        if function is not None:
            constants.setdefault(function, set()).update(compared)
        texts.extend(PREDICATE_TEXTS.get(atom.test, ()))
    for function, together in sorted(constants.items()):
        texts.extend(CELLS[function].witnesses(together))
    return tuple(dict.fromkeys([*texts, FRESH]))


def _literals(term: Term) -> list[str]:
    """The literal texts of a term's operands, and the quoted texts inside them (what an
    expression over several inputs compares them with)."""
    found: list[str] = []
    pending: list[object] = [term]
    while pending:
        operand = pending.pop()
        if isinstance(operand, str):
            found += [operand, *(a or b for a, b in _QUOTED.findall(operand))]
        elif isinstance(operand, Apply):
            pending.extend(operand.operands)
        elif isinstance(operand, tuple):
            pending.extend(operand)
    return found


def decide_predicate(atom: PredicateAtom, concrete: Mapping[Input, str], host: object) -> bool:
    """Truth of a predicate atom under concrete input strings."""
    test, _display = PREDICATES[atom.test]
    try:
        return test(evaluate_term(atom.term, concrete, host))
    except Exception:  # an undecidable term satisfies no predicate
        return False
