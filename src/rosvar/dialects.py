"""The dialects rosvar ships, registered with the core's registry
(:mod:`rosvar.interpreter.dialect`), which finds them by :class:`RosVersion` and never
imports them. Each is imported on first use: a ROS 1 analysis never imports ROS 2's
frontends, actions and substitutions, nor the other way round.

Imported with the package (``rosvar/__init__.py``), above every layer, so that the registry
is filled whatever module a program imports first.
"""

from __future__ import annotations

from rosvar.interpreter.dialect import Dialect, register
from rosvar.ros.version import RosVersion


def _ros1() -> Dialect:
    from rosvar.ros1 import tags  # noqa: F401 - registers the tag handlers
    from rosvar.ros1.dialect import ROS1

    return ROS1


def _ros2() -> Dialect:
    from rosvar.ros2 import tags  # noqa: F401 - registers the tag handlers
    from rosvar.ros2.dialect import ROS2

    return ROS2


register(RosVersion.ROS1, _ros1)
register(RosVersion.ROS2, _ros2)
