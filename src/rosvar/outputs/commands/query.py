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

MAPPING = r"[A-Za-z_~/][\w/~]*:="
"""A ``name:=value`` word: an arg given to the query, not a path or the expression."""


def cmd_query(options: argparse.Namespace) -> int:
    from rosvar.analyses.query.channels import channel_collections
    from rosvar.analyses.query.evaluator import QueryEngine
    from rosvar.analyses.query.parser import QueryError
    from rosvar.analyses.robot_description.edges import Simulation
    from rosvar.outputs.documents.query import result_document

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
    simulation = Simulation(analysis)
    engine = QueryEngine(analysis, collections=channel_collections(interfaces, simulation))
    warn_unknown_args(analysis, [m.file for m in engine.models], args)
    try:
        results = engine.run(expression, args)
    except QueryError as error:
        print(f"rosvar: {error}\n  {expression}\n  {' ' * error.col}^", file=sys.stderr)
        return EXIT_USAGE
    documents = [result_document(engine, result) for result in results]
    if options.json:
        print_json({"query": expression, "results": documents})
        return EXIT_OK
    for document in documents:
        example = document["example"]
        given = " ".join(f"{k}:={v}" for k, v in example.items()) or "(defaults)"  # type: ignore[attr-defined]
        print(f"{document['kind']} {document['name']}  [{document['launch_file']}]")
        print(f"  when {document['condition']}; e.g. {given}")
    print(f"{len(results)} result{'' if len(results) == 1 else 's'}")
    return EXIT_OK
