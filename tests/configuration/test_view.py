"""Views: a step's graph derived from the earlier step's, unchanged entries kept as objects."""

from __future__ import annotations

from collections import Counter
from typing import TYPE_CHECKING

from configuration.helpers import configurator, run
from rosvar.configuration.graph import ElementKind
from rosvar.configuration.presence import Presence
from rosvar.outputs.documents.state import graph_document

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
        assert graph_document(derived.graph) == graph_document(fresh.graph)


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


C = """
  <arg name="cam" default="true"/>
  <rosparam>{gains: {p: 1, i: 2}, rate: 10}</rosparam>
  <node pkg="p" type="t" name="cam" if="$(arg cam)">
    <remap from="image" to="raw" if="$(arg cam)"/>
  </node>
  <include file="$(find nowhere)/x.launch"/>
"""


def test_a_view_not_shown_before_is_derived_as_one_computed_afresh(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", A)
    ws.launch("b.launch", B)
    engine = configurator(ws)
    for n in range(1, len(STEPS)):  # states whose graph nobody asks for
        run(engine, *STEPS[:n]).summary  # noqa: B018 (judged, not rendered)
    last = run(engine, *STEPS)
    assert graph_document(last.graph) == graph_document(run(configurator(ws), *STEPS).graph)


def test_a_summary_counts_the_entries_the_graph_shows(ws: LaunchWorkspace) -> None:
    """A YAML load shows an entry per key, an error only while not absent."""
    ws.launch("a.launch", A)
    ws.launch("c.launch", C)
    engine = configurator(ws)
    steps = ("select c.launch", "set c.launch:cam=false", "select a.launch")
    errors = 0
    for n in range(len(steps) + 1):
        state = run(engine, *steps[:n])
        summary = state.summary  # before the graph: judged without it
        graph = state.graph
        for kind, entries in (
            (ElementKind.NODE, graph.nodes),
            (ElementKind.PARAM, graph.params),
            (ElementKind.TOPIC, graph.topics),
            (ElementKind.ERROR, graph.errors),
        ):
            counted = Counter(entry["presence"] for entry in entries)
            assert summary.counts[kind] == {p: counted[p] for p in Presence}
        assert summary.errors == [e for e in graph.errors if e["presence"] == Presence.PRESENT]
        errors += len(summary.errors)
    assert errors and summary.counts[ElementKind.PARAM][Presence.PRESENT] == 3
