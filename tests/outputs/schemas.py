"""The JSON schemas of ``docs/schema``, which the documents rosvar writes must satisfy."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

SCHEMAS = Path(__file__).resolve().parents[2] / "docs" / "schema"


def schema_check(document: object, name: str) -> None:
    jsonschema = pytest.importorskip("jsonschema")
    path = SCHEMAS / name
    if not path.is_file():
        pytest.skip(f"no schema {path}")
    jsonschema.validate(document, json.loads(path.read_text()))
