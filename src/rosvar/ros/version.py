"""The ROS versions rosvar reads: ROS 1 (roslaunch) and ROS 2 (ros2/launch)."""

from __future__ import annotations

from enum import StrEnum


class RosVersion(StrEnum):
    ROS1 = "ros1"
    ROS2 = "ros2"

    @property
    def label(self) -> str:
        """The name people write: ``ROS 1``."""
        return f"ROS {self.value.removeprefix('ros')}"
