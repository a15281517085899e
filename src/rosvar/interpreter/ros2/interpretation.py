"""Interpret one ROS 2 entry launch file with given launch arguments."""

from __future__ import annotations

from collections.abc import Mapping

from rosvar.frontends import registry
from rosvar.frontends.ros1_xml.parser import Snapshot
from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.ros2 import tags as _tags  # noqa: F401 - registers the handlers
from rosvar.interpreter.ros2.context import Context
from rosvar.interpreter.ros2.dialect import ROS2
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import UNSET
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
    it = Interpretation(
        workspace,
        space,
        lambda _file, _name: (),
        lambda _name: (UNSET,),  # a variable not given is not set (a clean environment)
        file,
        Snapshot(registry.load),
        ROS2,
    )
    try:
        context = Context(file)
        context.configurations = {
            name: Choice.const(space, value) for name, value in arguments.items()
        }
        context.env = {name: Choice.const(space, value) for name, value in env.items()}
        it.stack.append(file)
        root = it.load(file)
        if root is not None:
            with it.at(root):
                it.walk(root.children, context)
        failing = space.false
        for error in it.model.errors:
            failing |= error.condition
        it.model.loads = ~failing
        it.model.diagnostics = it.sink.items
        return it.model
    finally:
        it.close()
