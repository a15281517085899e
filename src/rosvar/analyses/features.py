"""Feature model extraction (the paper's Algorithm 1) and the analyses its solver answers.

Root → launch files → their args that affect the computation graph (AFFECTSCG)
→ an xor-group of each arg's values (GETVALUES: the interpreter's input domains).
Cross-tree constraints: an ``<include>`` *requires* the included file (under the
include's condition); files whose declarations clash by name *exclude* each
other (under the arg values where the clash happens). Everything is one BDD in
the analysis' condition space, so counting, core/dead features and explanations
are solver questions, not enumeration.
"""

from __future__ import annotations

import os
from collections import deque
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import cached_property

import dd.cudd as _cudd

from rosvar.analyses.conflicts import Clash, Occurrence, clashes, index, repeated_inclusions
from rosvar.analyses.counting import CountedDiagram, Weight
from rosvar.diagnostics import Diagnostic, Location, Severity
from rosvar.interpreter.analysis import Analysis, collector_paused
from rosvar.interpreter.model import DeferredValue, LaunchModel, ParamDecl
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import (
    BDD,
    ConditionSpace,
    FileAtom,
    PredicateAtom,
    SlotAtom,
    exactly_one,
    memory_estimate,
    walked_support,
)
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, Slot
from rosvar.logic.terms import Apply, Hole, Operand, term_inputs
from rosvar.logic.transfer import transfer
from rosvar.workspace.paths import real_path


@dataclass
class ValueFeature:
    id: str
    value: str
    slot: Slot
    default: bool
    variable: BDD


@dataclass
class ArgFeature:
    id: str
    file: str
    name: str
    input: ArgInput
    default: str | None
    boolean: bool
    location: Location | None
    values: list[ValueFeature] = field(default_factory=list)


@dataclass
class FileFeature:
    id: str
    file: str
    variable: BDD
    args: list[ArgFeature] = field(default_factory=list)

    def variable_names(self) -> list[str]:
        """The file's variable, then its args' values: a block of the solver's order (the
        names are the same in the analysis' manager and the solver's)."""
        return [_name(self.variable)] + [_name(v.variable) for a in self.args for v in a.values]


@dataclass
class Constraint:
    """A cross-tree constraint: ``formula`` must hold; ``text`` says why, for people."""

    kind: str  # "requires", "excludes", "loads"
    files: tuple[str, ...]
    formula: BDD
    condition: BDD  # when it bites (include condition, clash condition)
    text: str
    locations: tuple[Location, ...] = ()
    unconditional: bool = False


class ModelTooLarge(Exception):
    """The solver's BDDs would outgrow their budget: the model is listed, not solved."""


@dataclass
class FeatureModel:
    """The feature tree and its cross-tree constraints, with the solver that answers on them.

    The pairwise views — ``clashes``, ``internal`` and the ``excludes`` entries of
    ``constraints`` — are built on first use: they grow with the square of the files
    redeclaring a name, and neither the solver nor the count needs them. ``solution``
    is the solver, or why it was not built (``solver`` raises that then).
    """

    space: ConditionSpace
    files: list[FileFeature]
    requires: list[Constraint]
    declarations: Mapping[tuple[str, str], list[Occurrence]]  # by (kind, resolved name)
    launch_models: list[LaunchModel]
    diagnostics: list[Diagnostic] = field(default_factory=list)
    products: bool = False  # built for the configuration engine (``extract``'s ``products``)
    solution: Solver | ModelTooLarge = field(init=False)

    @property
    def solved(self) -> bool:
        """Whether the solver was built within its budget."""
        return not isinstance(self.solution, ModelTooLarge)

    @property
    def solver(self) -> Solver:
        if isinstance(self.solution, ModelTooLarge):
            raise ModelTooLarge(*self.solution.args)
        return self.solution

    @cached_property
    def clashes(self) -> list[Clash]:
        return clashes(self.declarations)

    @cached_property
    def internal(self) -> list[Clash]:
        """Clashes inside one file: two of its nodes, or one file included twice."""
        found = [c for c in self.clashes if c.first.file == c.second.file and c.kind == "node"]
        return found + [c for model in self.launch_models for c in repeated_inclusions(model)]

    @cached_property
    def constraints(self) -> list[Constraint]:
        return self.requires + _excludes(self.space, self.files, self.clashes)

    def feature_ids(self) -> list[str]:
        ids: list[str] = []
        for file in self.files:
            ids.append(file.id)
            for arg in file.args:
                ids.append(arg.id)
                ids.extend(v.id for v in arg.values)
        return ids


def _term_inputs(value: Operand) -> set[ArgInput]:
    return {i for i in term_inputs(value) if isinstance(i, ArgInput)}


_TERMS = (Hole, Apply)  # a union type written inline is built anew at every call


def graph_inputs(model: LaunchModel) -> set[ArgInput]:
    """Args whose value changes a node, param or remap (AFFECTSCG), read off the BDD supports.

    The interpreter already followed ``value=`` args, include arg passing and
    ``pass_all_args``, so an arg affects the graph exactly when one of its atoms
    is in the support of a presence condition or of a branch of an attribute.
    """
    if not model.inputs:  # no args to look for (28 of Husky's 137 files)
        return set()
    space = model.space
    true = space.true
    conditions: set[BDD] = set()  # elements share conditions: each support is taken once
    terms: set[ArgInput] = set()
    choices: dict[int, Choice[object]] = {}  # and choices (one per literal, shared): by id
    for node in model.nodes:
        conditions.add(node.condition)
        for key in ("name", "namespace", "pkg", "type", "args", "machine"):
            field_value = node.fields[key]
            choices[id(field_value)] = field_value
        for remap in node.remaps:
            conditions.add(remap.condition)
            for raw in (remap.source, remap.target):
                if isinstance(raw, _TERMS):
                    terms.update(_term_inputs(raw))
    for param in model.params:
        conditions.add(param.condition)
        if isinstance(param, ParamDecl):
            choices[id(param.name)] = param.name
            choices[id(param.value)] = param.value
    for choice in choices.values():
        for condition, leaf in choice:
            if condition != true:
                conditions.add(condition)
            if isinstance(leaf, DeferredValue):
                leaf = leaf.raw
            if isinstance(leaf, _TERMS):
                terms.update(_term_inputs(leaf))
    support: set[str] = set()
    for condition in conditions:
        support |= space.support(condition)
    inputs = {
        atom.input
        for atom in (space.atom_of(name) for name in support)
        if isinstance(atom, SlotAtom) and isinstance(atom.input, ArgInput)
    }
    predicate_inputs = {
        i
        for atom in (space.atom_of(name) for name in support)
        if isinstance(atom, PredicateAtom)
        for i in _term_inputs(atom.term)
    }
    return {i for i in inputs | terms | predicate_inputs if i.file == model.file}


def _given_by_include(space: ConditionSpace, target: FileFeature) -> BDD:
    """The included file's args at their defaults (as when not given on the command line;
    ``<default: …>`` where the default is a substitution): a file loaded by an include takes
    its args from the include, so in a product that includes it its own args are not free
    (a required arg, without a default, is left alone)."""
    unset = space.true
    for arg in target.args:
        defaults = sorted((v.slot is not UNSET, v.id) for v in arg.values if v.default)
        if defaults:
            by_id = {v.id: v for v in arg.values}
            unset &= by_id[defaults[0][1]].variable
    return unset


def _set_by_value(model: LaunchModel) -> set[str]:
    """Args whose every declaration gives a ``value=``: roslaunch refuses to override them
    from the command line, so they are no features (as the paper's A leaves them out)."""
    return {a.name for a in model.args if a.value is not None} - {
        a.name for a in model.args if a.value is None
    }


def _value_text(slot: Slot, default_text: str | None) -> str:
    if slot is OTHER:
        return "<other>"
    if slot is UNSET:
        return f"<default: {default_text}>" if default_text else "<unset>"
    return str(slot)


@collector_paused()  # it rescanned the whole heap of models: a third of 2,000 files' time
def extract(
    analysis: Analysis,
    files: Sequence[str] | None = None,
    progress: Callable[[int, int, str], None] | None = None,
    *,
    products: bool = False,
) -> FeatureModel:
    """Algorithm 1 over ``files`` (default: every launch file of the workspace).

    ``products``: the model of the products the configuration engine builds, where a file
    loaded by an include takes its args from the include, so its own are at their defaults
    (:func:`_given_by_include`); the paper's model leaves them free.
    """
    space = analysis.space
    chosen = list(files if files is not None else analysis.workspace.launch_files)
    models: list[LaunchModel] = []
    for number, file in enumerate(chosen):
        if progress is not None:
            progress(number, len(chosen), file)
        models.append(analysis.model(file))
    features: list[FileFeature] = []
    by_file: dict[str, FileFeature] = {}
    requires: list[Constraint] = []
    feature_inputs: set[ArgInput] = set()
    for model in models:
        label = analysis.label(model.file)
        feature = FileFeature(label, model.file, space.file_atom(model.file, label))
        affecting = graph_inputs(model)
        declared = {a.name: a for a in model.args if a.input is not None}
        fixed = _set_by_value(model)
        for name, input_ in model.inputs.items():
            if input_ not in affecting or name in fixed:
                continue
            decl = declared.get(name)
            default = model.unset_defaults.get(name) or (decl.default if decl else None)
            domain = model.domains[name]
            arg = ArgFeature(
                id=f"{label}:{name}",
                file=model.file,
                name=name,
                input=input_,
                default=default,
                boolean={s for s in domain if isinstance(s, str)} <= {"true", "false"}
                and any(isinstance(s, str) for s in domain),
                location=decl.location if decl else None,
            )
            for slot in domain:
                if slot is UNSET and (decl is None or decl.default is None):
                    continue  # a required arg must be given
                text = _value_text(slot, decl.default if decl else None)
                arg.values.append(
                    ValueFeature(
                        id=f"{label}:{name}={text}",
                        value=text,
                        slot=slot,
                        default=(slot == default) or slot is UNSET,
                        variable=space.slot(input_, slot),
                    )
                )
            feature.args.append(arg)
            feature_inputs.add(input_)
        features.append(feature)
        by_file[real_path(model.file)] = feature
    for model in models:
        source = by_file[real_path(model.file)]
        for include in model.includes:
            if not include.resolved or include.location.file != model.file:
                continue
            for condition, target in include.file:
                target_feature = by_file.get(real_path(str(target)))
                if target_feature is None:
                    continue
                when = include.condition & condition
                unset = _given_by_include(space, target_feature) if products else space.true
                requires.append(
                    Constraint(
                        "requires",
                        (source.id, target_feature.id),
                        ~(source.variable & when) | (target_feature.variable & unset),
                        when,
                        f"{source.id} includes {target_feature.id}"
                        + (
                            ", which takes no args from the command line then"
                            if unset != space.true
                            else ""
                        ),
                        (include.location,),
                        space.valid_implies(when),
                    )
                )
    buckets = index(models)
    feature_model = FeatureModel(
        space, features, requires, buckets, models, _unknown_values(features), products
    )
    try:
        _check_links(buckets, len(features))
        feature_model.solution = _formula(
            space, features, requires, buckets, lambda: feature_model.constraints
        )
    except ModelTooLarge as too_large:
        # kept without its traceback, whose frames hold the half-built BDDs
        feature_model.solution = ModelTooLarge(*too_large.args)
        feature_model.diagnostics.append(
            Diagnostic(
                "model-too-large",
                Severity.WARNING,
                f"the feature model is listed but not solved: {too_large}; the number of "
                "valid configurations and core/dead features are unknown",
                Location(", ".join(analysis.workspace.roots)),
            )
        )
    return feature_model


LINK_BUDGET = 20_000
LINKS_PER_FILE = 50
"""Most pairs of files sharing a declared name before the solver is not attempted:
``LINK_BUDGET + LINKS_PER_FILE × files``.

The pairs are what ordering the variables and listing the ``excludes`` constraints cost,
quadratic where many files redeclare a name; workspaces that link this many files
through their clashes also have BDDs far beyond the memory budget. Real systems link a
few files per file (Husky: 501 pairs for 137 files), so a workspace of many systems gets
a budget that grows with it.
"""


def _check_links(buckets: Mapping[tuple[str, str], Sequence[Occurrence]], files: int) -> None:
    """Raise :class:`ModelTooLarge` before any pairwise work if clashes link too many files."""
    groups = {frozenset(o.file for o in occurrences) for occurrences in buckets.values()}
    links = sum(len(group) * (len(group) - 1) // 2 for group in groups)
    budget = LINK_BUDGET + LINKS_PER_FILE * files
    if links > budget:
        raise ModelTooLarge(f"{links:,} pairs of files declare a common name (budget {budget:,})")


def _excludes(
    space: ConditionSpace, features: Sequence[FileFeature], found: Sequence[Clash]
) -> list[Constraint]:
    """One ``excludes`` constraint per pair of files whose declarations clash."""
    by_file = {f.file: f for f in features}  # an occurrence's file is its model's file
    between: dict[tuple[str, str], list[Clash]] = {}
    for clash in found:
        if clash.first.file != clash.second.file:
            key = tuple(sorted(clash.files))
            between.setdefault(key, []).append(clash)  # type: ignore[arg-type]
    constraints = []
    for (file_a, file_b), pair_clashes in sorted(between.items()):
        a, b = by_file[file_a], by_file[file_b]
        condition = space.false
        for clash in pair_clashes:
            condition |= clash.condition
        names = sorted({f"{c.kind} {c.name}" for c in pair_clashes})
        constraints.append(
            Constraint(
                "excludes",
                (a.id, b.id),
                ~(a.variable & b.variable & condition),
                condition,
                f"{a.id} and {b.id} both declare {', '.join(names[:3])}"
                + (f" (+{len(names) - 3} more)" if len(names) > 3 else ""),
                tuple(loc for c in pair_clashes for loc in (c.first.location, c.second.location)),
                space.valid_implies(condition),
            )
        )
    return constraints


def _unknown_values(features: Sequence[FileFeature]) -> list[Diagnostic]:
    """Args whose values static analysis could not find: only a typed-in value remains."""
    found = []
    for feature in features:
        for arg in feature.args:
            if all(not isinstance(v.slot, str) for v in arg.values):
                found.append(
                    Diagnostic(
                        "values-unknown",
                        Severity.NOTE,
                        f"no value of arg '{arg.name}' could be inferred; it keeps the "
                        "<other> slot for a value given at configuration time (or a hints file)",
                        arg.location or Location(feature.file, 1, 1),
                    )
                )
    return found


def _name(variable: BDD) -> str:
    return str(variable.var)


FORCE_ROUNDS = 100
FORCE_PATIENCE = 10  # rounds without a shorter span before FORCE stops


def _order(
    space: ConditionSpace, features: Sequence[FileFeature], links: Iterable[Sequence[str]]
) -> list[str]:
    """Feature variables in file blocks: linked files close together, components apart.

    A constraint between two files is cheap for a BDD only if their variables are
    close in the order: every constraint pending across a level can double the
    diagram's width there. Cuthill–McKee (a breadth-first search from a file with
    few links) finds the components and a first order of each; FORCE then refines
    it (``_force``). The components go smallest first, so that conjoining them
    never passes below the largest diagram (a conjunction walks every part of one
    operand lying above the other's variables).
    """
    neighbours: dict[str, set[str]] = {f.id: set() for f in features}
    for a, b in links:  # files a constraint links (feature ids)
        if a != b:
            neighbours[a].add(b)
            neighbours[b].add(a)
    by_id = {f.id: f for f in features}
    visited: set[str] = set()
    components: list[list[str]] = []
    for start in sorted(by_id, key=lambda f: (len(neighbours[f]), f)):
        if start in visited:
            continue
        visited.add(start)
        component: list[str] = []
        queue = deque([start])
        while queue:
            current = queue.popleft()
            component.append(current)
            for nxt in sorted(neighbours[current] - visited, key=lambda f: (len(neighbours[f]), f)):
                visited.add(nxt)
                queue.append(nxt)
        components.append(_force(component, neighbours))
    blocks = [[name for i in files for name in by_id[i].variable_names()] for files in components]
    blocks.sort(key=len)
    _ = space
    return [name for block in blocks for name in block]


def _force(files: list[str], neighbours: Mapping[str, set[str]]) -> list[str]:
    """FORCE (Aloul, Markov and Sakallah, 2003) on one component's files.

    Each round moves every file to the mean centre of its links and ranks the files
    by that; the order with the shortest total span (the summed distance between
    linked files) is kept, and the search stops once spans stop shrinking. Linear
    in the links per round. On Husky, whose clone-and-own configurations form a
    grid of requires and excludes, it shrinks the diagram by a third and its
    construction several times over against Cuthill–McKee alone.
    """
    links = [(a, b) for a in files for b in neighbours[a] if a < b]
    if not links:
        return files
    position = {f: i for i, f in enumerate(files)}

    def span() -> int:
        return sum(abs(position[a] - position[b]) for a, b in links)

    best, shortest, stale = files, span(), 0
    for _round in range(FORCE_ROUNDS):
        if stale == FORCE_PATIENCE:
            break
        pull = dict.fromkeys(files, 0.0)
        for a, b in links:
            centre = (position[a] + position[b]) / 2
            pull[a] += centre
            pull[b] += centre
        files = sorted(files, key=lambda f: (pull[f] / len(neighbours[f]), position[f]))
        position = {f: i for i, f in enumerate(files)}
        length = span()
        best, shortest, stale = (
            (files, length, 0) if length < shortest else (best, shortest, stale + 1)
        )
    return best


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
    the arg's number of values (``count``). On Husky this diagram is a third of
    ``formula``, built and counted several times faster. ``formula``, over every
    variable, is built on first use (propagation and the engine need it).
    """

    def __init__(
        self,
        manager: _cudd.BDD,
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
        with _memory_bound(self.manager, self._workspace_files):
            trees = _arg_trees(self.manager, self._args)
            return conjoin(self.manager, [*trees, *self._constraints])

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


def _arg_trees(manager: _cudd.BDD, args: Sequence[tuple[str, list[str]]]) -> list[BDD]:
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
        manager: _cudd.BDD,
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
        return self.manager.var(_name(variable))

    def file_tree(self, feature: FileFeature) -> BDD:
        """One file's part of the feature tree (``∃`` the other files' variables ``. tree``)."""
        return conjoin(self.manager, self.arg_trees(feature))

    def arg_trees(self, feature: FileFeature) -> list[BDD]:
        """The parts of the feature tree of each arg of a file: the file is selected exactly
        when one of the arg's values is (their conjunction is ``file_tree``)."""
        args = [
            (_name(feature.variable), [_name(v.variable) for v in a.values]) for a in feature.args
        ]
        return _arg_trees(self.manager, args)

    @cached_property
    def component_of(self) -> dict[str, int]:
        """Variable name → index of the component it belongs to."""
        return {v: n for n, c in enumerate(self.components) for v in c.variables}

    def restrict(self, choices: Mapping[str, bool]) -> list[BDD]:
        """Each component's formula under ``choices`` (variable name → value).

        Each component gets only its own choices: ``dd``'s ``let`` costs as much as
        the cube it is given, and untouched components are returned as they are.
        """
        own: list[dict[str, bool]] = [{} for _ in self.components]
        for name, value in choices.items():
            own[self.component_of[name]][name] = value
        return [
            self.manager.let(mine, c.formula) if mine else c.formula
            for c, mine in zip(self.components, own, strict=True)
        ]

    def count(self, choices: Mapping[str, bool] | None = None) -> int:
        """Valid configurations (agreeing with ``choices``), exactly: the product of the
        components' counts. Variables fixed by ``choices`` no longer count as free."""
        total = 1
        for component in self.components:
            total *= component.count(choices or {})
        return total


SOLVER_CACHE = 1 << 20
"""Most entries of CUDD's computed table in the solver's manager (``dd`` lets it grow without
bound). Components are built one after another and share no variable, so the table only
helps within one component's conjunction; grown with the whole workspace it only cost
page faults and cache misses: 16 M entries (512 MB) for 10,000 generated files, whose
conjunctions took 15 s instead of 6 s with 1 M entries (the same hit rate, 17 %). Husky's
table never outgrows its first 256 k entries."""


def _formula(
    space: ConditionSpace,
    features: Sequence[FileFeature],
    requires: Sequence[Constraint],
    buckets: Mapping[tuple[str, str], Sequence[Occurrence]],
    constraints: Callable[[], Sequence[Constraint]],
) -> Solver:
    """The whole feature model over file and value variables only, one BDD per component.

    Atoms that are not features (predicates on typed-in values, environment
    variables, other files' plumbing) are quantified out of each constraint:
    an ``<other>`` value is taken as able to do anything a typed value could.
    Exclusions enter per clashing name, not per pair of files (``_exclusions``), and
    the pairs of files they link are found per name too (``_excluding``): the
    pairwise ``excludes`` constraints (``constraints``, every cross-tree constraint)
    are built only if asked for.
    """
    files = {f.file: f for f in features}
    declaring = _declaring(space, files, buckets)
    excluding = [(files[a].id, files[b].id) for a, b in _excluding(declaring)]
    keep = _order(space, features, [*(c.files for c in requires), *excluding])
    kept = set(keep)
    manager = _cudd.BDD(memory_estimate(len(features)))  # dd's default touches 8 MB at once
    manager.configure(reordering=False, max_cache_hard=SOLVER_CACHE)
    manager.declare(*keep)  # a fresh manager in the chosen order (reordering in place is slow)

    def translate(formula: BDD) -> BDD:
        return transfer(formula, manager, {n for n in space.support(formula) if n not in kept})

    with _memory_bound(manager, len(features)):
        linked = _Links([f.id for f in features])
        pieces: list[tuple[str, BDD]] = []
        for constraint in requires:
            linked.join(constraint.files)
            pieces.append((constraint.files[0], translate(constraint.formula)))
        for members, exclusion in _exclusions(space, manager, files, declaring, kept, translate):
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
                (_name(f.variable), [_name(v.variable) for v in a.values])
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


def _declaring(
    space: ConditionSpace,
    files: Mapping[str, FileFeature],
    buckets: Mapping[tuple[str, str], Sequence[Occurrence]],
) -> list[dict[str, BDD]]:
    """For each name declared by two files or more, when each of them declares it; names
    declared alike (a moveit configuration's files share dozens of parameter names, all
    under the same conditions) once for all."""
    done: set[frozenset[tuple[str, BDD]]] = set()
    found = []
    for occurrences in buckets.values():
        when: dict[str, BDD] = {}
        for occurrence in occurrences:
            if occurrence.file in files:
                when[occurrence.file] = (
                    when.get(occurrence.file, space.false) | occurrence.condition
                )
        alike = frozenset(when.items())
        if len(when) >= 2 and alike not in done:
            done.add(alike)
            found.append(when)
    return found


def _excluding(declaring: Iterable[Mapping[str, BDD]]) -> list[tuple[str, str]]:
    """The pairs of files (paths) declaring a common name under conditions that can hold
    together: the files of the ``excludes`` constraints (``conflicts.clashes``' pairs of
    declarations, taken per file: the conjunction of two disjunctions is satisfiable
    when one pair of their terms is)."""
    pairs: set[tuple[str, str]] = set()
    for when in declaring:
        files = sorted(when)
        for position, first in enumerate(files):
            for second in files[position + 1 :]:
                if (first, second) in pairs:
                    continue
                both = when[first] & when[second]
                if both != both.bdd.false:
                    pairs.add((first, second))
    return sorted(pairs)


def _exclusions(
    space: ConditionSpace,
    manager: _cudd.BDD,
    files: Mapping[str, FileFeature],
    declaring: Iterable[Mapping[str, BDD]],
    kept: set[str],
    translate: Callable[[BDD], BDD],
) -> Iterator[tuple[list[str], BDD]]:
    """The excludes constraints, as one at-most-one per clashing name (plus rare pairs).

    The pairs of files clashing on a name ``n`` exclude each other exactly when at
    most one file ``f`` has ``F ∧ C_f`` (``C_f``: when ``f`` declares ``n``) —
    one BDD linear in the files instead of one constraint per pair, which is what
    makes clone-and-own systems (cliques of files redeclaring the same names)
    cheap. Where ``C_f`` mentions atoms that are not features, quantifying them
    out does not distribute over the names, so such files keep the pairwise
    constraint, restricted to those names: together this is the conjunction of
    the pairwise ``excludes`` exactly.
    """
    dirty: dict[tuple[str, str], BDD] = {}
    literals: dict[tuple[str, BDD], BDD | None] = {}  # F ∧ C_F in the solver; None: unclean
    for when in declaring:
        clean: list[tuple[str, BDD]] = []
        unclean: list[str] = []
        for file, condition in when.items():
            if (file, condition) not in literals:
                literals[file, condition] = (
                    transfer(files[file].variable & condition, manager)
                    if space.support(condition) <= kept
                    else None
                )
            literal = literals[file, condition]
            if literal is None:
                unclean.append(file)
            else:
                clean.append((file, literal))
        for position, file in enumerate(unclean):
            for other in [*unclean[position + 1 :], *(f for f, _x in clean)]:
                pair = (file, other) if file < other else (other, file)
                dirty[pair] = dirty.get(pair, space.false) | (when[file] & when[other])
        if len(clean) >= 2:
            clean.sort(key=lambda item: manager.level_of_var(_name(files[item[0]].variable)))
            yield [files[f].id for f, _x in clean], _at_most_one(manager, [x for _f, x in clean])
    for (first, second), condition in dirty.items():
        a, b = files[first], files[second]
        if condition != space.false:
            yield [a.id, b.id], translate(~(a.variable & b.variable & condition))


def _at_most_one(manager: _cudd.BDD, literals: Sequence[BDD]) -> BDD:
    """At most one of ``literals`` holds: a chain built from the last literal up."""
    result, none = manager.true, manager.true
    for literal in reversed(literals):
        result = (literal & none) | (~literal & result)
        none &= ~literal
    return result


MEMORY_BUDGET = 128 << 20
MEMORY_PER_FILE = 256 << 10
"""Bytes the solver's BDD manager may use while the model is built (CUDD enforces it):
``MEMORY_BUDGET + MEMORY_PER_FILE × files``.

Husky, the largest corpus system, peaks near 31 MB (a million nodes take about 100 MB);
workspaces of many such systems need about 0.2 MB per launch file (2,000 generated files:
408 MB). A workspace whose exclusions span the whole order reaches the bound within
seconds and would go on for hours. A bound on memory, unlike one on time, does not depend
on the machine's load: the same model is solved, or not, everywhere.
"""


@contextmanager
def _memory_bound(manager: _cudd.BDD, files: int) -> Iterator[None]:
    """Building in ``manager`` within the memory budget of ``files`` launch files, or
    :class:`ModelTooLarge`.

    Past the bound CUDD returns NULL, which ``dd`` reports as a ValueError (operators)
    or a RuntimeError (``apply`` and the like), told from other errors by their text.
    The bound is lifted afterwards: the solver's later questions must not fail on a
    model it holds.
    """
    budget = MEMORY_BUDGET + MEMORY_PER_FILE * files
    unbounded = manager.configure(max_memory=budget)["max_memory"]
    try:
        yield
    except (ValueError, RuntimeError) as error:
        if not any(sign in str(error) for sign in ("NULL", "out of memory")):
            raise
        raise ModelTooLarge(f"its BDD outgrew {budget >> 20} MB") from error
    finally:
        manager.configure(max_memory=unbounded)


def conjoin(manager: _cudd.BDD, parts: Sequence[BDD]) -> BDD:
    """Conjunction scheduled from the bottom of the order up, by each part's top variable.

    Each intermediate result is then the conjunction of every part lying below some
    level, never a part reaching far up without those that prune it — the result
    does not grow beyond the final diagram's width (ordering by the deepest
    variable instead made Husky's intermediate results twenty times the final one).
    """

    constants = (manager.true, manager.false)

    def top(part: BDD) -> int:
        return -1 if part in constants else int(part.level)  # the root is the top variable

    result = manager.true
    for part in sorted(parts, key=top, reverse=True):
        result &= part
    return result


def count_configurations(model: FeatureModel) -> int | None:
    """Valid configurations, exactly (weighted model counting per component, no
    enumeration); None: unknown.

    Unknown when the model was too large to solve (``FeatureModel.solution``).
    """
    if not model.solved:
        return None
    return model.solver.count()


@dataclass
class Verdict:
    feature: str
    kind: str  # "core" or "dead"
    because: list[str]


def core_and_dead(model: FeatureModel) -> list[Verdict]:
    """Features in every (core) or no (dead) valid configuration, with the constraints why.

    A value of a dead file is dead for the same reason (it needs its file): it shares the
    file's explanation instead of searching again — a file that includes one it clashes
    with has every value dead, and each search costs many conjunctions.
    """
    solver = model.solver
    verdicts: list[Verdict] = []
    possible = possible_values(solver)

    def values_of(variable: BDD) -> set[bool]:
        return possible.get(_name(variable), {False, True})

    for file in model.files:
        variable = solver.var(file.variable)
        dead_file = True not in values_of(variable)
        if dead_file:
            because = explain(model, variable)
            verdicts.append(Verdict(file.id, "dead", because))
        elif False not in values_of(variable):
            verdicts.append(Verdict(file.id, "core", explain(model, ~variable)))
        for value in (v for arg in file.args for v in arg.values):
            variable = solver.var(value.variable)
            if dead_file:
                verdicts.append(Verdict(value.id, "dead", because))
            elif True not in values_of(variable):
                verdicts.append(Verdict(value.id, "dead", explain(model, variable)))
            elif False not in values_of(variable):
                verdicts.append(Verdict(value.id, "core", explain(model, ~variable)))
    return verdicts


def possible_values(solver: Solver, formula: BDD | None = None) -> dict[str, set[bool]]:
    """For every variable, the values it takes in some valid configuration — one BDD pass.

    A value is possible when some path to TRUE sets it, or skips the variable's level
    (then it is free). Asking the solver twice per feature instead costs two
    operations on the whole diagram each, minutes on a large system. ``formula``
    (default: the whole model) may be a component's formula, restricted or not; the
    answer is then meant for that component's variables only.

    The whole model is read off each component's ``counted`` diagram, never building
    the full formulas, from the lists its count read (``CountedDiagram.taken``, no ``dd``
    wrapper per edge: 60 against 120–220 ms on Husky's large component): a value a
    stand-in counts for is possible where the stand-in is true, and left out where it is
    false or, in a group of two or more, where
    another value of the group is taken instead.
    """
    manager = solver.manager
    names = [manager.var_at_level(level) for level in range(len(solver.variables))]
    if formula is not None:
        return _one_pass(manager, names, formula)
    possible: dict[str, set[bool]] = {}
    for component in solver.components:
        if component.counted == manager.false:  # no valid configuration at all
            return {name: set() for name in names}
        found = component.counted_diagram.taken()
        possible.update((name, found[name]) for name in component.counted_variables)
        for stand_in, group in component.stand_ins:
            taken = found[stand_in]
            values = {True} if True in taken else set()
            if False in taken or (True in taken and len(group) > 1):
                values.add(False)
            possible.update((name, set(values)) for name in group)
    return possible


def _one_pass(manager: _cudd.BDD, names: Sequence[str], root: BDD) -> dict[str, set[bool]]:
    """``possible_values`` of ``root`` over the levels ``names`` (all of the manager's)."""
    depth = len(names)
    possible: dict[str, set[bool]] = {name: set() for name in names}
    free = [0] * (depth + 1)  # difference array over levels skipped by some edge
    true, false = manager.true, manager.false  # each access builds a new wrapper: hoisted
    if root == false:
        return possible

    def skip(start: int, stop: int) -> None:
        if start < stop:
            free[start] += 1
            free[stop] -= 1

    skip(0, depth if root == true else root.level)
    seen: set[BDD] = set()
    stack = [root]
    while stack:
        u = stack.pop()
        if u in seen or u == true:
            continue
        seen.add(u)
        negated, here = u.negated, u.level
        taken = possible[names[here]]
        for value, child in ((False, u.low), (True, u.high)):
            if negated:
                child = ~child
            if child == false:
                continue
            taken.add(value)
            if child == true:
                skip(here + 1, depth)
            else:
                skip(here + 1, child.level)
                stack.append(child)
    running = 0
    for position, name in enumerate(names):
        running += free[position]
        if running > 0:
            possible[name] = {False, True}
    return possible


def explain(model: FeatureModel, goal: BDD) -> list[str]:
    """A minimal set of cross-tree constraints that rules ``goal`` out (deletion-based).

    The search starts from the constraints around the feature's file and widens one
    hop of the constraint graph at a time: explanations are local in practice, and
    conjoining every constraint of a large system for each trial would be quadratic
    in expensive BDD operations. Only the tree parts of the files the constraints and
    ``goal`` mention take part: the other files' parts are satisfiable on their own.
    """
    solver = model.solver
    false = solver.manager.false
    mentioned = walked_support(goal)
    files = {f.id for f in model.files if _name(f.variable) in mentioned} | {
        f.id
        for f in model.files
        for a in f.args
        for v in a.values
        if _name(v.variable) in mentioned
    }
    by_id = {f.id: f for f in model.files}
    chosen: list[int] = []
    while True:
        chosen = [n for n, c in enumerate(model.constraints) if set(c.files) & files]
        involved = files | {f for n in chosen for f in model.constraints[n].files}
        tree = conjoin(solver.manager, [solver.file_tree(by_id[f]) for f in sorted(involved)])
        formula = tree & goal
        for number in chosen:
            formula &= solver.constraints[number]
        if formula == false:
            break
        wider = files | {f for n in chosen for f in model.constraints[n].files}
        if wider == files:
            return ["the whole model (no local reason found)"]
        files = wider
    kept = chosen
    position = 0
    while position < len(kept):
        trial = kept[:position] + kept[position + 1 :]
        formula = tree & goal
        for number in trial:
            formula &= solver.constraints[number]
        if formula == false:
            kept = trial
        else:
            position += 1
    return [model.constraints[n].text for n in kept] or ["the feature tree itself"]


def simplest_trigger(space: ConditionSpace, condition: BDD) -> dict[str, str]:
    """An arg assignment making ``condition`` true with the fewest non-default choices.

    A cheapest path through the BDD, where choosing a non-default value costs 1
    and an ``<other>`` value costs 3; the inputs the path leaves open keep their
    defaults.
    """
    involved = {
        atom.input
        for atom in (space.atom_of(n) for n in space.support(condition))
        if isinstance(atom, SlotAtom)
    }
    target = condition
    for input_ in involved:
        target &= space.input_constraint(input_)
    if target == space.false:
        return {}
    memo: dict[BDD, tuple[float, dict[str, bool]]] = {}

    def cheapest(u: BDD) -> tuple[float, dict[str, bool]]:
        if u == space.true:
            return 0.0, {}
        if u == space.false:
            return float("inf"), {}
        if u in memo:
            return memo[u]
        var = u.var
        low_cost, low_path = cheapest(space.bdd.let({var: False}, u))
        high_cost, high_path = cheapest(space.bdd.let({var: True}, u))
        high_cost += _cost(space, var)
        best = (
            (low_cost, {var: False, **low_path})
            if low_cost <= high_cost
            else (high_cost, {var: True, **high_path})
        )
        memo[u] = best
        return best

    _cost_total, path = cheapest(target)
    chosen: dict[str, str] = {}
    for name, value in path.items():
        atom = space.atom_of(name)
        if value and isinstance(atom, SlotAtom):
            input_ = atom.input
            key = (
                f"{_short(input_.file)}:{input_.name}"
                if isinstance(input_, ArgInput)
                else str(input_)
            )
            chosen[key] = _value_text(atom.slot, None)
        elif value and isinstance(atom, FileAtom):
            chosen[atom.label] = "selected"
    return chosen


def _short(file: str) -> str:
    return os.path.basename(file)


def _cost(space: ConditionSpace, name: str) -> float:
    atom = space.atom_of(name)
    if not isinstance(atom, SlotAtom):
        return 0.0
    if atom.slot is OTHER:
        return 3.0
    if atom.slot is UNSET or atom.slot == _first(space, atom):
        return 0.0
    return 1.0


def _first(space: ConditionSpace, atom: SlotAtom) -> Slot:
    return space.domain(atom.input)[0]
