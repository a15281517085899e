"""Views: a step's graph derived from the earlier step's, unchanged entries kept as objects."""

from __future__ import annotations

from typing import TYPE_CHECKING

from configuration.helpers import configurator, run

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

A = """
  <arg name="robot" default="kobuki"/>
  <node pkg="p" type="t" name="$(arg robot)"/>
  <node pkg="p" type="t" name="fixed"/>
"""
B = '  <arg name="cam" default="true"/>\n  <node pkg="p" type="t" name="cam" if="$(arg cam)"/>'
STEPS = ("select a.launch", "select b.launch", "set a.launch:robot=husky", "set b.launch:cam=false")


def test_a_derived_view_equals_one_computed_afresh(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", A)
    ws.launch("b.launch", B)
    engine = configurator(ws)
    for n in range(1, len(STEPS) + 1):
        derived = run(engine, *STEPS[:n])  # from the view of the step before
        fresh = run(configurator(ws), *STEPS[:n])
        assert derived.graph.to_json() == fresh.graph.to_json()


def test_entries_a_step_does_not_reach_stay_the_same_objects(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", A)
    ws.launch("b.launch", B)
    engine = configurator(ws)
    before = run(engine, *STEPS[:2])
    after = run(engine, *STEPS[:3])  # a value for a.launch's robot: b.launch is not reached
    pairs = list(zip(before.graph.nodes, after.graph.nodes, strict=True))
    kept = {x["name"] for x, y in pairs if x is y}
    assert "/cam" in kept and "/fixed" in kept
    renamed = {(x["name"], x["presence"], y["presence"]) for x, y in pairs if x is not y}
    assert renamed  # the robot's variants changed presence
    assert all(old != new for _name, old, new in renamed)
