"""``<node>`` (launch_ros's ``Node``), ``<executable>``, ``<node_container>`` and
``<load_composable_node>`` with their ``composable_node``, ``param``, ``remap`` and ``env``
children. Composable nodes get the context's remaps and parameters as nodes do.

A node gets the pushed namespace (``ros_namespace``) and, before its own, the global
remaps and parameters of the context; nested ``<param>`` groups make dotted names.
Name composition and parameter files are left to resolution, which sees one configuration.
"""

from __future__ import annotations

from collections.abc import Callable

from rosvar.files import FileRefused, read_file
from rosvar.frontends.entity import Entity
from rosvar.interpreter.booleans import bool_value
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import EnvSetting, NodeDecl, NodeParameter, Raw, Remap
from rosvar.logic.choice import Choice, Fail, combine
from rosvar.ros2.api.actions import SHARED
from rosvar.ros2.context import Context, optional
from rosvar.ros2.conventions.names import node_problem
from rosvar.ros2.conventions.namespaces import make_absolute, prefix_namespace
from rosvar.ros2.conventions.parameters import PARAMETER_TYPES, coerce
from rosvar.ros2.dialect import ROS2, tag
from rosvar.ros2.nodes import NAMES_CHECKED, ProcessKind
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
    container = it.strip(named, "<node_container> name")  # a term: known once configured
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
    if kind in NAMES_CHECKED:  # what launch_ros refuses fails here, where it is known
        fields["name"] = _checked(it, fields["name"], _name_failure, "<node> name")
        fields["namespace"] = _checked(
            it, fields["namespace"], _namespace_failure, "<node> namespace"
        )
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
            trigger=context.trigger,
        )
    )
    started = context.events.started
    key = str(entity.location)
    started[key] = started.get(key, it.space.false) | it.pc  # its start is an event
    return fields


def _checked(
    it: Interpretation[Context],
    value: Choice[Raw | None],
    failure: Callable[[str], Fail | None],
    what: str,
) -> Choice[Raw | None]:
    """``value`` without the known texts launch_ros refuses, each an error (the same
    choice where none is: declarations of one scope share it)."""
    failures = {leaf: failure(leaf) for leaf in value.values() if isinstance(leaf, str)}
    if not any(failures.values()):
        return value
    checked = value.map(lambda leaf: (failures[leaf] or leaf) if isinstance(leaf, str) else leaf)
    return it.strip(checked, what)


def _name_failure(name: str) -> Fail | None:
    problem = node_problem(name, None)
    return None if problem is None else Fail(problem, "node-invalid")


def _namespace_failure(own: str) -> Fail | None:
    """An own namespace as launch_ros makes it absolute (a pushed one is checked when it is
    pushed; an absolute own one replaces it)."""
    problem = node_problem(None, make_absolute(prefix_namespace(None, own)))
    return None if problem is None else Fail(problem, "node-invalid")


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
    own = None if entity.has(SHARED) else it.location  # a rule for several nodes: a group's
    for condition, (s, t) in split(it, combine([source, target], tuple)):
        out.append(Remap(it.pc & condition, s, t, own))


def _env(
    it: Interpretation[Context], entity: Entity, context: Context, out: list[EnvSetting]
) -> None:
    name, value = it.required(entity, "name", context), it.required(entity, "value", context)
    if name is None or value is None:
        return
    for condition, (n, v) in split(it, combine([name, value], tuple)):
        out.append(EnvSetting(it.pc & condition, n, v))


def _untyped_literal(entity: Entity) -> bool:
    """A YAML or Python parameter whose value is a string without substitutions: launch
    takes it as it is, where XML coerces the text (``ParameterValue('7', value_type=int)``
    and ``{value: '7', type: int}`` fail, ``<param value="7" type="int"/>`` is 7)."""
    text = entity.get("value")
    typed_frontend = entity.location.file.endswith((".py", ".yaml", ".yml"))
    return typed_frontend and text is not None and "value" not in entity.typed and "$(" not in text


def _coercion(leaf: Raw, kind: str) -> Fail | None:
    """Why launch refuses ``leaf`` as a value of ``<param type=kind>``, if it does (a value
    known per configuration only is coerced when it is known, by ``resolve``)."""
    if not isinstance(leaf, str):
        return None
    try:
        coerce(leaf, kind)
    except ValueError as error:
        return Fail(str(error), "param-invalid")
    return None


def _substituted_file(
    it: Interpretation[Context], path: str, context: Context, out: list[NodeParameter]
) -> None:
    """``allow_substs``: the file's text with its substitutions performed in the context as
    it is here, as launch_ros' ``ParameterFile`` does before the node reads it."""
    try:
        text = read_file(path, it.workspace.confinement()).decode()
    except (FileRefused, OSError, UnicodeDecodeError) as error:
        it.unread_installs(path)
        it.fail(it.space.true, "param-invalid", f"parameter file {path} is not readable: {error}")
        return
    _substituted_text(it, text, path, context, out)


def _substituted_text(
    it: Interpretation[Context], text: str, path: str, context: Context, out: list[NodeParameter]
) -> None:
    substituted = Ros2Substituter(it).resolve(text, context)
    assert substituted is not None
    value: Choice[Raw] = it.strip(substituted, f"parameter file {path}")
    for condition, leaf in split(it, value):
        out.append(NodeParameter(it.pc & condition, None, None, path, content=leaf))


def _written_file(
    it: Interpretation[Context],
    entity: Entity,
    allow: Choice[bool | Raw],
    context: Context,
    out: list[NodeParameter],
) -> None:
    """A parameter file the Python frontend's helper writes (``content``: its text in each
    configuration, :mod:`rosvar.ros2.frontends.python.written`; ``from``: what wrote it);
    ``allow_substs``: its substitutions performed, as of a file read."""
    label = entity.get("from") or "a file written at launch time"
    text = it.attr(entity, "content", context)
    assert text is not None
    for condition, leaf in split(it, text):
        substs = allow.where(lambda value: value is True) & condition
        if isinstance(leaf, str) and substs != it.space.false:
            with it.under(substs):
                _substituted_text(it, leaf, label, context, out)
        plain = condition & ~substs if isinstance(leaf, str) else condition
        if plain != it.space.false:
            out.append(NodeParameter(it.pc & plain, None, None, label, content=leaf))


def _param(
    it: Interpretation[Context],
    entity: Entity,
    context: Context,
    prefix: str,
    out: list[NodeParameter],
) -> None:
    source = it.attr(entity, "from", context)
    label = "<param> attribute 'allow_substs'"
    if "content" in entity.attributes:
        allow = bool_value(it, it.attr(entity, "allow_substs", context), False, label)
        _written_file(it, entity, allow, context, out)
        return
    if source is not None:
        allow = bool_value(it, it.attr(entity, "allow_substs", context), False, label)
        for condition, file in split(it, source):
            substs = allow.where(lambda leaf: leaf is True) & condition
            if isinstance(file, str) and substs != it.space.false:
                with it.under(substs):
                    _substituted_file(it, file, context, out)
            plain = condition & ~substs
            if plain != it.space.false:
                out.append(NodeParameter(it.pc & plain, None, None, file))
        return
    name = it.required(entity, "name", context)
    if name is None:
        return
    nested = [child for child in entity.children if child.tag == "param"]
    value = it.attr(entity, "value", context)
    kind = entity.get("type")  # launch reads the identifier as it is written
    problem = None
    if nested and value is not None:
        problem = "nested parameters and value attributes are mutually exclusive"
    elif kind is not None and kind not in PARAMETER_TYPES:
        problem = f"Got invalid type identifier '{kind}'"
    elif kind is not None and nested:
        problem = "nested parameters and type attributes are mutually exclusive"
    elif kind not in (None, "str", "yaml") and _untyped_literal(entity):
        problem = f"value='{entity.get('value')}' is not an instance of {kind}"
    if problem is not None:
        it.fail(it.space.true, "param-invalid", problem)
        return
    if kind == "yaml" and _untyped_literal(entity):
        kind = "str"  # a YAML or Python string stays one
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
                    refused = _coercion(leaf, kind) if kind else None
                    if refused is not None:
                        it.fail(v_condition, refused.code, refused.message)
                    else:
                        out.append(
                            NodeParameter(it.pc & v_condition, prefix + key, leaf, kind=kind)
                        )
