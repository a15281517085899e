"""What the commands read from their options: the workspace, the hints, the node interfaces,
the analysis, the launch files and environment of a configuration. Problems found on the way
are printed on stderr, and a command that cannot start is told so by a None."""

from __future__ import annotations

import argparse
import difflib
import os
import sys
from collections.abc import Iterable, Mapping, Sequence
from typing import TYPE_CHECKING

from rosvar.outputs.commands.exit_codes import EXIT_INPUT, EXIT_USAGE

if TYPE_CHECKING:
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.workspace import Workspace
    from rosvar.workspace.hints import Hints
    from rosvar.workspace.interfaces.model import Interfaces
    from rosvar.workspace.packages import Package


def workspace_of(paths: Sequence[str], options: argparse.Namespace) -> Workspace:
    """The packages and launch files below ``paths``; those below ``--deps`` (then the
    environment's ROS_PACKAGE_PATH and AMENT_PREFIX_PATH) resolve ``$(find)`` but add no
    launch files."""
    from rosvar.workspace import discover

    workspace = discover(paths, deps=options.deps, allow_outside=options.allow_outside_workspace)
    for diagnostic in workspace.diagnostics:
        print(diagnostic, file=sys.stderr)
    return workspace


def warn_unknown_args(analysis: Analysis, files: Sequence[str], args: Mapping[str, str]) -> None:
    """A ``name:=value`` that no launched file reads is ignored (by roslaunch too): say so,
    a misspelt name would otherwise go unnoticed."""
    known = sorted({name for file in files for name in analysis.model(file).inputs})
    for name in args:
        if name not in known:
            near = difflib.get_close_matches(name, known, n=1)
            hint = f"; did you mean '{near[0]}'?" if near else ""
            print(
                f"rosvar: warning: no launched file has an arg '{name}'; it is ignored{hint} "
                f"(args: {', '.join(known) or 'none'})",
                file=sys.stderr,
            )


def launch_files_of(launches: Sequence[Sequence[str]], workspace: Workspace) -> list[str] | None:
    """``--launch FILE`` and ``--launch PKG FILE`` (looked up as ``roslaunch PKG FILE`` does)
    as paths; None (after a message) when a file cannot be found."""
    files = []
    for words in launches:
        if len(words) == 1:
            files.append(os.path.abspath(words[0]))
            continue
        package, name = words
        found = workspace.find_resource(package, name)
        if found is None or len(found) != 1:
            why = (
                f"package '{package}' is not in the workspace"
                if found is None
                else f"multiple files named [{name}] in package [{package}]: {', '.join(found)}"
                if found
                else f"no file named [{name}] in package [{package}]"
            )
            print(f"rosvar: {why}", file=sys.stderr)
            return None
        files.extend(found)
    return files


def environment_of(items: Sequence[str]) -> dict[str, str] | None:
    """``--env NAME=VALUE`` words as a mapping; None (after a message) when one is malformed."""
    env: dict[str, str] = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name:
            print(f"rosvar: --env expects NAME=VALUE, got {item!r}", file=sys.stderr)
            return None
        env[name] = value
    return env


def analysis_of(
    options: argparse.Namespace,
    env: dict[str, str] | None = None,
    paths: Sequence[str] | None = None,
    args: Mapping[str, str] | None = None,
) -> Analysis | None:
    """The analysis of the workspace below ``paths`` (``options.paths``), with the hints'
    values and the given args and environment as known values; None (after a message) when
    there is no launch file."""
    from rosvar.interpreter.workspace_models import Analysis

    workspace = workspace_of(options.paths if paths is None else paths, options)
    if not workspace.launch_files:
        print("rosvar: no launch files found", file=sys.stderr)
        return None
    hints = hints_of(options)
    for diagnostic in hints.diagnostics:
        print(diagnostic, file=sys.stderr)
    env_values = {k: list(v) for k, v in hints.env.items()}
    arg_values = {k: list(v) for k, v in hints.args.items()}
    for name, value in (args or {}).items():  # given values split conditions, as in resolve
        arg_values.setdefault(name, []).append(value)
    for name, value in (env or {}).items():  # given values split conditions, as in resolve
        env_values.setdefault(name, []).append(value)
    return Analysis(workspace, arg_values, env_values, hints.executables)


def analysis_with_env(options: argparse.Namespace) -> tuple[Analysis, dict[str, str]] | int:
    """The analysis of commands that take ``--env``, or the exit code when it cannot start."""
    env = environment_of(options.env)
    if env is None:
        return EXIT_USAGE
    analysis = analysis_of(options, env)
    return EXIT_INPUT if analysis is None else (analysis, env)


def hints_of(options: argparse.Namespace) -> Hints:
    """The hints file of ``options`` (if any), with a diagnostic per refused ``when:``."""
    from rosvar.workspace.hints import load_hints

    hints = load_hints(getattr(options, "hints", None))
    if hints.nodes:  # the checks of ``when:`` import the interfaces' model: only if needed
        from rosvar.analyses.when import refusals

        hints.diagnostics.extend(refusals(hints.nodes))
    return hints


def interfaces_of(
    workspace: Workspace, options: argparse.Namespace, packages: Iterable[Package] | None = None
) -> Interfaces:
    """The interfaces of ``packages`` (the workspace's), the catalogue of the workspace's
    ROS version when ``options.catalogue``, then the hints' entries."""
    from rosvar.workspace.interfaces.catalogue import load_catalogue
    from rosvar.workspace.interfaces.extraction import extract_interfaces
    from rosvar.workspace.interfaces.overrides import add_catalogue, apply_hints

    everything = workspace.packages.values()
    chosen = everything if packages is None else packages
    interfaces = extract_interfaces(chosen, workspace.confinement(), everything)
    hints = hints_of(options)
    interfaces.diagnostics.extend(hints.diagnostics)
    if getattr(options, "catalogue", True):
        add_catalogue(interfaces, load_catalogue(workspace.ros_version))
    apply_hints(interfaces, hints.nodes)
    return interfaces
