"""``rosvar metrics``: the paper's Table I and II metrics, a row per system."""

from __future__ import annotations

import argparse
import sys

from rosvar.diagnostics import Severity
from rosvar.outputs.commands.exit_codes import EXIT_INPUT, EXIT_OK
from rosvar.outputs.commands.loading import analysis_of
from rosvar.outputs.commands.terminal import print_json, progress

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
    from rosvar.outputs.documents.metrics import metrics_document

    rows: dict[str, dict[str, int]] = {}
    for path in options.paths:
        analysis = analysis_of(options, paths=[path])
        if analysis is None:
            return EXIT_INPUT
        features = extract(analysis, progress=progress)
        for diagnostic in features.diagnostics:
            if diagnostic.severity is Severity.ERROR:  # a file not read counts for nothing
                print(f"rosvar: {diagnostic}", file=sys.stderr)
        rows[path] = metrics_document(compute(analysis, features))
    if options.json:
        print_json(next(iter(rows.values())) if len(rows) == 1 else rows)
        return EXIT_OK
    keys = list(next(iter(rows.values())))
    width = max(len("system"), *(len(path) for path in rows))
    print(f"{'system':<{width}}" + "".join(f" {key:>5}" for key in keys))
    for path, metrics in rows.items():
        print(f"{path:<{width}}" + "".join(f" {metrics[key]:>5}" for key in keys))
    print(f"\n{METRICS_LEGEND}")
    return EXIT_OK
