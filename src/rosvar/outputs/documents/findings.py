"""The checks' findings as ``rosvar check --format json`` and the web UI's checks write them:
each condition described, with an example configuration that triggers it."""

from __future__ import annotations

from collections.abc import Iterable

from rosvar.analyses.checks import Finding
from rosvar.analyses.communication import Uninterfaced
from rosvar.analyses.feature_model.operations import simplest_trigger
from rosvar.logic.conditions import ConditionSpace


def finding_document(finding: Finding, space: ConditionSpace) -> dict[str, object]:
    return {
        "check": str(finding.check),
        "severity": finding.severity.value,
        "name": finding.name,
        "message": finding.message,
        "file": finding.file,
        "condition": space.describe(finding.condition),
        "example": simplest_trigger(space, finding.condition, witnesses=True),
        "locations": [location.to_json() for location in finding.locations],
    }


def uninterfaced_documents(nodes: Iterable[Uninterfaced]) -> list[dict[str, object]]:
    """The nodes without a known interface, as ``check`` and ``query`` list them in JSON."""
    return [{"names": list(u.names), "executable": u.unit, **u.location.to_json()} for u in nodes]
