"""``rosvar interfaces``: the topics, services, actions and parameters of every node and
nodelet below the given package roots, read from their sources."""

from __future__ import annotations

import argparse
import os
import sys

from rosvar.outputs.commands.exit_codes import EXIT_OK
from rosvar.outputs.commands.loading import interfaces_of, workspace_of
from rosvar.outputs.commands.terminal import print_json


def cmd_interfaces(options: argparse.Namespace) -> int:
    from rosvar.outputs.documents.interfaces import interfaces_document

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
