"""Analysis-space conditions as solver BDDs, under what the configuration fixes up front.

A presence condition of the variational model speaks about every atom of the analysis:
environment variables, args that are no features (they stay unset: they change nothing in
the graph), and predicates on typed-in values. The solver knows only feature variables.
Lowering fixes the environment (as ``rosvar resolve``: a variable not given is unset) and
the unset args, and bounds what is still open — predicates on an arg's ``<other>`` text
that the user may type later — from below (``must``: for every text) and from above
(``may``: for some text). Both bounds are copied into the solver's manager.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Collection, Mapping, Sequence
from dataclasses import dataclass

from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.atoms import Atom, PredicateAtom, SlotAtom
from rosvar.logic.bdd import BDD, transfer
from rosvar.logic.conditions import decide_predicate
from rosvar.logic.inputs import EnvInput, Input
from rosvar.logic.terms import term_inputs
from rosvar.memo import Memo

_NONE: frozenset[str] = frozenset()
COPIES = 100_000
"""Copied diagram nodes kept for the last set of open atoms hidden (``_copy``): the
conditions copied one after the other, of one file's elements, share most of their nodes
(its ``launched``), other files' few."""


@dataclass(frozen=True)
class Bounds:
    """A condition in the solver: ``must`` ⊆ condition ⊆ ``may`` (equal when nothing is open)."""

    must: BDD
    may: BDD

    @property
    def exact(self) -> bool:
        return bool(self.must == self.may)


class Lowering:
    """Copies conditions from the analysis' manager to the solver's, fixed atoms substituted."""

    def __init__(self, analysis: Analysis, model: FeatureModel, env: Mapping[str, str]) -> None:
        space = analysis.space
        self.space = space
        self.manager = model.solver.manager
        self.host = analysis.package_table()
        solver_variables = set(model.solver.variables)
        self.feature_inputs: set[Input] = {arg.input for file in model.files for arg in file.args}
        self._analysis = analysis
        self._env = env
        self.concrete: dict[Input, str] = {}
        for input_ in space.inputs():
            self._take(input_)
        truth = space.assignment({i: self.concrete.get(i) for i in space.inputs()}, self.host)
        self.fixed: dict[str, bool] = {}
        self.open: set[str] = set()
        self._solver_variables = solver_variables
        for atom in space.atoms():
            name = space.variable_name(atom)
            if name not in solver_variables:
                self._classify(name, atom, functools.partial(truth.__getitem__, name))
        # condition → fixed, and the open atoms of its support (most have none: one set)
        self._fixed: dict[BDD, tuple[BDD, frozenset[str]]] = {}
        self._bounds: dict[BDD, Bounds] = {}  # by fixed condition
        self._decided: Memo[tuple[BDD, frozenset[tuple[Input, str]]], Bounds] = Memo()
        self._cares: dict[frozenset[object], BDD] = {}  # by ``care_key``
        self._satisfiable: dict[BDD, bool] = {}
        self._copies: dict[frozenset[str], dict[BDD, BDD]] = {}  # the last open atoms hidden

    def _take(self, input_: Input) -> None:
        """Record ``input_``'s concrete value: its environment variable's, or an arg's
        default where no feature chooses it."""
        if isinstance(input_, EnvInput):
            if input_.name in self._env:
                self.concrete[input_] = self._env[input_.name]
        elif input_ not in self.feature_inputs:
            default = self._analysis.model(input_.file).unset_defaults.get(input_.name)
            if default is not None:
                self.concrete[input_] = default

    def _truth_of(self, atom: Atom) -> bool:
        """The truth of an atom made after this lowering, under the concrete inputs."""
        if isinstance(atom, PredicateAtom):
            return decide_predicate(atom, self.concrete, self.host)
        if isinstance(atom, SlotAtom):
            if atom.input not in self.concrete:
                self._take(atom.input)
            return self.space.held(atom.input, self.concrete.get(atom.input)) == atom.slot
        return False  # a launch file: none is part of the product the lowering fixes

    def _classify(self, name: str, atom: Atom, truth: Callable[[], bool]) -> None:
        """Fix ``atom`` (to ``truth()``), or keep it open: a predicate on a feature arg."""
        if isinstance(atom, SlotAtom) and atom.input in self.feature_inputs:
            self.fixed[name] = False  # a selected arg holds one of its feature values
        elif isinstance(atom, PredicateAtom) and term_inputs(atom.term) & self.feature_inputs:
            self.open.add(name)
        else:
            self.fixed[name] = truth()

    def fix(self, condition: BDD) -> BDD:
        """``condition`` with the fixed atoms substituted (still in the analysis' manager).

        An atom made after this lowering (a hint's ``when:`` on a typed text, built with
        the graph; an input the checks' simulation reads first) is classified when first
        met."""
        found = self._fixed.get(condition)
        if found is None:
            support = self.space.support(condition)
            for name in support - self.fixed.keys() - self.open - self._solver_variables:
                atom = self.space.atom_of(name)
                self._classify(name, atom, functools.partial(self._truth_of, atom))
            values = {n: self.fixed[n] for n in support if n in self.fixed}
            fixed = self.space.cofactor(condition, values)
            kept = support  # the support of ``fixed`` when nothing was fixed
            if values:
                kept = self.space.support(fixed)
            found = self._fixed[condition] = (fixed, frozenset(kept & self.open) or _NONE)
            if fixed not in self._satisfiable:
                self._satisfiable[fixed] = self._judge(fixed, kept)
        return found[0]

    def bounds(self, condition: BDD) -> Bounds:
        """``condition`` fixed and copied into the solver's manager: only conditions found
        satisfiable are, as a copy costs a walk of the diagram and new nodes."""
        fixed = self.fix(condition)
        found = self._bounds.get(fixed)
        if found is None:
            found = self._bounds[fixed] = self._copy(fixed, self._fixed[condition][1])
        return found

    def conjunction(self, factors: Sequence[BDD]) -> BDD:
        """The conjunction of fixed ``factors`` (itself fixed: fixing is a cofactor, which
        distributes over ∧), with its bounds conjoined from the factors' in the solver's
        manager when no two factors share an open atom (∀ distributes over ∧, and ∃ over
        a conjunction of functions of disjoint variables).

        An element's condition is its file's ``launched`` ∧ its own ∧ the branches of its
        fields: each factor is copied once, where a copy of each conjunction walked the
        large ``launched`` of a file included from many places again for each element."""
        fixed = factors[0]
        for factor in factors[1:]:
            fixed &= factor
        if fixed in self._bounds:
            return fixed
        for factor in factors:
            self.fix(factor)  # the factor itself: remembered with its open atoms
        opens = [self._fixed[factor][1] for factor in factors]
        union = frozenset().union(*opens)
        if fixed not in self._fixed:
            self._fixed[fixed] = (fixed, union or _NONE)
        if sum(map(len, opens)) == len(union):
            bounds = [self.bounds(factor) for factor in factors]
            must, may = bounds[0].must, bounds[0].may
            for each in bounds[1:]:
                must, may = must & each.must, may & each.may
            self._bounds[fixed] = Bounds(must, may)
        return fixed

    def built(self) -> None:
        """Let the build's caches go: after it, conditions are lowered again only for
        typed texts (``decide``), and the caches held every condition of the graph in
        both managers, and the copies' nodes."""
        self._fixed.clear()
        self._bounds.clear()
        self._cares.clear()
        self._satisfiable.clear()
        self._copies.clear()

    def lower(self, condition: BDD) -> tuple[BDD, Bounds]:
        return self.fix(condition), self.bounds(condition)

    def satisfiable(self, fixed: BDD) -> bool:
        """``space.satisfiable`` of a lowered condition (``fix`` answers it on the way)."""
        found = self._satisfiable.get(fixed)
        if found is None:
            found = self._satisfiable[fixed] = self._judge(fixed, self.space.support(fixed))
        return found

    def _judge(self, fixed: BDD, support: set[str]) -> bool:
        """Satisfiability with the facts that matter conjoined once per support: the
        variants of one element share theirs."""
        key = self.space.care_key(support)  # far fewer than supports
        care = self._cares.get(key)
        if care is None:
            care = self._cares[key] = self.space.care_over(support)
        return bool((fixed & care) != self.space.false)

    def decide(self, condition: BDD, typed: Mapping[Input, str]) -> Bounds:
        """Bounds once the open predicates whose terms the ``typed`` texts complete are decided."""
        key = (condition, frozenset(typed.items()))
        found = self._decided.get(key)
        if found is None:
            fixed = self.fix(condition)
            concrete = {**self.concrete, **typed}
            values: dict[str, bool] = {}
            for name in self.space.support(fixed) & self.open:
                atom = self.space.atom_of(name)
                assert isinstance(atom, PredicateAtom)
                if term_inputs(atom.term) <= concrete.keys():
                    values[name] = decide_predicate(atom, concrete, self.host)
            decided = self.space.cofactor(fixed, values)
            found = self._copy(decided, self.space.support(decided) & self.open)
            self._decided[key] = found
        return found

    def _copy(self, fixed: BDD, open_: Collection[str]) -> Bounds:
        """In the solver's manager: ``∀ open. fixed`` and ``∃ open. fixed`` (``open_``: the
        open atoms of its support)."""
        hidden = frozenset(open_)
        copies = self._copies.get(hidden)
        if copies is None or len(copies) > COPIES:
            self._copies = {hidden: {}}  # the last set's only: the next condition's is alike
            copies = self._copies[hidden]
        may = transfer(fixed, self.manager, open_, copies)
        return Bounds(~transfer(~fixed, self.manager, open_, copies) if open_ else may, may)
