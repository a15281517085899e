"""``rosvar check``: the problems of the communication graph and the parameters in any
configuration, as text, JSON or SARIF, and the exit code ``--fail-on`` asks for; with a
baseline, only the findings it does not hold."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from rosvar.diagnostics import Severity
from rosvar.outputs.commands.exit_codes import EXIT_FAILS, EXIT_INPUT, EXIT_OK, EXIT_USAGE
from rosvar.outputs.commands.loading import analysis_of, interfaces_of
from rosvar.outputs.commands.terminal import print_json, progress, shown_location, shown_path

if TYPE_CHECKING:  # the analyses are imported when a check runs, not when the CLI starts
    from rosvar.analyses.checks import Finding
    from rosvar.analyses.communication import Uninterfaced
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.logic.conditions import ConditionSpace

FAIL_LEVELS = {Severity.NOTE: 0, Severity.WARNING: 1, Severity.ERROR: 2}
"""The severities ``--fail-on`` takes, in order: a finding at least as severe fails."""


@dataclass
class Checked:
    """One workspace checked: its analysis, findings with their fingerprints, and the nodes
    whose interface is unknown."""

    analysis: Analysis
    files: int
    findings: list[Finding]
    fingerprints: list[str]
    uninterfaced: list[Uninterfaced]


def checked(options: argparse.Namespace, paths: Sequence[str] | None = None) -> Checked | None:
    from rosvar.analyses.communication import uninterfaced
    from rosvar.analyses.fingerprints import Fingerprints
    from rosvar.analyses.graph_inputs import graph_inputs

    analysis = analysis_of(options, paths=paths)
    if analysis is None:
        return None
    interfaces = interfaces_of(analysis.workspace, options)
    models = analysis.all_models(progress)
    findings = graph_inputs(analysis, interfaces).findings(models)
    workspace = analysis.workspace
    prints = Fingerprints(
        workspace.packages.values(), [*workspace.roots, *workspace.dependency_roots]
    )
    unknown = uninterfaced(analysis.space, models, interfaces)
    return Checked(analysis, len(models), findings, [prints.of(f) for f in findings], unknown)


def cmd_check(options: argparse.Namespace) -> int:
    from rosvar.analyses.fingerprints import new_findings
    from rosvar.outputs.commands.baseline import BaselineError, fingerprints_in, revision_paths

    try:
        known = fingerprints_in(options.baseline) if options.baseline else None
        run = checked(options)
        if run is None:
            return EXIT_INPUT
        if options.baseline_rev:
            with revision_paths(options.paths, options.baseline_rev) as paths:
                before = checked(options, paths)
            known = before.fingerprints if before is not None else []
    except BaselineError as error:
        print(f"rosvar: {error}", file=sys.stderr)
        return EXIT_USAGE
    findings = run.findings
    if known is not None:
        findings = new_findings(findings, run.fingerprints, known)
    _print(options, run, findings, known is not None)
    threshold = FAIL_LEVELS[Severity(options.fail_on)]
    failing = any(FAIL_LEVELS[f.severity] >= threshold for f in findings)
    return EXIT_FAILS if failing else EXIT_OK


def _print(options: argparse.Namespace, run: Checked, findings: list[Finding], new: bool) -> None:
    """``findings`` (``new`` ones, with a baseline) in the format asked for; notes hidden
    from the text unless ``--all``."""
    from rosvar.outputs.documents.findings import finding_document
    from rosvar.outputs.sarif import sarif

    space = run.analysis.space
    prints = dict(zip(map(id, run.findings), run.fingerprints, strict=True))
    fingerprints = [prints[id(f)] for f in findings]
    if options.format == "sarif":
        print_json(sarif(findings, space, fingerprints))
        return
    if options.format == "json":
        documents = [
            {**finding_document(f, space), "fingerprint": fingerprint}
            for f, fingerprint in zip(findings, fingerprints, strict=True)
        ]
        unknown = [
            {"names": list(u.names), "executable": u.unit, **u.location.to_json()}
            for u in run.uninterfaced
        ]
        print_json({"findings": documents, "uninterfaced": unknown})
        return
    shown = [f for f in findings if options.all or f.severity is not Severity.NOTE]
    for finding in shown:
        _print_finding(finding, space)
    counts = {s: sum(1 for f in findings if f.severity is s) for s in Severity}
    hidden = len(findings) - len(shown)
    if hidden:
        print(f"{hidden} notes not shown (--all shows them)")
    if run.uninterfaced:
        print(
            f"{len(run.uninterfaced)} launched nodes have no known interfaces: their topics "
            "are not checked" + (" (--all lists them)" if not options.all else ":")
        )
        if options.all:
            for node in run.uninterfaced:
                print(
                    f"    {', '.join(node.names)} ({node.unit}) at {shown_location(node.location)}"
                )
    print(
        f"{len(findings)} {'new ' if new else ''}findings in {run.files} launch files: "
        + ", ".join(f"{counts[s]} {s.value}s" for s in Severity)
    )


def _print_finding(finding: Finding, space: ConditionSpace) -> None:
    from rosvar.outputs.documents.findings import finding_document

    where, *related = finding.locations
    document = finding_document(finding, space)
    example = ", ".join(f"{k}={v}" for k, v in document["example"].items())  # type: ignore[attr-defined]
    print(f"{shown_location(where)}: {finding.severity.value}[{finding.check}]: {finding.message}")
    when = document["condition"]
    when = "in every configuration" if when == "true" else f"when {when}"
    print(f"    {when}" + (f"; e.g. {example}" if example else ""))
    if finding.file != where.file:
        print(f"    launched from {shown_path(finding.file)}")
    for location in related:
        print(f"    see {shown_location(location)}")
