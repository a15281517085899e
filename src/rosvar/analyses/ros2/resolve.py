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

import yaml

from rosvar.files import FileRefused, read_file
from rosvar.interpreter.model import LaunchModel, NodeDecl, Raw
from rosvar.interpreter.ros2.interpretation import interpret
from rosvar.logic.conditions import ConditionSpace
from rosvar.ros.ros2_namespaces import full_name, make_absolute, prefix_namespace
from rosvar.ros.ros2_parameters import ALL_NODES, Source, effective, file_entries, typed
from rosvar.workspace import Workspace


@dataclass
class Ros2Resolution:
    nodes: list[dict[str, object]] = field(default_factory=list)
    errors: list[dict[str, object]] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        return not self.errors

    def to_json(self) -> dict[str, object]:
        return {"ok": self.ok, "nodes": self.nodes, "errors": self.errors}


def resolve_ros2(
    workspace: Workspace,
    file: str,
    arguments: Mapping[str, str],
    env: Mapping[str, str] | None = None,
) -> Ros2Resolution:
    space = ConditionSpace()
    model = interpret(workspace, space, file, arguments, env or {})
    return restrict(model)


def restrict(model: LaunchModel) -> Ros2Resolution:
    """The present nodes and errors of a model whose conditions are all constant."""
    true = model.space.true
    result = Ros2Resolution()
    for error in model.errors:
        if error.condition == true:
            result.errors.append(
                {"code": error.code, "message": error.message, "location": error.location.to_json()}
            )
    for decl in model.nodes:
        if decl.condition == true:
            try:
                result.nodes.append(_node(decl))
            except ValueError as error:
                result.errors.append(
                    {
                        "code": "node-invalid",
                        "message": str(error),
                        "location": decl.location.to_json(),
                    }
                )
    return result


def _text(decl: NodeDecl, key: str) -> str | None:
    value: Raw | None = decl.field(key).single()
    if value is not None and not isinstance(value, str):
        raise ValueError(f"<node> attribute '{key}' is not known")
    return value


def _node(decl: NodeDecl) -> dict[str, object]:
    true = decl.condition.bdd.true
    name = _text(decl, "name")
    namespace = make_absolute(
        prefix_namespace(_text(decl, "ros_namespace"), _text(decl, "namespace"))
    )
    fqn = None
    if name is not None:
        fqn = full_name(_text(decl, "ros_namespace"), _text(decl, "namespace"), name)
    sources: list[Source] = []
    for param in decl.parameters:
        if param.condition != true:
            continue
        if param.file is not None:
            sources.append(Source(entries=tuple(_file(str(param.file)))))
        elif param.name is not None and param.value is not None:
            # global (-p) and inline (a generated file) parameters both apply to /**
            value = typed(str(param.value))
            sources.append(Source(entries=((ALL_NODES, {str(param.name): value}),)))
    args = _text(decl, "args")
    return {
        "kind": _text(decl, "kind"),
        "package": _text(decl, "pkg"),
        "executable": _text(decl, "exec") or _text(decl, "cmd"),
        "name": name,
        "namespace": namespace,
        "fqn": fqn,
        "remappings": [[r.source, r.target] for r in decl.remaps if r.condition == true],
        "parameters": effective(fqn, sources),
        "arguments": None if decl.field("plugin").single() else shlex.split(args or ""),
        "plugin": _text(decl, "plugin"),
        "container": _text(decl, "container"),
    }


def _file(path: str) -> list[tuple[str, dict[str, object]]]:
    try:
        text = read_file(path).decode()
    except (FileRefused, OSError, UnicodeDecodeError) as error:
        raise ValueError(f"parameter file {path} is not readable: {error}") from None
    try:
        return file_entries(yaml.safe_load(text))
    except yaml.YAMLError as error:
        raise ValueError(f"parameter file {os.path.basename(path)}: {error}") from None
