"""``ros2 launch FILE``: the walk of an entry launch file, its launch arguments the command
line's."""

from __future__ import annotations

from collections.abc import Mapping

from rosvar.frontends.entity import Entity
from rosvar.interpreter.domains import entry_declarations
from rosvar.interpreter.interpretation import Interpretation
from rosvar.ros2 import schema
from rosvar.ros2.context import Context
from rosvar.ros2.events import fire


def walk_entry(
    it: Interpretation[Context], file: str, root: Entity, undeclared: Mapping[str, str]
) -> set[str]:
    """The file over every command line: the declared launch arguments are the command
    line's, and so are the ``undeclared`` ones included files declare; the included files'
    args read where they were not set (before their declaration, or outside its group) are
    returned."""
    context = entry_context(it, file, root, undeclared)
    walk_actions(it, root, context)
    return {n for n in it.model.settable if n in context.unset_reads and n not in undeclared}


def walk_actions(it: Interpretation[Context], root: Entity, context: Context) -> None:
    """Run the entry file's actions, then its timers, in ``context`` (the command line's
    launch configurations)."""
    schema.check(it, root)
    with it.at(root):
        it.walk(root.children, context)
        fire(it, context)


def entry_context(
    it: Interpretation[Context], file: str, root: Entity, settable: Mapping[str, str]
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
