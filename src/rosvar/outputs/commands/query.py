"""``rosvar query``: the elements a query selects, each with the condition under which it
does and an example configuration."""

from __future__ import annotations

import argparse
import re
import sys

from rosvar.outputs.commands.exit_codes import EXIT_INPUT, EXIT_OK, EXIT_USAGE
from rosvar.outputs.commands.loading import analysis_of, interfaces_of, warn_unknown_args
from rosvar.outputs.commands.terminal import print_json, progress
from rosvar.ros.names import command_line_mappings

CHANNEL_COLLECTIONS = ("topics", "services", "actions")
"""The collections made of the nodes' interfaces, whose answers miss what unknown nodes use."""
MAPPING = r"[A-Za-z_~/][\w/~]*:="
"""A ``name:=value`` word: an arg given to the query, not a path or the expression."""


def cmd_query(options: argparse.Namespace) -> int:
    from rosvar.analyses.communication import uninterfaced
    from rosvar.analyses.graph_inputs import graph_inputs
    from rosvar.analyses.query.evaluator import QueryEngine
    from rosvar.analyses.query.parser import QueryError, parse
    from rosvar.outputs.documents.query import USERS, result_document

    words = [*options.words, *options.mappings]
    args = command_line_mappings([w for w in words if re.match(MAPPING, w)])
    *paths, expression = [w for w in options.words if not re.match(MAPPING, w)] or [""]
    if not paths:
        print("rosvar: query needs PATH... and an expression", file=sys.stderr)
        return EXIT_USAGE
    analysis = analysis_of(options, paths=paths, args=args)
    if analysis is None:
        return EXIT_INPUT
    analysis.all_models(progress)  # interpreted once, with the progress shown
    interfaces = interfaces_of(analysis.workspace, options)
    engine = QueryEngine(analysis, collections=graph_inputs(analysis, interfaces).collections())
    warn_unknown_args(analysis, [m.file for m in engine.models], args)
    try:
        results = engine.run(expression, args)
    except QueryError as error:
        print(f"rosvar: {error}\n  {expression}\n  {' ' * error.col}^", file=sys.stderr)
        return EXIT_USAGE
    documents = [result_document(engine, result) for result in results]
    # the nodes' interfaces matter to the channels only (a node query lists them all)
    over_channels = parse(expression).collection in CHANNEL_COLLECTIONS
    unknown = uninterfaced(analysis.space, engine.models, interfaces) if over_channels else []
    if options.json:
        unknowns = [
            {"names": list(u.names), "executable": u.unit, **u.location.to_json()} for u in unknown
        ]
        print_json({"query": expression, "results": documents, "uninterfaced": unknowns})
        return EXIT_OK
    for document in documents:
        example = document["example"]
        given = " ".join(f"{k}:={v}" for k, v in example.items()) or "(defaults)"  # type: ignore[attr-defined]
        print(f"{document['kind']} {document['name']}  [{document['launch_file']}]")
        print(f"  when {document['condition']}; e.g. {given}")
        for side in USERS:
            users = document.get(side)
            if isinstance(users, list):
                shown = ", ".join(_user(u) for u in users) or "none"
                print(f"  {side}: {shown}")
    if unknown:
        print(
            f"{len(unknown)} launched nodes have no known interfaces: their topics are not "
            "among the results (--json lists them)"
        )
    print(f"{len(results)} result{'' if len(results) == 1 else 's'}")
    return EXIT_OK


def _user(document: dict[str, str]) -> str:
    condition = document["condition"]
    return document["node"] + ("" if condition == "true" else f" (when {condition})")
