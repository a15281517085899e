"""Findings of ``rosvar check`` as SARIF 2.1.0, the format code-scanning tools read.

A finding's condition and example configuration have no SARIF field of their own: they go
into the message (people read it) and into the result's ``properties`` (tools read those).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from rosvar import __version__
from rosvar.analyses.checks import DESCRIPTIONS, Check, Finding
from rosvar.analyses.fingerprints import VERSION
from rosvar.diagnostics import Location
from rosvar.logic.conditions import ConditionSpace
from rosvar.outputs.documents.findings import finding_document

SCHEMA = (
    "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json"
)


def sarif(
    findings: Sequence[Finding], space: ConditionSpace, fingerprints: Sequence[str] = ()
) -> dict[str, object]:
    """The SARIF log of ``findings``; ``fingerprints`` (one per finding, when given) are
    their ``partialFingerprints``, which code scanning and ``--baseline`` match runs by."""
    rules = list(Check)
    prints: list[str | None] = [*fingerprints] or [None] * len(findings)
    return {
        "$schema": SCHEMA,
        "version": "2.1.0",
        "runs": [
            {
                "tool": {
                    "driver": {
                        "name": "rosvar",
                        "version": __version__,
                        "rules": [
                            {"id": str(rule), "shortDescription": {"text": DESCRIPTIONS[rule]}}
                            for rule in rules
                        ],
                    }
                },
                "results": [
                    _result(f, space, rules.index(f.check), p)
                    for f, p in zip(findings, prints, strict=True)
                ],
            }
        ],
    }


def _result(
    finding: Finding, space: ConditionSpace, rule: int, fingerprint: str | None
) -> dict[str, object]:
    document = finding_document(finding, space)
    primary, *related = finding.locations
    prints = {} if fingerprint is None else {"partialFingerprints": {VERSION: fingerprint}}
    return {
        "ruleId": str(finding.check),
        "ruleIndex": rule,
        "level": finding.severity.value,
        "message": {"text": f"{finding.message} (when {document['condition']})"},
        "locations": [_location(primary)],
        "relatedLocations": [
            {"id": index, **_location(location)} for index, location in enumerate(related)
        ],
        **prints,
        "properties": {
            "launchFile": finding.file,
            "condition": document["condition"],
            "example": document["example"],
        },
    }


def _location(location: Location) -> dict[str, object]:
    file = location.file  # a catalogue entry's is the URL of its source
    uri = file if "://" in file else Path(os.path.abspath(file)).as_uri()
    physical: dict[str, object] = {"artifactLocation": {"uri": uri}}
    if location.line > 0:
        region: dict[str, int] = {"startLine": location.line}
        if location.col > 0:
            region["startColumn"] = location.col
        physical["region"] = region
    return {"physicalLocation": physical}
