"""``<timer>``, ``<ros_timer>`` and ``<shutdown>``: a timer's actions run after the whole
description, in time order, in the context as it is then; a shutdown cancels the timers
pending that allow it."""

from __future__ import annotations

from pathlib import Path

import pytest

from ros2.tags.launches import launch

TIMERS = """<launch><arg name="stop" default="false"/>
  <timer period="2.0"><node pkg="pkg" exec="late" name="late_$(var v)"/></timer>
  <ros_timer period="1"><node pkg="pkg" exec="early" name="early_$(var v)"/></ros_timer>
  <timer period="0.5" cancel_on_shutdown="false"><let name="w" value="kept"/></timer>
  <shutdown reason="stop" if="$(var stop)"/>
  <let name="v" value="final"/>
  <node pkg="pkg" exec="now" name="now"/>
</launch>"""


@pytest.mark.oracle
@pytest.mark.parametrize("stop", ["false", "true"])
def test_timers_and_shutdowns_agree_with_ros2_launch(tmp_path: Path, stop: str) -> None:
    it = launch(tmp_path, TIMERS)
    names = {node["name"] for node in it.matches_oracle({"stop": stop})["nodes"]}
    assert names == ({"now"} if stop == "true" else {"now", "early_final", "late_final"})


def test_a_timers_nodes_are_cancelled_where_a_shutdown_runs(tmp_path: Path) -> None:
    it = launch(tmp_path, TIMERS)
    nodes = {node.field("exec").branches[0][1]: node.condition for node in it.model.nodes}
    assert nodes["now"] == it.analysis.space.true
    for late in (nodes["late"], nodes["early"]):
        assert it.never(late & it.given("stop", "true"))
        assert it.implies(it.given("stop", "false"), late)


@pytest.mark.oracle
def test_a_period_that_is_no_number_fails(tmp_path: Path) -> None:
    it = launch(tmp_path, '<launch><timer period="soon"><log message="m"/></timer></launch>')
    assert [e.code for e in it.model.errors] == ["timer-period"]
    it.matches_oracle({})
