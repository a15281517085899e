"""The actions that change what later nodes get (``<set_remap>``, ``<set_parameter>``,
``<set_parameters_from_file>``, the environment's) and ``<reset>``, which forgets the launch
configurations: confined by a scoped group up to the lists it shares."""

from __future__ import annotations

from pathlib import Path

import pytest

from ros2.tags.launches import launch


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{}, {"sim": "true"}])
def test_global_remaps_and_parameters_agree_with_ros2_launch(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    it = launch(
        tmp_path,
        """<launch><arg name="sim" default="false"/>
          <set_parameter name="use_sim_time" value="$(var sim)"/>
          <group>
            <set_remap from="in" to="out"/>
            <set_parameter name="inner" value="1"/>
            <set_parameters_from_file filename="$(dirname)/params.yaml"/>
            <node pkg="pkg" exec="a" name="a"><remap from="in" to="own"/></node>
          </group>
          <node pkg="pkg" exec="b" name="b"/>
        </launch>""",
        files={"params.yaml": "/**:\n  ros__parameters:\n    from_file: 2\n"},
    )
    it.matches_oracle(arguments)


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{}, {"keep": "k2"}])
def test_environment_and_reset_agree_with_ros2_launch(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    it = launch(
        tmp_path,
        """<launch><arg name="keep" default="k1"/>
          <set_env name="A" value="1"/>
          <append_env name="A" value="2"/>
          <append_env name="A" value="0" prepend="true" separator=";"/>
          <set_env name="B" value="gone"/><unset_env name="B"/>
          <node pkg="pkg" exec="a" name="a">
            <param name="a" value="$(env A)"/><param name="b" value="$(env B unset)"/></node>
          <reset_env/>
          <push-ros-namespace namespace="ns"/>
          <reset><keep name="kept" value="$(var keep)"/></reset>
          <node pkg="pkg" exec="b" name="b_$(var kept)_$(var keep missing)">
            <param name="a" value="$(env A none)"/></node>
        </launch>""",
    )
    it.matches_oracle(arguments)


def test_a_reset_under_a_condition_forgets_only_there(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """<launch><arg name="forget" default="false"/><let name="v" value="set"/>
          <reset if="$(var forget)"/>
          <node pkg="pkg" exec="a" name="a_$(var v unset)"/></launch>""",
    )
    (node,) = it.model.nodes
    names = {leaf: condition for condition, leaf in node.field("name")}
    assert set(names) == {"a_unset", "a_set"}
    assert it.implies(it.given("forget", "true"), names["a_unset"])
    assert it.implies(it.given("forget", "false"), names["a_set"])
