"""The ROS 2 dialect: its frontends (by file suffix), its substitution language, the launch
context as its scope, what a node declaration means and the resolution of one command line;
its tag registry is filled by :mod:`rosvar.ros2.tags`, a handler for each action of the launch
API's registry (:mod:`rosvar.ros2.api.actions`)."""

from collections.abc import Callable

from rosvar.interpreter.interpretation import Handler
from rosvar.interpreter.semantics import Semantics
from rosvar.ros.version import RosVersion
from rosvar.ros2 import (
    boolean_substitutions,  # noqa: F401 - registers their handlers
    controllers,  # noqa: F401 - registers its spawners' controllers
    parameter_checks,  # noqa: F401 - registers ROS 2's own checks
    term_cells,  # noqa: F401 - registers its term functions' cells
    written_files,  # noqa: F401 - registers $(rosvar-written-file)
)
from rosvar.ros2.api.actions import ACTIONS
from rosvar.ros2.context import Context
from rosvar.ros2.entry import walk_entry
from rosvar.ros2.frontends import registry
from rosvar.ros2.include_memo import forget_walks
from rosvar.ros2.nodes import ROS2_NODES
from rosvar.ros2.resolve import ROS2_CHECKS, node_fields, resolve
from rosvar.ros2.substitutions import Ros2Substituter, forget_resolved

ROS2: Semantics[Context] = Semantics(
    RosVersion.ROS2,
    registry.load,
    Ros2Substituter,
    walk_entry,
    ROS2_NODES,
    resolve,
    node_fields,
    ROS2_CHECKS,
    bind=registry.workspace_loader,
    released=[forget_resolved, forget_walks],
)


def tag(name: str) -> Callable[[Handler[Context]], Handler[Context]]:
    """Register the handler of the action exposed as ``<name>``; an action the registry does
    not know, or an element its parent reads, has none."""
    action = ACTIONS.by_name.get(name)
    if action is None or not action.walked:
        raise ValueError(f"<{name}> is no action of the launch API's registry")
    return ROS2.tag(name)
