"""``ros2 launch FILE name:=value``: the nodes ROS 2 would start, in the oracle's shape.

The model of a ROS 2 file interpreted with given arguments holds constant values; this
picks the present elements, composes names (pushed namespace, node namespace) and merges
parameters (global ones, files and inline ones in command-line order).
"""

from __future__ import annotations

import os
import shlex
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Protocol

import yaml

from rosvar import bounded_yaml
from rosvar.diagnostics import Location
from rosvar.files import Confinement, read_file
from rosvar.interpreter.model import LaunchModel, NodeDecl, Raw
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.ros1.resolve import ResolutionError, Restriction
from rosvar.ros2.conventions import command_line
from rosvar.ros2.conventions.parameters import ALL_NODES, Source, effective, file_entries, typed
from rosvar.ros2.launch import interpret
from rosvar.ros2.tags.node import ProcessKind
from rosvar.workspace import Workspace

UNINTERPRETED = frozenset({"nesting-too-deep"})
"""Diagnostics of parts the walk left out (a limit): no configuration can be told without them."""


@dataclass
class Ros2Resolution:
    nodes: list[dict[str, object]] = field(default_factory=list)
    errors: list[dict[str, object]] = field(default_factory=list)
    warnings: list[dict[str, object]] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not self.errors

    def to_json(self) -> dict[str, object]:
        return {
            "ok": self.ok,
            "nodes": self.nodes,
            "errors": self.errors,
            "warnings": self.warnings,
        }


def resolve_ros2(
    workspace: Workspace,
    file: str,
    arguments: Mapping[str, str],
    env: Mapping[str, str] | None = None,
) -> Ros2Resolution:
    space = ConditionSpace()
    model = interpret(workspace, space, file, arguments, env or {})
    return restrict(model, Constant(space), workspace.confinement())


def resolve_variational(
    analysis: Analysis, file: str, arguments: Mapping[str, str], env: Mapping[str, str]
) -> Ros2Resolution:
    """The same, read off the file's model over every command line (``analysis.model``)."""
    model = analysis.model(file)
    view = Restriction(analysis, model, arguments, env)
    return restrict(model, view, analysis.workspace.confinement())


class View(Protocol):
    """One configuration of a model: which conditions hold, what values are."""

    def holds(self, condition: BDD) -> bool: ...

    def pick(self, choice: Choice[object], location: Location, what: str) -> object: ...

    def evaluate(self, value: Raw, location: Location, what: str) -> str: ...


class Constant:
    """The view of a model interpreted with fixed arguments: values are constants, and the
    only inputs, the environment variables read, are not set."""

    def __init__(self, space: ConditionSpace) -> None:
        self.space = space
        self.assignment = space.assignment({})

    def holds(self, condition: BDD) -> bool:
        return self.space.evaluate(condition, self.assignment)

    def pick(self, choice: Choice[object], location: Location, what: str) -> object:
        value = next((leaf for condition, leaf in choice if self.holds(condition)), None)
        if value is not None and not isinstance(value, str):
            raise ValueError(f"{what} is not known")
        return value

    def evaluate(self, value: Raw, location: Location, what: str) -> str:
        if not isinstance(value, str):
            raise ValueError(f"{what} is not known")
        return value


def restrict(model: LaunchModel, view: View, confinement: Confinement) -> Ros2Resolution:
    """The present nodes and errors of ``model`` in the configuration ``view`` shows (its
    parameter files read within ``confinement``)."""
    result = Ros2Resolution()
    for diagnostic in model.diagnostics:
        if diagnostic.code in UNINTERPRETED:
            where = diagnostic.location.to_json()
            result.errors.append(
                {"code": diagnostic.code, "message": diagnostic.message, "location": where}
            )
    for error in model.errors:
        if view.holds(error.condition):
            result.errors.append(
                {"code": error.code, "message": error.message, "location": error.location.to_json()}
            )
    for decl in model.nodes:
        if view.holds(decl.condition):
            try:
                result.nodes.append(_node(decl, view, confinement, result.warnings))
            except (ValueError, ResolutionError) as error:
                result.errors.append(
                    {
                        "code": "node-invalid",
                        "message": str(error),
                        "location": decl.location.to_json(),
                    }
                )
    return result


def _node(
    decl: NodeDecl, view: View, confinement: Confinement, warnings: list[dict[str, object]]
) -> dict[str, object]:
    def text(key: str) -> str | None:
        value = view.pick(decl.field(key), decl.location, f"<node> attribute '{key}'")
        return None if value is None else str(value)

    def known(value: Raw, what: str) -> str:
        return view.evaluate(value, decl.location, what)

    kind = text("kind")
    if kind == ProcessKind.PROCESS:
        return {"kind": kind, "cmd": shlex.split(text("cmd") or "")}
    argv = shlex.split(text("args") or "")
    ros_args = text("ros_args")
    if ros_args is not None:
        argv += ["--ros-args", *shlex.split(ros_args)]
    given = command_line.parse(argv)  # before launch_ros's own --ros-args section
    name = given.name or text("name")
    if given.namespace is not None:
        namespace: str | None = given.namespace
    else:
        texts = {key: text(key) for key in decl.schema.namespace.keys}
        namespace = decl.schema.namespace.text(texts)
    fqn = None
    if name is not None:
        fqn = (namespace or "").rstrip("/") + "/" + name
    sources: list[Source] = []
    for parameter in given.parameters:
        if isinstance(parameter, str):
            sources.append(Source(entries=tuple(parameter_file(parameter, confinement))))
        else:
            sources.append(Source(*parameter))
    for param in decl.parameters:
        if not view.holds(param.condition):
            continue
        if param.file is not None:
            path = known(param.file, "parameter file")
            if param.globally:  # launch_ros asserts that a global parameter file exists
                path = os.path.abspath(path)
                if not os.path.isfile(path):
                    raise ValueError(
                        f"parameter file {path} of <set_parameters_from_file> is missing"
                    )
            elif kind != ProcessKind.COMPOSABLE_NODE and not os.path.isfile(path):
                # launch_ros leaves a node's missing file out, with a warning
                warnings.append(
                    {
                        "code": "parameter-file-missing",
                        "message": f"Parameter file path is not a file: {path}",
                        "location": decl.location.to_json(),
                    }
                )
                continue
            sources.append(Source(entries=tuple(parameter_file(path, confinement))))
        elif param.name is not None and param.value is not None:
            # global (-p) and inline (a generated file) parameters both apply to /**
            value = typed(known(param.value, "parameter value"))
            entry = {known(param.name, "parameter name"): value}
            sources.append(Source(entries=((ALL_NODES, entry),)))
    remaps = [[source, target] for source, target in given.remaps]
    remaps += [
        [known(r.source, "remapping"), known(r.target, "remapping")]
        for r in decl.remaps
        if view.holds(r.condition)
    ]
    return {
        "kind": kind,
        "package": text("pkg"),
        "executable": text("exec"),
        "name": name,
        "namespace": namespace,
        "fqn": fqn,
        "remappings": remaps,
        "parameters": effective(fqn, sources),
        "arguments": None if text("plugin") else given.program,
        "plugin": text("plugin"),
        "container": text("container"),
    }


def parameter_file(path: str, confinement: Confinement) -> list[tuple[str, dict[str, object]]]:
    """A parameter file's entries (node pattern, parameters), read through the workspace's
    gate and the bounded YAML loader; ``ValueError`` when refused or unreadable (a refused
    file is never opened, so nothing of it is told)."""
    try:
        text = read_file(path, confinement).decode()
    except (OSError, UnicodeDecodeError) as error:
        raise ValueError(f"parameter file {path} is not readable: {error}") from None
    try:
        return file_entries(bounded_yaml.safe_load(text))
    except yaml.YAMLError as error:
        raise ValueError(f"parameter file {os.path.basename(path)}: {error}") from None
