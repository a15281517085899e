"""``rosvar resolve --json``: one configuration's nodes, tests, parameters, conflicts, errors
and warnings, and its communication graph, one shape for both ROS versions
(``docs/json-schema.md``, ``docs/schema/resolve.schema.json``)."""

from __future__ import annotations

from rosvar.analyses.communication import JSON_SIDES, ResolvedGraph
from rosvar.diagnostics import Diagnostic
from rosvar.interpreter.resolution import Conflict, Resolution, ResolutionError, ResolvedNode


def resolution_document(result: Resolution) -> dict[str, object]:
    document: dict[str, object] = {
        "ok": result.ok,
        "nodes": [node_document(node) for node in result.sorted_nodes()],
        "tests": [node_document(test) for test in sorted(result.tests, key=lambda t: t.name)],
        "params": dict(sorted(result.params.items())),
        "conflicts": [_conflict(conflict) for conflict in result.conflicts],
        "errors": [_finding(error) for error in result.errors],
    }
    if result.warnings:
        document["warnings"] = [_finding(warning) for warning in result.warnings]
    if result.on_events:
        document["on_events"] = [node_document(node) for node in result.on_events]
    return document


def node_document(node: ResolvedNode) -> dict[str, object]:
    """A NODE (or TEST): the fields both ROS versions have, its dialect's own after ``type``
    (a ROS 2 node's parameters after them), a test's at the end."""
    return {
        "name": node.name,
        "namespace": node.namespace,
        "package": node.package,
        "type": node.executable,
        **node.attributes,
        **({} if node.parameters is None else {"parameters": node.parameters}),
        "remaps": [list(pair) for pair in node.remaps],
        "env": [list(pair) for pair in node.env],
        "filename": node.filename,
        "line": node.location.line,
        "col": node.location.col,
        **(node.test or {}),
    }


def graph_document(graph: ResolvedGraph) -> dict[str, object]:
    """``topics``, ``services`` and ``actions``: each resolved name with its types and the
    nodes on each side, sorted."""
    document: dict[str, object] = {}
    for channel, entries in graph.items():
        provided, used = JSON_SIDES[channel]
        document[str(channel)] = [
            {
                "name": entry.name,
                "types": list(entry.types),
                provided: list(entry.providers),
                used: list(entry.users),
            }
            for entry in entries
        ]
    return document


def _conflict(conflict: Conflict) -> dict[str, object]:
    return {
        "kind": conflict.kind,
        "name": conflict.name,
        "locations": [location.to_json() for location in conflict.locations],
    }


def _finding(finding: ResolutionError | Diagnostic) -> dict[str, object]:
    return {"code": finding.code, "message": finding.message, **finding.location.to_json()}
