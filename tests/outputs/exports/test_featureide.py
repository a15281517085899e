"""FeatureIDE XML export: valid against ``featureide.xsd`` (FeatureIDE's structure, with
flamapy's stricter needs) and read back by flamapy's FeatureIDEReader with the same features,
constraints and configurations."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any
from xml.etree import ElementTree

import pytest

from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.operations import count_configurations
from rosvar.outputs.exports import featureide
from rosvar.outputs.exports._common import Tree

from .test_uvl import tricky

if TYPE_CHECKING:
    from conftest import LaunchWorkspace  # tests/conftest.py

    from .conftest import Flamapy

SCHEMA = Path(__file__).with_name("featureide.xsd")


@pytest.fixture(scope="module")
def schema() -> Any:
    etree = pytest.importorskip("lxml.etree", reason="lxml is a test extra")
    return etree.XMLSchema(etree.parse(str(SCHEMA)))


def validate(schema: Any, text: str) -> None:
    from lxml import etree

    document = etree.fromstring(text.encode("utf-8"))
    assert schema.validate(document), schema.error_log


def check(model: FeatureModel, flamapy: Flamapy, schema: Any) -> None:
    text = featureide.write(model)
    validate(schema, text)
    tree = Tree(model)
    read = flamapy.featureide(text)
    names = tree.names()
    assert read.root.name == names[tree.root]
    assert sorted(flamapy.names(read)) == sorted(names.values())
    true = model.solver.manager.true
    assert len(read.get_constraints()) == sum(1 for c in model.solver.constraints if c != true)
    assert flamapy.count(read) == count_configurations(model)


def test_corpus(model: FeatureModel, flamapy: Flamapy, schema: Any) -> None:
    check(model, flamapy, schema)


def test_tricky_names(ws: LaunchWorkspace, flamapy: Flamapy, schema: Any) -> None:
    model = tricky(ws)
    check(model, flamapy, schema)
    text = featureide.write(model)
    assert 'name="pkg/launch/main.launch:label=say &quot;hi&quot;"' in text
    assert 'name="pkg/launch/main.launch:pct=50%25"' in text  # % is the escape character


def test_examples_structure(examples_model: FeatureModel, flamapy: Flamapy) -> None:
    root = ElementTree.fromstring(featureide.write(examples_model))
    struct = root.find("struct")
    assert struct is not None
    (top,) = list(struct)
    assert (top.tag, top.get("name"), top.get("abstract")) == ("and", "examples", "true")
    files = {f.get("name"): f for f in top}
    assert files["example/launch/teleop_only.launch"].tag == "feature"
    control = files["example/launch/control.xml"]
    assert control.tag == "and" and control.get("mandatory") is None  # files are optional
    arg = control[0]
    assert (arg.tag, arg.get("mandatory"), arg.get("abstract")) == ("alt", "true", "true")
    assert [v.get("name") for v in arg] == [
        "example/launch/control.xml:use_teleop=true",
        "example/launch/control.xml:use_teleop=false",
        "example/launch/control.xml:use_teleop=<other>",
    ]
    rules = root.findall("constraints/rule")
    assert [ElementTree.tostring(r[0], encoding="unicode").split() for r in rules][2] == [
        "<not>",
        "<conj>",
        "<var>example/launch/control.xml</var>",
        "<var>example/launch/teleop_only.launch</var>",
        "</conj>",
        "</not>",
    ]
    read = flamapy.featureide(featureide.write(examples_model))
    assert flamapy.brute_force_count(read) == 798


def test_long_conjunctions_are_binary(ws: LaunchWorkspace, flamapy: Flamapy, schema: Any) -> None:
    """An include under three conditions: flamapy would drop a third conj operand."""
    ws.launch(
        "main.launch",
        """
  <arg name="a" default="true"/>
  <arg name="b" default="true"/>
  <arg name="c" default="true"/>
  <node pkg="pkg" type="t" name="n_$(arg a)_$(arg b)_$(arg c)"/>
  <group if="$(arg a)"><group if="$(arg b)">
    <include file="$(find pkg)/launch/inc.launch" if="$(arg c)"/>
  </group></group>
""",
    )
    ws.launch("inc.launch", '  <node pkg="pkg" type="t" name="inc"/>')
    model = extract(ws.analysis())
    text = featureide.write(model)
    assert text.count("<conj>") >= 2
    check(model, flamapy, schema)


def test_comments_never_break_xml(ws: LaunchWorkspace, flamapy: Flamapy, schema: Any) -> None:
    """Constraint reasons name ROS names; ``--`` may not appear inside an XML comment."""
    for name in ("a--b.launch", "c.launch"):
        ws.launch(name, '  <node pkg="pkg" type="t" name="x--y"/>')
    model = extract(ws.analysis())
    assert any("--" in c.text for c in model.constraints)
    check(model, flamapy, schema)
