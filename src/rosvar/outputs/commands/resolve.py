"""``rosvar resolve``: one concrete configuration, as roslaunch (or ros2 launch) would load
it: its nodes, parameters and communication graph, conflicts, errors and warnings, one
printer (and one JSON document) for both ROS versions."""

from __future__ import annotations

import argparse
import os
import sys
from typing import TYPE_CHECKING

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

if TYPE_CHECKING:
    from rosvar.analyses.communication import ResolvedGraph
    from rosvar.interpreter.resolution import Resolution


def cmd_resolve(options: argparse.Namespace) -> int:
    from rosvar.analyses.communication import resolved_graph
    from rosvar.analyses.robot_description.edges import configuration_edges
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.outputs.documents.resolution import graph_document, resolution_document

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
    # The given values become known slots: conditions split on them instead of
    # leaving them to <other> terms (the semantics does not change).
    analysis = Analysis(
        workspace,
        extra_values={k: [v] for k, v in args.items()},
        env_values={k: [v] for k, v in env.items()},
    )
    warn_unknown_args(analysis, files, args)
    interfaces = interfaces_of(workspace, options)
    for diagnostic in interfaces.diagnostics:
        if diagnostic.code == "hints-invalid":
            print(diagnostic, file=sys.stderr)
    # before resolving: reading the descriptions declares the environment they read
    simulated = configuration_edges(analysis, files, args, env, interfaces)
    result = analysis.resolve(files, args, env)
    if result.ok:
        result.errors.extend(simulated.errors)
    graph = resolved_graph(result.nodes, interfaces, result.params, simulated.edges)
    if options.json:
        print_json({**resolution_document(result), **graph_document(graph)})
    else:
        _print(result, graph)
    return EXIT_OK if result.ok else EXIT_FAILS


def _print(result: Resolution, graph: ResolvedGraph) -> None:
    """The nodes (a ROS 2 node with the parameters it starts with), the parameter server,
    the communication graph, then why the configuration fails and what it warns of."""
    for node in result.sorted_nodes():
        print(f"node  {node.name}  ({node.package or '-'}/{node.executable or '-'})")
        for name, value in (node.parameters or {}).items():
            print(f"  param {name} = {value!r}")
    for name, value in sorted(result.params.items()):
        print(f"param {name} = {value!r}")
    for channel, entries in graph.items():
        for entry in entries:
            types = ", ".join(entry.types)
            providers, users = ", ".join(entry.providers) or "-", ", ".join(entry.users) or "-"
            print(f"{channel[:-1]:<7} {entry.name} [{types}]: {providers} → {users}")
    for conflict in result.conflicts:
        where = ", ".join(shown_location(loc) for loc in conflict.locations)
        print(f"conflict: {conflict.kind} {conflict.name} at {where}")
    for error in result.errors:
        print(f"error: {shown_location(error.location)}: {error.message}")
    for warning in result.warnings:
        print(f"warning: {shown_location(warning.location)}: {warning.message}")
