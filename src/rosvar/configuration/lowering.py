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

from collections.abc import Mapping
from dataclasses import dataclass

from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.interpreter.substitution import PackageTable
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD, transfer
from rosvar.logic.conditions import PredicateAtom, SlotAtom, decide_predicate
from rosvar.logic.inputs import EnvInput, Input
from rosvar.logic.terms import term_inputs
from rosvar.memo import Memo


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
        self.host = PackageTable(
            {name: package.path for name, package in analysis.workspace.packages.items()}
        )
        solver_variables = set(model.solver.variables)
        self.feature_inputs: set[Input] = {arg.input for file in model.files for arg in file.args}
        self.concrete: dict[Input, str] = {}
        for input_ in space.inputs():
            if isinstance(input_, EnvInput):
                if input_.name in env:
                    self.concrete[input_] = env[input_.name]
            elif input_ not in self.feature_inputs:
                default = analysis.model(input_.file).unset_defaults.get(input_.name)
                if default is not None:
                    self.concrete[input_] = default
        truth = space.assignment({i: self.concrete.get(i) for i in space.inputs()}, self.host)
        self.fixed: dict[str, bool] = {}
        self.open: set[str] = set()
        for atom in space.atoms():
            name = space.variable_name(atom)
            if name in solver_variables:
                continue
            if isinstance(atom, SlotAtom) and atom.input in self.feature_inputs:
                self.fixed[name] = False  # a selected arg holds one of its feature values
            elif isinstance(atom, PredicateAtom) and term_inputs(atom.term) & self.feature_inputs:
                self.open.add(name)
            else:
                self.fixed[name] = truth[name]
        self._fixed: dict[BDD, tuple[BDD, set[str]]] = {}  # condition → fixed, its support
        self._bounds: dict[BDD, Bounds] = {}  # by fixed condition
        self._decided: Memo[tuple[BDD, frozenset[tuple[Input, str]]], Bounds] = Memo()
        self._cares: dict[frozenset[str], BDD] = {}
        self._satisfiable: dict[BDD, bool] = {}

    def fix(self, condition: BDD) -> BDD:
        """``condition`` with the fixed atoms substituted (still in the analysis' manager)."""
        found = self._fixed.get(condition)
        if found is None:
            support = self.space.support(condition)
            values = {n: self.fixed[n] for n in support if n in self.fixed}
            fixed = self.space.cofactor(condition, values)
            kept = support  # the support of ``fixed`` when nothing was fixed
            if values:
                kept = self.space.support(fixed)
            found = self._fixed[condition] = (fixed, kept)
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
        key = frozenset(support)
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
            found = self._copy(decided, self.space.support(decided))
            self._decided[key] = found
        return found

    def _copy(self, fixed: BDD, support: set[str]) -> Bounds:
        """In the solver's manager: ``∀ open. fixed`` and ``∃ open. fixed`` (``support``:
        that of ``fixed``)."""
        open_ = support & self.open
        may = transfer(fixed, self.manager, open_)
        return Bounds(~transfer(~fixed, self.manager, open_) if open_ else may, may)
