"""The feature model as clauses of an incremental SAT solver: valid configurations on demand.

The engine asks "is there a valid configuration under the user literals where ``g`` holds?"
again and again, and an answer "yes" is worth most with an example: a new witness, which
settles many other questions. A BDD answers the first part only after restricting the
component's formula by the literals (a new diagram per question, as large as the formula),
while an incremental SAT solver takes the user literals as *assumptions*: it builds nothing
per question and keeps what it learnt, whatever was asked before.

Every variable the solver assigns costs time in every call, so the clauses are kept over
the feature variables alone where they can be: the feature tree is split into one part per
arg of a file (the file and the arg's values: the tree is their conjunction), and each part
and each cross-tree constraint (``Solver.constraints``; with the tree they make the
components' formulas) becomes one clause per path of its BDD to FALSE. A goal (a condition
bound) gets a *switch*: a fresh variable that implies it by the same clauses, assumed when
the goal is asked for. A diagram with too many paths is translated by Tseitin's encoding
instead: one variable per node, equivalent to it.

A solver that explains refusals holds each cross-tree constraint behind a *selector* (a
fresh variable that switches it on): the constraints that rule some literals out are then
an unsatisfiable core of the selectors, made minimal by dropping them one at a time, each
question within a budget of conflicts, so that an explanation costs bounded work however
the constraints interlock (their BDD conjunctions took minutes on Husky).
"""

from __future__ import annotations

from collections.abc import Sequence

from pysat.solvers import Solver as _Sat

from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.logic.bdd import (
    BDD,
    Manager,
    children_first,
    cofactors,
    complemented,
    regular,
    walked_support,
)

BACKEND = "glucose4"
"""The solver pysat drives: it follows preferred phases (CaDiCaL 1.9.5 through pysat does
not), which makes a model show many suspects open at once; of those that do, the fastest on
the corpus (docs/performance.md)."""
PATHS = 256
"""Paths to FALSE up to which a diagram becomes clauses of its own; else Tseitin's."""

GROWTH = 2
"""Switches per feature variable after which the solver starts afresh."""
EXPLANATION_CONFLICTS = 20_000
"""Conflicts a question of an explanation may take (``Sat.core``): the corpus's take at
most a few hundred; past it the explanation stops, the same on every machine."""

Clause = list[int]


class Sat:
    """An incremental SAT solver for some components of the feature model: variable
    ``i + 1`` is the ``i``-th of their feature variables, which sit at positions ``offset``
    on in the solver's order, so a model shifted by ``offset`` is a configuration's bits.

    The engine keeps one per component (``per_component``): a question about one
    component then assigns its variables only, not the whole workspace's: the engine asks
    about every file, so one solver for all would make its construction quadratic.
    """

    def __init__(
        self,
        manager: Manager,
        variables: Sequence[str],
        offset: int,
        parts: list[BDD],
        guarded: Sequence[BDD] = (),
    ):
        """``guarded``: parts held behind a selector each, for ``core``."""
        self.manager = manager
        self._atoms = {variable: i + 1 for i, variable in enumerate(variables)}
        self._width = len(variables)
        self._offset = offset
        self._true = self._width + 1  # a variable every model sets: TRUE
        self._parts = parts
        self._guarded = list(guarded)
        self._start()

    @classmethod
    def whole(cls, model: FeatureModel) -> Sat:
        """One solver for every component."""
        solver = model.solver
        parts = list(solver.constraints)
        for file in model.files:
            parts.extend(solver.arg_trees(file))
        return cls(solver.manager, solver.variables, 0, parts)

    @classmethod
    def per_component(cls, model: FeatureModel) -> list[Sat]:
        """One solver per component, with the constraints and tree parts of its files
        (components are contiguous in the solver's order and share no variable)."""
        constraints = _constraints_by_component(model)
        return [
            cls._of(model, n, [model.solver.constraints[c] for c in mine], ())
            for n, mine in enumerate(constraints)
        ]

    @classmethod
    def explaining(cls, model: FeatureModel, component: int) -> tuple[Sat, list[int]]:
        """A solver for the component whose constraints are guarded (``core``), and the
        numbers of those constraints (in ``FeatureModel.constraints``), in its order."""
        numbers = _constraints_by_component(model)[component]
        guarded = [model.solver.constraints[n] for n in numbers]
        return cls._of(model, component, [], guarded), numbers

    @classmethod
    def _of(
        cls, model: FeatureModel, component: int, parts: list[BDD], guarded: Sequence[BDD]
    ) -> Sat:
        """The solver of ``component``: its files' tree parts, ``parts`` and ``guarded``."""
        solver = model.solver
        mine = solver.components[component]
        trees = [
            tree
            for file in model.files
            if (variables := file.variable_names())
            and solver.component_of[variables[0]] == component
            for tree in solver.arg_trees(file)
        ]
        offset = solver.variables.index(mine.variables[0]) if mine.variables else 0
        return cls(solver.manager, mine.variables, offset, [*parts, *trees], guarded)

    def _start(self) -> None:
        """A fresh solver with the model's clauses: also once switches made too many
        variables (each call pays for every variable, and every switch stays one)."""
        self._top = self._true
        self._nodes: dict[BDD, int] = {}  # regular BDD node → its Tseitin variable
        self._goals: dict[BDD, int] = {}  # goal → its switch (or Tseitin literal)
        self._sat = _Sat(name=BACKEND, bootstrap_with=[[self._true]])
        for part in self._parts:
            clauses = self._clauses(part)
            if clauses is None:
                clauses = [[self._literal(part)]]
            self._sat.append_formula(clauses)
        self._selectors = [self._goal(part) for part in self._guarded]  # assumed: part on
        self._base = self._top

    def atom(self, variable: str, value: bool) -> int:
        """The literal ``variable = value``."""
        return self._atoms[variable] if value else -self._atoms[variable]

    def _goal(self, u: BDD) -> int:
        """A literal that implies ``u`` (made on first use): assumed, it asks for ``u``."""
        found = self._goals.get(u)
        if found is None:
            clauses = self._clauses(u)
            if clauses is None:
                found = self._literal(u)
            else:
                found = self._variable()
                self._sat.append_formula([[-found, *clause] for clause in clauses])
            self._goals[u] = found
        return found

    def _variable(self) -> int:
        """A fresh SAT variable."""
        self._top += 1
        return self._top

    def _clauses(self, u: BDD) -> list[Clause] | None:
        """``u`` as clauses over feature variables (one per path to FALSE); None when
        there would be more than ``PATHS``."""
        false = self.manager.false
        if _false_paths(u, false, {}) > PATHS:
            return None
        clauses: list[Clause] = []
        stack: list[tuple[BDD, Clause]] = [(u, [])]
        while stack:
            v, clause = stack.pop()
            if v.var is None:
                if v == false:
                    clauses.append(clause)
                continue
            x = self._atoms[v.var]
            low, high = cofactors(v)
            stack += [(low, [*clause, x]), (high, [*clause, -x])]
        return clauses

    def _literal(self, u: BDD) -> int:
        """A literal equivalent to ``u`` (Tseitin: its nodes translated on first use)."""
        if u.var is None:
            return self._true if u == self.manager.true else -self._true
        node = regular(u)
        found = self._nodes.get(node)
        if found is None:
            self._translate(node)
            found = self._nodes[node]
        return -found if complemented(u) else found

    def _translate(self, root: BDD) -> None:
        """Clauses for every node under ``root`` not translated yet, children first."""
        nodes, clauses = self._nodes, []
        for node in children_first(root, _inner_children, nodes):
            assert node.var is not None  # an inner node
            n, x = self._variable(), self._atoms[node.var]
            nodes[node] = n
            low, high = (self._literal(child) for child in cofactors(node))  # a regular node
            clauses += [
                [-n, -x, high],
                [-n, x, low],
                [n, -x, -high],
                [n, x, -low],
                [n, -high, -low],  # implied, but it lets propagation go up without x
                [-n, high, low],
            ]
        self._sat.append_formula(clauses)

    def core(self, atoms: Sequence[int]) -> list[int] | None:
        """A minimal set of the guarded parts (their indices) that, with the other parts, no
        configuration with the literals of ``atoms`` satisfies; None when a question ran
        out of its budget (``EXPLANATION_CONFLICTS``) first, or some configuration does."""
        on = {selector: index for index, selector in enumerate(self._selectors)}
        kept = list(on)
        answer = self._limited([*atoms, *kept])
        if answer is not False:
            return None
        core = set(self._sat.get_core() or ())
        kept = [literal for literal in kept if literal in core]
        position = 0
        while position < len(kept):  # deletion: drop each part the others do without
            trial = kept[:position] + kept[position + 1 :]
            answer = self._limited([*atoms, *trial])
            if answer is None:
                return None
            if answer:
                position += 1
            else:
                kept = trial
        return sorted(on[literal] for literal in kept)

    def _limited(self, assumptions: Sequence[int]) -> bool | None:
        """``satisfiable`` within ``EXPLANATION_CONFLICTS`` conflicts (None: not known)."""
        self._sat.conf_budget(EXPLANATION_CONFLICTS)
        found = self._sat.solve_limited(assumptions=assumptions)
        return None if found is None else bool(found)

    def satisfiable(self, assumptions: Sequence[int]) -> bool:
        """Some valid configuration satisfies every literal of ``assumptions``."""
        return bool(self._sat.solve(assumptions=assumptions))

    def model(
        self,
        atoms: Sequence[int],
        goal: BDD | None = None,
        some: Sequence[int] = (),
        prefer: Sequence[int] = (),
    ) -> int | None:
        """A valid configuration (bit ``i``: the ``i``-th variable) with the literals of
        ``atoms`` (see ``atom``), where ``goal`` holds and at least one literal of
        ``some`` does, if given; where it has a choice, it takes the literals of
        ``prefer``. None when there is none."""
        if self._top - self._base > GROWTH * self._width:
            self._start()
        assumptions = list(atoms)
        if goal is not None:
            assumptions.append(self._goal(goal))
        if prefer:
            self._sat.set_phases(prefer)
        switch = None
        if some:
            switch = self._variable()  # the clause holds only while assumed: retired below
            self._sat.add_clause([-switch, *some])
            assumptions.append(switch)
        found = None
        if self._sat.solve(assumptions=assumptions):
            model = self._sat.get_model()[: self._width]
            bits = "".join(["1" if literal > 0 else "0" for literal in reversed(model)])
            found = int(bits, 2) << self._offset if bits else 0
        if switch is not None:
            self._sat.add_clause([-switch])  # (the model must be read before)
        return found


def _false_paths(v: BDD, false: BDD, counts: dict[BDD, int]) -> int:
    """How many paths lead from ``v`` to FALSE (``counts``: those known, by node)."""
    if v.var is None:
        return int(v == false)
    found = counts.get(v)
    if found is None:
        found = counts[v] = sum(_false_paths(child, false, counts) for child in cofactors(v))
    return found


def _inner_children(node: BDD) -> list[BDD]:
    return [regular(c) for c in cofactors(node) if c.var is not None]


def _constraints_by_component(model: FeatureModel) -> list[list[int]]:
    """The numbers of the cross-tree constraints (``Solver.constraints``) of each component
    (a constant FALSE constraint goes to all)."""
    solver = model.solver
    component_of = solver.component_of
    found: list[list[int]] = [[] for _ in solver.components]
    for number, constraint in enumerate(solver.constraints):
        support = walked_support(constraint)
        for n in {component_of[v] for v in support} if support else range(len(found)):
            found[n].append(number)
    return found
