"""The feature model as JSON: the tree, the constraints with readable conditions, and the
solver's answers (configurations, core and dead features, conflicts with a trigger).

Everything a front end needs without linking rosvar or a BDD library; ``formula`` is the
constraint over feature ids as the other formats write it.
"""

from __future__ import annotations

import json
from typing import Any

from rosvar.analyses.feature_model.features import ArgFeature, FileFeature, ValueFeature
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.operations import (
    VerdictKind,
    core_and_dead,
    count_configurations,
)
from rosvar.outputs.documents.diagnostics import diagnostic_document
from rosvar.outputs.exports._common import Tree, Triggers, conflicts
from rosvar.outputs.exports._formula import LOGIC_OPERATORS, exported, render


def _feature(tree: Tree, index: int) -> dict[str, Any]:
    entry = tree.entries[index]
    feature = entry.feature
    data: dict[str, Any] = {"id": entry.id, "kind": entry.kind, "parent": entry.parent}
    children = [e.id for e in tree.children.get(entry.id, [])]
    if isinstance(feature, FileFeature):
        data.update(path=feature.file, args=children)
    elif isinstance(feature, ArgFeature):
        data.update(
            name=feature.name,
            default=feature.default,
            boolean=feature.boolean,
            values=children,
            location=feature.location.to_json() if feature.location else None,
        )
    elif isinstance(feature, ValueFeature):
        data.update(value=feature.value, default=feature.default)
    return data


def document(model: FeatureModel) -> dict[str, Any]:
    """The JSON document as Python data (``write`` serialises it)."""
    tree = Tree(model)
    describe = model.space.describe
    formulas = (
        {e.source: render(e.formula, str, LOGIC_OPERATORS) for e in exported(tree)}
        if model.solved
        else {}
    )
    verdicts: dict[VerdictKind, list[dict[str, Any]] | None] = dict.fromkeys(VerdictKind)
    if model.solved:  # unknown (null) for a model too large to solve
        found = core_and_dead(model)
        for kind in verdicts:
            verdicts[kind] = [
                {"feature": v.feature, "because": v.because} for v in found if v.kind == kind
            ]
    trigger = Triggers(model)
    return {
        "system": tree.root,
        "features": [_feature(tree, i) for i in range(len(tree.entries))],
        "constraints": [
            {
                "kind": c.kind,
                "files": [tree.files[f] for f in c.files],
                "condition": describe(c.condition),
                "unconditional": c.unconditional,
                "text": c.text,
                "formula": formulas.get(number),
                "locations": [loc.to_json() for loc in c.locations],
            }
            for number, c in enumerate(model.constraints)
        ],
        "configurations": count_configurations(model),
        "diagnostics": [diagnostic_document(d) for d in model.diagnostics],
        "core": verdicts[VerdictKind.CORE],
        "dead": verdicts[VerdictKind.DEAD],
        "conflicts": [
            {
                "kind": clash.kind,
                "name": clash.name,
                "files": [tree.file_id(f) for f in clash.files],
                "condition": describe(clash.condition),
                "trigger": trigger(clash.condition),
                "locations": [clash.first.location.to_json(), clash.second.location.to_json()],
            }
            for clash in conflicts(model)
        ],
    }


def write(model: FeatureModel) -> str:
    return json.dumps(document(model), indent=2, ensure_ascii=False) + "\n"
