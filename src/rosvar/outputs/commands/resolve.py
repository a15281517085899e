"""``rosvar resolve``: one concrete configuration, as roslaunch (or ros2 launch) would load
it: its nodes, parameters and communication graph, conflicts and errors."""

from __future__ import annotations

import argparse
import os
import sys
from typing import TYPE_CHECKING

from rosvar.diagnostics import Location
from rosvar.outputs.commands.exit_codes import EXIT_FAILS, EXIT_INPUT, EXIT_OK, EXIT_USAGE
from rosvar.outputs.commands.loading import (
    environment_of,
    interfaces_of,
    launch_files_of,
    warn_unknown_args,
    workspace_of,
)
from rosvar.outputs.commands.terminal import print_json, shown_location
from rosvar.ros.names import command_line_mappings
from rosvar.ros.version import RosVersion

if TYPE_CHECKING:
    from rosvar.workspace import Workspace


def cmd_resolve(options: argparse.Namespace) -> int:
    from rosvar.analyses.communication import resolved_graph
    from rosvar.analyses.robot_description.edges import configuration_edges
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.ros1.resolve import resolve

    paths = [os.path.abspath(words[0]) for words in options.launch if len(words) == 1]
    missing = [f for f in paths if not os.path.isfile(f)]
    if missing:
        print(f"rosvar: launch file not found: {', '.join(missing)}", file=sys.stderr)
        return EXIT_INPUT
    # the launch files' own packages are known even when no PATH contains them
    workspace = workspace_of([*options.paths, *paths], options)
    files = launch_files_of(options.launch, workspace)
    if files is None:
        return EXIT_INPUT
    env = environment_of(options.env)
    if env is None:
        return EXIT_USAGE
    args = command_line_mappings(options.args)
    if len(files) == 1 and workspace.ros_version is RosVersion.ROS2:
        return _resolve_ros2(workspace, files[0], args, env, options)
    # The given values become known slots: conditions split on them instead of
    # leaving them to <other> terms (the semantics does not change).
    analysis = Analysis(
        workspace,
        extra_values={k: [v] for k, v in args.items()},
        env_values={k: [v] for k, v in env.items()},
    )
    warn_unknown_args(analysis, files, args)
    # before resolving: reading the descriptions declares the environment they read
    simulated = configuration_edges(analysis, files, args, env)
    result = resolve(analysis, files, args, env)
    if result.ok:
        result.errors.extend(simulated.errors)
    document = result.to_json()
    interfaces = interfaces_of(workspace, options)
    for diagnostic in interfaces.diagnostics:
        if diagnostic.code == "hints-invalid":
            print(diagnostic, file=sys.stderr)
    graph = resolved_graph(result.nodes, interfaces, result.scopes, result.params, simulated.edges)
    document.update(graph)
    if options.json:
        print_json(document)
    else:
        for node in document["nodes"]:  # type: ignore[attr-defined]
            print(f"node  {node['name']}  ({node['package']}/{node['type']})")
        for name, value in document["params"].items():  # type: ignore[attr-defined]
            print(f"param {name} = {value!r}")
        _print_graph(graph)
        for conflict in result.conflicts:
            where = ", ".join(shown_location(loc) for loc in conflict.locations)
            print(f"conflict: {conflict.kind} {conflict.name} at {where}")
        for error in result.errors:
            print(f"error: {shown_location(error.location)}: {error.message}")
    return EXIT_OK if result.ok else EXIT_FAILS


def _print_graph(graph: dict[str, list[dict[str, object]]]) -> None:
    from rosvar.analyses.communication import JSON_SIDES, Channel

    for channel in Channel:
        provided, used = JSON_SIDES[channel]
        for element in graph[channel]:
            types = ", ".join(element["types"])  # type: ignore[arg-type]
            providers = ", ".join(element[provided]) or "-"  # type: ignore[arg-type]
            users = ", ".join(element[used]) or "-"  # type: ignore[arg-type]
            print(f"{channel[:-1]:<7} {element['name']} [{types}]: {providers} → {users}")


def _resolve_ros2(
    workspace: Workspace,
    file: str,
    args: dict[str, str],
    env: dict[str, str],
    options: argparse.Namespace,
) -> int:
    """``ros2 launch FILE name:=value``: the nodes it starts (in the ROS 2 oracle's shape),
    and the topics, services and actions their interfaces give."""
    from rosvar.analyses.communication import resolved_graph
    from rosvar.ros2.conventions.namespaces import unnamed
    from rosvar.ros2.resolve import resolve_ros2

    result = resolve_ros2(workspace, file, args, env)
    graph = resolved_graph(result.nodes, interfaces_of(workspace, options))
    if options.json:
        print_json({**result.to_json(), **graph})
    else:
        for node in result.nodes:
            name = node["fqn"] or unnamed(node["namespace"], node["executable"])  # type: ignore[arg-type]
            print(f"node  {name}  ({node['package']}/{node['executable']})")
            for name, value in node["parameters"].items():  # type: ignore[attr-defined]
                print(f"  param {name} = {value!r}")
            for source, target in node["remappings"]:  # type: ignore[attr-defined]
                print(f"  remap {source} -> {target}")
        _print_graph(graph)
        for error in result.errors:
            at = Location(**error["location"])  # type: ignore[arg-type]
            print(f"error: {shown_location(at)}: {error['message']}")
    return EXIT_OK if result.ok else EXIT_FAILS
