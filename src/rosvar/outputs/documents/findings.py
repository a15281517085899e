"""The checks' findings as ``rosvar check --format json`` and the web UI's checks write them:
each condition described, with an example configuration that triggers it."""

from __future__ import annotations

from rosvar.analyses.checks import Finding
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
        "example": simplest_trigger(space, finding.condition),
        "locations": [location.to_json() for location in finding.locations],
    }
