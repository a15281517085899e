"""``rosvar features``: the feature model (the paper's Algorithm 1) in one of the export
formats."""

from __future__ import annotations

import argparse
import sys

from rosvar.diagnostics import Severity
from rosvar.outputs.commands.exit_codes import EXIT_INPUT, EXIT_OK
from rosvar.outputs.commands.loading import analysis_of
from rosvar.outputs.commands.terminal import progress


def cmd_features(options: argparse.Namespace) -> int:
    from rosvar.analyses.feature_model.extraction import extract
    from rosvar.outputs.exports import write

    analysis = analysis_of(options)
    if analysis is None:
        return EXIT_INPUT
    model = extract(analysis, progress=progress)
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
