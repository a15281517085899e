"""The ``rosvar`` command line: its parser (each command's options, help and example) and the
dispatch to the commands, whose running and printing live in ``rosvar.outputs.commands``
(one module each); the exit codes are ``rosvar.outputs.commands.exit_codes``'s.
"""

from __future__ import annotations

import argparse
import contextlib
import gc
import os
import sys
from collections.abc import Sequence

from rosvar import __version__
from rosvar.configuration.choices import Action
from rosvar.diagnostics import Severity
from rosvar.outputs.commands.analyze import FILES_PER_JOB, cmd_analyze
from rosvar.outputs.commands.check import FAIL_LEVELS, cmd_check
from rosvar.outputs.commands.configure import cmd_configure
from rosvar.outputs.commands.exit_codes import EXIT_OK, EXIT_TOO_LARGE
from rosvar.outputs.commands.features import cmd_features
from rosvar.outputs.commands.interfaces import cmd_interfaces
from rosvar.outputs.commands.metrics import cmd_metrics
from rosvar.outputs.commands.query import cmd_query
from rosvar.outputs.commands.resolve import cmd_resolve
from rosvar.outputs.commands.serve import cmd_serve
from rosvar.outputs.exports import FORMATS

# The commands import what they need when they run: `dd` (and CUDD), the interpreter, numpy
# and the web server are not what `--version`, `--help` or another command pays for.


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
        "  rosvar check examples --format sarif --fail-on warning > rosvar.sarif\n"
        "  rosvar check examples --baseline-rev origin/main --fail-on warning"
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
    interfaces.add_argument(
        "--missing",
        action="store_true",
        help="instead, the executables the launch files below PATH run that no source, "
        "catalogue entry or hint describes, most launched first",
    )
    interfaces.set_defaults(run=cmd_interfaces)


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
        help="exit with 1 when a (new, with a baseline) finding is at least this severe "
        "(default: error)",
    )
    check.add_argument(
        "--all", action="store_true", help="text: also the notes and the nodes without interfaces"
    )
    baseline = check.add_mutually_exclusive_group()
    baseline.add_argument(
        "--baseline",
        metavar="FILE",
        help="report only the findings not in FILE (an earlier --format json or sarif output)",
    )
    baseline.add_argument(
        "--baseline-rev",
        metavar="REV",
        help="report only the findings the workspace did not have at git revision REV",
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
        from rosvar.analyses.feature_model.features import ModelTooLarge  # imported if raised

        if not isinstance(error, ModelTooLarge):
            raise
        from rosvar.outputs.commands.too_large import too_large_text

        # what needs the solver of a model listed but not solved
        paths = getattr(options, "paths", [])
        print(too_large_text(error, options.command, paths), file=sys.stderr)
        return EXIT_TOO_LARGE
