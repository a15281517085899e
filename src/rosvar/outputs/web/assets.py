"""The single-page app's files, read once from package data.

The servable set is fixed when the server starts: a request path is only ever looked up in
this table, never joined onto a directory, so no request can reach another file.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

STATIC = Path(__file__).resolve().parent / "static"
INDEX = "index.html"
ASSET_PREFIX = "/assets/"

CONTENT_TYPES = {
    ".html": "text/html; charset=utf-8",
    ".js": "text/javascript; charset=utf-8",
    ".css": "text/css; charset=utf-8",
    ".svg": "image/svg+xml",
    ".md": "text/plain; charset=utf-8",
    ".LICENSE": "text/plain; charset=utf-8",
}
"""Only files with these suffixes are served; anything else in the directory stays private."""


@dataclass(frozen=True)
class Asset:
    body: bytes
    content_type: str


def load_assets(static: Path = STATIC) -> dict[str, Asset]:
    """URL path → asset: ``/`` is the app's page, ``/assets/<relative path>`` the rest."""
    table: dict[str, Asset] = {}
    for path in sorted(static.rglob("*")):
        content_type = CONTENT_TYPES.get(path.suffix)
        if content_type is None or not path.is_file():
            continue
        name = path.relative_to(static).as_posix()
        url = "/" if name == INDEX else f"{ASSET_PREFIX}{name}"
        table[url] = Asset(path.read_bytes(), content_type)
    return table
