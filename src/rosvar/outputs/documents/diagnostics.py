"""Diagnostics as every document writes them (a location's fields beside the message)."""

from __future__ import annotations

from rosvar.diagnostics import Diagnostic


def diagnostic_document(diagnostic: Diagnostic) -> dict[str, object]:
    return {
        "code": diagnostic.code,
        "severity": diagnostic.severity.value,
        "message": diagnostic.message,
        **diagnostic.location.to_json(),
    }
