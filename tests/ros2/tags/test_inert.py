"""``<log>``, ``<set_use_sim_time>`` and ``<set_ros_log_dir>`` start nothing and change no
node, but their attributes are read, and fail the launch, as launch's."""

from __future__ import annotations

from pathlib import Path

import pytest

from ros2.tags.launches import launch


@pytest.mark.oracle
def test_actions_that_start_nothing_leave_the_nodes_as_they_are(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """<launch><arg name="who" default="me"/>
          <log message="starting $(var who)"/>
          <set_ros_log_dir new_log_dir="/tmp/rosvar-log"/>
          <node pkg="pkg" exec="a" name="a_$(var who)"/>
        </launch>""",
    )
    assert [node["name"] for node in it.matches_oracle({"who": "you"})["nodes"]] == ["a_you"]


@pytest.mark.oracle
def test_what_they_read_can_fail(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """<launch><log message="$(var nobody)"/><node pkg="pkg" exec="a" name="a"/></launch>""",
    )
    assert [e.code for e in it.model.errors] == ["var-undefined"]
    assert it.matches_oracle({})["ok"] is False


def test_set_use_sim_time_is_accepted_and_reads_its_value(tmp_path: Path) -> None:
    """Not compared: the oracle's stand-in ROS node never answers ``SetUseSimTime``."""
    it = launch(
        tmp_path,
        """<launch><set_use_sim_time value="$(var sim)"/><set_use_sim_time/>
          <node pkg="pkg" exec="a" name="a"/></launch>""",
    )
    assert sorted(e.code for e in it.model.errors) == ["attribute-missing", "var-undefined"]
    (node,) = it.model.nodes
    assert node.condition == it.analysis.space.true


@pytest.mark.oracle
def test_a_missing_attribute_fails(tmp_path: Path) -> None:
    it = launch(tmp_path, '<launch><log/><node pkg="pkg" exec="a" name="a"/></launch>')
    assert [e.code for e in it.model.errors] == ["attribute-missing"]
    it.matches_oracle({})
