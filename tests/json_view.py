"""rosvar's JSON documents as the tests read them.

The package types a document as ``dict[str, object]``: its producers must not rely on what
a value holds. A test does rely on it, and asserts it: the assertions that follow are the
document's type check, so it reads the document as JSON is read, any value in any field.
"""

from __future__ import annotations

from typing import Any


def read(document: object) -> Any:
    """``document`` (a JSON document or one of its values), its fields readable as any value."""
    return document
