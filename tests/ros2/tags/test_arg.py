"""``<arg>`` (``DeclareLaunchArgument``) and ``<let>`` (``SetLaunchConfiguration``): global
launch configurations, a default only where nothing is set, choices that fail the launch."""

from __future__ import annotations

from pathlib import Path

import pytest

from ros2.tags.launches import launch
from rosvar.logic.inputs import OTHER, UNSET

MAIN = """<launch>
  <arg name="mode" default="fast"><choice value="fast"/><choice value="slow"/></arg>
  <arg name="robot"/>
  <let name="label" value="$(var robot)_$(var mode)"/>
  <node pkg="pkg" exec="driver" name="$(var label)"/>
</launch>"""


def test_defaults_choices_and_required_arguments_in_the_model(tmp_path: Path) -> None:
    it = launch(tmp_path, MAIN, values={"robot": ["r1"], "mode": ["bad"]})
    model = it.model
    assert [a.name for a in model.args] == ["mode", "robot"]
    (driver,) = model.nodes
    named = {leaf: condition for condition, leaf in driver.field("name") if isinstance(leaf, str)}
    r1 = it.given("robot", "r1")
    assert it.same(named["r1_slow"], r1 & it.given("mode", "slow"))
    assert it.same(named["r1_fast"], r1 & (it.given("mode", "fast") | it.given("mode", UNSET)))
    fails = ~model.loads
    assert it.implies(it.given("mode", "bad") | it.given("mode", OTHER), fails)  # no choice
    assert it.implies(it.given("robot", UNSET), fails)  # no value, no default
    assert it.implies(r1 & (it.given("mode", "slow") | it.given("mode", UNSET)), model.loads)


@pytest.mark.oracle
@pytest.mark.parametrize(
    "arguments",
    [{"robot": "r1"}, {"robot": "r1", "mode": "slow"}, {"robot": "r1", "mode": "bad"}, {}],
)
def test_given_defaulted_refused_and_missing_arguments_agree_with_ros2_launch(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    it = launch(tmp_path, MAIN, values={"robot": ["r1"], "mode": ["bad"]})
    it.matches_oracle(arguments)


CHOSEN = """<launch>
  <arg name="prefix" default=""/>
  <arg name="mode" default="$(var prefix)fast"><choice value="fast"/><choice value="slow"/></arg>
  <node pkg="pkg" exec="driver" name="$(var mode)"/>
</launch>"""
CHOSEN_ARGUMENTS = [
    ({}, True),
    ({"prefix": "z"}, False),
    ({"mode": "z"}, False),
    ({"mode": "slow"}, True),
]


def test_a_value_only_a_configuration_knows_is_checked_against_the_choices(tmp_path: Path) -> None:
    it = launch(tmp_path, CHOSEN)
    assert it.implies(it.given("mode", OTHER), ~it.model.loads)  # no choice is <other>
    # a default that only the prefix makes: told once the prefix is known
    assert not it.implies(it.given("prefix", OTHER), ~it.model.loads)
    for arguments, ok in CHOSEN_ARGUMENTS:
        assert it.analysis.resolve([str(it.main)], arguments).ok is ok, arguments


@pytest.mark.oracle
@pytest.mark.parametrize(("arguments", "ok"), CHOSEN_ARGUMENTS)
def test_values_outside_the_choices_agree_with_ros2_launch(
    tmp_path: Path, arguments: dict[str, str], ok: bool
) -> None:
    assert launch(tmp_path, CHOSEN).matches_oracle(arguments)["ok"] is ok


@pytest.mark.oracle
def test_an_included_files_let_and_arg_reach_the_includer(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """<launch>
          <let name="v" value="outer"/>
          <include file="$(dirname)/inner.launch.xml"/>
          <node pkg="pkg" exec="a" name="$(var v)_$(var w)"/>
        </launch>""",
        files={
            "inner.launch.xml": """<launch>
              <arg name="w" default="declared"/>
              <let name="v" value="$(var v)_inner"/>
            </launch>"""
        },
    )
    assert it.matches_oracle({})["nodes"][0]["name"] == "outer_inner_declared"
    it.matches_oracle({"w": "given"})


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{"path": "/given.yaml"}, {}])
def test_a_default_is_evaluated_only_where_no_value_is_given(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    """A default naming an absent package fails the launch only when it is used
    (autoware's ``voxel_grid_based_euclidean_cluster.launch.py``, which its includer
    always gives a path)."""
    it = launch(
        tmp_path,
        """<launch>
  <arg name="path" default="$(find-pkg-share absent_pkg)/config.yaml"/>
  <node pkg="pkg" exec="driver" name="driver" args="$(var path)"/>
</launch>""",
        values={"path": ["/given.yaml"]},
    )
    assert it.implies(it.given("path", "/given.yaml"), it.model.loads)
    assert it.implies(it.given("path", UNSET), ~it.model.loads)
    it.matches_oracle(arguments)
