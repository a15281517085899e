"""``<node>`` and ``<test>``: presence conditions, fields as conditional values, name conflicts."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest

from json_view import read
from rosvar.interpreter.model import LaunchModel, NodeDecl
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.outputs.documents.resolution import resolution_document

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

FIG1 = """
  <arg name="use_teleop" default="true"/>
  <node pkg="pkg" type="teleop_node" name="teleop" if="$(arg use_teleop)"/>
  <node pkg="pkg" type="planner_node" name="planner" unless="$(arg use_teleop)"/>
"""


def by_name(model: LaunchModel) -> dict[str, list[NodeDecl]]:
    result: dict[str, list[NodeDecl]] = {}
    for node in model.nodes:
        name = node.fields["name"].single()
        result.setdefault(str(name), []).append(node)
    return result


def condition_of(model: LaunchModel, name: str) -> BDD:
    [node] = by_name(model)[name]
    return node.condition


def test_fig1_presence_conditions_partition_the_loading_configurations(ws: LaunchWorkspace) -> None:
    model = ws.model(ws.launch("fig1.launch", FIG1))
    space = model.space
    teleop, planner = condition_of(model, "teleop"), condition_of(model, "planner")
    # both nodes are in the model: the default does not fix the arg
    assert teleop != space.false and planner != space.false
    assert (teleop & planner & space.valid) == space.false  # mutually exclusive
    loads = space.valid & model.loads
    assert (loads & ~(teleop | planner)) == space.false  # one of them whenever the file loads
    assert space.satisfiable(teleop & loads) and space.satisfiable(planner & loads)
    assert space.describe(teleop) == "use_teleop"
    # configurations with a non-boolean value (e.g. use_teleop:=maybe) are the ones that fail
    assert not space.valid_implies(model.loads)


def test_fig1_restrictions(ws: LaunchWorkspace) -> None:
    file = ws.launch("fig1.launch", FIG1)

    def names(args: dict[str, str]) -> list[object]:
        resolution = ws.resolve(file, args)
        assert resolution.ok, resolution.errors
        return [n.name for n in resolution.nodes]

    assert names({}) == ["/teleop"]
    assert names({"use_teleop": "true"}) == ["/teleop"]
    assert names({"use_teleop": "false"}) == ["/planner"]  # unless is not inverted
    assert names({"use_teleop": "1"}) == ["/teleop"]  # <other> value decided by predicate
    assert names({"use_teleop": "0"}) == ["/planner"]
    assert names({"use_teleop": "TRUE"}) == ["/teleop"]
    failed = ws.resolve(file, {"use_teleop": "maybe"})
    assert not failed.ok and failed.errors[0].code == "bool-invalid"


def test_fig1_unless_branch_reads_as_negation(ws: LaunchWorkspace) -> None:
    model = ws.model(ws.launch("fig1.launch", FIG1))
    assert model.space.describe(condition_of(model, "planner")) == "¬use_teleop"


@pytest.mark.oracle
def test_fig1_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("fig1.launch", FIG1)
    ws.assert_agrees(
        file, [{}, {"use_teleop": "false"}, {"use_teleop": "0"}, {"use_teleop": "maybe"}]
    )


SAME_NAME = """
  <arg name="sim" default="false"/>
  <node pkg="pkg" type="sim_controller" name="controller" if="$(arg sim)"/>
  <node pkg="pkg" type="real_controller" name="controller" unless="$(arg sim)"/>
"""


def test_same_named_nodes_stay_two_declarations(ws: LaunchWorkspace) -> None:
    file = ws.launch("same.launch", SAME_NAME)
    model = ws.model(file)
    nodes = by_name(model)["controller"]
    assert len(nodes) == 2
    types = sorted(str(n.fields["type"].single()) for n in nodes)
    assert types == ["real_controller", "sim_controller"]
    c1, c2 = (n.condition for n in nodes)
    assert (c1 & c2 & model.space.valid) == model.space.false
    for args in ({}, {"sim": "true"}, {"sim": "false"}):
        resolution = ws.resolve(file, args)
        assert resolution.ok and resolution.conflicts == []
        assert [n.name for n in resolution.nodes] == ["/controller"]
    assert ws.resolve(file, {"sim": "true"}).nodes[0].executable == "sim_controller"


DUPLICATE_SOMETIMES = """
  <arg name="two_drivers" default="false"/>
  <node pkg="pkg" type="driver" name="driver"/>
  <node pkg="pkg" type="driver" name="driver" if="$(arg two_drivers)"/>
"""


def test_duplicate_names_conflict_only_where_both_are_present(ws: LaunchWorkspace) -> None:
    file = ws.launch("dup.launch", DUPLICATE_SOMETIMES)
    model = ws.model(file)
    first, second = by_name(model)["driver"]
    both = first.condition & second.condition
    assert model.space.describe(both) == "two_drivers"

    fine = ws.resolve(file, {})
    assert fine.ok and fine.conflicts == []
    clash = ws.resolve(file, {"two_drivers": "true"})
    assert not clash.ok
    [conflict] = clash.conflicts
    assert conflict.kind == "node-name" and conflict.name == "/driver"
    assert [loc.line for loc in conflict.locations] == [4, 5]  # <launch>, blank line, <arg>
    assert {loc.file for loc in conflict.locations} == {file}
    document = read(resolution_document(clash))
    assert document["ok"] is False and document["conflicts"][0]["name"] == "/driver"


@pytest.mark.oracle
def test_duplicate_names_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("dup.launch", DUPLICATE_SOMETIMES)
    results = ws.assert_agrees(file, [{}, {"two_drivers": "true"}])
    assert results[0]["ok"] and not results[1]["ok"]
    assert "multiple nodes named" in results[1]["error"]


FIELDS = """
  <arg name="robot" default="r1"/>
  <arg name="verbose" default="false"/>
  <group ns="$(arg robot)">
    <node pkg="pkg" type="driver" name="driver_$(arg robot)" args="--robot $(arg robot)"
          output="screen" respawn="$(arg verbose)" required="false" cwd="node">
      <param name="rate" value="10"/>
      <remap from="cmd" to="/$(arg robot)/cmd_vel"/>
      <env name="ROBOT" value="$(arg robot)"/>
    </node>
  </group>
  <test pkg="pkg" type="check" test-name="check_$(arg robot)" time-limit="12" retry="2"/>
"""


def test_node_fields_are_conditional_values(ws: LaunchWorkspace) -> None:
    file = ws.launch("fields.launch", FIELDS)
    model = ws.model(file)
    [node] = [n for n in model.nodes if not n.is_test]
    [test] = [n for n in model.nodes if n.is_test]
    names: Choice[object] = node.fields["name"]
    assert "driver_r1" in names.values() and len(names) == 2  # r1 and an <other> term
    r1 = names.where(lambda v: v == "driver_r1")
    assert model.space.describe(r1, known_only=False) == "robot=r1"
    assert node.fields["namespace"].where(lambda v: v == "/r1/") != model.space.false
    assert test.fields["test-name"].where(lambda v: v == "check_r1") != model.space.false

    resolution = ws.resolve(file, {"robot": "r2", "verbose": "true"})
    assert resolution.ok, resolution.errors
    [entry] = resolution.nodes
    assert entry.name == "/r2/driver_r2"
    assert entry.namespace == "/r2/"
    assert entry.args == "--robot r2"
    assert entry.attributes["respawn"] is True and entry.attributes["required"] is False
    assert entry.remaps == [("cmd", "/r2/cmd_vel")]
    assert entry.env == [("ROBOT", "r2")]
    assert resolution.params == {"/r2/driver_r2/rate": 10}
    [test_entry] = resolution.tests
    assert test_entry.test is not None and test_entry.test["test_name"] == "check_r2"
    assert (test_entry.test["time_limit"], test_entry.test["retry"]) == (12.0, 2)


@pytest.mark.oracle
def test_node_fields_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("fields.launch", FIELDS)
    ws.assert_agrees(
        file,
        [{}, {"robot": "r2", "verbose": "true"}, {"verbose": "yes"}, {"robot": "a/b"}],
    )


INVALID_SOMETIMES = """
  <arg name="out" default="screen"/>
  <node pkg="pkg" type="t" name="n" output="$(arg out)"/>
  <node pkg="pkg" type="t" name="m" respawn="true" required="$(arg out)"/>
"""


def test_invalid_field_values_fail_only_in_their_configurations(ws: LaunchWorkspace) -> None:
    file = ws.launch("invalid.launch", INVALID_SOMETIMES)
    model = ws.model(file)
    assert model.errors, "an output value outside log/screen must be an error somewhere"
    assert all(e.code == "node-invalid" for e in model.errors)
    assert model.space.satisfiable(model.loads)
    # out:=screen loads (required="screen" is not a bool... so it fails); out:=log too
    assert not ws.resolve(file, {}).ok
    assert not ws.resolve(file, {"out": "true"}).ok  # respawn and required both true
    assert not ws.resolve(file, {"out": "log"}).ok  # required="log" is not a bool


@pytest.mark.oracle
def test_invalid_field_values_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("invalid.launch", INVALID_SOMETIMES)
    ws.assert_agrees(file, [{}, {"out": "log"}, {"out": "true"}, {"out": "false"}])


def test_missing_required_attribute_is_an_error_event(ws: LaunchWorkspace) -> None:
    file = ws.launch("missing.launch", '  <node pkg="pkg" name="n"/>')
    model = ws.model(file)
    [error] = model.errors
    assert error.code == "attribute-missing" and "'type'" in error.message
    assert (error.location.line, error.location.col) == (2, 3)
    assert model.loads == model.space.false


ANON = """
  <node pkg="pkg" type="t" name="$(anon talker)"/>
  <node pkg="pkg" type="t" name="$(anon listener)"/>
  <group>
    <node pkg="pkg" type="t" name="$(anon talker)" ns="other"/>
  </group>
"""


@pytest.mark.oracle
def test_anonymous_names_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("anon.launch", ANON)
    [result] = ws.assert_agrees(file, [{}])
    assert len(result["nodes"]) == 3
