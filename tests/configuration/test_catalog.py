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


@pytest.mark.parametrize(
    ("text", "near"),
    [
        ("control.launch", ["pkg/launch/control.xml"]),  # issue 30.6: "no feature", no hint
        ("robot.launch", ["pkg/launch/robot.launch", "other/launch/robot.launch"]),
        ("control.launch:use_teleop=true", ["pkg/launch/control.xml:use_teleop=true"]),
        ("pkg/launch/control.xml:use_telop", ["pkg/launch/control.xml:use_teleop"]),
        ("robto.launch", ["pkg/launch/robot.launch", "other/launch/robot.launch"]),
    ],
)
def test_a_file_named_as_people_name_it_is_suggested(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch, text: str, near: list[str]
) -> None:
    ws.launch(
        "control.xml",
        '  <arg name="use_teleop" default="true"/>\n'
        '  <node pkg="p" type="t" name="n" if="$(arg use_teleop)"/>',
    )
    ws.launch("robot.launch", '  <node pkg="p" type="t" name="r"/>')
    ws.launch("robot.launch", '  <node pkg="p" type="t" name="s"/>', package="other")
    monkeypatch.chdir(ws.root)
    catalog = Catalog(extract(ws.analysis()))
    with pytest.raises(ChoiceError) as refused:
        catalog.lookup(text)
    said = str(refused.value).partition("did you mean ")[2].rstrip("?").split(" or ")
    assert {f"'{n}'" for n in near} <= set(said) and len(said) <= 3
