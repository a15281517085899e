"""Actions that change what later nodes get: ``<set_remap>``, ``<set_parameter>``,
``<set_parameters_from_file>``, ``<set_env>``, ``<unset_env>``, ``<append_env>``,
``<reset_env>``, and ``<reset>``, which forgets the launch configurations. They live in launch
configurations (the environment in its own stack), so scoped groups confine them, up to the
shared lists of :meth:`Context.scoped`."""

from __future__ import annotations

import os
from dataclasses import replace

from rosvar.frontends.entity import Entity
from rosvar.interpreter.booleans import bool_value
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import Raw
from rosvar.logic.choice import Choice, Fail, combine
from rosvar.logic.terms import concat
from rosvar.ros2.context import Context, GlobalParam, GlobalRemap, optional
from rosvar.ros2.dialect import tag
from rosvar.ros2.include_memo import configuration_names
from rosvar.ros2.tags.common import assign, set_configuration


@tag("set_remap")
@processed
def set_remap(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    source, target = it.required(entity, "from", context), it.required(entity, "to", context)
    if source is None or target is None:
        return
    if context.remaps is None:
        context.remaps = []
    for condition, (s, t) in split(it, combine([source, target], tuple)):
        context.remaps.append(GlobalRemap(it.pc & condition, s, t))


@tag("set_parameter")
@processed
def set_parameter(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    name, value = it.required(entity, "name", context), it.required(entity, "value", context)
    if name is None or value is None:
        return
    if context.params is None:
        context.params = []
    for condition, (n, v) in split(it, combine([name, value], tuple)):
        context.params.append(GlobalParam(it.pc & condition, n, v))


@tag("set_parameters_from_file")
@processed
def set_parameters_from_file(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    file = it.required(entity, "filename", context)
    if file is None:
        return
    if context.params is None:
        context.params = []
    for condition, path in split(it, file):
        context.params.append(GlobalParam(it.pc & condition, None, None, path))


@tag("reset")
@processed
def reset(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    """``ResetLaunchConfigurations``: the ``<keep>`` values, read before, are all that stays."""
    kept: list[tuple[Choice[Raw], Choice[Raw]]] = []
    for keep in entity.children:
        with it.at(keep):
            name, value = it.required(keep, "name", context), it.required(keep, "value", context)
        if name is not None and value is not None:
            kept.append((name, value))
    configuration_names(it, context)  # what it forgets depends on what is set
    context.forgetting.happened = True
    if it.pc == it.space.true:
        context.reset()
    else:  # only where this path runs: each value and each global remap or parameter
        none = Choice.const(it.space, None)
        context.configurations = {
            key: assign(it, context.get(key), none) for key in list(context.configurations)
        }
        if context.namespace is not None:
            context.namespace = assign(it, context.namespace, none)
        outside = ~it.pc
        if context.remaps is not None:
            context.remaps = [replace(r, condition=r.condition & outside) for r in context.remaps]
        if context.params is not None:
            context.params = [replace(p, condition=p.condition & outside) for p in context.params]
    for name, value in kept:
        for condition, key in split(it, name):
            if not isinstance(key, str):
                it.fail(condition, "value-unknown", "<keep> name depends on an unknown value")
                continue
            with it.under(condition) as live:
                if live:
                    set_configuration(it, context, key, optional(value))


@tag("set_env")
@processed
def set_env(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    name, value = entity.get("name"), it.required(entity, "value", context)
    if name and value is not None:
        context.env[name] = assign(it, _current(it, context, name), optional(value))


@tag("unset_env")
@processed
def unset_env(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    name = entity.get("name")
    if name:
        context.env[name] = assign(it, _current(it, context, name), Choice.const(it.space, None))


def _current(it: Interpretation[Context], context: Context, name: str) -> Choice[Raw | None]:
    """The variable's value before this action: set by the launch, or the environment's."""
    value = context.env.get(name)
    return it.env_value(name) if value is None else value


@tag("reset_env")
@processed
def reset_env(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    """``ResetEnvironment``: every variable back to its value when the launch started (a
    scoped group's end still restores the environment it began with)."""
    for name, current in context.env.items():
        context.env[name] = assign(it, current, it.env_value(name))


@tag("append_env")
@processed
def append_env(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    """``AppendEnvironmentVariable``: ``value`` after (``prepend``: before) the variable's
    value and ``separator`` (``:``), or alone where the variable is not set."""
    name, value = entity.get("name"), it.required(entity, "value", context)
    if not name or value is None:
        return
    prepend = bool_value(it, it.attr(entity, "prepend", context), False, "<append_env> prepend")
    separator = it.attr(entity, "separator", context) or Choice.const(it.space, os.pathsep)
    current = _current(it, context, name)
    appended = combine([current, value, prepend, separator], _append)
    context.env[name] = assign(it, current, it.strip(appended, "<append_env>"))


def _append(leaves: list[Raw | bool | None]) -> Raw | Fail | None:
    current, value, prepend, separator = leaves
    if current is None:
        return value  # type: ignore[return-value]  # a text
    if not isinstance(prepend, bool):
        return Fail("<append_env> prepend depends on an unknown value", "value-unknown")
    parts = [value, separator, current] if prepend else [current, separator, value]
    return concat(parts)  # type: ignore[arg-type]  # texts
