"""The ``rosvar`` command line.

Exit codes: 0 success; 1 the analysed launch configuration fails (errors or
conflicts, ``resolve``) or a choice was refused (``configure``); 2 usage error;
3 nothing to analyse (no launch file found, a ``--launch`` file missing).
"""

from __future__ import annotations

import argparse
import contextlib
import gc
import json
import os
import sys
import time
from collections.abc import Sequence

from rosvar import __version__
from rosvar.analyses.features import ModelTooLarge, extract
from rosvar.analyses.metrics import compute
from rosvar.analyses.resolve import resolve
from rosvar.configuration.choices import Action, ChoiceError, UserChoice
from rosvar.configuration.derivation import Presence
from rosvar.configuration.engine import ConfigurationState, Configurator, Selection
from rosvar.diagnostics import Severity
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.describe import describe_model
from rosvar.outputs.exports import WRITERS, write
from rosvar.outputs.web.server import make_server
from rosvar.ros.names import command_line_mappings
from rosvar.workspace import Workspace, discover
from rosvar.workspace.hints import load_hints

EXIT_OK, EXIT_FAILS, EXIT_USAGE, EXIT_INPUT, EXIT_TOO_LARGE = 0, 1, 2, 3, 4


def _progress(index: int, total: int, file: str) -> None:
    if total >= 50 and sys.stderr.isatty():
        sys.stderr.write(f"\r[{index + 1}/{total}] {os.path.basename(file)[:50]:<50}")
        if index + 1 == total:
            sys.stderr.write("\n")
        sys.stderr.flush()


def _print_json(document: object) -> None:
    """``document`` on stdout: indented for a terminal, on one line for a pipe or a file.

    Python's fast JSON encoder only writes without indentation: indented, printing a large
    analysis takes longer than computing it (``jq`` indents it again)."""
    indent = 2 if sys.stdout.isatty() else None
    sys.stdout.write(json.dumps(document, indent=indent, ensure_ascii=False) + "\n")


def _workspace(paths: Sequence[str], options: argparse.Namespace) -> Workspace:
    workspace = discover(paths, allow_outside=options.allow_outside_workspace)
    for diagnostic in workspace.diagnostics:
        print(diagnostic, file=sys.stderr)
    return workspace


def cmd_analyze(options: argparse.Namespace) -> int:
    workspace = _workspace(options.paths, options)
    if not workspace.launch_files:
        print("rosvar: no launch files found", file=sys.stderr)
        return EXIT_INPUT
    analysis = Analysis(workspace)
    models = analysis.all_models(_progress)
    if options.json:
        _print_json({"files": [describe_model(m) for m in models]})
        return EXIT_OK
    cwd = os.getcwd()
    diagnostics = [d for m in models for d in m.diagnostics]
    print(f"{len(models)} launch files, {len(workspace.packages)} packages")
    print(f"{'file':<60} {'args':>5} {'nodes':>6} {'params':>7} {'errors':>7}")
    for model in models:
        name = os.path.relpath(model.file, cwd)
        print(
            f"{name[-60:]:<60} {len(model.inputs):>5} {len(model.nodes):>6} "
            f"{len(model.params):>7} {len(model.errors):>7}"
        )
    errors = [d for d in diagnostics if d.severity is Severity.ERROR]
    print(f"\n{len(diagnostics)} diagnostics ({len(errors)} errors)")
    for diagnostic in diagnostics[:20]:
        print(f"  {diagnostic}")
    if len(diagnostics) > 20:
        print(f"  ... {len(diagnostics) - 20} more (use --json)")
    return EXIT_OK


def cmd_resolve(options: argparse.Namespace) -> int:
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
    # The given values become known slots: conditions split on them instead of
    # leaving them to <other> terms (the semantics does not change).
    analysis = Analysis(
        workspace,
        extra_values={k: [v] for k, v in args.items()},
        env_values={k: [v] for k, v in env.items()},
    )
    result = resolve(analysis, files, args, env)
    document = result.to_json()
    if options.json:
        _print_json(document)
    else:
        for node in document["nodes"]:  # type: ignore[attr-defined]
            print(f"node  {node['name']}  ({node['package']}/{node['type']})")
        for name, value in document["params"].items():  # type: ignore[attr-defined]
            print(f"param {name} = {value!r}")
        for conflict in result.conflicts:
            where = ", ".join(str(loc) for loc in conflict.locations)
            print(f"conflict: {conflict.kind} {conflict.name} at {where}")
        for error in result.errors:
            print(f"error: {error.location}: {error.message}")
    return EXIT_OK if result.ok else EXIT_FAILS


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


def _analysis(options: argparse.Namespace, env: dict[str, str] | None = None) -> Analysis | None:
    workspace = _workspace(options.paths, options)
    if not workspace.launch_files:
        print("rosvar: no launch files found", file=sys.stderr)
        return None
    hints = load_hints(getattr(options, "hints", None))
    for diagnostic in hints.diagnostics:
        print(diagnostic, file=sys.stderr)
    env_values = {k: list(v) for k, v in hints.env.items()}
    for name, value in (env or {}).items():  # given values split conditions, as in resolve
        env_values.setdefault(name, []).append(value)
    return Analysis(workspace, hints.args, env_values, hints.executables)


def _analysis_with_env(options: argparse.Namespace) -> tuple[Analysis, dict[str, str]] | int:
    """The analysis of commands that take ``--env``, or the exit code when it cannot start."""
    env = _environment(options.env)
    if env is None:
        return EXIT_USAGE
    analysis = _analysis(options, env)
    return EXIT_INPUT if analysis is None else (analysis, env)


def cmd_features(options: argparse.Namespace) -> int:
    analysis = _analysis(options)
    if analysis is None:
        return EXIT_INPUT
    model = extract(analysis, progress=_progress)
    text = write(model, options.format)
    if options.output:
        with open(options.output, "w", encoding="utf-8") as handle:
            handle.write(text)
    else:
        sys.stdout.write(text)
    return EXIT_OK


def cmd_metrics(options: argparse.Namespace) -> int:
    analysis = _analysis(options)
    if analysis is None:
        return EXIT_INPUT
    model = extract(analysis, progress=_progress)
    metrics = compute(analysis, model).to_json()
    if options.json:
        _print_json(metrics)
    else:
        print("  ".join(f"{key}={value}" for key, value in metrics.items()))
    return EXIT_OK


def cmd_configure(options: argparse.Namespace) -> int:
    loaded = _analysis_with_env(options)
    if isinstance(loaded, int):
        return loaded
    analysis, env = loaded
    try:
        choices = [UserChoice.parse(action, text) for action, text in options.choices]
        configurator = Configurator(analysis, extract(analysis, progress=_progress), env)
        if options.finish:
            choices += configurator.completion(choices)
        state = configurator.state(choices)
    except ChoiceError as error:
        print(f"rosvar: {error}", file=sys.stderr)
        return EXIT_USAGE
    if options.json:
        _print_json(state.to_json())
    else:
        _print_state(state)
    return EXIT_FAILS if state.refused else EXIT_OK


def _print_state(state: ConfigurationState) -> None:
    """The summary of a configuration step, for people."""
    features = state.features.values()
    files = [(k, f) for k, f in state.features.items() if f.kind == "file"]
    print(
        f"{len(state.features) - state.unselected} of {len(state.features)} features decided, "
        f"{state.unselected} unselected; {state.configurations} valid configurations"
    )
    for refusal in state.refused:
        print(f"refused: {refusal.reason}")
    chosen = [k for k, f in files if f.state == Selection.SELECTED]
    print(f"selected files: {', '.join(chosen) if chosen else 'none'}")
    graph = state.graph
    for kind, elements in (("nodes", graph.nodes), ("params", graph.params)):
        counts = {p: sum(1 for e in elements if e["presence"] == p) for p in Presence}
        print(
            f"{kind}: {counts[Presence.PRESENT]} present, "
            f"{counts[Presence.UNDETERMINED]} undetermined"
        )
    for error in graph.errors:
        if error["presence"] == Presence.PRESENT:
            print(f"error: {error['file']}:{error['line']}: {error['message']}")
    for conflict in state.conflicts:
        when = f", when {conflict.condition}" if conflict.condition else ""
        print(
            f"conflict ({conflict.status}): {' and '.join(conflict.files)}: "
            f"{', '.join(conflict.names)}{when}"
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
        if f.kind == "arg"
        and f.state == Selection.SELECTED
        and any(v.parent == k and v.state == Selection.UNSELECTED for v in features)
    ]
    print(f"left: {len(open_files)} files to select or deselect, {len(open_args)} args to set")
    for arg in [*state.untyped, *open_args][:10]:
        print(f"  --set {arg}=...")


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
    loaded = _analysis_with_env(options)
    if isinstance(loaded, int):
        return loaded
    analysis, env = loaded
    started = time.perf_counter()
    files = len(analysis.workspace.launch_files)
    print(f"rosvar: analysing {files} launch files ...", file=sys.stderr, flush=True)
    model = extract(analysis, progress=_progress)
    print("rosvar: building the configuration engine ...", file=sys.stderr, flush=True)
    configurator = Configurator(analysis, model, env)
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


def parser() -> argparse.ArgumentParser:
    top = argparse.ArgumentParser(
        prog="rosvar",
        description="Variability analysis of ROS launch files: all configurations at once.",
    )
    top.add_argument("--version", action="version", version=f"rosvar {__version__}")
    commands = top.add_subparsers(dest="command", required=True)
    analyze = commands.add_parser("analyze", help="interpret every launch file below PATH")
    analyze.add_argument("paths", nargs="+", metavar="PATH")
    analyze.add_argument("--json", action="store_true", help="machine-readable output")
    analyze.set_defaults(run=cmd_analyze)
    res = commands.add_parser(
        "resolve", help="one concrete configuration, as roslaunch would load it"
    )
    res.add_argument(
        "paths", nargs="*", metavar="PATH", help="package roots (and name:=value args)"
    )
    res.add_argument(
        "--launch",
        action="append",
        nargs="+",
        required=True,
        metavar=("FILE|PKG", "FILE"),
        help="a launch file, or a package and a file name in it (as roslaunch takes them)",
    )
    res.add_argument("--env", action="append", default=[], metavar="NAME=VALUE")
    res.add_argument("--json", action="store_true")
    res.set_defaults(run=cmd_resolve)
    features = commands.add_parser("features", help="the feature model (paper Algorithm 1)")
    features.add_argument("paths", nargs="+", metavar="PATH")
    features.add_argument("--hints", metavar="FILE", help="YAML with extra values (docs/hints.md)")
    features.add_argument("--format", choices=sorted(WRITERS), default="text")
    features.add_argument("-o", "--output", metavar="FILE")
    features.set_defaults(run=cmd_features)
    metrics = commands.add_parser("metrics", help="the paper's Table I and II metrics")
    metrics.add_argument("paths", nargs="+", metavar="PATH")
    metrics.add_argument("--hints", metavar="FILE")
    metrics.add_argument("--json", action="store_true")
    metrics.set_defaults(run=cmd_metrics)
    configure = commands.add_parser(
        "configure", help="one step of a configuration: the state after the given choices"
    )
    configure.add_argument("paths", nargs="+", metavar="PATH")
    for action in Action:
        metavar = "FILE:ARG=VALUE" if action == Action.SET else "FEATURE"
        configure.add_argument(
            f"--{action}", dest="choices", action=_Choice, const=action, metavar=metavar
        )
    configure.set_defaults(choices=[])
    configure.add_argument("--finish", action="store_true", help="finish with defaults")
    configure.add_argument("--env", action="append", default=[], metavar="NAME=VALUE")
    configure.add_argument("--hints", metavar="FILE")
    configure.add_argument("--json", action="store_true")
    configure.set_defaults(run=cmd_configure)
    serve = commands.add_parser("serve", help="configure step by step in the browser")
    serve.add_argument("paths", nargs="+", metavar="PATH")
    serve.add_argument("--host", default="127.0.0.1", help="address to bind (default: loopback)")
    serve.add_argument("--port", type=int, default=8080, help="port (0: any free one)")
    serve.add_argument("--env", action="append", default=[], metavar="NAME=VALUE")
    serve.add_argument("--hints", metavar="FILE")
    serve.set_defaults(run=cmd_serve)
    for command in (analyze, res, features, metrics, configure, serve):
        command.add_argument(
            "--allow-outside-workspace",
            action="store_true",
            help="read files (includes, textfile, rosparam) outside PATH, its packages and "
            "ROS_PACKAGE_PATH (never /proc, /sys, /dev)",
        )
    return top


def main(argv: Sequence[str] | None = None) -> int:
    top = parser()
    options, extra = top.parse_known_args(argv)
    mappings = [word for word in extra if ":=" in word]
    if len(mappings) != len(extra) or (mappings and options.command != "resolve"):
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
    except ModelTooLarge as error:  # what needs the solver of a model listed but not solved
        print(f"rosvar: the feature model is too large to solve: {error}", file=sys.stderr)
        return EXIT_TOO_LARGE
    finally:
        # free BDD nodes before their manager: CUDD complains when the interpreter
        # tears modules down in an arbitrary order
        gc.collect()
