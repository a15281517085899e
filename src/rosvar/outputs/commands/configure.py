"""``rosvar configure``: one step of a configuration, the state after the given choices,
as a summary for people or the whole state as JSON."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from dataclasses import replace
from typing import TYPE_CHECKING, cast

from rosvar.outputs.commands.exit_codes import EXIT_FAILS, EXIT_OK, EXIT_USAGE
from rosvar.outputs.commands.loading import analysis_with_env, interfaces_of
from rosvar.outputs.commands.terminal import building, print_json, progress, relative_location
from rosvar.ros.version import RosVersion

if TYPE_CHECKING:
    from rosvar.configuration.engine import ConfigurationState

SHOWN_NAMES = 3
"""The clashing names a conflict's line shows at most (the nodes are always shown)."""
SHOWN_UNKNOWN = 5
"""The places rosvar could not read that the summary lists (``--json`` has them all)."""


def cmd_configure(options: argparse.Namespace) -> int:
    from rosvar.analyses.feature_model.extraction import extract
    from rosvar.configuration.choices import ChoiceError, UserChoice
    from rosvar.configuration.engine import Configurator
    from rosvar.outputs.documents.state import state_document
    from rosvar.outputs.web.entries import render

    loaded = analysis_with_env(options)
    if isinstance(loaded, int):
        return loaded
    analysis, env = loaded
    try:
        choices = [UserChoice.parse(action, text) for action, text in options.choices]
        model = extract(analysis, progress=progress, products=True, env=env)
        interfaces = interfaces_of(analysis.workspace, options)
        configurator = Configurator(
            analysis,
            model,
            env,
            progress=building(tty_only=True),
            interfaces=interfaces,
            render=render,
        )
        if options.finish:
            choices += configurator.completion(choices)
        state = configurator.state(choices)
    except ChoiceError as error:
        print(f"rosvar: {error}", file=sys.stderr)
        return EXIT_USAGE
    if options.json:
        print_json(state_document(state))
    else:
        _print_state(state, analysis.workspace.ros_version)
    return EXIT_FAILS if state.refused or state.launches is False else EXIT_OK


def _print_state(state: ConfigurationState, ros: RosVersion) -> None:
    """The summary of a configuration step, for people (a ROS 2 node holds its own
    parameters: they are counted on the nodes, not as the parameter server's)."""
    from rosvar.analyses.feature_model.features import FeatureKind
    from rosvar.configuration.command import launch_tool
    from rosvar.configuration.engine import Selection
    from rosvar.configuration.graph import ElementKind
    from rosvar.configuration.presence import Presence
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
    _print_unknown(state)
    if state.complete:
        print(
            state.command
            or "nothing to launch (no file selected, or an <other> value lacks its text)"
        )
        if state.launches is False:
            print(
                f"this product does not launch: {launch_tool(ros)} stops at the errors or "
                "conflicts above"
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


def _print_unknown(state: ConfigurationState) -> None:
    """What rosvar could not read of the selected files, said at every step while it lasts:
    the graph shown may lack what those places load."""
    count = len(state.unknown)
    if not count:
        return
    places = "place" if count == 1 else "places"
    print(f"not known: {count} {places} of the selected files that rosvar could not read")
    for diagnostic in state.unknown[:SHOWN_UNKNOWN]:
        print(f"  {replace(diagnostic, location=relative_location(diagnostic.location))}")
    if count > SHOWN_UNKNOWN:
        print(f"  ... {count - SHOWN_UNKNOWN} more (use --json)")
