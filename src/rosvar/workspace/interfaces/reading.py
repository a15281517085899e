"""Reading source files for extraction: the one place that opens them.

Sources are read whole and decoded leniently (a stray byte in a comment must not hide a
node's interface); a file beyond :data:`MAX_SOURCE_BYTES` is skipped, since no hand-written
node is that large and a generated or vendored blob is not worth parsing.
"""

from __future__ import annotations

import os

MAX_SOURCE_BYTES = 4 * 1024 * 1024


def read_source(path: str) -> bytes | None:
    """The bytes of ``path``; None when it cannot be read or is too large."""
    try:
        if os.path.getsize(path) > MAX_SOURCE_BYTES:
            return None
        with open(path, "rb") as handle:
            return handle.read()
    except OSError:
        return None


def read_text(path: str) -> str | None:
    data = read_source(path)
    return None if data is None else data.decode("utf-8", errors="replace")
