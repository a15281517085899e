"""Interpret one ROS 2 entry launch file: with given launch arguments, or over all of them."""

from __future__ import annotations

from collections.abc import Mapping

from rosvar.frontends.entity import Entity
from rosvar.frontends.xml import Snapshot
from rosvar.interpreter.domains import entry_declarations
from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.model import LaunchModel
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import UNSET
from rosvar.ros2 import schema
from rosvar.ros2 import tags as _tags  # noqa: F401 - registers the handlers
from rosvar.ros2.context import Context
from rosvar.ros2.dialect import ROS2
from rosvar.ros2.frontends import registry
from rosvar.ros2.tags.timer import fire
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
        it.stack.append(file)
        root = it.load(file)
        if root is not None:
            context = Context(file)
            context.configurations = {
                name: Choice.const(space, value) for name, value in arguments.items()
            }
            context.env = {name: Choice.const(space, value) for name, value in env.items()}
            walk_entry(it, root, context)
        return it.finish()
    finally:
        it.close()


def walk_entry(it: Interpretation, root: Entity, context: Context) -> None:
    """Run the entry file's actions, then its timers, in ``context`` (the command line's
    launch configurations)."""
    schema.check(it, root)
    with it.at(root):
        it.walk(root.children, context)
        fire(it, context)


def entry_context(
    it: Interpretation, file: str, root: Entity, settable: Mapping[str, str]
) -> Context:
    """The context of ``ros2 launch file ...`` over every command line: each launch argument
    the file declares is an input, not set where it is not given, and so is each of
    ``settable`` (:attr:`LaunchModel.settable`: ``ros2 launch`` sets any ``name:=value``
    before loading, so an included file's declaration takes it); other included files'
    arguments become inputs where they are declared."""
    names = list(
        dict.fromkeys(
            name for d in entry_declarations(root) if (name := d.get("name")) and "$" not in name
        )
    )
    extra = {name: declared for name, declared in settable.items() if name not in names}
    context = Context(file, open_command_line=True)
    context.configurations = it.entry_args(file, [*names, *extra], None, extra)
    it.model.settable.update(extra)
    return context
