"""``rosvar interfaces``: the topics, services, actions and parameters of every node and
nodelet below the given package roots, read from their sources; with ``--missing``, the
launched nodes that still have none (what the catalogue or hints should cover next)."""

from __future__ import annotations

import argparse
import os
import sys
from collections import defaultdict
from typing import TYPE_CHECKING

from rosvar.outputs.commands.exit_codes import EXIT_INPUT, EXIT_OK
from rosvar.outputs.commands.loading import analysis_of, interfaces_of, workspace_of
from rosvar.outputs.commands.terminal import print_json, progress

if TYPE_CHECKING:
    from rosvar.analyses.communication import Uninterfaced


def cmd_interfaces(options: argparse.Namespace) -> int:
    from rosvar.outputs.documents.interfaces import interfaces_document

    if options.missing:
        return _missing(options)
    roots = [os.path.abspath(path) for path in options.paths]
    workspace = workspace_of(options.paths, options)
    packages = [
        package
        for package in workspace.packages.values()
        if any(os.path.commonpath([package.path, root]) in (package.path, root) for root in roots)
    ]
    interfaces = interfaces_of(workspace, options, packages)
    if options.json:
        print_json(interfaces_document(interfaces))
        return EXIT_OK
    for node in interfaces.listed():
        print(f"{node.package} {node.executable} ({node.kind})")
        for entry in node.entries:
            detail = entry.type if entry.type is not None else f"default {entry.default}"
            print(f"  {entry.role:<14} {entry.name:<40} {detail}  {entry.location}")
    for diagnostic in interfaces.diagnostics:
        print(diagnostic, file=sys.stderr)
    return EXIT_OK


def _missing(options: argparse.Namespace) -> int:
    """The launched executables and nodelet classes that no source, catalogue entry or hint
    gives an interface, most launched (``<node>`` elements) first; those of a package outside
    the workspace (third-party, what the catalogue is for) apart from the workspace's own."""
    from rosvar.analyses.communication import uninterfaced

    analysis = analysis_of(options)
    if analysis is None:
        return EXIT_INPUT
    options.catalogue = True  # the catalogue counts as an interface, as in the graph
    interfaces = interfaces_of(analysis.workspace, options)
    models = analysis.all_models(progress)
    found = missing_units(uninterfaced(analysis.space, models, interfaces))
    own = set(analysis.workspace.packages)
    rows = [
        {
            "executable": unit,
            "launches": len(sites),
            "third_party": unit.split("/")[0] not in own,
            "launched_at": sites,
        }
        for unit, sites in found
    ]
    if options.json:
        print_json({"missing": rows})
        return EXIT_OK
    for row in rows:
        where = "third-party" if row["third_party"] else "workspace"
        print(f"{row['launches']:>4}  {row['executable']}  ({where})")
    return EXIT_OK


def missing_units(nodes: list[Uninterfaced]) -> list[tuple[str, list[str]]]:
    """Per executable (``pkg/exec``, a nodelet's ``pkg/Class``): the ``<node>`` elements that
    launch it (``file:line``), most launched first, then by name."""
    sites: defaultdict[str, list[str]] = defaultdict(list)
    for node in nodes:
        sites[node.unit].append(f"{node.location.file}:{node.location.line}")
    return sorted(sites.items(), key=lambda item: (-len(item[1]), item[0]))
