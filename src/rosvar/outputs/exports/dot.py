"""The feature model as a Graphviz DOT digraph, for ``dot -Tsvg``.

Tree edges follow feature-diagram habit: an open circle at an optional child (file), a
filled one at a mandatory child (arg); an arg's values hang off it as an alternative
group. Default values are bold with a ✓. Cross-tree constraints are dashed: ``requires``
an arrow to the required file, ``excludes`` a red double-headed edge, each labelled with
its condition when it has one.
"""

from __future__ import annotations

from rosvar.analyses.feature_model.features import (
    ArgFeature,
    ConstraintKind,
    FileFeature,
    ValueFeature,
)
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.outputs.exports._common import Tree


def quote(text: str) -> str:
    """A DOT double-quoted string; backslashes are doubled so labels show them as typed."""
    escaped = text.replace("\\", "\\\\").replace('"', '\\"')
    return '"' + escaped.replace("\r", "").replace("\n", "\\n") + '"'


def _attributes(**attributes: str) -> str:
    return "[" + ", ".join(f"{key}={quote(value)}" for key, value in attributes.items()) + "]"


def write(model: FeatureModel) -> str:
    tree = Tree(model)
    root = tree.root
    lines = [
        f"digraph {quote(root)} {{",
        "  rankdir=LR;",
        '  node [shape=box, style=rounded, fontname="Helvetica"];',
        '  edge [fontname="Helvetica", fontsize=10];',
        f"  {quote(root)} {_attributes(label=root, shape='box', style='bold')};",
    ]
    for entry in tree.entries:
        feature = entry.feature
        node = quote(entry.id)
        parent = quote(entry.parent if entry.parent is not None else root)
        if isinstance(feature, FileFeature):
            lines.append(f"  {node} {_attributes(label=feature.id)};")
            lines.append(f"  {parent} -> {node} {_attributes(arrowhead='odot')};")
        elif isinstance(feature, ArgFeature):
            label = f"{feature.name}\n(one of {len(feature.values)})"
            lines.append(f"  {node} {_attributes(label=label, shape='ellipse', style='solid')};")
            lines.append(f"  {parent} -> {node} {_attributes(arrowhead='dot')};")
        elif isinstance(feature, ValueFeature):
            if feature.default:
                look = _attributes(label=f"✓ {feature.value}", shape="plain", fontcolor="darkgreen")
            else:
                look = _attributes(label=feature.value, shape="plain")
            lines.append(f"  {node} {look};")
            lines.append(f"  {parent} -> {node} {_attributes(arrowhead='none', style='solid')};")
    describe = model.space.describe
    for constraint in model.constraints:
        source, target = (quote(tree.files[f]) for f in constraint.files)
        label = "" if constraint.unconditional else describe(constraint.condition)
        style = {"style": "dashed", "constraint": "false", "tooltip": constraint.text}
        if label:
            style["label"] = label
        if constraint.kind == ConstraintKind.EXCLUDES:
            style.update(color="red", fontcolor="red", dir="both")
        else:
            style.update(color="blue", fontcolor="blue")
        lines.append(f"  {source} -> {target} {_attributes(**style)};")
    lines.append("}")
    return "\n".join(lines) + "\n"
