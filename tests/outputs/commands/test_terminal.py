"""How the text outputs spell places for people."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from rosvar.diagnostics import Location
from rosvar.outputs.commands.terminal import shown_location, shown_path


def test_a_path_is_shown_relative_unless_the_absolute_one_is_shorter(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "ws" / "pkg").mkdir(parents=True)
    monkeypatch.chdir(tmp_path / "ws")
    assert shown_path(str(tmp_path / "ws" / "pkg" / "a.launch")) == os.path.join("pkg", "a.launch")
    assert shown_path("/") == "/"


def test_a_place_no_file_holds_is_shown_as_it_is() -> None:
    """A finding's place whose file is not known (a xacro path only known per
    configuration) is no crash of the text output."""
    assert shown_path("") == ""
    assert shown_location(Location("", 0, 0)) == ""
