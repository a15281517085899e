"""Frontends chosen by file suffix."""

from __future__ import annotations

from pathlib import Path

import pytest

from rosvar.ros2.frontends.registry import frontend, load


def test_xml_files_load_through_the_xml_frontend(tmp_path: Path) -> None:
    file = tmp_path / "a.launch.xml"
    file.write_text('<launch><node pkg="p" exec="e"/></launch>')
    root = load(file).root
    assert root is not None and [c.tag for c in root.children] == ["node"]


def test_a_suffix_takes_one_frontend() -> None:
    with pytest.raises(ValueError, match="two frontends"):
        frontend(".xml")(load)
