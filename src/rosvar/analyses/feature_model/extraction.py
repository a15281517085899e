"""Algorithm 1: the feature model of a workspace's launch files, read off their models.

The args that make a feature are those affecting the computation graph (``graph_inputs``),
their values the interpreter's input domains; an ``<include>`` becomes a *requires*
constraint. The solver is built at once, within its budgets (``solver.build``).
"""

from __future__ import annotations

import itertools
import os
from collections.abc import Callable, Mapping, Sequence

from rosvar.analyses.conflicts import Occurrence, index, internal_clashes
from rosvar.analyses.feature_model.environment import fixed_environment
from rosvar.analyses.feature_model.features import (
    ArgFeature,
    Constraint,
    ConstraintKind,
    FileFeature,
    ModelPart,
    ModelTooLarge,
    ValueFeature,
    launched_conditions,
    value_text,
)
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.solver import build
from rosvar.diagnostics import Diagnostic, Location, Severity
from rosvar.interpreter.model import DeferredValue, LaunchModel, ParamDecl
from rosvar.interpreter.workspace_models import Analysis, collector_paused
from rosvar.logic.atoms import PredicateAtom, SlotAtom
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import UNSET, ArgInput
from rosvar.logic.terms import Apply, Hole, Operand, term_inputs
from rosvar.workspace.paths import real_path


def _term_inputs(value: Operand) -> set[ArgInput]:
    return {i for i in term_inputs(value) if isinstance(i, ArgInput)}


_TERMS = (Hole, Apply)  # a union type written inline is built anew at every call


GRAPH_FIELDS = (
    *("name", "namespace", "pkg", "type", "args", "machine"),
    *("exec", "plugin", "container", "ros_namespace"),
)
"""A node's fields that shape the graph: ROS 1's, then those only a ROS 2 node has (its
pushed namespace is a field of its own: ROS 1's ``namespace`` holds its group's)."""


def graph_inputs(model: LaunchModel) -> set[ArgInput]:
    """Args whose value changes a node, param or remap (AFFECTSCG), read off the BDD supports.

    The interpreter already followed ``value=`` args, include arg passing and
    ``pass_all_args``, so an arg affects the graph exactly when one of its atoms
    is in the support of a presence condition or of a branch of an attribute.
    """
    if not model.inputs:  # no args to look for: common among the files of a system
        return set()
    space = model.space
    true = space.true
    conditions: set[BDD] = set()  # elements share conditions: each support is taken once
    terms: set[ArgInput] = set()
    choices: dict[int, Choice[object]] = {}  # and choices (one per literal, shared): by id
    for node in model.nodes:
        conditions.add(node.condition)
        for key in GRAPH_FIELDS:
            field_value = node.fields.get(key)
            if field_value is not None:
                choices[id(field_value)] = field_value
        for parameter in node.parameters:  # a ROS 2 node's own parameters
            conditions.add(parameter.condition)
            for raw in (parameter.name, parameter.value, parameter.file):
                if isinstance(raw, _TERMS):
                    terms.update(_term_inputs(raw))
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


def error_inputs(model: LaunchModel) -> set[ArgInput]:
    """Args on which roslaunch stopping depends (an arg used where the graph does not show
    it, as a node's ``output``, must still be set): a product's command must be able to
    give them, though the paper's AFFECTSCG leaves them out."""
    space = model.space
    return {
        atom.input
        for error in model.errors
        for atom in (space.atom_of(name) for name in space.support(error.condition))
        if isinstance(atom, SlotAtom)
        and isinstance(atom.input, ArgInput)
        and atom.input.file == model.file
    }


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


@collector_paused()  # the collector would rescan the whole heap of models as it grows
def extract(
    analysis: Analysis,
    files: Sequence[str] | None = None,
    progress: Callable[[int, int, str], None] | None = None,
    *,
    products: bool = False,
    env: Mapping[str, str] | None = None,
) -> FeatureModel:
    """Algorithm 1 over ``files`` (default: every launch file of the workspace).

    ``products``: the model of the products the configuration engine builds, where a file
    loaded by an include takes its args from the include, so its own are at their defaults
    (:func:`_given_by_include`), and the environment is ``env`` (a variable not given is
    unset, :mod:`.environment`); the paper's model leaves both free.
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
        affecting = graph_inputs(model) | (error_inputs(model) if products else set())
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
                doc=decl.doc if decl else None,
            )
            for slot in domain:
                if slot is UNSET and (decl is None or decl.default is None):
                    continue  # a required arg must be given
                text = value_text(slot, decl.default if decl else None)
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
                        ConstraintKind.REQUIRES,
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
    buckets = index(models, launched_conditions(features, requires) if products else None)
    # a file included by several entry files reports its problems once per entry file: once here
    found = list(dict.fromkeys(d for model in models for d in model.diagnostics))
    environment = dict(env or {})
    feature_model = FeatureModel(
        space,
        features,
        requires,
        buckets,
        models,
        [*found, *_unknown_values(features)],
        products,
        environment,
    )
    try:
        _check_links(buckets, len(features))
        cross_tree = feature_model.cross_tree
        feature_model.solution = build(
            space,
            features,
            requires,
            buckets,
            lambda: cross_tree.constraints,
            internal_clashes(buckets) if products else (),
            fixed_environment(space, environment, analysis.package_table()) if products else None,
        )
    except ModelTooLarge as too_large:
        # kept without its traceback, whose frames hold the half-built BDDs
        parts = largest_parts(analysis, features, requires, buckets)
        feature_model.solution = ModelTooLarge(str(too_large), parts)
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


LINK_BUDGET = 2_000
LINKS_PER_FILE = 25
"""Most pairs of files sharing a declared name before the solver is not attempted:
``LINK_BUDGET + LINKS_PER_FILE × files``.

The pairs are what ordering the variables and listing the ``excludes`` constraints cost,
quadratic where many files redeclare a name; workspaces that link this many files
through their clashes also have BDDs far beyond the memory budget, and reach it only
after minutes. Real systems link a few files per file (the corpus at most 4, generated
workspaces shaped like it 12), so a workspace of many systems gets a budget that grows
with it; where every file shares names with a hundred others (the uniform shape, whose
files at one position in every package declare the same names) the constraints form a
grid whose diagram outgrows any budget (docs/performance.md, "Feature model", budgets).
"""


def _check_links(buckets: Mapping[tuple[str, str], Sequence[Occurrence]], files: int) -> None:
    """Raise :class:`ModelTooLarge` before any pairwise work if clashes link too many files."""
    groups = {frozenset(o.file for o in occurrences) for occurrences in buckets.values()}
    links = sum(len(group) * (len(group) - 1) // 2 for group in groups)
    budget = LINK_BUDGET + LINKS_PER_FILE * files
    if links > budget:
        raise ModelTooLarge(f"{links:,} pairs of files declare a common name (budget {budget:,})")


LARGEST_PARTS = 3
"""The groups of linked files a model too large to solve is described by, at most."""
PART_PACKAGES = 5
"""The packages each of them is described by, at most (the most files first)."""


def largest_parts(
    analysis: Analysis,
    features: Sequence[FileFeature],
    requires: Sequence[Constraint],
    buckets: Mapping[tuple[str, str], Sequence[Occurrence]],
) -> list[ModelPart]:
    """The largest groups of files that includes and shared names link: the components
    the solver would build. Linear in the declarations (each name joins its files in a
    chain), where listing the pairs that clash would not be."""
    parent = {f.file: f.file for f in features}

    def root(file: str) -> str:
        while parent[file] != file:
            parent[file] = parent[parent[file]]
            file = parent[file]
        return file

    def join(files: Sequence[str]) -> None:
        for first, second in itertools.pairwise(files):
            parent[root(second)] = root(first)

    by_id = {f.id: f.file for f in features}
    for constraint in requires:
        join([by_id[i] for i in constraint.files])
    for occurrences in buckets.values():
        join(sorted({o.file for o in occurrences if o.file in parent}))
    groups: dict[str, list[str]] = {}
    for file in parent:
        groups.setdefault(root(file), []).append(file)
    found = []
    for files in sorted(groups.values(), key=len, reverse=True)[:LARGEST_PARTS]:
        counts: dict[tuple[str, str], int] = {}
        for file in files:
            package = analysis.workspace.package_of(file)
            key = (package.name, package.path) if package else ("", os.path.dirname(file))
            counts[key] = counts.get(key, 0) + 1
        ranked = sorted(counts.items(), key=lambda item: (-item[1], item[0]))
        first = tuple((n, p, c) for (n, p), c in ranked[:PART_PACKAGES])
        found.append(ModelPart(len(files), len(ranked), first))
    return found


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
