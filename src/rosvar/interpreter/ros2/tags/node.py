"""``<node>`` (launch_ros's ``Node``) and ``<executable>`` with their ``param``, ``remap``
and ``env`` children.

A node gets the pushed namespace (``ros_namespace``) and, before its own, the global
remaps and parameters of the context; nested ``<param>`` groups make dotted names.
Name composition and parameter files are left to resolution, which sees one configuration.
"""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import EnvSetting, NodeDecl, NodeParameter, Raw, Remap
from rosvar.interpreter.ros2.context import Context
from rosvar.interpreter.ros2.dialect import tag
from rosvar.interpreter.ros2.tags.common import optional
from rosvar.logic.choice import Choice, combine

FIELDS = ("pkg", "exec", "name", "namespace", "args", "ros_args", "launch-prefix", "output")


@tag("node")
@tag("executable")
@processed
def node(it: Interpretation, entity: Entity, context: Context) -> None:
    it.required(entity, "exec" if entity.tag == "node" else "cmd", context)
    fields: dict[str, Choice[Raw | None]] = {}
    for key in (*FIELDS, "cmd"):
        value = it.attr(entity, key, context)
        fields[key] = Choice.const(it.space, None) if value is None else optional(value)
    fields["ros_namespace"] = context.namespace or Choice.const(it.space, None)
    remaps = [Remap(r.condition, r.source, r.target) for r in context.remaps or ()]
    parameters = [NodeParameter(p.condition, p.name, p.value) for p in context.params or ()]
    env: list[EnvSetting] = []
    for child in entity.children:
        with it.at(child), it.under(it.condition_of(child, context)) as live:
            if not live:
                continue
            if child.tag == "remap":
                _remap(it, child, context, remaps)
            elif child.tag == "param":
                _param(it, child, context, "", parameters)
            elif child.tag == "env":
                _env(it, child, context, env)
            else:
                it.warn("tag-unknown", f"unrecognized '{child.tag}' tag in <{entity.tag}> tag")
    it.model.nodes.append(
        NodeDecl(it.pc, entity.location, context.filename, False, fields, remaps, env, parameters)
    )


def _remap(it: Interpretation, entity: Entity, context: Context, out: list[Remap]) -> None:
    source, target = it.required(entity, "from", context), it.required(entity, "to", context)
    if source is None or target is None:
        return
    for condition, (s, t) in split(it, combine([source, target], tuple)):
        out.append(Remap(it.pc & condition, s, t))


def _env(it: Interpretation, entity: Entity, context: Context, out: list[EnvSetting]) -> None:
    name, value = it.required(entity, "name", context), it.required(entity, "value", context)
    if name is None or value is None:
        return
    for condition, (n, v) in split(it, combine([name, value], tuple)):
        out.append(EnvSetting(it.pc & condition, n, v))


def _param(
    it: Interpretation, entity: Entity, context: Context, prefix: str, out: list[NodeParameter]
) -> None:
    source = it.attr(entity, "from", context)
    if source is not None:
        for condition, file in split(it, source):
            out.append(NodeParameter(it.pc & condition, None, None, file))
        return
    name = it.required(entity, "name", context)
    if name is None:
        return
    nested = [child for child in entity.children if child.tag == "param"]
    value = it.attr(entity, "value", context)
    if nested and value is not None:
        it.fail(
            it.space.true,
            "param-invalid",
            "nested parameters and value attributes are mutually exclusive",
        )
        return
    for condition, key in split(it, name):
        with it.under(condition):
            if not isinstance(key, str):
                it.fail(it.space.true, "value-unknown", "a parameter name is not known")
            elif nested:
                for child in nested:
                    _param(it, child, context, f"{prefix}{key}.", out)
            elif value is None:
                it.fail(
                    it.space.true,
                    "param-invalid",
                    "either a value attribute or nested params are needed",
                )
            else:
                for v_condition, leaf in split(it, value):
                    out.append(NodeParameter(it.pc & v_condition, prefix + key, leaf))
