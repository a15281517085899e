"""``rosvar analyze``: every launch file of a workspace interpreted, as a table of counts
with the first diagnostics, or the whole model as JSON."""

from __future__ import annotations

import argparse
import sys
from dataclasses import replace
from typing import TYPE_CHECKING

from rosvar.diagnostics import Diagnostic, Severity
from rosvar.outputs.commands.exit_codes import EXIT_INPUT, EXIT_OK
from rosvar.outputs.commands.loading import workspace_of
from rosvar.outputs.commands.terminal import print_json, progress, relative_location, shown_path

if TYPE_CHECKING:
    from rosvar.interpreter.model import LaunchModel

FILES_PER_JOB = 50
"""Fewest launch files worth a process of their own when ``--jobs`` is not given (each
takes a fork and the return of its results)."""


def cmd_analyze(options: argparse.Namespace) -> int:
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.outputs.describe import describe_model

    workspace = workspace_of(options.paths, options)
    if not workspace.launch_files:
        print("rosvar: no launch files found", file=sys.stderr)
        return EXIT_INPUT
    analysis = Analysis(workspace)
    jobs = _jobs(options.jobs, len(workspace.launch_files))
    if options.json and sys.stdout.isatty():
        print_json({"files": analysis.map_models(describe_model, jobs, progress)})
        return EXIT_OK
    if options.json:  # one line, as print_json writes it, each file's part by its process
        parts = analysis.map_models(_model_json, jobs, progress)
        sys.stdout.write('{"files": [' + ", ".join(parts) + "]}\n")
        return EXIT_OK
    rows = analysis.map_models(_analyzed_row, jobs, progress)
    # a file included by several entry files reports its problems once per entry file: once here
    diagnostics = list(dict.fromkeys(d for _row, found in rows for d in found))
    print(f"{len(rows)} launch files, {len(workspace.packages)} packages")
    print(f"{'file':<60} {'args':>5} {'nodes':>6} {'params':>7} {'errors':>7}")
    for (file, *counts), _found in rows:
        name = shown_path(file)
        if len(name) > 60:  # its tail, marked: the file names differ at the end
            name = "…" + name[-59:]
        inputs, nodes, params, failed = counts
        print(f"{name:<60} {inputs:>5} {nodes:>6} {params:>7} {failed:>7}")
    errors = [d for d in diagnostics if d.severity is Severity.ERROR]
    print(f"\n{len(diagnostics)} diagnostics ({len(errors)} errors)")
    for diagnostic in diagnostics[:20]:
        print(f"  {replace(diagnostic, location=relative_location(diagnostic.location))}")
    if len(diagnostics) > 20:
        print(f"  ... {len(diagnostics) - 20} more (use --json)")
    return EXIT_OK


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
    from rosvar.outputs.describe import possible_errors

    errors = len(possible_errors(model))
    counts = (len(model.inputs), len(model.nodes), len(model.params), errors)
    return (model.file, *counts), model.diagnostics
