"""The processes ``ros2/tags/node.py`` starts (``<node>``, ``<executable>``, ``<node_container>``,
``<load_composable_node>``): named, remapped and parameterised as launch_ros does (a node's
typed fields are ``test_node.py``'s)."""

from __future__ import annotations

from pathlib import Path

import pytest

from ros2.tags.launches import launch
from rosvar.logic.inputs import OTHER

PARAMS = "/**:\n  ros__parameters:\n    rate: 5\n    name: from_file\n"


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{}, {"rate": "20", "extra": "--flag"}])
def test_a_node_agrees_with_ros2_launch(tmp_path: Path, arguments: dict[str, str]) -> None:
    it = launch(
        tmp_path,
        """<launch><arg name="rate" default="10"/><arg name="extra" default="''"/>
          <node pkg="pkg" exec="talker" name="talk" namespace="ns" exec_name="talking"
                args="--a 'two words' $(var extra)" ros_args="--log-level debug">
            <param from="$(dirname)/params.yaml"/>
            <param name="rate" value="$(var rate)"/>
            <param name="gains" value="[1.0, 2.5]"/>
            <param name="group"><param name="inner" value="x"/></param>
            <remap from="chatter" to="$(var rate)/chatter"/>
            <env name="E" value="1"/>
          </node>
        </launch>""",
        files={"params.yaml": PARAMS},
    )
    it.matches_oracle(arguments)


def test_a_nodes_fields_hold_each_configurations_value(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """<launch><arg name="exe" default="a"/>
          <node pkg="pkg" exec="$(var exe)" name="n"/></launch>""",
        values={"exe": ["b"]},
    )
    (node,) = it.model.nodes
    executables = {leaf: condition for condition, leaf in node.field("exec")}
    assert it.same(executables["b"], it.given("exe", "b"))
    assert it.implies(it.given("exe", "a"), executables["a"])
    other = [c for leaf, c in executables.items() if not isinstance(leaf, str)]  # a term
    assert len(other) == 1 and it.same(other[0], it.given("exe", OTHER))


@pytest.mark.oracle
def test_processes_and_composable_nodes_agree_with_ros2_launch(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """<launch>
          <executable cmd="echo $(var word 'hi there')" name="echo" output="screen"/>
          <node_container pkg="rclcpp_components" exec="component_container" name="box"
                          namespace="c">
            <composable_node pkg="pkg" plugin="pkg::A" name="a">
              <param name="p" value="1"/><extra_arg name="use_intra_process_comms" value="true"/>
            </composable_node>
          </node_container>
          <load_composable_node target="/c/box">
            <composable_node pkg="pkg" plugin="pkg::B" name="b" namespace="late"/>
          </load_composable_node>
        </launch>""",
    )
    it.matches_oracle({}, strict=False)
