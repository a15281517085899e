"""``ros2 launch FILE name:=value``: what ROS 2 would start, read off the file's model.

The file's model over every command line is restricted to the given arguments, as ROS 1's
resolution does (:class:`~rosvar.interpreter.resolution.Restriction`): the present nodes are
picked, their names composed (the pushed namespace, the node's own, its ``--ros-args``
renames) and their parameters merged (the ``--ros-args`` ones, then global ones, files and
inline ones, in command-line order).
"""

from __future__ import annotations

import os
import shlex
from collections.abc import Mapping, Sequence

import yaml

from rosvar import bounded_yaml
from rosvar.diagnostics import Diagnostic, Location, Severity, leaves_unknown
from rosvar.files import Confinement, read_file
from rosvar.interpreter import resolution
from rosvar.interpreter.model import (
    INCLUDE_UNREAD,
    LaunchModel,
    NodeDecl,
    NodeField,
    NodeParameter,
    Raw,
)
from rosvar.interpreter.resolution import (
    Checks,
    Resolution,
    ResolutionError,
    ResolvedNode,
    Restriction,
)
from rosvar.memo import Memo
from rosvar.ros2.api.event_handlers import EVENT_HANDLERS
from rosvar.ros2.conventions import command_line
from rosvar.ros2.conventions.names import node_problem
from rosvar.ros2.conventions.namespaces import unnamed
from rosvar.ros2.conventions.parameters import (
    ALL_NODES,
    Source,
    coerce,
    effective,
    file_entries,
    typed,
)
from rosvar.ros2.nodes import NAMES_CHECKED, ROS2_NODES, ProcessKind

UNINTERPRETED = frozenset({"nesting-too-deep"})
"""Diagnostics of parts the walk left out (a limit): no configuration can be told without them."""
LATER = frozenset(h.tag for h in EVENT_HANDLERS if not h.at_launch)
"""The triggers of what starts after the launch started."""
SETTLED = frozenset({"value-too-complex", "package-unknown"})
"""Warnings of the model that one configuration settles: a value computed again with its
concrete values, a package that, where it matters, fails as ``value-unknown``."""


def resolve(
    models: resolution.Models, files: Sequence[str], args: Mapping[str, str], env: Mapping[str, str]
) -> Resolution:
    """What ``ros2 launch FILE name:=value...`` starts for each of ``files`` (each launched
    on its own: ``ros2 launch`` takes one file), in environment ``env``."""
    result = Resolution()
    for file in files:
        model = models.model(file)
        restriction = Restriction(models, model, args, env)
        for diagnostic in model.diagnostics:
            if diagnostic.code in UNINTERPRETED:
                where = diagnostic.location
                result.errors.append(ResolutionError(diagnostic.code, diagnostic.message, where))
        result.warnings.extend(_unfollowed(model, restriction))
        for error in model.errors:
            if restriction.holds(error.condition):
                result.errors.append(restriction.error(error))
        for decl in model.nodes:
            if restriction.holds(decl.condition):
                later = decl.trigger.partition("(")[0] in LATER
                try:
                    (result.on_events if later else result.nodes).append(
                        _node(decl, restriction, result.warnings)
                    )
                except (ValueError, ResolutionError) as error:
                    result.errors.append(ResolutionError("node-invalid", str(error), decl.location))
    return result


def _unfollowed(model: LaunchModel, r: Restriction) -> list[Diagnostic]:
    """What rosvar did not follow in the files this configuration loads (the Python
    frontend's ``python-not-followed``, a module or a read refused...), as ``analyze`` lists
    it: a node whose parameters a helper rewrote would otherwise seem to have none. A
    launch file included only in other configurations says nothing; a module's diagnostics
    are kept wherever it was imported; an include rosvar did not read, where it is made."""
    loaded = {model.file}
    unread = set()
    for include in model.includes:
        if r.holds(include.condition):
            if not include.resolved:
                unread.add(include.location)
            try:
                loaded.add(r.raw(include.file, include.location, "<include> file") or "")
            except ResolutionError:
                continue  # the include's own error says it
    return [
        diagnostic
        for diagnostic in model.diagnostics
        if diagnostic.severity is Severity.WARNING
        and leaves_unknown(diagnostic)
        and diagnostic.code not in SETTLED
        and (diagnostic.location.file in loaded or diagnostic.location.file not in model.files)
        and (diagnostic.code != INCLUDE_UNREAD or diagnostic.location in unread)
    ]


def _node(decl: NodeDecl, r: Restriction, warnings: list[Diagnostic]) -> ResolvedNode:
    """The process ``decl`` starts, named and given its parameters as launch_ros and rcl
    do."""
    schema = decl.schema

    def text(key: str) -> str | None:
        choice = decl.field(key)
        if not r.holds(choice.covered()):  # it failed here: the model's error says why
            return None
        value = r.pick(choice, decl.location, f"<node> attribute '{key}'")
        return None if value is None else str(value)

    def read(accessor: NodeField) -> str | None:
        return accessor.text({key: text(key) for key in accessor.keys})

    def known(value: Raw, what: str) -> str:
        return r.evaluate(value, decl.location, what)

    kind = text("kind")
    if kind == ProcessKind.PROCESS:
        cmd = shlex.split(text("cmd") or "")
        program = cmd[0] if cmd else None
        attributes = _attributes(kind, None, None, None, None, cmd, decl.trigger)
        return ResolvedNode(
            name=unnamed(None, os.path.basename(program or "")),
            own_name=None,
            namespace=None,
            package=None,
            executable=program,
            args=shlex.join(cmd[1:]),
            plugin=None,
            remaps=[],
            env=_env(decl, r),
            location=decl.location,
            filename=decl.filename,
            version=schema.version,
            attributes=attributes,
        )
    argv = shlex.split(text("args") or "")
    ros_args = text("ros_args")
    if ros_args is not None:
        argv += ["--ros-args", *shlex.split(ros_args)]
    check_node({key: text(key) for key in CHECKED}, decl.location)
    given = command_line.parse(argv)  # before launch_ros's own --ros-args section
    name = given.name or read(schema.name)
    namespace = given.namespace if given.namespace is not None else read(schema.namespace)
    fqn = None if name is None else (namespace or "").rstrip("/") + "/" + name
    parameters = effective(fqn, _sources(decl, r, given, kind, warnings))
    remaps = list(given.remaps)
    remaps += [
        (known(remap.source, "remapping"), known(remap.target, "remapping"))
        for remap in decl.remaps
        if r.holds(remap.condition)
    ]
    executable, plugin = read(schema.executable), read(schema.plugin)
    arguments = None if plugin else given.program
    return ResolvedNode(
        name=fqn or unnamed(namespace, executable),
        own_name=name,
        namespace=namespace,
        package=read(schema.package),
        executable=executable,
        args=text("args") or "",
        plugin=plugin,
        remaps=remaps,
        env=_env(decl, r),
        location=decl.location,
        filename=decl.filename,
        version=schema.version,
        attributes=_attributes(kind, fqn, plugin, text("container"), arguments, None, decl.trigger),
        parameters=parameters,
    )


def _attributes(
    kind: str | None,
    fqn: str | None,
    plugin: str | None,
    container: str | None,
    arguments: list[str] | None,
    cmd: list[str] | None,
    trigger: str,
) -> dict[str, object]:
    """What only a ROS 2 process has, named as the oracle names it: what it is (``kind``: a
    node, a lifecycle node, a container, a composable node, a process), its fully qualified
    name (None where its code names it), a composable node's class and container, the
    program's own arguments (not a composable node's), a process's command, and what starts
    it (``trigger``: ``launch``, ``timer@2s``, ``on_process_start(FILE:LINE:COL)``...)."""
    return {
        "kind": kind,
        "fqn": fqn,
        "plugin": plugin,
        "container": container,
        "arguments": arguments,
        "cmd": cmd,
        "trigger": trigger,
    }


def _env(decl: NodeDecl, r: Restriction) -> list[tuple[str, str]]:
    """The ``<env>`` settings of the process, in order."""
    return [
        (r.evaluate(e.name, decl.location, "env"), r.evaluate(e.value, decl.location, "env"))
        for e in decl.env
        if r.holds(e.condition)
    ]


def _sources(
    decl: NodeDecl,
    r: Restriction,
    given: command_line.RosArguments,
    kind: str | None,
    warnings: list[Diagnostic],
) -> list[Source]:
    """The node's parameter sources in the order rcl reads them: its ``--ros-args`` ones,
    then the global ones and its own (files and inline values)."""
    sources: list[Source] = []
    for parameter in given.parameters:
        if isinstance(parameter, str):
            sources.append(Source(entries=tuple(parameter_file(parameter, r.confinement))))
        else:
            sources.append(Source(*parameter))
    for param in decl.parameters:
        if not r.holds(param.condition):
            continue
        if param.content is not None:  # allow_substs: the text substituted
            text = r.evaluate(param.content, decl.location, "parameter file")
            path = r.evaluate(param.file or "", decl.location, "parameter file")
            sources.append(Source(entries=tuple(parameter_entries(text, path))))
        elif param.file is not None:
            path = r.evaluate(param.file, decl.location, "parameter file")
            if param.globally:  # launch_ros asserts that a global parameter file exists
                path = os.path.abspath(path)
                if not os.path.isfile(r.confinement.source(path)):
                    raise ValueError(
                        f"parameter file {path} of <set_parameters_from_file> is missing"
                    )
            elif kind != ProcessKind.COMPOSABLE_NODE and not os.path.isfile(
                r.confinement.source(path)
            ):
                # launch_ros leaves a node's missing file out, with a warning
                message = f"Parameter file path is not a file: {path}"
                warnings.append(
                    Diagnostic("parameter-file-missing", Severity.WARNING, message, decl.location)
                )
                continue
            sources.append(Source(entries=tuple(parameter_file(path, r.confinement))))
        elif param.name is not None and param.value is not None:
            # global (-p) and inline (a generated file) parameters both apply to /**
            text = r.evaluate(param.value, decl.location, "parameter value")
            value = typed(text) if param.kind is None else coerce(text, param.kind)
            entry = {r.evaluate(param.name, decl.location, "parameter name"): value}
            sources.append(Source(entries=((ALL_NODES, entry),)))
    return sources


def parameter_file(path: str, confinement: Confinement) -> list[tuple[str, dict[str, object]]]:
    """A parameter file's entries (node pattern, parameters), read through the workspace's
    gate and the bounded YAML loader; ``ValueError`` when refused or unreadable (a refused
    file is never opened, so nothing of it is told)."""
    try:
        text = read_file(path, confinement).decode()
    except (OSError, UnicodeDecodeError) as error:
        raise ValueError(f"parameter file {path} is not readable: {error}") from None
    return parameter_entries(text, path)


def given_entries(
    parameter: NodeParameter, confinement: Confinement
) -> list[tuple[str, dict[str, object]]] | None:
    """The entries of a node's parameter file whose text is known (read inside the
    workspace's confinement; ``allow_substs``: its substituted text); None where it is not
    (a path or text known only per configuration, a file refused or unreadable: the model's
    diagnostics say so)."""
    path = parameter.file
    if path is None or not isinstance(path, str):
        return None
    try:
        if parameter.content is None:
            return parameter_file(path, confinement)
        if isinstance(parameter.content, str):
            return parameter_entries(parameter.content, path)
    except ValueError:
        pass
    return None


_PARSED: Memo[str, list[tuple[str, dict[str, object]]]] = Memo(256)
"""Parameter files' entries by their text: the checks read a node's files in every entry file
that launches it (a shared YAML parsed 30,000 times in ``check`` of ros2dense-120)."""


def parameter_entries(text: str, path: str) -> list[tuple[str, dict[str, object]]]:
    """The entries of a parameter file's text (a new list; the callers only read the
    entries); ``ValueError`` when it is no such file."""
    found = _PARSED.get(text)
    if found is None:
        try:
            found = _PARSED[text] = file_entries(bounded_yaml.safe_load(text))
        except yaml.YAMLError as error:
            raise ValueError(f"parameter file {os.path.basename(path)}: {error}") from None
    return list(found)


def node_fields(
    node: NodeDecl,
    text: Mapping[str, str | None],
    parameters: Sequence[tuple[str | None, str | None]],
    confinement: Confinement,
) -> dict[str, object]:
    """A node's name, namespace, arguments and parameters as ``ros2 launch`` composes them:
    the pushed namespace, the node's own, its parameters merged in order (as
    :func:`resolve`'s). A node
    with no name takes one from its executable at run time: it is shown as ``⟨EXEC⟩`` in its
    namespace, its ``fqn`` null. A parameter not known yet (an arg still open) or a file not
    readable is left out."""
    fqn = node.schema.full_name.text(text)
    sources: list[Source] = []
    for first, second in parameters:
        try:
            if not first:
                sources.append(Source(entries=tuple(parameter_file(second or "", confinement))))
            else:
                sources.append(Source(entries=((ALL_NODES, {first: typed(second or "")}),)))
        except ValueError:
            continue
    return {
        "name": node.schema.label.text(text),
        "fqn": fqn,
        "namespace": node.schema.namespace.text(text) or "/",
        "args": text.get("args") or "",
        "parameters": effective(fqn, sources),
        "trigger": node.trigger,
    }


CHECKED = ("kind", *ROS2_NODES.name.keys, *ROS2_NODES.namespace.keys)
"""The fields :func:`check_node` reads."""


def check_node(text: Mapping[str, str | None], location: Location) -> dict[str, object]:
    """launch_ros's checks of a node's strings: its name and its namespace (the pushed one
    prefixed) valid names, or the launch stops (``node-invalid``)."""
    if text.get("kind") in NAMES_CHECKED:
        name, namespace = ROS2_NODES.name.text(text), ROS2_NODES.namespace.text(text)
        problem = node_problem(name, namespace)
        if problem is not None:
            raise ResolutionError("node-invalid", problem, location)
    return {}


def _no_test(_text: Mapping[str, str | None], _location: Location) -> dict[str, object]:
    """ROS 2 has no ``<test>`` (launch_testing's tests are processes)."""
    return {}


def _remap_unchecked(_source: str | None, _target: str | None, _location: Location) -> None:
    """launch_ros hands a remap's names to the node unchecked."""


def _coerced(text: str, kind: str, location: Location) -> None:
    """launch_ros coerces a ``<param type>``'s text as the launch loads (``param-invalid``
    where it cannot: ``type="int"`` of a text typed ``abc``)."""
    try:
        coerce(text, kind)
    except ValueError as error:
        raise ResolutionError("param-invalid", str(error), location) from None


ROS2_CHECKS = Checks(node=check_node, test=_no_test, remap=_remap_unchecked, parameter=_coerced)
"""launch_ros's checks of a node's strings, for the typed texts of the configuration graph."""
