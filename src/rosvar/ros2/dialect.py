"""The ROS 2 dialect: its tag registry (filled by :mod:`rosvar.ros2.tags`) and
its substitution language."""

from rosvar.interpreter.dialect import Dialect, RosVersion
from rosvar.ros2.substitutions import Ros2Substituter

ROS2 = Dialect(RosVersion.ROS2, Ros2Substituter)
tag = ROS2.tag
