"""Dialects keep their tag registries apart."""

from __future__ import annotations

import pytest

from rosvar.interpreter.interpretation import ROS1
from rosvar.ros2.dialect import ROS2
from rosvar.ros2.entry import interpret  # noqa: F401 - registers


def test_each_dialect_has_its_own_tags() -> None:
    assert "let" in ROS2.tags and "let" not in ROS1.tags
    assert ROS1.tags["node"] is not ROS2.tags["node"]


def test_a_tag_is_registered_once() -> None:
    with pytest.raises(ValueError, match="registered twice"):
        ROS2.tag("let")(ROS2.tags["let"])
