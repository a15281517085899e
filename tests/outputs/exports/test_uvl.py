"""UVL export: flamapy's UVLReader reads it back with the same features, names and constraints,
and the configurations of what it read are those of rosvar's solver."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING
from urllib.parse import unquote

from hypothesis import given
from hypothesis import strategies as st

from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.operations import count_configurations
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.exports import uvl
from rosvar.outputs.exports._common import Tree, escape
from rosvar.workspace import discover

if TYPE_CHECKING:
    from conftest import LaunchWorkspace  # tests/conftest.py

    from .conftest import Flamapy

MAIN = """
  <arg name="mode" default="a.b"/>
  <arg name="label" default='say "hi"'/>
  <arg name="pct" default="50%"/>
  <arg name="use_x" default="true"/>
  <node pkg="pkg" type="t" name="n_$(arg mode)"/>
  <node pkg="pkg" type="t" name="m" if="$(eval mode == 'x%2Ey')"/>
  <node pkg="pkg" type="t" name="k" if="$(eval mode == 'x.y')"/>
  <param name="p" value="$(arg label)"/>
  <param name="q" value="$(arg pct)"/>
  <include file="$(find pkg)/launch/other.launch" if="$(arg use_x)"/>
"""
OTHER = '  <node pkg="pkg" type="t" name="shared"/>'
CLASH = """
  <arg name="on" default="false"/>
  <node pkg="pkg" type="t" name="shared" if="$(arg on)"/>
"""


def tricky(ws: LaunchWorkspace) -> FeatureModel:
    """Values with ``.``, ``"``, ``%`` (and one that looks escaped), a conditional include and
    a conditional clash."""
    ws.launch("main.launch", MAIN)
    ws.launch("other.launch", OTHER)
    ws.launch("clash.launch", CLASH)
    return extract(ws.analysis())


def check_round_trip(model: FeatureModel, flamapy: Flamapy) -> None:
    tree = Tree(model)
    read = flamapy.uvl(uvl.write(model))
    names = flamapy.names(read)
    expected = tree.names(uvl.RESERVED)
    assert len(names) == len(model.feature_ids()) + 1
    assert sorted(names) == sorted(expected.values())
    assert read.root.name == expected[tree.root]
    assert {unquote(n) for n in names} == {tree.root, *model.feature_ids()}
    true = model.solver.manager.true
    assert len(read.get_constraints()) == sum(1 for c in model.solver.constraints if c != true)
    assert flamapy.count(read) == count_configurations(model)


def test_corpus_round_trip(model: FeatureModel, flamapy: Flamapy) -> None:
    check_round_trip(model, flamapy)


def test_examples_count_by_enumeration(examples_model: FeatureModel, flamapy: Flamapy) -> None:
    read = flamapy.uvl(uvl.write(examples_model))
    # control.xml selected: 6 · 10 · 13 = 780; not: robot out, mapping out or sim≠false
    # (1 + 2 · 2 · 2 = 9), teleop_only free (2): 18. Together 798.
    assert flamapy.brute_force_count(read) == count_configurations(examples_model) == 798


def test_tricky_names_round_trip(ws: LaunchWorkspace, flamapy: Flamapy) -> None:
    model = tricky(ws)
    check_round_trip(model, flamapy)
    text = uvl.write(model)
    assert '"pkg/launch/main%2Elaunch:mode=x%2Ey"' in text  # the value x.y
    assert '"pkg/launch/main%2Elaunch:mode=x%252Ey"' in text  # the value x%2Ey
    assert '"pkg/launch/main%2Elaunch:label=say %22hi%22" {default}' in text
    assert '"pkg/launch/main%2Elaunch:use_x=true" => "pkg/launch/other%2Elaunch"' in text
    assert '!("pkg/launch/clash%2Elaunch:on=true" & "pkg/launch/other%2Elaunch")' in text


def test_examples_text(examples_model: FeatureModel) -> None:
    text = uvl.write(examples_model)
    lines = text.splitlines()
    assert lines[2:4] == ["features", '\t"examples" {abstract}']
    assert '\t\t\t"example/launch/teleop_only%2Elaunch"' in lines
    assert '\t\t\t\t\t"example/launch/control%2Exml:use_teleop" {abstract}' in lines
    assert '\t\t\t\t\t\t\t"example/launch/control%2Exml:use_teleop=true" {default}' in lines
    constraints = lines[lines.index("constraints") + 1 :]
    formulas = [line.strip() for line in constraints if not line.strip().startswith("//")]
    assert formulas == [
        '"example/launch/mapping%2Elaunch:sim=false" => "example/launch/control%2Exml"',
        '"example/launch/robot%2Elaunch" => "example/launch/control%2Exml"',
        '!("example/launch/control%2Exml" & "example/launch/teleop_only%2Elaunch")',
    ]


def test_root_named_like_a_file(tmp_path: Path, flamapy: Flamapy) -> None:
    """A package folder ``x.launch`` holding ``x.launch``: the root's name equals a file id."""
    package = tmp_path / "x.launch"
    package.mkdir()
    (package / "package.xml").write_text("<package><name>pkg</name></package>")
    (package / "x.launch").write_text(
        '<launch><arg name="a" default="1"/><node pkg="pkg" type="t" name="n_$(arg a)"/></launch>'
    )
    model = extract(Analysis(discover([str(package)], ros_package_path="")))
    tree = Tree(model)
    assert tree.entries[0].id == "x.launch"
    assert tree.root == "x.launch%~2"
    read = flamapy.uvl(uvl.write(model))
    assert read.root.name == "x%2Elaunch%25~2"  # the unique id, escaped
    assert len(set(flamapy.names(read))) == len(model.feature_ids()) + 1
    assert flamapy.count(read) == count_configurations(model) == 3


def test_same_relative_path_in_two_roots(tmp_path: Path, flamapy: Flamapy) -> None:
    """Two roots holding the same relative path: the later file is named by its full path."""
    for root in ("one", "two"):
        launch = tmp_path / root / "pkg" / "launch"
        launch.mkdir(parents=True)
        (tmp_path / root / "pkg" / "package.xml").write_text("<package><name>pkg</name></package>")
        (launch / "x.launch").write_text(
            '<launch><arg name="a" default="1"/><node pkg="pkg" type="t" name="n_$(arg a)"/>'
            "</launch>"
        )
    workspace = discover([str(tmp_path / "one"), str(tmp_path / "two")], ros_package_path="")
    model = extract(Analysis(workspace))
    later = str(tmp_path / "two" / "pkg" / "launch" / "x.launch")
    assert [f.id for f in model.files] == ["pkg/launch/x.launch", later]
    ids = model.feature_ids()
    assert len(set(ids)) == len(ids)
    read = flamapy.uvl(uvl.write(model))
    assert len(set(flamapy.names(read))) == len(ids) + 1
    # each file off, or on with a=1 or another a (3 × 3), but not both on with a=1: /n_1 twice
    assert flamapy.count(read) == count_configurations(model) == 8


@given(st.text(max_size=12), st.text(max_size=12))
def test_escape_is_injective_and_reversible(a: str, b: str) -> None:
    assert unquote(escape(a, uvl.RESERVED)) == a
    assert (escape(a, uvl.RESERVED) == escape(b, uvl.RESERVED)) == (a == b)
    assert not set(escape(a, uvl.RESERVED)) & set(uvl.RESERVED + "\n\r")
