"""The ROS 1 dialect: roslaunch's XML, substitution args and scope, what a ``<node>`` means and
the resolution of one configuration; its tag registry is filled by :mod:`rosvar.ros1.tags`."""

from rosvar.frontends.xml import load_launch_file
from rosvar.interpreter.semantics import Semantics
from rosvar.interpreter.substitution_args import Substituter
from rosvar.ros.version import RosVersion
from rosvar.ros1 import controllers  # noqa: F401 - registers its spawners' controllers
from rosvar.ros1.entry import walk_entry
from rosvar.ros1.nodes import ROS1_NODES
from rosvar.ros1.resolve import ROS1_CHECKS, node_fields, resolve
from rosvar.ros1.scope import Scope

ROS1: Semantics[Scope] = Semantics(
    RosVersion.ROS1,
    load_launch_file,
    Substituter,
    walk_entry,
    ROS1_NODES,
    resolve,
    node_fields,
    ROS1_CHECKS,
)
tag = ROS1.tag
"""Register a ROS 1 tag handler."""
