"""Query results as ``rosvar query --json`` writes them (``docs/schema/query.schema.json``)."""

from __future__ import annotations

from rosvar.analyses.query.evaluator import QueryEngine, Result


def result_document(engine: QueryEngine, result: Result) -> dict[str, object]:
    """``result`` with its condition described and an example configuration selecting it."""
    element, condition = result.element, result.condition
    location = element.location
    return {
        "kind": str(element.kind),
        "name": element.name,
        "launch_file": element.file,
        "condition": engine.space.describe(condition),
        "example": dict(engine.example(condition)),
        **({"file": location.file, "line": location.line} if location is not None else {}),
    }
