"""Feature ids spelled as the user gives the files; any spelling of a file finds it."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

import pytest

from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.catalog import Catalog
from rosvar.configuration.choices import ChoiceError

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def test_ids_follow_the_spelling_and_the_tree(ws: LaunchWorkspace) -> None:
    path = ws.launch(
        "a.launch", '  <arg name="x" default="1"/>\n  <node pkg="p" type="t" name="n$(arg x)"/>'
    )
    catalog = Catalog(extract(ws.analysis()), {os.path.realpath(path): "A"})
    assert [f.id for f in catalog] == ["A", "A:x", "A:x=1", "A:x=<other>"]
    assert [(f.kind, f.parent) for f in catalog] == [
        ("file", None), ("arg", "A"), ("value", "A:x"), ("value", "A:x")
    ]  # fmt: skip
    assert catalog.lookup(f"{path}:x=1").id == "A:x=1"  # the file by another spelling
    assert catalog.lookup("A:x").variable == catalog.lookup("A").variable
    with pytest.raises(ChoiceError):
        catalog.lookup("A:y")


def test_default_spelling_is_relative_to_the_current_directory(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    ws.launch("a.launch", '  <node pkg="p" type="t" name="n"/>')
    monkeypatch.chdir(ws.root)
    assert [f.id for f in Catalog(extract(ws.analysis()))] == ["pkg/launch/a.launch"]


def test_a_file_by_its_feature_model_id_or_any_path_and_near_misses_suggested(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch, tmp_path_factory: pytest.TempPathFactory
) -> None:
    """``rosvar features`` prints ids from the workspace root; the user's shell is elsewhere."""
    path = ws.launch(
        "a.launch", '  <arg name="x" default="1"/>\n  <node pkg="p" type="t" name="n$(arg x)"/>'
    )
    model = extract(ws.analysis())
    monkeypatch.chdir(tmp_path_factory.mktemp("elsewhere"))
    catalog = Catalog(model)
    [file] = model.files
    spelled = catalog.lookup(path).id
    for text in (file.id, path, os.path.relpath(path)):
        assert catalog.lookup(f"{text}:x=1").id == f"{spelled}:x=1"
    with pytest.raises(ChoiceError, match=r"did you mean '.*a\.launch:x'"):
        catalog.lookup(f"{spelled}:y")
