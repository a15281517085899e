"""``<node>`` (launch_ros's ``Node``), ``<executable>``, ``<node_container>`` and
``<load_composable_node>`` with their ``composable_node``, ``param``, ``remap`` and ``env``
children. Composable nodes get the context's remaps and parameters as nodes do.

A node gets the pushed namespace (``ros_namespace``) and, before its own, the global
remaps and parameters of the context; nested ``<param>`` groups make dotted names.
Name composition and parameter files are left to resolution, which sees one configuration.
"""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import EnvSetting, NodeDecl, NodeParameter, Raw, Remap
from rosvar.logic.choice import Choice, Fail, combine
from rosvar.logic.terms import is_term
from rosvar.ros2.context import Context, optional
from rosvar.ros2.dialect import ROS2, tag
from rosvar.ros2.nodes import ProcessKind
from rosvar.ros2.substitutions import Ros2Substituter

FIELDS = (
    "pkg", "exec", "cmd", "plugin", "name", "namespace", "args", "ros_args", "launch-prefix",
    "output",
)  # fmt: skip


KINDS = {
    "node": ProcessKind.NODE,
    "lifecycle_node": ProcessKind.LIFECYCLE_NODE,
    "executable": ProcessKind.PROCESS,
    "node_container": ProcessKind.CONTAINER,
}
REQUIRED = {"node": "exec", "lifecycle_node": "exec", "executable": "cmd", "node_container": "exec"}
COMMAND_LINES = frozenset({"cmd", "args", "ros_args"})
"""Attributes split into arguments before substitution (launch's ``_parse_cmdline``); the
model holds them as one ``shlex``-quoted text."""
NESTED = ("composable_node", "extra_arg")  # handled by their parent, not as settings


@tag("node")
@tag("lifecycle_node")
@tag("executable")
@tag("node_container")
@processed
def node(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    it.required(entity, REQUIRED[entity.tag], context)
    fields = _declare(it, entity, context, KINDS[entity.tag], None)
    named = ROS2.nodes.full_name.over(fields)
    container = it.strip(named.map(_container_name), "<node_container> name")
    _composables(it, entity, context, container)


@tag("load_composable_node")
@processed
def load_composable_node(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    target = it.required(entity, "target", context)
    if target is not None:
        _composables(it, entity, context, optional(target))


def _composables(
    it: Interpretation[Context], entity: Entity, context: Context, container: Choice[Raw | None]
) -> None:
    for child in entity.children:
        if child.tag == "composable_node":
            with it.at(child), it.under(it.condition_of(child, context)) as live:
                if live:
                    _declare(it, child, context, ProcessKind.COMPOSABLE_NODE, container)


def _container_name(name: Raw | None) -> Raw | Fail | None:
    """What a ``<load_composable_node>`` of the container names as its target."""
    return Fail("a container's name is not known", "value-unknown") if is_term(name) else name


def _declare(
    it: Interpretation[Context],
    entity: Entity,
    context: Context,
    kind: ProcessKind,
    container: Choice[Raw | None] | None,
) -> dict[str, Choice[Raw | None]]:
    """Record one process or composable node with the context's remaps and parameters."""
    none: Choice[Raw | None] = Choice.const(it.space, None)
    fields: dict[str, Choice[Raw | None]] = {}
    for key in FIELDS:
        value = (
            _command_line(it, entity, key, context)
            if key in COMMAND_LINES
            else it.attr(entity, key, context)
        )
        fields[key] = none if value is None else optional(value)
    fields["ros_namespace"] = context.namespace or none
    fields["kind"] = Choice.const(it.space, kind)
    fields["container"] = container or none
    remaps = [Remap(r.condition, r.source, r.target) for r in context.remaps or ()]
    parameters = [
        NodeParameter(p.condition, p.name, p.value, p.file, globally=True)
        for p in context.params or ()
    ]
    env: list[EnvSetting] = []
    for child in entity.children:
        if child.tag in NESTED:
            continue
        with it.at(child), it.under(it.condition_of(child, context)) as live:
            if not live:
                continue
            if child.tag == "remap":
                _remap(it, child, context, remaps)
            elif child.tag == "param":
                _param(it, child, context, "", parameters)
            elif child.tag == "env":
                _env(it, child, context, env)
    it.model.nodes.append(
        NodeDecl(
            it.pc,
            entity.location,
            context.filename,
            False,
            fields,
            remaps,
            env,
            ROS2.nodes,
            parameters=parameters,
        )
    )
    return fields


def _command_line(
    it: Interpretation[Context], entity: Entity, key: str, context: Context
) -> Choice[Raw] | None:
    text = entity.get(key)
    if text is None:
        return None
    value = Ros2Substituter(it).command_line(text, context)
    return it.strip(value, f"<{entity.tag}> attribute '{key}'")


def _remap(it: Interpretation[Context], entity: Entity, context: Context, out: list[Remap]) -> None:
    source, target = it.required(entity, "from", context), it.required(entity, "to", context)
    if source is None or target is None:
        return
    for condition, (s, t) in split(it, combine([source, target], tuple)):
        out.append(Remap(it.pc & condition, s, t))


def _env(
    it: Interpretation[Context], entity: Entity, context: Context, out: list[EnvSetting]
) -> None:
    name, value = it.required(entity, "name", context), it.required(entity, "value", context)
    if name is None or value is None:
        return
    for condition, (n, v) in split(it, combine([name, value], tuple)):
        out.append(EnvSetting(it.pc & condition, n, v))


def _param(
    it: Interpretation[Context],
    entity: Entity,
    context: Context,
    prefix: str,
    out: list[NodeParameter],
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
