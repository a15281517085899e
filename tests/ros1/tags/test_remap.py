"""``<remap>``: scoped renamings, later ones hiding earlier ones, under conditions."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest

if TYPE_CHECKING:
    from conftest import LaunchWorkspace
    from rosvar.logic.bdd import BDD

REMAPS = """
  <arg name="sim" default="false"/>
  <arg name="scan" default="scan"/>
  <remap from="cmd_vel" to="/mux/cmd_vel"/>
  <remap from="cmd_vel" to="/sim/cmd_vel" if="$(arg sim)"/>
  <group ns="g">
    <remap from="odom" to="/odometry//filtered/"/>
    <node pkg="pkg" type="t" name="inner">
      <remap from="scan" to="$(arg scan)"/>
      <remap from="odom" to="odom_raw" unless="$(arg sim)"/>
    </node>
  </group>
  <node pkg="pkg" type="t" name="outer"/>
"""


def test_remaps_carry_conditions(ws: LaunchWorkspace) -> None:
    file = ws.launch("remaps.launch", REMAPS)
    model = ws.model(file)
    space = model.space
    nodes = {str(n.fields["name"].single()): n for n in model.nodes}
    given = model.inputs["sim"]

    def holds_when(condition: BDD) -> set[str]:
        return {
            value
            for value in ("true", "false", "1", "0")
            if space.evaluate(condition, space.assignment({given: value}))
        }

    inner = {(r.source, r.target): holds_when(r.condition) for r in nodes["inner"].remaps}
    assert inner[("cmd_vel", "/mux/cmd_vel")] == {"false", "0"}
    assert inner[("cmd_vel", "/sim/cmd_vel")] == {"true", "1"}
    # canonicalized, and hidden by the node's own remap unless sim
    assert inner[("odom", "/odometry/filtered")] == {"true", "1"}
    assert inner[("odom", "odom_raw")] == {"false", "0"}
    outer = {(r.source, r.target) for r in nodes["outer"].remaps}
    assert outer == {("cmd_vel", "/mux/cmd_vel"), ("cmd_vel", "/sim/cmd_vel")}


def test_remaps_per_configuration(ws: LaunchWorkspace) -> None:
    file = ws.launch("remaps.launch", REMAPS)
    nodes = {n.name: n for n in ws.resolve(file, {"sim": "true", "scan": "/base_scan"}).nodes}
    assert nodes["/g/inner"].remaps == [
        ("cmd_vel", "/sim/cmd_vel"),
        ("odom", "/odometry/filtered"),
        ("scan", "/base_scan"),
    ]
    assert nodes["/outer"].remaps == [("cmd_vel", "/sim/cmd_vel")]


@pytest.mark.oracle
def test_remaps_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("remaps.launch", REMAPS)
    ws.assert_agrees(
        file,
        [{}, {"sim": "true"}, {"sim": "1"}, {"scan": "/base_scan"}, {"scan": "1bad"}],
        modes=["fresh"],
    )
    ws.assert_agrees(file, [{}, {"sim": "true"}, {"sim": "1"}, {"scan": "/base_scan"}])


def test_illegal_remap_from_other_value_fails(ws: LaunchWorkspace) -> None:
    file = ws.launch("remaps.launch", REMAPS)
    assert not ws.resolve_fresh(file, {"scan": "1bad"}).ok  # a known slot: checked
    resolution = ws.resolve(file, {"scan": "1bad"})
    assert not resolution.ok
    assert resolution.errors[0].code == "remap-invalid"


@pytest.mark.oracle
def test_illegal_remap_from_other_value_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.assert_agrees(ws.launch("remaps.launch", REMAPS), [{"scan": "1bad"}], modes=["shared"])


def test_invalid_remaps_are_errors(ws: LaunchWorkspace) -> None:
    empty = ws.model(ws.launch("empty.launch", '  <remap from="" to="b"/>'))
    illegal = ws.model(ws.launch("illegal.launch", '  <remap from="a" to="1b"/>'))
    missing = ws.model(ws.launch("missing.launch", '  <remap from="a"/>'))
    assert [e.code for e in empty.errors] == ["remap-invalid"]
    assert [e.code for e in illegal.errors] == ["remap-invalid"]
    assert [e.code for e in missing.errors] == ["attribute-missing"]
    assert all(m.errors[0].location.line == 2 for m in (empty, illegal, missing))
