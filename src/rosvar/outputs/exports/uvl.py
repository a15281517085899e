"""The feature model in UVL, the Universal Variability Language (as flamapy reads it).

Every name is quoted, so ``/``, ``:``, ``=``, ``<other>`` and spaces stay as they are;
inside quotes UVL forbids only ``"``, ``.`` (the namespace separator) and line breaks,
which are percent-encoded (``control.xml`` → ``control%2Exml``) together with ``%``
itself, so that the names remain distinct and decode back with ``urllib.parse.unquote``.
"""

from __future__ import annotations

from rosvar.analyses.feature_model.features import ArgFeature, FeatureKind, ValueFeature
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.outputs.exports._common import Tree
from rosvar.outputs.exports._formula import exported, render

RESERVED = '".'
INDENT = "\t"


def name(names: dict[str, str], feature_id: str) -> str:
    return f'"{names[feature_id]}"'


def write(model: FeatureModel) -> str:
    """UVL: root (abstract) → optional files → mandatory args (abstract) → alternative values."""
    tree = Tree(model)
    names = tree.names(RESERVED)
    constraints = exported(tree)
    lines = [
        f"// rosvar feature model of {_comment(tree.root)}: launch files (optional)"
        " > args (mandatory) > values (alternative)",
        "// names percent-encode '%', '.' and '\"' (unquote them to get rosvar's feature ids)",
        "features",
        f"{INDENT}{name(names, tree.root)} {{abstract}}",
    ]
    files = [e for e in tree.entries if e.kind == FeatureKind.FILE]
    if files:
        lines.append(INDENT * 2 + "optional")
    for entry in tree.entries:
        feature = entry.feature
        indent = INDENT * (2 * entry.depth + 1)
        if isinstance(feature, ArgFeature):
            lines.append(f"{indent}{name(names, entry.id)} {{abstract}}")
            if feature.values:
                lines.append(indent + INDENT + "alternative")
        elif isinstance(feature, ValueFeature):
            default = " {default}" if feature.default else ""
            lines.append(f"{indent}{name(names, entry.id)}{default}")
        else:
            lines.append(f"{indent}{name(names, entry.id)}")
            if feature.args:
                lines.append(indent + INDENT + "mandatory")
    if constraints:
        lines.append("constraints")
        for constraint in constraints:
            lines.append(f"{INDENT}// {_comment(constraint.text)}")
            lines.append(f"{INDENT}{render(constraint.formula, lambda i: name(names, i))}")
    return "\n".join(lines) + "\n"


def _comment(text: str) -> str:
    return " ".join(text.split())
