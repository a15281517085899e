"""The ROS 2 dialect: its frontends (by file suffix), its substitution language, the launch
context as its scope; its tag registry is filled by :mod:`rosvar.ros2.tags`."""

from rosvar.interpreter.semantics import Semantics
from rosvar.ros.version import RosVersion
from rosvar.ros2.context import Context
from rosvar.ros2.entry import walk_entry
from rosvar.ros2.frontends import registry
from rosvar.ros2.substitutions import Ros2Substituter

ROS2: Semantics[Context] = Semantics(RosVersion.ROS2, registry.load, Ros2Substituter, walk_entry)
tag = ROS2.tag
"""Register a ROS 2 tag handler."""
