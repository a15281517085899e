"""A configuration step as its document: ``rosvar configure --json`` prints it, the web API
answers with it (``docs/configure.md``).

The engine hands out one object per feature and state: its document is made once and then
the same dict, so the web UI's deltas compare an unchanged feature by identity."""

from __future__ import annotations

from weakref import WeakKeyDictionary

from rosvar.configuration.choices import Refusal, UserChoice
from rosvar.configuration.conflicts import ConflictState
from rosvar.configuration.engine import ConfigurationState, FeatureState
from rosvar.configuration.view import Graph
from rosvar.outputs.documents.diagnostics import diagnostic_document

EXACT_INTEGER = 2**53
"""Larger counts of configurations are written as strings (JSON readers lose the digits)."""

_FEATURES: WeakKeyDictionary[FeatureState, dict[str, object]] = WeakKeyDictionary()
"""Each feature state's document, kept while the engine keeps the state."""


def state_document(state: ConfigurationState, graph: Graph | None = None) -> dict[str, object]:
    """``graph``: the state's graph as the document shows it (default: ``state.graph``, its
    conditions described; the web page's overview reads ``state.outline``)."""
    count = state.configurations
    return {
        "features": {k: feature_document(v) for k, v in state.features.items()},
        "conflicts": [conflict_document(c) for c in state.conflicts],
        "graph": graph_document(state.graph if graph is None else graph),
        "complete": state.complete,
        "command": state.command,
        "refused": [refusal_document(r) for r in state.refused],
        "choices": [choice_document(c) for c in state.choices],
        "configurations": count if count <= EXACT_INTEGER else str(count),
        "unselected": state.unselected,
        "launched": [launch.spelled for group in state.commands for launch in group],
        "untyped": state.untyped,
        "launches": state.launches,
        "unknown": [diagnostic_document(d) for d in state.unknown],
    }


def feature_document(feature: FeatureState) -> dict[str, object]:
    document = _FEATURES.get(feature)
    if document is None:
        document = _FEATURES[feature] = {
            "kind": feature.kind,
            "file": feature.file,
            "package": feature.package,
            "arg": feature.arg,
            "value": feature.value,
            "parent": feature.parent,
            "state": feature.state,
            "derived": feature.derived,
        }
        if feature.doc:  # on the few args that have one
            document["doc"] = feature.doc
    return document


def graph_document(graph: Graph) -> dict[str, object]:
    return {
        "nodes": graph.nodes,
        "tests": graph.tests,
        "params": graph.params,
        "topics": graph.topics,
        "services": graph.services,
        "actions": graph.actions,
        "errors": graph.errors,
    }


def conflict_document(conflict: ConflictState) -> dict[str, object]:
    return {
        "files": list(conflict.files),
        "names": list(conflict.names),
        "status": conflict.status,
        "condition": conflict.condition,
    }


def choice_document(choice: UserChoice) -> dict[str, object]:
    return {"action": choice.action, "feature": choice.feature, "value": choice.value}


def refusal_document(refusal: Refusal) -> dict[str, object]:
    return {"choice": choice_document(refusal.choice), "reason": refusal.reason}
