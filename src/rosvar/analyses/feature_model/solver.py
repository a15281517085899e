"""The feature model as BDDs in a manager of its own, ordered for it, one per component.

Atoms that are not features are quantified out of the constraints, the variables ordered
(``ordering``), the excludes constraints taken per clashing name (``exclusions``); files
linked by no constraint fall into separate components, each built and asked about alone.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from functools import cached_property

from rosvar.analyses.conflicts import Clash, Occurrence
from rosvar.analyses.feature_model.counting import CountedDiagram
from rosvar.analyses.feature_model.exclusions import declaring, excluding, exclusions
from rosvar.analyses.feature_model.features import Constraint, FileFeature, ModelTooLarge, name_of
from rosvar.analyses.feature_model.ordering import order, widest_cut
from rosvar.logic import bdd
from rosvar.logic.bdd import (
    BDD,
    Manager,
    Weight,
    cofactor,
    conjoin,
    conjoin_within,
    new_manager,
    transfer,
    walked_support,
)
from rosvar.logic.conditions import ConditionSpace, exactly_one, memory_estimate


class Component:
    """Files linked by cross-tree constraints, and their formula.

    Components share no variable, so every question about the whole model splits
    into one per component (a count is the product of the components' counts),
    and each component is built and asked about on its own.

    A count needs only the variables some constraint mentions: the values no
    constraint mentions are interchangeable, tied to the rest by their xor-group
    alone. So ``counted`` keeps, of each arg, the values constraints mention plus
    one stand-in for the others, weighted by how many it stands for — or, for an
    arg no constraint mentions, none: its file's variable stands in, weighted by
    the arg's number of values (``count``). This diagram is much smaller than
    ``formula``, and built and counted faster. ``formula``, over every
    variable, is built on first use (propagation and the engine need it).
    """

    def __init__(
        self,
        manager: Manager,
        files: list[str],
        variables: list[str],
        args: Sequence[tuple[str, list[str]]],
        constraints: Sequence[BDD],
        workspace_files: int,
    ) -> None:
        self.manager = manager
        self.files = files  # feature ids
        self.variables = variables  # its feature variables, in the solver's order (contiguous)
        self._args = args  # (file variable, its values' variables) of each arg
        self._constraints = constraints
        self._workspace_files = workspace_files  # what the memory budget is measured by
        mentioned: set[str] = set()
        for constraint in constraints:
            mentioned |= walked_support(constraint)
        self.stand_ins: list[tuple[str, list[str]]] = []  # (stand-in, the values it counts for)
        kept: list[tuple[str, list[str]]] = []
        for file, values in args:
            others = [name for name in values if name not in mentioned]
            if len(others) == len(values):
                self.stand_ins.append((file, values))
                continue
            if len(others) > 1:
                self.stand_ins.append((others[0], others))
            kept.append((file, [name for name in values if name not in others[1:]]))
        left_out = {
            name for stand_in, names in self.stand_ins for name in names if name != stand_in
        }
        self.counted_variables = [name for name in variables if name not in left_out]
        self.counted = conjoin(manager, [*_arg_trees(manager, kept), *constraints])

    @cached_property
    def counted_diagram(self) -> CountedDiagram:
        """``counted`` under the weights of no choice (the count of every configuration)."""
        return CountedDiagram(self.manager, self.counted, self._weights({}))

    @cached_property
    def tree(self) -> BDD:
        """The component's part of the feature tree."""
        return conjoin(self.manager, _arg_trees(self.manager, self._args))

    @cached_property
    def formula(self) -> BDD:
        """Its files' tree ∧ their cross-tree constraints, over all its variables."""
        with memory_bound(self.manager, self._workspace_files):
            trees = _arg_trees(self.manager, self._args)
            return conjoin(self.manager, [*trees, *self._constraints])

    def larger_than(self, nodes: int) -> bool:
        """``formula`` has more than ``nodes`` nodes: told while it is built, which stops
        there (a large component's formula reaches millions of nodes, wanted only to be
        left alone)."""
        if "formula" in self.__dict__:
            return bool(self.formula.dag_size > nodes)
        with memory_bound(self.manager, self._workspace_files):
            trees = _arg_trees(self.manager, self._args)
            return conjoin_within(self.manager, [*trees, *self._constraints], nodes) is None

    def count(self, choices: Mapping[str, bool]) -> int:
        """Valid configurations of the component agreeing with ``choices``: a weighted count
        of ``counted``, which after the first recomputes only the levels above the deepest
        choice."""
        return (
            self.counted_diagram.count(self._weights(choices))
            if choices
            else self.counted_diagram.first
        )

    def _weights(self, choices: Mapping[str, bool]) -> dict[str, Weight]:
        """A chosen variable weighs 1 for its value, 0 for the other; a stand-in is true
        for as many ways as the values it counts for that ``choices`` leave open."""
        weights = {name: _weight(choices.get(name)) for name in self.counted_variables}
        for stand_in, values in self.stand_ins:
            off, on = (1, 1) if stand_in in values else weights[stand_in]
            chosen = [choices[v] for v in values if v in choices]
            ways = int(chosen.count(True) == 1) if True in chosen else len(values) - len(chosen)
            weights[stand_in] = (0 if True in chosen else off, on * ways)
        return weights


def _weight(choice: bool | None) -> Weight:
    return (1, 1) if choice is None else (0, 1) if choice else (1, 0)


def _arg_trees(manager: Manager, args: Sequence[tuple[str, list[str]]]) -> list[BDD]:
    """Each arg's part of the tree: its file selected ⇔ exactly one of its values."""
    trees = []
    for file, names in args:
        present = manager.var(file)
        values = [manager.var(name) for name in names]
        none = manager.true
        for value in values:
            none &= ~value
        trees.append((present & exactly_one(manager, values)) | (~present & none))
    return trees


class Solver:
    """The feature model as BDDs in a manager of its own, ordered for it.

    ``components`` hold the model: one formula per group of linked files.
    ``formula`` is their conjunction, built on first use (cheap: components occupy
    contiguous levels); so are ``tree`` and each component's formula. ``constraints``
    are the cross-tree constraints one by one, as in ``FeatureModel.constraints``, for
    explanations and exports; they are translated on first use, since counting and
    propagation never need them.
    """

    def __init__(
        self,
        manager: Manager,
        variables: list[str],
        components: list[Component],
        constraints: Callable[[], list[BDD]],
    ) -> None:
        self.manager = manager
        self.variables = variables
        self.components = components
        self._translate = constraints

    @cached_property
    def tree(self) -> BDD:
        """The feature tree alone."""
        return conjoin(self.manager, [c.tree for c in self.components])

    @cached_property
    def constraints(self) -> list[BDD]:
        return self._translate()

    @cached_property
    def formula(self) -> BDD:
        """Everything: the conjunction of the components."""
        return conjoin(self.manager, [c.formula for c in self.components])

    def var(self, variable: BDD) -> BDD:
        """The counterpart of an analysis-space feature variable."""
        return self.manager.var(name_of(variable))

    def file_tree(self, feature: FileFeature) -> BDD:
        """One file's part of the feature tree (``∃`` the other files' variables ``. tree``)."""
        return conjoin(self.manager, self.arg_trees(feature))

    def arg_trees(self, feature: FileFeature) -> list[BDD]:
        """The parts of the feature tree of each arg of a file: the file is selected exactly
        when one of the arg's values is (their conjunction is ``file_tree``)."""
        args = [
            (name_of(feature.variable), [name_of(v.variable) for v in a.values])
            for a in feature.args
        ]
        return _arg_trees(self.manager, args)

    @cached_property
    def component_of(self) -> dict[str, int]:
        """Variable name → index of the component it belongs to."""
        return {v: n for n, c in enumerate(self.components) for v in c.variables}

    def restrict(self, choices: Mapping[str, bool]) -> list[BDD]:
        """Each component's formula under ``choices`` (variable name → value).

        Each component gets only its own choices: a cofactor costs as much as the cube
        it is given, and untouched components are returned as they are.
        """
        own: list[dict[str, bool]] = [{} for _ in self.components]
        for name, value in choices.items():
            own[self.component_of[name]][name] = value
        return [cofactor(c.formula, mine) for c, mine in zip(self.components, own, strict=True)]

    def count(self, choices: Mapping[str, bool] | None = None) -> int:
        """Valid configurations (agreeing with ``choices``), exactly: the product of the
        components' counts. Variables fixed by ``choices`` no longer count as free."""
        total = 1
        for component in self.components:
            total *= component.count(choices or {})
        return total


SOLVER_CACHE = 1 << 18
"""Most entries of CUDD's computed table in the solver's manager (``dd`` lets it grow without
bound). Components are built one after another and share no variable, so the table only
helps within one component's conjunction; grown with the whole workspace it only costs
page faults and cache misses, at the same hit rate (docs/performance.md)."""


CUT_BUDGET = 300
"""Most constraints between files crossing one point of the solver's order (``widest_cut``)
before the solver is not attempted. The corpus and the generated workspaces shaped like it
stay below 110, whatever their size (systems side by side are ordered apart); workspaces
whose files each clash with dozens of others cross it at a hundred files, and their
diagrams outgrow the memory budget only after many seconds (docs/performance.md, "Feature
model", budgets)."""


def build(
    space: ConditionSpace,
    features: Sequence[FileFeature],
    requires: Sequence[Constraint],
    buckets: Mapping[tuple[str, str], Sequence[Occurrence]],
    constraints: Callable[[], Sequence[Constraint]],
    internal: Sequence[Clash] = (),
    fixed: Mapping[str, bool] | None = None,
) -> Solver:
    """The whole feature model over file and value variables only, one BDD per component.

    Atoms that are not features (predicates on typed-in values, environment
    variables, other files' plumbing) are quantified out of each constraint:
    an ``<other>`` value is taken as able to do anything a typed value could.
    Exclusions enter per clashing name, not per pair of files (``exclusions``), and
    the pairs of files they link are found per name too (``excluding``): the
    pairwise ``excludes`` constraints (``constraints``, every cross-tree constraint)
    are built only if asked for. ``internal`` clashes exclude their file (the engine's
    model: a file loading two nodes of one name fails alone). ``fixed`` atoms (the engine's
    environment, :mod:`.environment`) are substituted before the rest is quantified out.
    """
    files = {f.file: f for f in features}
    declared = declaring(space, files, buckets)
    requiring = [c.files for c in requires]
    links = [*requiring, *((files[a].id, files[b].id) for a, b in excluding(declared))]
    keep = order(features, [*requiring, *([files[f].id for f in when] for when in declared)])
    crossing = widest_cut(keep, features, links)
    if crossing > CUT_BUDGET:
        raise ModelTooLarge(
            f"{crossing:,} constraints between files cross one point of the solver's "
            f"variable order (budget {CUT_BUDGET:,})"
        )
    kept = set(keep)
    manager = new_manager(memory_estimate(len(features)), SOLVER_CACHE)
    manager.declare(*keep)  # a fresh manager in the chosen order (reordering in place is slow)

    def translate(formula: BDD) -> BDD:
        support = space.support(formula)
        if fixed:
            values = {n: fixed[n] for n in support if n in fixed}
            if values:
                formula = space.cofactor(formula, values)
                support = space.support(formula)
        return transfer(formula, manager, {n for n in support if n not in kept})

    with memory_bound(manager, len(features)):
        linked = _Links([f.id for f in features])
        pieces: list[tuple[str, BDD]] = []
        for constraint in requires:
            linked.join(constraint.files)
            pieces.append((constraint.files[0], translate(constraint.formula)))
        for members, exclusion in exclusions(
            space, manager, files, declared, kept, translate, internal
        ):
            linked.join(members)
            pieces.append((members[0], exclusion))
        grouped: dict[str, list[BDD]] = {}
        for file_id, piece in pieces:
            grouped.setdefault(linked.find(file_id), []).append(piece)
        level = {name: index for index, name in enumerate(keep)}
        by_id = {f.id: f for f in features}
        components = []
        for root, members in linked.groups().items():
            variables = [name for file_id in members for name in by_id[file_id].variable_names()]
            variables.sort(key=level.__getitem__)
            args = [
                (name_of(f.variable), [name_of(v.variable) for v in a.values])
                for f in (by_id[file_id] for file_id in members)
                for a in f.args
            ]
            components.append(
                Component(manager, members, variables, args, grouped.get(root, []), len(features))
            )
        components.sort(key=lambda c: level[c.variables[0]] if c.variables else -1)
    return Solver(manager, keep, components, lambda: [translate(c.formula) for c in constraints()])


class _Links:
    """Union-find over feature ids: which files constraints link into one component."""

    def __init__(self, ids: Sequence[str]) -> None:
        self.parent = {i: i for i in ids}

    def find(self, item: str) -> str:
        root = item
        while self.parent[root] != root:
            root = self.parent[root]
        while self.parent[item] != root:
            self.parent[item], item = root, self.parent[item]
        return root

    def join(self, items: Sequence[str]) -> None:
        roots = [self.find(i) for i in items]
        for other in roots[1:]:
            self.parent[other] = roots[0]

    def groups(self) -> dict[str, list[str]]:
        found: dict[str, list[str]] = {}
        for item in self.parent:
            found.setdefault(self.find(item), []).append(item)
        return found


MEMORY_BUDGET = 128 << 20
MEMORY_PER_FILE = 256 << 10
"""Bytes the solver's BDD manager may use while the model is built (CUDD enforces it):
``MEMORY_BUDGET + MEMORY_PER_FILE × files``.

The largest corpus system stays far below the base budget, and workspaces of many such
systems need a fraction of the per-file share (docs/performance.md). A workspace whose
exclusions span the whole order reaches the bound quickly, where it would otherwise go on
for hours. A bound on memory, unlike one on time, does not depend
on the machine's load: the same model is solved, or not, everywhere.
"""


@contextmanager
def memory_bound(manager: Manager, files: int) -> Iterator[None]:
    """Building in ``manager`` within the memory budget of ``files`` launch files, or
    :class:`ModelTooLarge` (``bdd.memory_bound``)."""
    try:
        with bdd.memory_bound(manager, MEMORY_BUDGET + MEMORY_PER_FILE * files):
            yield
    except bdd.OutOfMemory as error:
        raise ModelTooLarge(str(error)) from error
