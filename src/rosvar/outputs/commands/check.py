"""``rosvar check``: the problems of the communication graph and the parameters in any
configuration, as text, JSON or SARIF, and the exit code ``--fail-on`` asks for."""

from __future__ import annotations

import argparse

from rosvar.diagnostics import Severity
from rosvar.outputs.commands.exit_codes import EXIT_FAILS, EXIT_INPUT, EXIT_OK
from rosvar.outputs.commands.loading import analysis_of, interfaces_of
from rosvar.outputs.commands.terminal import print_json, progress, shown_location, shown_path

FAIL_LEVELS = {Severity.NOTE: 0, Severity.WARNING: 1, Severity.ERROR: 2}
"""The severities ``--fail-on`` takes, in order: a finding at least as severe fails."""


def cmd_check(options: argparse.Namespace) -> int:
    from rosvar.analyses.checks import check_models
    from rosvar.analyses.robot_description.edges import Simulation
    from rosvar.outputs.documents.findings import finding_document
    from rosvar.outputs.sarif import sarif

    analysis = analysis_of(options)
    if analysis is None:
        return EXIT_INPUT
    interfaces = interfaces_of(analysis.workspace, options)
    models = analysis.all_models(progress)
    described = Simulation(analysis)
    findings = check_models(
        analysis.space, models, interfaces, analysis.workspace.confinement(), described
    )
    if options.format == "sarif":
        print_json(sarif(findings, analysis.space))
    elif options.format == "json":
        print_json({"findings": [finding_document(f, analysis.space) for f in findings]})
    else:
        for finding in findings:
            where, *related = finding.locations
            document = finding_document(finding, analysis.space)
            example = ", ".join(f"{k}={v}" for k, v in document["example"].items())  # type: ignore[attr-defined]
            print(
                f"{shown_location(where)}: {finding.severity.value}[{finding.check}]: "
                f"{finding.message}"
            )
            when = document["condition"]
            when = "in every configuration" if when == "true" else f"when {when}"
            print(f"    {when}" + (f"; e.g. {example}" if example else ""))
            if finding.file != where.file:
                print(f"    launched from {shown_path(finding.file)}")
            for location in related:
                print(f"    see {shown_location(location)}")
        counts = {s: sum(1 for f in findings if f.severity is s) for s in Severity}
        print(
            f"{len(findings)} findings in {len(models)} launch files: "
            + ", ".join(f"{counts[s]} {s.value}s" for s in Severity)
        )
    threshold = FAIL_LEVELS[Severity(options.fail_on)]
    failing = any(FAIL_LEVELS[f.severity] >= threshold for f in findings)
    return EXIT_FAILS if failing else EXIT_OK
