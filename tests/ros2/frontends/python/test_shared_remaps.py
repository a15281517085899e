"""Remaps a Python launch file gives to several nodes as one rule (``shared_remaps.py``)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from ros2.test_parameter_checks import MANIFEST
from rosvar.frontends.entity import Entity
from rosvar.outputs.cli import main
from rosvar.ros2.api.actions import SHARED
from rosvar.ros2.frontends.python.parser import parse_python_launch_bytes

SHARED_LIST = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    remappings = [('/tf', 'tf'), ('/tf_static', 'tf_static')]
    return LaunchDescription([
        Node(package='demo', executable='mover', name='mover',
             remappings=remappings + [('cmd_vel', 'cmd_vel_nav')]),
        Node(package='demo', executable='mapper', name='mapper',
             remappings=remappings + [('skan', 'scan_front')]),
        Node(package='demo', executable='mapper', name='alone',
             remappings=[('/tf', 'odom')]),
    ])
"""
"""One list in a variable, given to two nodes (one of them extends it); a third node gives
/tf a list of its own."""


def _remaps(text: str) -> dict[str, list[tuple[str | None, bool]]]:
    """Each node's remaps: the source and whether the reading marked it shared."""
    root = parse_python_launch_bytes(text.encode(), "/ws/demo/launch/main.launch.py").root
    assert root is not None
    nodes: list[Entity] = [child for child in root.children if child.tag == "node"]
    return {
        str(node.get("name")): [(remap.get("from"), remap.has(SHARED)) for remap in node.children]
        for node in nodes
    }


def test_a_pair_of_one_list_given_to_several_nodes_is_shared() -> None:
    assert _remaps(SHARED_LIST) == {
        "mover": [("/tf", True), ("/tf_static", True), ("cmd_vel", False)],
        "mapper": [("/tf", True), ("/tf_static", True), ("skan", False)],
        "alone": [("/tf", False)],  # by other texts: not each node's
    }


EVERY_NODE = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo', executable='mover', name='a', remappings=[('/tf', 'tf')]),
        Node(package='demo', executable='mapper', name='b',
             remappings=[('/tf', 'tf'), ('odom', 'odometry')]),
    ])
"""


def test_the_same_pair_written_for_every_node_of_the_file_is_shared() -> None:
    assert _remaps(EVERY_NODE) == {
        "a": [("/tf", True)],
        "b": [("/tf", True), ("odom", False)],
    }
    one = EVERY_NODE.replace("[('/tf', 'tf')]),\n", "[]),\n")  # /a gives none: /b's is its own
    assert _remaps(one) == {"a": [], "b": [("/tf", False), ("odom", False)]}


NODE = """#include <rclcpp/rclcpp.hpp>
class Node{name} : public rclcpp::Node {{
 public:
  Node{name}() : Node("{name}") {{ {uses} }}
  rclcpp::SubscriptionBase::SharedPtr sub_;
  rclcpp::PublisherBase::SharedPtr pub_;
}};
int main(int argc, char** argv) {{ rclcpp::spin(std::make_shared<Node{name}>()); }}
"""
USES = {
    "mover": 'sub_ = create_subscription<geometry_msgs::msg::Twist>("cmd_vel", 10, on_twist); '
    'pub_ = create_publisher<nav_msgs::msg::Odometry>("odom", 10);',
    "mapper": 'sub_ = create_subscription<sensor_msgs::msg::LaserScan>("scan", 10, on_scan);',
}
"""What each executable of package ``demo`` uses."""


def test_remap_unused_speaks_of_a_nodes_own_remaps_only(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """No node uses /tf: the shared list renames for both nodes it reaches, as a group's
    remap, and is no mistake; /mapper's own remap of skan (it uses scan) and /alone's own
    remap of /tf are."""
    package = tmp_path / "demo"
    for folder in ("src", "launch"):
        (package / folder).mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST.replace("bringup", "demo"))
    executables = [f"add_executable({name} src/{name}.cpp)" for name in USES]
    lines = ["project(demo)", "find_package(ament_cmake REQUIRED)", *executables]
    (package / "CMakeLists.txt").write_text("\n".join([*lines, "ament_package()", ""]))
    for name, uses in USES.items():
        (package / "src" / f"{name}.cpp").write_text(NODE.format(name=name, uses=uses))
    (package / "launch" / "main.launch.py").write_text(SHARED_LIST)
    main(["check", str(tmp_path), "--format", "json"])
    found = json.loads(capsys.readouterr().out)["findings"]
    unused = sorted((f["name"], f["message"]) for f in found if f["check"] == "remap-unused")
    assert unused == [
        (
            "/skan",
            "/mapper never uses /skan: its remap to scan_front renames nothing (it uses /scan)",
        ),
        ("/tf", "/alone never uses /tf: its remap to odom renames nothing"),
    ]
