"""Actions that change what later nodes get: ``<set_remap>``, ``<set_parameter>``,
``<set_env>``, ``<unset_env>``. They live in launch configurations (the environment in its
own stack), so scoped groups confine them, up to the shared lists of :meth:`Context.scoped`."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import Raw
from rosvar.interpreter.ros2.context import Context, GlobalParam, GlobalRemap, optional
from rosvar.interpreter.ros2.dialect import tag
from rosvar.interpreter.ros2.tags.common import assign
from rosvar.logic.choice import Choice, combine


@tag("set_remap")
@processed
def set_remap(it: Interpretation, entity: Entity, context: Context) -> None:
    source, target = it.required(entity, "from", context), it.required(entity, "to", context)
    if source is None or target is None:
        return
    if context.remaps is None:
        context.remaps = []
    for condition, (s, t) in split(it, combine([source, target], tuple)):
        context.remaps.append(GlobalRemap(it.pc & condition, s, t))


@tag("set_parameter")
@processed
def set_parameter(it: Interpretation, entity: Entity, context: Context) -> None:
    name, value = it.required(entity, "name", context), it.required(entity, "value", context)
    if name is None or value is None:
        return
    if context.params is None:
        context.params = []
    for condition, (n, v) in split(it, combine([name, value], tuple)):
        context.params.append(GlobalParam(it.pc & condition, n, v))


@tag("set_env")
@processed
def set_env(it: Interpretation, entity: Entity, context: Context) -> None:
    name, value = entity.get("name"), it.required(entity, "value", context)
    if name and value is not None:
        context.env[name] = assign(it, _current(it, context, name), optional(value))


@tag("unset_env")
@processed
def unset_env(it: Interpretation, entity: Entity, context: Context) -> None:
    name = entity.get("name")
    if name:
        context.env[name] = assign(it, _current(it, context, name), Choice.const(it.space, None))


def _current(it: Interpretation, context: Context, name: str) -> Choice[Raw | None]:
    """The variable's value before this action: set by the launch, or the environment's."""
    value = context.env.get(name)
    return it.env_value(name) if value is None else value
