"""``<group>`` (``GroupAction``) and ``<push-ros-namespace>``: a scoped group pushes and pops
the launch configurations (the namespace among them); ``forwarding="false"`` starts from its
``<keep>`` values only."""

from __future__ import annotations

from pathlib import Path

import pytest

from ros2.tags.launches import launch

GROUPS = """<launch>
  <let name="v" value="outer"/>
  <group scoped="{scoped}">
    <push-ros-namespace namespace="robot"/>
    <let name="v" value="inner"/>
    <node pkg="pkg" exec="a" name="a_$(var v)"/>
  </group>
  <group forwarding="false"><keep name="k" value="$(var v)"/>
    <node pkg="pkg" exec="b" name="b_$(var k)"/>
  </group>
  <push_ros_namespace namespace="/top"/>
  <node pkg="pkg" exec="c" name="c_$(var v)" namespace="own"/>
</launch>"""


@pytest.mark.oracle
@pytest.mark.parametrize("scoped", ["true", "false"])
def test_scoped_and_unscoped_groups_agree_with_ros2_launch(tmp_path: Path, scoped: str) -> None:
    it = launch(tmp_path, GROUPS.format(scoped=scoped))
    nodes = {node["name"]: node for node in it.matches_oracle({})["nodes"]}
    inner = scoped == "false"  # an unscoped group's let and namespace stay
    assert set(nodes) == {"a_inner", f"b_{'inner' if inner else 'outer'}",
                          f"c_{'inner' if inner else 'outer'}"}  # fmt: skip
    assert nodes[f"c_{'inner' if inner else 'outer'}"]["namespace"] == "/top/own"


def test_a_group_under_a_condition_gives_its_nodes_the_condition(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """<launch><arg name="on" default="true"/>
          <group if="$(var on)"><node pkg="pkg" exec="a" name="a"/></group>
        </launch>""",
    )
    (node,) = it.model.nodes
    assert it.implies(it.given("on", "true"), node.condition)
    assert it.never(node.condition & it.given("on", "false"))


@pytest.mark.oracle
def test_namespaces_compose_relative_absolute_and_computed(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """<launch><arg name="ns" default="r1"/>
          <group><push-ros-namespace namespace="$(var ns)"/>
            <push-ros-namespace namespace="arm/"/>
            <node pkg="pkg" exec="a" name="a"/>
            <node pkg="pkg" exec="b" name="b" namespace="/abs"/>
          </group>
          <group><push-ros-namespace namespace="/x"/><push-ros-namespace namespace="/y"/>
            <node pkg="pkg" exec="c" name="c"/></group>
        </launch>""",
    )
    it.matches_oracle({})
    it.matches_oracle({"ns": "/other"})


@pytest.mark.oracle
def test_both_python_names_of_push_ros_namespace_agree_with_ros2_launch(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushROSNamespace, PushRosNamespace


def generate_launch_description():
    return LaunchDescription([
        GroupAction([PushROSNamespace('one'), Node(package='pkg', executable='a', name='a')]),
        GroupAction([PushRosNamespace('two'), Node(package='pkg', executable='b', name='b')]),
    ])
""",
        suffix=".launch.py",
    )
    assert it.model.diagnostics == []
    nodes = it.matches_oracle({})["nodes"]
    assert sorted(node["namespace"] for node in nodes) == ["/one", "/two"]


@pytest.mark.oracle
def test_a_namespace_no_file_names_is_pushed_in_the_model_over_every_command_line(
    tmp_path: Path,
) -> None:
    """The generated workspace's namespace argument (issue 28): given a value no file names,
    the model over every command line pushes it as a term, composed once it is known."""
    it = launch(
        tmp_path,
        """<launch><arg name="ns" default="robot"/>
          <group><push-ros-namespace namespace="$(var ns)"/>
            <push-ros-namespace namespace="arm"/><node pkg="pkg" exec="a" name="a"/></group>
        </launch>""",
    )
    assert it.model.diagnostics == []
    (node,) = it.matches_oracle({"ns": "robot_b"})["nodes"]
    assert node["namespace"] == "/robot_b/arm"
