"""Which ROS a package belongs to, from its manifest's build tool."""

from __future__ import annotations

import pytest

from rosvar.frontends.entity import Entity
from rosvar.frontends.xml import parse_xml_bytes
from rosvar.ros.version import RosVersion
from rosvar.workspace.ros_version import build_tool_version, majority, package_version


def manifest(body: str) -> Entity:
    text = f'<package format="3"><name>p</name>{body}</package>'
    root = parse_xml_bytes(text.encode(), "package.xml").root
    assert root is not None
    return root


@pytest.mark.parametrize(
    ("body", "expected"),
    [
        ("<buildtool_depend>catkin</buildtool_depend>", RosVersion.ROS1),
        ("<buildtool_depend>ament_cmake</buildtool_depend>", RosVersion.ROS2),
        ("<buildtool_depend>ament_cmake_auto</buildtool_depend>", RosVersion.ROS2),
        ("<export><build_type>ament_python</build_type></export>", RosVersion.ROS2),
        ("<buildtool_depend>cmake</buildtool_depend>", None),
        ("<depend>roscpp</depend>", None),
        # The declared build type decides over a build tool dependency.
        (
            "<buildtool_depend>catkin</buildtool_depend>"
            "<export><build_type>ament_cmake</build_type></export>",
            RosVersion.ROS2,
        ),
        # A neutral first tool does not hide a telling one.
        (
            "<buildtool_depend>cmake</buildtool_depend><buildtool_depend>catkin</buildtool_depend>",
            RosVersion.ROS1,
        ),
    ],
)
def test_package_version(body: str, expected: RosVersion | None) -> None:
    assert package_version(manifest(body)) == expected


def test_build_tool_prefix_is_not_a_substring_match() -> None:
    assert build_tool_version("ament") is None
    assert build_tool_version("catkin_virtualenv") is None
    assert build_tool_version("ament_lint_auto") == RosVersion.ROS2


def test_majority() -> None:
    assert majority([]) is None
    assert majority([RosVersion.ROS2, RosVersion.ROS1, RosVersion.ROS2]) == RosVersion.ROS2
    assert majority([RosVersion.ROS2, RosVersion.ROS1]) == RosVersion.ROS1
