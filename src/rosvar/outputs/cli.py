"""The ``rosvar`` command line.

Exit codes: 0 success; 1 the analysed launch configuration fails (errors or
conflicts, ``resolve``) or a choice was refused (``configure``); 2 usage error;
3 nothing to analyse (no launch file found, a ``--launch`` file missing); 4 the feature
model is too large to solve and the command needs its solver.

One module, past the usual length: it is the whole command-line surface — each command's
options, help, examples, printing and exit code, read and changed together — and each
command stays a short function that imports its analyses only when it runs.
"""

from __future__ import annotations

import argparse
import contextlib
import difflib
import gc
import os
import sys
import time
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import replace
from typing import TYPE_CHECKING, cast

from rosvar import __version__
from rosvar.configuration.choices import Action
from rosvar.diagnostics import Diagnostic, Location, Severity
from rosvar.outputs.exports import FORMATS
from rosvar.ros.names import command_line_mappings
from rosvar.ros.version import RosVersion

# Each command imports what it needs when it runs: `dd` (and CUDD), the interpreter, numpy
# and the web server are not what `--version`, `--help` or another command pays for.
if TYPE_CHECKING:
    from rosvar.configuration.engine import ConfigurationState, Progress
    from rosvar.interpreter.model import LaunchModel
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.workspace import Workspace
    from rosvar.workspace.hints import Hints
    from rosvar.workspace.interfaces.model import Interfaces
    from rosvar.workspace.packages import Package

EXIT_OK, EXIT_FAILS, EXIT_USAGE, EXIT_INPUT, EXIT_TOO_LARGE = 0, 1, 2, 3, 4
FILES_PER_JOB = 50
"""Fewest launch files worth a process of their own when ``--jobs`` is not given (each
takes a fork and the return of its results)."""


def _progress(index: int, total: int, file: str) -> None:
    if total >= 50 and sys.stderr.isatty():
        sys.stderr.write(f"\r[{index + 1}/{total}] {os.path.basename(file)[:50]:<50}")
        if index + 1 == total:
            sys.stderr.write("\n")
        sys.stderr.flush()


def _building(tty_only: bool) -> Progress:
    """Shows how far the configuration engine's build is: one line rewritten in place on
    a terminal, else (unless ``tty_only``) a line per phase."""
    tty = sys.stderr.isatty()

    def show(phase: str, done: int, total: int) -> None:
        if tty:
            end = "\n" if phase == "ready" else ""
            counted = f" {done:,}/{total:,}" if total > 1 else ""
            line = f"rosvar: building the configuration engine: {phase}{counted}"
            sys.stderr.write(f"\r{line:<79}{end}")
        elif not tty_only and done == 0:
            sys.stderr.write(f"rosvar: building the configuration engine: {phase} ...\n")
        sys.stderr.flush()

    return show


def _jobs(requested: int | None, files: int) -> int:
    """Processes to analyse ``files`` launch files with: as asked, else one per processor
    this process may use but no fewer than ``FILES_PER_JOB`` files each."""
    from rosvar.forked import available_jobs

    if requested is not None:
        return max(1, requested)
    return max(1, min(available_jobs(), files // FILES_PER_JOB))


def _model_json(model: LaunchModel) -> str:
    import json

    from rosvar.outputs.describe import describe_model

    return json.dumps(describe_model(model), ensure_ascii=False)


def _analyzed_row(model: LaunchModel) -> tuple[tuple[str, int, int, int, int], list[Diagnostic]]:
    """What ``analyze``'s table shows of ``model``, and its diagnostics."""
    counts = (len(model.inputs), len(model.nodes), len(model.params), len(model.errors))
    return (model.file, *counts), model.diagnostics


def _print_json(document: object) -> None:
    """``document`` on stdout: indented for a terminal, on one line for a pipe or a file.

    Python's fast JSON encoder only writes without indentation: indented, printing a large
    analysis takes longer than computing it (``jq`` indents it again)."""
    import json

    indent = 2 if sys.stdout.isatty() else None
    sys.stdout.write(json.dumps(document, indent=indent, ensure_ascii=False) + "\n")


def _workspace(paths: Sequence[str], options: argparse.Namespace) -> Workspace:
    """The packages and launch files below ``paths``; those below ``--deps`` (then the
    environment's ROS_PACKAGE_PATH and AMENT_PREFIX_PATH) resolve ``$(find)`` but add no
    launch files."""
    from rosvar.workspace import discover

    workspace = discover(paths, deps=options.deps, allow_outside=options.allow_outside_workspace)
    for diagnostic in workspace.diagnostics:
        print(diagnostic, file=sys.stderr)
    return workspace


def cmd_analyze(options: argparse.Namespace) -> int:
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.outputs.describe import describe_model

    workspace = _workspace(options.paths, options)
    if not workspace.launch_files:
        print("rosvar: no launch files found", file=sys.stderr)
        return EXIT_INPUT
    analysis = Analysis(workspace)
    jobs = _jobs(options.jobs, len(workspace.launch_files))
    if options.json and sys.stdout.isatty():
        _print_json({"files": analysis.map_models(describe_model, jobs, _progress)})
        return EXIT_OK
    if options.json:  # one line, as _print_json writes it, each file's part by its process
        parts = analysis.map_models(_model_json, jobs, _progress)
        sys.stdout.write('{"files": [' + ", ".join(parts) + "]}\n")
        return EXIT_OK
    rows = analysis.map_models(_analyzed_row, jobs, _progress)
    # a file included by several entry files reports its problems once per entry file: once here
    diagnostics = list(dict.fromkeys(d for _row, found in rows for d in found))
    print(f"{len(rows)} launch files, {len(workspace.packages)} packages")
    print(f"{'file':<60} {'args':>5} {'nodes':>6} {'params':>7} {'errors':>7}")
    for (file, *counts), _found in rows:
        name = _shown(file)
        if len(name) > 60:  # its tail, marked: the file names differ at the end
            name = "…" + name[-59:]
        inputs, nodes, params, failed = counts
        print(f"{name:<60} {inputs:>5} {nodes:>6} {params:>7} {failed:>7}")
    errors = [d for d in diagnostics if d.severity is Severity.ERROR]
    print(f"\n{len(diagnostics)} diagnostics ({len(errors)} errors)")
    for diagnostic in diagnostics[:20]:
        print(f"  {replace(diagnostic, location=_relative(diagnostic.location))}")
    if len(diagnostics) > 20:
        print(f"  ... {len(diagnostics) - 20} more (use --json)")
    return EXIT_OK


def cmd_resolve(options: argparse.Namespace) -> int:
    from rosvar.analyses.communication import resolved_graph
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.ros1.resolve import resolve

    paths = [os.path.abspath(words[0]) for words in options.launch if len(words) == 1]
    missing = [f for f in paths if not os.path.isfile(f)]
    if missing:
        print(f"rosvar: launch file not found: {', '.join(missing)}", file=sys.stderr)
        return EXIT_INPUT
    # the launch files' own packages are known even when no PATH contains them
    workspace = _workspace([*options.paths, *paths], options)
    files = _launch_files(options.launch, workspace)
    if files is None:
        return EXIT_INPUT
    env = _environment(options.env)
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
    _warn_unknown_args(analysis, files, args)
    result = resolve(analysis, files, args, env)
    document = result.to_json()
    interfaces = _interfaces(workspace, options)
    for diagnostic in interfaces.diagnostics:
        if diagnostic.code == "hints-invalid":
            print(diagnostic, file=sys.stderr)
    graph = resolved_graph(result.nodes, interfaces, result.scopes, result.params)
    document.update(graph)
    if options.json:
        _print_json(document)
    else:
        for node in document["nodes"]:  # type: ignore[attr-defined]
            print(f"node  {node['name']}  ({node['package']}/{node['type']})")
        for name, value in document["params"].items():  # type: ignore[attr-defined]
            print(f"param {name} = {value!r}")
        _print_graph(graph)
        for conflict in result.conflicts:
            where = ", ".join(_where(loc) for loc in conflict.locations)
            print(f"conflict: {conflict.kind} {conflict.name} at {where}")
        for error in result.errors:
            print(f"error: {_where(error.location)}: {error.message}")
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
    graph = resolved_graph(result.nodes, _interfaces(workspace, options))
    if options.json:
        _print_json({**result.to_json(), **graph})
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
            print(f"error: {error['message']}")
    return EXIT_OK if result.ok else EXIT_FAILS


def _shown(path: str) -> str:
    """A path for people: relative to the current directory, unless the absolute one is
    shorter (a file far from it)."""
    relative = os.path.relpath(path)
    absolute = os.path.abspath(path)
    return relative if len(relative) <= len(absolute) else absolute


def _relative(location: Location) -> Location:
    """``location`` with its file as :func:`_shown` spells it."""
    return replace(location, file=_shown(location.file))


def _where(location: Location) -> str:
    return str(location if "://" in location.file else _relative(location))


def _warn_unknown_args(analysis: Analysis, files: Sequence[str], args: Mapping[str, str]) -> None:
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


def _launch_files(launches: Sequence[Sequence[str]], workspace: Workspace) -> list[str] | None:
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


def _environment(items: Sequence[str]) -> dict[str, str] | None:
    """``--env NAME=VALUE`` words as a mapping; None (after a message) when one is malformed."""
    env: dict[str, str] = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name:
            print(f"rosvar: --env expects NAME=VALUE, got {item!r}", file=sys.stderr)
            return None
        env[name] = value
    return env


def _analysis(
    options: argparse.Namespace,
    env: dict[str, str] | None = None,
    paths: Sequence[str] | None = None,
    args: Mapping[str, str] | None = None,
) -> Analysis | None:
    from rosvar.interpreter.workspace_models import Analysis

    workspace = _workspace(options.paths if paths is None else paths, options)
    if not workspace.launch_files:
        print("rosvar: no launch files found", file=sys.stderr)
        return None
    hints = _hints(options)
    for diagnostic in hints.diagnostics:
        print(diagnostic, file=sys.stderr)
    env_values = {k: list(v) for k, v in hints.env.items()}
    arg_values = {k: list(v) for k, v in hints.args.items()}
    for name, value in (args or {}).items():  # given values split conditions, as in resolve
        arg_values.setdefault(name, []).append(value)
    for name, value in (env or {}).items():  # given values split conditions, as in resolve
        env_values.setdefault(name, []).append(value)
    return Analysis(workspace, arg_values, env_values, hints.executables)


def _analysis_with_env(options: argparse.Namespace) -> tuple[Analysis, dict[str, str]] | int:
    """The analysis of commands that take ``--env``, or the exit code when it cannot start."""
    env = _environment(options.env)
    if env is None:
        return EXIT_USAGE
    analysis = _analysis(options, env)
    return EXIT_INPUT if analysis is None else (analysis, env)


def cmd_features(options: argparse.Namespace) -> int:
    from rosvar.analyses.feature_model.extraction import extract
    from rosvar.outputs.exports import write

    analysis = _analysis(options)
    if analysis is None:
        return EXIT_INPUT
    model = extract(analysis, progress=_progress)
    text = write(model, options.format)
    if options.format == "text":  # the text summarises its notes: they are listed here
        for diagnostic in model.diagnostics:
            if diagnostic.severity is Severity.NOTE:
                print(diagnostic, file=sys.stderr)
    if options.output:
        with open(options.output, "w", encoding="utf-8") as handle:
            handle.write(text)
    else:
        sys.stdout.write(text)
    return EXIT_OK


METRICS_LEGEND = (
    "LF launch files: LV in no conflict, LC in a potential one (LC_U: an unconditional one, "
    "LC_A: all depend on args)\n"
    "A args a user can set: ACG those affecting the computation graph, AS those of them with "
    "non-Boolean values (AS_D: with a default, AS_V: with values inferred besides it)\n"
    "IF if/unless decided by ACG args (IF_M: the most by one arg); see docs/features.md#metrics"
)


def cmd_metrics(options: argparse.Namespace) -> int:
    """One row per PATH: each is a system, analysed on its own (dependencies come from
    ``--deps`` and ``ROS_PACKAGE_PATH``, not from the other PATHs)."""
    from rosvar.analyses.feature_model.extraction import extract
    from rosvar.analyses.metrics import compute

    rows: dict[str, dict[str, int]] = {}
    for path in options.paths:
        analysis = _analysis(options, paths=[path])
        if analysis is None:
            return EXIT_INPUT
        rows[path] = compute(analysis, extract(analysis, progress=_progress)).to_json()
    if options.json:
        _print_json(next(iter(rows.values())) if len(rows) == 1 else rows)
        return EXIT_OK
    keys = list(next(iter(rows.values())))
    width = max(len("system"), *(len(path) for path in rows))
    print(f"{'system':<{width}}" + "".join(f" {key:>5}" for key in keys))
    for path, metrics in rows.items():
        print(f"{path:<{width}}" + "".join(f" {metrics[key]:>5}" for key in keys))
    print(f"\n{METRICS_LEGEND}")
    return EXIT_OK


def cmd_configure(options: argparse.Namespace) -> int:
    from rosvar.analyses.feature_model.extraction import extract
    from rosvar.configuration.choices import ChoiceError, UserChoice
    from rosvar.configuration.engine import Configurator

    loaded = _analysis_with_env(options)
    if isinstance(loaded, int):
        return loaded
    analysis, env = loaded
    try:
        choices = [UserChoice.parse(action, text) for action, text in options.choices]
        model = extract(analysis, progress=_progress, products=True)
        interfaces = _interfaces(analysis.workspace, options)
        configurator = Configurator(
            analysis, model, env, progress=_building(tty_only=True), interfaces=interfaces
        )
        if options.finish:
            choices += configurator.completion(choices)
        state = configurator.state(choices)
    except ChoiceError as error:
        print(f"rosvar: {error}", file=sys.stderr)
        return EXIT_USAGE
    if options.json:
        _print_json(state.to_json())
    else:
        _print_state(state, analysis.workspace.ros_version)
    return EXIT_FAILS if state.refused else EXIT_OK


def _print_state(state: ConfigurationState, ros: RosVersion) -> None:
    """The summary of a configuration step, for people (a ROS 2 node holds its own
    parameters: they are counted on the nodes, not as the parameter server's)."""
    from rosvar.analyses.feature_model.model import FeatureKind
    from rosvar.configuration.derivation import Presence
    from rosvar.configuration.engine import Selection
    from rosvar.configuration.graph import ElementKind
    from rosvar.outputs.describe import count_text

    features = state.features.values()
    files = [(k, f) for k, f in state.features.items() if f.kind == FeatureKind.FILE]
    print(
        f"{len(state.features) - state.unselected} of {len(state.features)} features decided, "
        f"{state.unselected} unselected; {count_text(state.configurations)} valid configurations"
    )
    for refusal in state.refused:
        print(f"refused: {refusal.reason}")
    chosen = [k for k, f in files if f.state == Selection.SELECTED]
    print(f"selected files: {', '.join(chosen) if chosen else 'none'}")
    summary = state.summary  # the graph in numbers: no condition described
    kinds = [("nodes", ElementKind.NODE)]
    if ros is RosVersion.ROS1:
        kinds.append(("params", ElementKind.PARAM))
    for kind, element in kinds:
        counts = summary.counts[element]
        print(
            f"{kind}: {counts[Presence.PRESENT]} present, "
            f"{counts[Presence.UNDETERMINED]} undetermined"
        )
    if ros is RosVersion.ROS2:
        present = [n for n in state.graph.nodes if n["presence"] == Presence.PRESENT]
        owned = sum(len(cast("dict[str, object]", n.get("parameters") or {})) for n in present)
        print(f"params: {owned} on the present nodes (a ROS 2 node holds its own)")
    for error in summary.errors:
        print(f"error: {error['file']}:{error['line']}: {error['message']}")
    for conflict in state.conflicts:
        when = f", when {conflict.condition}" if conflict.condition else ""
        print(
            f"conflict ({conflict.status}): {' and '.join(conflict.files)}: "
            f"{_clashing(conflict.names)}{when}"
        )
    if state.complete:
        print(
            state.command
            or "nothing to launch (no file selected, or an <other> value lacks its text)"
        )
        return
    open_files = [k for k, f in files if f.state == Selection.UNSELECTED]
    open_args = [
        k
        for k, f in state.features.items()
        if f.kind == FeatureKind.ARG
        and f.state == Selection.SELECTED
        and any(v.parent == k and v.state == Selection.UNSELECTED for v in features)
    ]
    print(f"left: {len(open_files)} files to select or deselect, {len(open_args)} args to set")
    for arg in [*state.untyped, *open_args][:10]:
        print(f"  --set {arg}=...")


SHOWN_NAMES = 3


def _clashing(names: Sequence[str]) -> str:
    """``node /x, param /x/a and 41 params``: the nodes and a few params (two configurations
    of one robot share most of their params; --json has them all)."""
    nodes = [n for n in names if n.startswith("node ")]
    params = [n for n in names if not n.startswith("node ")]
    shown = nodes + params[: max(0, SHOWN_NAMES - len(nodes))]
    left = len(names) - len(shown)
    if not left:
        return ", ".join(shown)
    return f"{', '.join(shown)} and {left} param{'s' if left > 1 else ''}"


class _Choice(argparse.Action):
    """Keeps every choice option in one list, in command-line order."""

    def __call__(
        self,
        parser: argparse.ArgumentParser,
        namespace: argparse.Namespace,
        values: object,
        option_string: str | None = None,
    ) -> None:
        found = list(getattr(namespace, self.dest, None) or [])
        found.append((self.const, str(values)))
        setattr(namespace, self.dest, found)


def cmd_serve(options: argparse.Namespace) -> int:
    from rosvar.analyses.feature_model.extraction import extract
    from rosvar.configuration.engine import Configurator
    from rosvar.outputs.web.server import make_server

    loaded = _analysis_with_env(options)
    if isinstance(loaded, int):
        return loaded
    analysis, env = loaded
    started = time.perf_counter()
    files = len(analysis.workspace.launch_files)
    print(f"rosvar: analysing {files} launch files ...", file=sys.stderr, flush=True)
    model = extract(analysis, progress=_progress, products=True)
    interfaces = _interfaces(analysis.workspace, options)
    configurator = Configurator(
        analysis, model, env, progress=_building(tty_only=False), interfaces=interfaces
    )
    try:
        server = make_server(configurator, options.host, options.port)
    except OSError as error:
        print(f"rosvar: cannot listen on {options.host}:{options.port}: {error}", file=sys.stderr)
        return EXIT_USAGE
    print(f"rosvar: ready in {time.perf_counter() - started:.1f} s", file=sys.stderr)
    print(f"rosvar: serving {server.url} (Ctrl-C stops)", flush=True)
    with server, contextlib.suppress(KeyboardInterrupt):  # Ctrl-C is how it stops
        server.serve_forever()
    return EXIT_OK


PATHS_HELP = (
    "folders to search for ROS packages and launch files (a workspace, a system's folder); "
    "packages on ROS_PACKAGE_PATH and AMENT_PREFIX_PATH are found too"
)
ENV_HELP = (
    "an environment variable of the configuration (repeatable); variables not given are "
    "unset: rosvar never reads its own environment for them"
)
HINTS_HELP = "YAML file with arg and env values analysis cannot infer (docs/hints.md)"
EXAMPLES = {
    "analyze": "rosvar analyze examples\n  rosvar analyze examples --json | jq '.files[0].nodes'",
    "resolve": (
        "rosvar resolve examples robot:=husky --launch examples/example/launch/mapping.launch\n"
        "  rosvar resolve examples --launch example mapping.launch --env ROBOT_HOME=/home/r"
    ),
    "features": (
        "rosvar features examples\n  rosvar features examples --format uvl -o example.uvl"
    ),
    "metrics": "rosvar metrics ../shared/corpus/kobuki ../shared/corpus/lizi",
    "configure": (
        "rosvar configure examples --select examples/example/launch/robot.launch \\\n"
        "      --set examples/example/launch/robot.launch:model=husky --finish"
    ),
    "serve": "rosvar serve examples ../shared/corpus/lizi --port 8080",
    "interfaces": "rosvar interfaces ../shared/corpus/kobuki --json | jq '.interfaces[0]'",
    "query": (
        "rosvar query examples \"nodes[self.package == 'pkg']\" robot:=husky\n"
        "  rosvar query examples 'for n in nodes where n.namespace == \"/\" return n' --json"
    ),
    "check": (
        "rosvar check ../shared/corpus/kobuki --deps ../shared/corpus/_external\n"
        "  rosvar check examples --format sarif --fail-on warning > rosvar.sarif"
    ),
}


def _workspace_options(command: argparse.ArgumentParser) -> None:
    command.add_argument(
        "--deps",
        action="append",
        default=[],
        metavar="PATH",
        help="packages below PATH resolve $(find) and executables but add no launch files "
        "(e.g. /opt/ros/noetic/share; repeatable; ROS_PACKAGE_PATH, then AMENT_PREFIX_PATH, "
        "are read after them)",
    )
    command.add_argument(
        "--allow-outside-workspace",
        action="store_true",
        help="read files (includes, textfile, rosparam) outside PATH, its packages, --deps, "
        "ROS_PACKAGE_PATH and AMENT_PREFIX_PATH (never /proc, /sys, /dev)",
    )


def _command(
    commands: argparse._SubParsersAction[argparse.ArgumentParser], name: str, help_: str
) -> argparse.ArgumentParser:
    """A sub-command with its help, an example and the pointer to the docs."""
    return commands.add_parser(
        name,
        help=help_,
        description=help_[0].upper() + help_[1:] + ".",
        epilog=f"example:\n  {EXAMPLES[name]}\n\nAll commands and options: docs/cli.md",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )


def _hints(options: argparse.Namespace) -> Hints:
    """The hints file of ``options`` (if any), with a diagnostic per refused ``when:``."""
    from rosvar.workspace.hints import load_hints

    hints = load_hints(getattr(options, "hints", None))
    if hints.nodes:  # the checks of ``when:`` import the interfaces' model: only if needed
        from rosvar.analyses.when import refusals

        hints.diagnostics.extend(refusals(hints.nodes))
    return hints


def _interfaces(
    workspace: Workspace, options: argparse.Namespace, packages: Iterable[Package] | None = None
) -> Interfaces:
    """The interfaces of ``packages`` (the workspace's), the catalogue's when
    ``options.catalogue`` and the workspace is ROS 1 (the catalogue's nodes are ROS 1
    builds), then the hints' entries."""
    from rosvar.workspace.interfaces.catalogue import load_catalogue
    from rosvar.workspace.interfaces.extraction import extract_interfaces
    from rosvar.workspace.interfaces.overrides import add_catalogue, apply_hints

    interfaces = extract_interfaces(workspace.packages.values() if packages is None else packages)
    hints = _hints(options)
    interfaces.diagnostics.extend(hints.diagnostics)
    if getattr(options, "catalogue", True) and workspace.ros_version == RosVersion.ROS1:
        add_catalogue(interfaces, load_catalogue())
    apply_hints(interfaces, hints.nodes)
    return interfaces


def cmd_interfaces(options: argparse.Namespace) -> int:
    roots = [os.path.abspath(path) for path in options.paths]
    workspace = _workspace(options.paths, options)
    packages = [
        package
        for package in workspace.packages.values()
        if any(os.path.commonpath([package.path, root]) in (package.path, root) for root in roots)
    ]
    interfaces = _interfaces(workspace, options, packages)
    if options.json:
        _print_json(interfaces.to_json())
        return EXIT_OK
    for node in interfaces.listed():
        print(f"{node.package} {node.executable} ({node.kind})")
        for entry in node.entries:
            detail = entry.type if entry.type is not None else f"default {entry.default}"
            print(f"  {entry.role:<14} {entry.name:<40} {detail}  {entry.location}")
    for diagnostic in interfaces.diagnostics:
        print(diagnostic, file=sys.stderr)
    return EXIT_OK


def _add_interfaces(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    interfaces = _command(
        commands,
        "interfaces",
        "topics, services, actions and parameters of every node and nodelet below PATH "
        "(read from their C++ and Python sources)",
    )
    interfaces.add_argument("paths", nargs="+", metavar="PATH", help="package roots to read")
    _workspace_options(interfaces)
    interfaces.add_argument("--json", action="store_true", help="machine-readable output")
    interfaces.add_argument(
        "--hints", metavar="FILE", help="YAML with interface entries (docs/hints.md, nodes:)"
    )
    interfaces.add_argument(
        "--catalogue",
        action="store_true",
        help="also list the bundled third-party nodes no source below PATH defines",
    )
    interfaces.set_defaults(run=cmd_interfaces)


MAPPING = r"[A-Za-z_~/][\w/~]*:="


def cmd_query(options: argparse.Namespace) -> int:
    import re

    from rosvar.analyses.query.channels import channel_collections
    from rosvar.analyses.query.evaluator import QueryEngine
    from rosvar.analyses.query.parser import QueryError

    words = [*options.words, *options.mappings]
    args = command_line_mappings([w for w in words if re.match(MAPPING, w)])
    *paths, expression = [w for w in options.words if not re.match(MAPPING, w)] or [""]
    if not paths:
        print("rosvar: query needs PATH... and an expression", file=sys.stderr)
        return EXIT_USAGE
    analysis = _analysis(options, paths=paths, args=args)
    if analysis is None:
        return EXIT_INPUT
    analysis.all_models(_progress)  # interpreted once, with the progress shown
    interfaces = _interfaces(analysis.workspace, options)
    engine = QueryEngine(analysis, collections=channel_collections(interfaces))
    _warn_unknown_args(analysis, [m.file for m in engine.models], args)
    try:
        results = engine.run(expression, args)
    except QueryError as error:
        print(f"rosvar: {error}\n  {expression}\n  {' ' * error.col}^", file=sys.stderr)
        return EXIT_USAGE
    documents = [engine.to_json(result) for result in results]
    if options.json:
        _print_json({"query": expression, "results": documents})
        return EXIT_OK
    for document in documents:
        example = document["example"]
        given = " ".join(f"{k}:={v}" for k, v in example.items()) or "(defaults)"  # type: ignore[attr-defined]
        print(f"{document['kind']} {document['name']}  [{document['launch_file']}]")
        print(f"  when {document['condition']}; e.g. {given}")
    print(f"{len(results)} result{'' if len(results) == 1 else 's'}")
    return EXIT_OK


def _add_query(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    query = _command(
        commands,
        "query",
        "the elements a query selects, each with the condition under which it does "
        "(docs/queries.md)",
    )
    query.add_argument(
        "words",
        nargs="+",
        metavar="PATH... EXPR",
        help=PATHS_HELP + "; then the query (COLLECTION[PREDICATE] or "
        "for X in COLLECTION where PREDICATE return X); name:=value words restrict it",
    )
    _workspace_options(query)
    query.add_argument("--hints", metavar="FILE", help=HINTS_HELP)
    query.add_argument("--json", action="store_true", help="the results as JSON")
    query.set_defaults(run=cmd_query)


FAIL_LEVELS = {Severity.NOTE: 0, Severity.WARNING: 1, Severity.ERROR: 2}


def cmd_check(options: argparse.Namespace) -> int:
    from rosvar.analyses.checks import check_models
    from rosvar.outputs.sarif import sarif

    analysis = _analysis(options)
    if analysis is None:
        return EXIT_INPUT
    interfaces = _interfaces(analysis.workspace, options)
    models = analysis.all_models(_progress)
    findings = check_models(analysis.space, models, interfaces, analysis.workspace.confinement())
    if options.format == "sarif":
        _print_json(sarif(findings, analysis.space))
    elif options.format == "json":
        _print_json({"findings": [f.to_json(analysis.space) for f in findings]})
    else:
        for finding in findings:
            where, *related = finding.locations
            document = finding.to_json(analysis.space)
            example = ", ".join(f"{k}={v}" for k, v in document["example"].items())  # type: ignore[attr-defined]
            print(f"{_where(where)}: {finding.severity.value}[{finding.check}]: {finding.message}")
            when = document["condition"]
            when = "in every configuration" if when == "true" else f"when {when}"
            print(f"    {when}" + (f"; e.g. {example}" if example else ""))
            if finding.file != where.file:
                print(f"    launched from {_shown(finding.file)}")
            for location in related:
                print(f"    see {_where(location)}")
        counts = {s: sum(1 for f in findings if f.severity is s) for s in Severity}
        print(
            f"{len(findings)} findings in {len(models)} launch files: "
            + ", ".join(f"{counts[s]} {s.value}s" for s in Severity)
        )
    threshold = FAIL_LEVELS[Severity(options.fail_on)]
    failing = any(FAIL_LEVELS[f.severity] >= threshold for f in findings)
    return EXIT_FAILS if failing else EXIT_OK


def _add_check(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    check = _command(
        commands,
        "check",
        "problems of the communication graph and the parameters in any configuration, "
        "each with its condition and an example (docs/checks.md)",
    )
    check.add_argument("paths", nargs="+", metavar="PATH", help=PATHS_HELP)
    _workspace_options(check)
    check.add_argument("--hints", metavar="FILE", help=HINTS_HELP + "; nodes: interfaces")
    check.add_argument(
        "--format", choices=["text", "json", "sarif"], default="text", help="output format"
    )
    check.add_argument(
        "--fail-on",
        choices=[s.value for s in FAIL_LEVELS],
        default=Severity.ERROR.value,
        help="exit with 1 when a finding is at least this severe (default: error)",
    )
    check.set_defaults(run=cmd_check)


def parser() -> argparse.ArgumentParser:
    top = argparse.ArgumentParser(
        prog="rosvar",
        description="Variability analysis of ROS launch files: all configurations at once.",
        epilog="example:\n  rosvar analyze examples\n\n"
        "'rosvar COMMAND --help' describes a command; all of them: docs/cli.md",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    top.add_argument("--version", action="version", version=f"rosvar {__version__}")
    commands = top.add_subparsers(dest="command", required=True, metavar="COMMAND")
    analyze = _command(commands, "analyze", "interpret every launch file below PATH")
    analyze.add_argument("paths", nargs="+", metavar="PATH", help=PATHS_HELP)
    _workspace_options(analyze)
    analyze.add_argument(
        "--json", action="store_true", help="the whole model as JSON (docs/json-schema.md)"
    )
    analyze.add_argument(
        "-j",
        "--jobs",
        type=int,
        metavar="N",
        help="processes that analyse the files (default: one per processor, at least "
        f"{FILES_PER_JOB} files each); the output is the same for every N",
    )
    analyze.set_defaults(run=cmd_analyze)
    res = _command(commands, "resolve", "one concrete configuration, as roslaunch would load it")
    res.add_argument(
        "paths",
        nargs="*",
        metavar="PATH",
        help=PATHS_HELP + "; name:=value words (the args, as for roslaunch) may stand anywhere",
    )
    _workspace_options(res)
    res.add_argument(
        "--launch",
        action="append",
        nargs="+",
        required=True,
        metavar=("FILE|PKG", "FILE"),
        help="a launch file, or a package and a file name in it (as roslaunch takes them); "
        "repeatable: several files share one command line",
    )
    res.add_argument("--env", action="append", default=[], metavar="NAME=VALUE", help=ENV_HELP)
    res.add_argument(
        "--hints", metavar="FILE", help="YAML with interface entries (docs/hints.md, nodes:)"
    )
    res.add_argument(
        "--json",
        action="store_true",
        help="nodes, params, topics, services, actions, conflicts and errors as JSON",
    )
    res.set_defaults(run=cmd_resolve)
    features = _command(commands, "features", "the feature model (paper Algorithm 1)")
    features.add_argument("paths", nargs="+", metavar="PATH", help=PATHS_HELP)
    _workspace_options(features)
    features.add_argument("--hints", metavar="FILE", help=HINTS_HELP)
    features.add_argument(
        "--format",
        choices=sorted(FORMATS),
        default="text",
        help="text (default; its notes go to stderr), json, uvl, featureide or dot",
    )
    features.add_argument("-o", "--output", metavar="FILE", help="write to FILE, not stdout")
    features.set_defaults(run=cmd_features)
    metrics = _command(commands, "metrics", "the paper's Table I and II metrics")
    metrics.add_argument("paths", nargs="+", metavar="PATH", help="one system per PATH: a row each")
    _workspace_options(metrics)
    metrics.add_argument("--hints", metavar="FILE", help=HINTS_HELP)
    metrics.add_argument(
        "--json", action="store_true", help="the metrics as JSON (keyed by PATH when several)"
    )
    metrics.set_defaults(run=cmd_metrics)
    configure = _command(
        commands, "configure", "one step of a configuration: the state after the given choices"
    )
    configure.add_argument("paths", nargs="+", metavar="PATH", help=PATHS_HELP)
    _workspace_options(configure)
    for action, metavar, help_ in (
        (Action.SELECT, "FEATURE", "put a file, arg or value in the product (FILE, FILE:ARG, "
         "FILE:ARG=VALUE; FILE as a path or as 'rosvar features' prints it)"),
        (Action.DESELECT, "FEATURE", "keep the feature out of the product"),
        (Action.UNSELECT, "FEATURE", "take back the earlier choice on the feature"),
        (Action.SET, "FILE:ARG=VALUE", "give an arg a value (any text: an unknown one is the "
         "arg's <other> value)"),
    ):  # fmt: skip
        configure.add_argument(
            f"--{action}",
            dest="choices",
            action=_Choice,
            const=action,
            metavar=metavar,
            help=help_ + "; repeatable, applied in order",
        )
    configure.set_defaults(choices=[])
    configure.add_argument(
        "--finish",
        action="store_true",
        help="finish with defaults: open args at their default, open files deselected",
    )
    configure.add_argument(
        "--env", action="append", default=[], metavar="NAME=VALUE", help=ENV_HELP
    )
    configure.add_argument("--hints", metavar="FILE", help=HINTS_HELP)
    configure.add_argument(
        "--json", action="store_true", help="the whole state as JSON (docs/configure.md)"
    )
    configure.set_defaults(run=cmd_configure)
    serve = _command(commands, "serve", "configure step by step in the browser")
    serve.add_argument("paths", nargs="+", metavar="PATH", help=PATHS_HELP)
    _workspace_options(serve)
    serve.add_argument("--host", default="127.0.0.1", help="address to bind (default: loopback)")
    serve.add_argument("--port", type=int, default=8080, help="port (0: any free one)")
    serve.add_argument("--env", action="append", default=[], metavar="NAME=VALUE", help=ENV_HELP)
    serve.add_argument("--hints", metavar="FILE", help=HINTS_HELP)
    serve.set_defaults(run=cmd_serve)
    _add_interfaces(commands)
    _add_query(commands)
    _add_check(commands)
    return top


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command of ``argv``; without ``argv`` the process is the command (the
    ``rosvar`` script, ``python -m rosvar``) and ends with it, skipping the interpreter's
    teardown: freeing a large analysis object by object and the modules' clean-up took
    longer than printing its JSON. Callers in a process that lives on pass ``argv``.

    Such a process also does without ``networkx``, which ``dd`` imports for graph exports
    rosvar does not use (it took longer than the rest of ``dd``): ``dd`` copes with its
    absence. Not in a process that lives on: there the different import order made pysat's
    solvers outlive their module at its teardown, with a warning for each."""
    if argv is None:
        sys.modules.setdefault("networkx", None)  # type: ignore[arg-type]
    try:
        code = _main(argv)
    except BaseException:
        gc.collect()
        raise
    if argv is None:
        _exit(code)
    # free BDD nodes before their manager: CUDD complains when the interpreter tears
    # modules down in an arbitrary order
    gc.collect()
    return code


def _exit(code: int) -> None:
    """End the process now, with what was written so far flushed (nothing else runs)."""
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(OSError, ValueError):
            stream.flush()
    os._exit(code)


def _main(argv: Sequence[str] | None) -> int:
    top = parser()
    options, extra = top.parse_known_args(argv)
    mappings = [word for word in extra if ":=" in word]
    if options.command == "query":  # the expression may follow an option
        options.words += [word for word in extra if word not in mappings]
        extra = mappings
    options.mappings = mappings
    if len(mappings) != len(extra) or (mappings and options.command not in ("resolve", "query")):
        top.error(f"unrecognized arguments: {' '.join(w for w in extra if w not in mappings)}")
    if options.command == "resolve":
        # ROS habit: name:=value words may stand anywhere on the command line
        words = [*options.paths, *mappings, *(w for group in options.launch for w in group)]
        options.args = [w for w in words if ":=" in w]
        options.paths = [p for p in options.paths if ":=" not in p]
        options.launch = [[w for w in group if ":=" not in w] for group in options.launch]
        for group in options.launch:
            if len(group) > 2 or (len(group) == 2 and os.path.isfile(group[0])):
                stray = " ".join(group[1:])
                top.error(f"unrecognized arguments: {stray} (--launch takes FILE or PKG FILE)")
    try:
        return int(options.run(options))
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return EXIT_OK
    except Exception as error:
        from rosvar.analyses.feature_model.model import ModelTooLarge  # imported if raised

        if not isinstance(error, ModelTooLarge):
            raise
        # what needs the solver of a model listed but not solved
        print(f"rosvar: the feature model is too large to solve: {error}", file=sys.stderr)
        return EXIT_TOO_LARGE
