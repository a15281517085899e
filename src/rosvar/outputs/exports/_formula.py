"""Cross-tree constraints as small propositional formulas over feature ids.

Feature-model formats take formulas, not BDDs. Each solver constraint (already over
file and value variables only) is written as an irredundant cover of prime implicants,
as a CNF (read as implications: ``a & b => c``) or as a DNF, whichever is shorter.
Simplification is done *modulo the feature tree*: a value implies its file and exactly one
value of an arg holds, so ``F & ¬F:x=a & ¬F:x=b`` is written ``F:x=c``. The tree is part
of every product, so the model's configurations do not change.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass

from rosvar.analyses.feature_model.features import FileFeature
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.logic.bdd import BDD, cofactors
from rosvar.outputs.exports._common import Tree


@dataclass(frozen=True)
class Var:
    name: str  # a feature id (or the root's name)


@dataclass(frozen=True)
class Not:
    operand: Formula


@dataclass(frozen=True)
class And:
    operands: tuple[Formula, ...]


@dataclass(frozen=True)
class Or:
    operands: tuple[Formula, ...]


@dataclass(frozen=True)
class Implies:
    premise: Formula
    conclusion: Formula


Formula = Var | Not | And | Or | Implies


@dataclass(frozen=True)
class Exported:
    """A constraint as formats write it; ``source`` is its index in ``model.constraints``."""

    formula: Formula
    source: int | None
    text: str


Literal = tuple[str, bool]  # (solver variable, polarity)
Cube = tuple[Literal, ...]


class _Covers:
    """Prime, irredundant covers in the solver's manager, modulo the feature tree."""

    def __init__(self, model: FeatureModel) -> None:
        solver = model.solver
        self.manager = solver.manager
        self.care: BDD = solver.tree
        # literals are written in the feature tree's order, not the solver's, which is chosen
        # for the diagrams' size and changes with every improvement of the ordering
        self.rank = {
            name: i
            for i, name in enumerate(name for f in model.files for name in f.variable_names())
        }
        # value variable → (its file's variable, every value variable of its arg)
        self.groups: dict[str, tuple[str, tuple[str, ...]]] = {}
        for file in model.files:
            file_var = str(file.variable.var)
            for arg in file.args:
                values = tuple(str(v.variable.var) for v in arg.values)
                for value in values:
                    self.groups[value] = (file_var, values)

    def cube(self, literals: Sequence[Literal]) -> BDD:
        result = self.manager.true
        for name, positive in literals:
            variable = self.manager.var(name)
            result &= variable if positive else ~variable
        return result

    def paths(self, u: BDD) -> Iterator[dict[str, bool]]:
        """The BDD's paths to ``true``: disjoint cubes whose union is ``u``."""
        if u == self.manager.false:
            return
        if u == self.manager.true:
            yield {}
            return
        name = str(u.var)
        for value, child in zip((False, True), cofactors(u), strict=True):
            for path in self.paths(child):
                yield {name: value, **path}

    def _positive_value(self, cube: dict[str, bool]) -> dict[str, bool]:
        """Negated values of an arg whose file is in the cube → the one value left."""
        for value, (file_var, values) in self.groups.items():
            if value in cube or not cube.get(file_var, False):
                continue
            left = [v for v in values if cube.get(v) is not False]
            if left == [value] and len(values) > 1:
                cube = {k: b for k, b in cube.items() if k not in values}
                cube[value] = True
        return cube

    def _drop_order(self, literal: Literal) -> tuple[bool, int]:
        return (literal[0] in self.groups, -self.rank[literal[0]])

    def cover(self, target: BDD) -> list[Cube]:
        """Cubes whose union equals ``target`` inside the tree, each prime, none redundant."""
        care = self.care
        outside = care & ~target
        expanded: list[Cube] = []
        for path in self.paths(target):
            cube = self._positive_value(path)
            literals = sorted(cube.items(), key=lambda lit: self.rank[lit[0]])
            # drop files first: a value literal already implies its file
            for literal in sorted(literals, key=self._drop_order):
                trial = [lit for lit in literals if lit != literal]
                if (self.cube(trial) & outside) == self.manager.false:
                    literals = trial
            cube_tuple = tuple(literals)
            if cube_tuple not in expanded:
                expanded.append(cube_tuple)
        expanded.sort(key=lambda c: (len(c), [(self.rank[n], p) for n, p in c]))
        kept = list(expanded)
        for cube_tuple in list(reversed(expanded)):  # the longest cubes go first
            others = self.manager.false
            for other in kept:
                if other is not cube_tuple:
                    others |= self.cube(other)
            if (care & self.cube(cube_tuple) & ~others) == self.manager.false:
                kept.remove(cube_tuple)
        return kept


def _literal(ids: dict[str, str], literal: Literal) -> Formula:
    name, positive = literal
    return Var(ids[name]) if positive else Not(Var(ids[name]))


def _conjunction(items: Sequence[Formula]) -> Formula:
    return items[0] if len(items) == 1 else And(tuple(items))


def _disjunction(items: Sequence[Formula]) -> Formula:
    return items[0] if len(items) == 1 else Or(tuple(items))


def _clause(ids: dict[str, str], falsifying: Cube) -> Formula:
    """The clause ruling ``falsifying`` out, read as an implication when it has premises."""
    premises = [Var(ids[n]) for n, positive in falsifying if positive]
    conclusions = [Var(ids[n]) for n, positive in falsifying if not positive]
    if not premises:
        return _disjunction(conclusions)
    if not conclusions:
        return Not(_conjunction(premises))
    return Implies(_conjunction(premises), _disjunction(conclusions))


def size(formula: Formula) -> int:
    """Literal occurrences: what a reader has to read."""
    if isinstance(formula, Var):
        return 1
    if isinstance(formula, Not):
        return size(formula.operand)
    if isinstance(formula, Implies):
        return size(formula.premise) + size(formula.conclusion)
    return sum(size(o) for o in formula.operands)


def compact(tree: Tree, u: BDD, covers: _Covers | None = None) -> Formula | None:
    """``u`` (a solver BDD) as a short formula; ``None`` when it holds in every tree product.

    ``false`` is written ``!root``: the root is in every product.
    """
    covers = covers if covers is not None else _Covers(tree.model)
    ids = tree.by_variable
    falsifying = covers.cover(~u)
    if not falsifying:
        return None
    cnf = [_clause(ids, cube) for cube in falsifying]
    satisfying = covers.cover(u)
    if not satisfying:
        return Not(Var(tree.root))
    dnf = [_conjunction([_literal(ids, lit) for lit in cube]) for cube in satisfying]
    as_cnf, as_dnf = _conjunction(cnf), _disjunction(dnf)
    return as_dnf if size(as_dnf) < size(as_cnf) else as_cnf


def exported(tree: Tree) -> list[Exported]:
    """Every constraint a format writes, in the model's order (vacuous ones left out).

    An arg without any value makes its file impossible (the tree asks for exactly one
    value); formats cannot say that in the tree, so it becomes a constraint ``!file``.
    """
    model = tree.model
    covers = _Covers(model)
    result: list[Exported] = []
    for entry in tree.entries:
        file = entry.feature
        if isinstance(file, FileFeature):
            empty = [arg.name for arg in file.args if not arg.values]
            if empty:
                text = f"{entry.id} has no possible value for {', '.join(empty)}"
                result.append(Exported(Not(Var(entry.id)), None, text))
    pairs = zip(model.constraints, model.solver.constraints, strict=True)
    for number, (constraint, u) in enumerate(pairs):
        formula = compact(tree, u, covers)
        if formula is not None:
            result.append(Exported(formula, number, constraint.text))
    return result


def to_bdd(tree: Tree, formula: Formula) -> BDD:
    """The formula back in the solver's manager (the root is always selected)."""
    manager = tree.model.solver.manager
    names = {feature_id: name for name, feature_id in tree.by_variable.items()}

    def build(f: Formula) -> BDD:
        if isinstance(f, Var):
            return manager.true if f.name == tree.root else manager.var(names[f.name])
        if isinstance(f, Not):
            return ~build(f.operand)
        if isinstance(f, Implies):
            return ~build(f.premise) | build(f.conclusion)
        if isinstance(f, And):
            result = manager.true
            for operand in f.operands:
                result &= build(operand)
            return result
        result = manager.false
        for operand in f.operands:
            result |= build(operand)
        return result

    return build(formula)


_PRECEDENCE = {Implies: 1, Or: 2, And: 3, Not: 4, Var: 5}
UVL_OPERATORS = ("!", " & ", " | ", " => ")
LOGIC_OPERATORS = ("¬", " ∧ ", " ∨ ", " ⇒ ")


def render(
    f: Formula, show: Callable[[str], str], operators: tuple[str, str, str, str] = UVL_OPERATORS
) -> str:
    """Infix text (not, and, or, implies), parenthesised only where precedence needs it.

    Precedence is UVL's (and the usual one): ``!`` over ``&`` over ``|`` over ``=>``.
    """
    negation, conjunction, disjunction, implication = operators

    def wrap(inner: Formula, outer: type) -> str:
        text = render(inner, show, operators)
        return f"({text})" if _PRECEDENCE[type(inner)] <= _PRECEDENCE[outer] else text

    if isinstance(f, Var):
        return show(f.name)
    if isinstance(f, Not):
        return negation + wrap(f.operand, Not)
    if isinstance(f, Implies):
        return wrap(f.premise, Implies) + implication + wrap(f.conclusion, Implies)
    joiner = conjunction if isinstance(f, And) else disjunction
    return joiner.join(wrap(o, type(f)) for o in f.operands)
