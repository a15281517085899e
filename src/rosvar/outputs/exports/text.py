"""The feature model as a report for people: sizes, the tree, constraints, solver findings.

Conditions are the analysis' readable ones (``describe``); core and dead features come
with the constraints that force them, conflicts with the assignment that triggers them
with the fewest non-default choices, so each finding says what to look at.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import replace

from rosvar.analyses.feature_model.features import (
    ArgFeature,
    ConstraintKind,
    FeatureKind,
    FileFeature,
    ValueFeature,
)
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.operations import core_and_dead, count_configurations
from rosvar.diagnostics import Location, Severity
from rosvar.outputs.describe import count_text
from rosvar.outputs.exports._common import Tree, Triggers, conflicts
from rosvar.workspace.paths import real_path

INDENT = "  "


def _plural(count: int, word: str) -> str:
    return f"{count} {word}{'' if count == 1 else 's'}"


def _where(location: Location, tree: Tree) -> Location:
    """``location`` in a launch file's id, which is shorter than its path."""
    return replace(location, file=tree.by_path.get(real_path(location.file), location.file))


def _summary(model: FeatureModel, tree: Tree, configurations: int | None) -> list[str]:
    files = [e for e in tree.entries if e.kind == FeatureKind.FILE]
    args = [e for e in tree.entries if e.kind == FeatureKind.ARG]
    values = [e for e in tree.entries if e.kind == FeatureKind.VALUE]
    kinds = Counter(c.kind for c in model.constraints)
    conditional = Counter(c.kind for c in model.constraints if not c.unconditional)
    by_kind = ", ".join(
        f"{count} {kind} ({conditional[kind]} conditional)" for kind, count in sorted(kinds.items())
    )
    return [
        f"Feature model of {tree.root}",
        f"{INDENT}{_plural(len(files), 'launch file')}, {_plural(len(args), 'arg feature')}, "
        f"{_plural(len(values), 'value')}",
        f"{INDENT}{_plural(len(model.constraints), 'constraint')}"
        + (f": {by_kind}" if by_kind else ""),
        f"{INDENT}{'unknown number of' if configurations is None else count_text(configurations)} "
        "valid configurations",
    ]


def _tree(tree: Tree) -> list[str]:
    lines = ["", "Tree (files optional, one value per arg, ✓ default)", f"{INDENT}{tree.root}"]
    for entry in tree.entries:
        feature = entry.feature
        indent = INDENT * (entry.depth + 1)
        if isinstance(feature, FileFeature):
            lines.append(f"{indent}{feature.id}")
        elif isinstance(feature, ArgFeature):
            extra = " (boolean)" if feature.boolean else ""
            if not feature.values:
                extra += " (no possible value: its file cannot be selected)"
            lines.append(f"{indent}{feature.name}{extra}")
        elif isinstance(feature, ValueFeature):
            mark = "✓" if feature.default else " "
            lines.append(f"{indent}{mark} {feature.value}")
    return lines


def _constraints(model: FeatureModel, tree: Tree) -> list[str]:
    lines = ["", "Constraints"]
    if not model.constraints:
        lines.append(f"{INDENT}none")
    describe = model.space.describe
    for constraint in model.constraints:
        a, b = (tree.files[f] for f in constraint.files)
        arrow = "→" if constraint.kind == ConstraintKind.REQUIRES else "⊗"
        when = "always" if constraint.unconditional else f"when {describe(constraint.condition)}"
        lines.append(f"{INDENT}{constraint.kind} {a} {arrow} {b}, {when}")
        lines.append(f"{INDENT * 2}{constraint.text}")
        where = [str(_where(loc, tree)) for loc in constraint.locations]
        if where:
            more = f" (+{len(where) - 4} more)" if len(where) > 4 else ""
            lines.append(f"{INDENT * 2}at {', '.join(where[:4])}{more}")
    return lines


def _verdicts(model: FeatureModel) -> list[str]:
    lines = ["", "Core and dead features"]
    if not model.solved:
        return [*lines, f"{INDENT}unknown: the model is too large to solve (see the diagnostics)"]
    verdicts = core_and_dead(model)
    if not verdicts:
        lines.append(f"{INDENT}none: every feature can be selected and deselected")
    for verdict in verdicts:
        lines.append(f"{INDENT}{verdict.kind} {verdict.feature}")
        for reason in verdict.because:
            lines.append(f"{INDENT * 2}because {reason}")
    return lines


def _conflicts(model: FeatureModel, tree: Tree) -> list[str]:
    lines = ["", "Conflicts (name clashes)"]
    found = conflicts(model)
    if not found:
        lines.append(f"{INDENT}none")
    trigger = Triggers(model)
    describe = model.space.describe
    for clash in found:
        first, second = clash.first, clash.second
        lines.append(
            f"{INDENT}{clash.kind} {clash.name}: {_where(first.location, tree)} and "
            f"{_where(second.location, tree)}, when {describe(clash.condition)}"
        )
        assignment = trigger(clash.condition)
        shown = ", ".join(f"{k}={v}" for k, v in assignment.items()) or "any values"
        lines.append(f"{INDENT * 2}simplest trigger: {shown}")
    return lines


def write(model: FeatureModel) -> str:
    tree = Tree(model)
    lines = _summary(model, tree, count_configurations(model))
    lines += _tree(tree)
    lines += _constraints(model, tree)
    lines += _verdicts(model)
    lines += _conflicts(model, tree)
    if model.diagnostics:
        lines += ["", "Diagnostics"]
        lines += [
            f"{INDENT}{replace(d, location=_where(d.location, tree))}"
            for d in model.diagnostics
            if d.severity is not Severity.NOTE
        ]
        notes = Counter(d.code for d in model.diagnostics if d.severity is Severity.NOTE)
        lines += [
            f"{INDENT}{_plural(count, 'note')} [{code}] (listed on stderr and in --format json)"
            for code, count in sorted(notes.items())
        ]
    return "\n".join(lines) + "\n"
