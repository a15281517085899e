"""The app's files: everything the page loads is served, vendored libraries carry licences."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rosvar.outputs.web.assets import ASSET_PREFIX, STATIC, load_assets


def test_page_references_only_served_assets() -> None:
    table = load_assets()
    page = table["/"].body.decode()
    referenced = re.findall(r'(?:src|href)="([^"]+)"', page)
    assert referenced, "the page loads its scripts and style"
    assert [url for url in referenced if url not in table] == []
    modules = [url for url in table if url.startswith(f"{ASSET_PREFIX}js/")]
    for url in modules:  # ES module imports resolve to served files too
        for name in re.findall(r'from "\./([^"]+)"', table[url].body.decode()):
            assert f"{ASSET_PREFIX}js/{name}" in table, f"{url} imports {name}"


def test_vendored_libraries_have_their_licences() -> None:
    vendor = STATIC / "vendor"
    libraries = sorted(vendor.glob("*.js"))
    assert libraries
    readme = (vendor / "README.md").read_text()
    for library in libraries:
        assert library.name in readme, f"{library.name} is not listed in vendor/README.md"
    for licence in re.findall(r"`([\w.-]+\.LICENSE)`", readme):
        assert "Permission is hereby granted" in (vendor / licence).read_text()


def test_only_known_kinds_of_file_are_served(tmp_path: Path) -> None:
    (tmp_path / "index.html").write_text("<html></html>")
    (tmp_path / "app.js").write_text("")
    (tmp_path / "notes.py").write_text("secret = 1")
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "deep.css").write_text("")
    table = load_assets(tmp_path)
    assert sorted(table) == ["/", "/assets/app.js", "/assets/sub/deep.css"]
    assert table["/"].content_type.startswith("text/html")


def test_package_data_ships_every_asset() -> None:
    """An installed rosvar serves the same app: pyproject's package-data covers static/."""
    tomllib = pytest.importorskip("tomllib")
    pyproject = tomllib.loads((Path(__file__).resolve().parents[3] / "pyproject.toml").read_text())
    patterns = pyproject["tool"]["setuptools"]["package-data"]["rosvar.outputs.web"]
    package = STATIC.parent
    shipped = {p for pattern in patterns for p in package.glob(pattern) if p.is_file()}
    served = {STATIC / url.removeprefix(ASSET_PREFIX) for url in load_assets() if url != "/"}
    assert served | {STATIC / "index.html"} <= shipped
