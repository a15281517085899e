"""``ros2 launch FILE name:=value ...``: one command line's interpretation of an entry file."""

from __future__ import annotations

from collections.abc import Mapping

from rosvar.frontends.xml import Snapshot
from rosvar.interpreter.model import LaunchModel
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import UNSET
from rosvar.ros2 import tags as _tags  # noqa: F401 - registers the handlers
from rosvar.ros2.context import Context
from rosvar.ros2.dialect import ROS2
from rosvar.ros2.entry import walk_actions
from rosvar.workspace import Workspace


def interpret(
    workspace: Workspace,
    space: ConditionSpace,
    file: str,
    arguments: Mapping[str, str],
    env: Mapping[str, str],
) -> LaunchModel:
    """The model of ``file`` launched as ``ros2 launch file name:=value ...``.

    Launch arguments are set before the file is loaded (as ``ros2 launch`` does), so a
    declaration's default applies only to those not given.
    """
    it = ROS2.interpretation(
        workspace,
        space,
        lambda _file, _name: (),
        lambda _name: (UNSET,),  # a variable not given is not set (a clean environment)
        file,
        Snapshot(ROS2.loader_for(workspace)),
    )
    try:
        it.stack.append(file)
        root = it.load(file)
        if root is not None:
            context = Context(file)
            context.configurations = {
                name: Choice.const(space, value) for name, value in arguments.items()
            }
            context.env = {name: Choice.const(space, value) for name, value in env.items()}
            walk_actions(it, root, context)
        return it.finish()
    finally:
        it.close()
