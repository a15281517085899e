"""Query results as ``rosvar query --json`` writes them (``docs/schema/query.schema.json``)."""

from __future__ import annotations

from rosvar.analyses.query.collections import ElementSet, Kind
from rosvar.analyses.query.evaluator import QueryEngine, Result

USERS = ("publishers", "subscribers", "servers", "clients")
"""The attributes of topics, services and actions that list the nodes using them."""
CHANNELS = (Kind.TOPIC, Kind.SERVICE, Kind.ACTION)


def result_document(engine: QueryEngine, result: Result) -> dict[str, object]:
    """``result`` with its condition described and an example configuration selecting it;
    a topic's (service's, action's) nodes on each side, with the conditions under which
    they use it where the result holds."""
    element, condition = result.element, result.condition
    location = element.location
    return {
        "kind": str(element.kind),
        "name": element.name,
        "launch_file": element.file,
        "condition": engine.space.describe(condition),
        "example": dict(engine.example(condition)),
        **({"file": location.file, "line": location.line} if location is not None else {}),
        **_users(engine, result),
    }


def _users(engine: QueryEngine, result: Result) -> dict[str, object]:
    found: dict[str, object] = {}
    element = result.element
    if element.kind not in CHANNELS:
        return found
    for side in USERS:
        try:
            value = element.attribute(side)
        except KeyError:  # services and actions have servers and clients
            continue
        nodes = []
        for _condition, members in value:
            if not isinstance(members, ElementSet):
                continue
            for used, node in members:
                both = used & result.condition
                if engine.satisfiable(both):
                    nodes.append({"node": node.name, "condition": engine.space.describe(both)})
        found[side] = nodes
    return found
