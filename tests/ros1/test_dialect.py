"""The ROS 1 dialect's tag registry: one handler per roslaunch tag."""

from __future__ import annotations

import pytest

from rosvar.interpreter.dialect import dialect_of
from rosvar.ros.version import RosVersion
from rosvar.ros1.dialect import ROS1, tag


def test_every_roslaunch_tag_has_a_handler() -> None:
    assert dialect_of(RosVersion.ROS1) is ROS1  # the registry's, with its handlers
    assert set(ROS1.tags) >= {
        "arg", "env", "group", "include", "machine", "master", "node", "param", "remap",
        "rosparam", "test",
    }  # fmt: skip


def test_a_second_handler_for_a_tag_is_refused() -> None:
    dialect_of(RosVersion.ROS1)
    handler = ROS1.tags["node"]
    with pytest.raises(ValueError, match="registered twice"):
        tag("node")(lambda _it, _entity, _scope: None)
    assert ROS1.tags["node"] is handler
