"""The ROS 2 dialect keeps its tag registry apart from ROS 1's."""

from __future__ import annotations

import pytest

from rosvar.interpreter.dialect import dialect_of
from rosvar.ros.version import RosVersion
from rosvar.ros1.dialect import ROS1
from rosvar.ros2.dialect import ROS2


def test_each_dialect_has_its_own_tags() -> None:
    assert dialect_of(RosVersion.ROS2) is ROS2 and dialect_of(RosVersion.ROS1) is ROS1
    assert "let" in ROS2.tags and "let" not in ROS1.tags
    assert len({ROS1.tags["node"], ROS2.tags["node"]}) == 2  # two handlers


def test_a_tag_is_registered_once() -> None:
    dialect_of(RosVersion.ROS2)
    with pytest.raises(ValueError, match="registered twice"):
        ROS2.tag("let")(ROS2.tags["let"])
