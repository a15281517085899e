"""Differential tests: every launch file of the corpus and of the fixtures, rosvar vs roslaunch.

Each test runs :mod:`tests.differential.harness` over one system (all its launch files, a few
configurations each), prints the counts and the most common difference classes (run pytest with
``-s`` to see them), and requires that no case differs. Cases in which roslaunch fails for a
reason outside the launch files (``roslaunch-failed``) are not held against rosvar.

To debug one system: ``.venv/bin/python -m tests.differential.harness --system husky --show 30``.
"""

from __future__ import annotations

import pytest

from .harness import (
    CORPUS,
    CORPUS_SYSTEMS,
    DIFFER,
    FIXTURES,
    SAMPLES,
    SEED,
    Report,
    requires_oracle,
    system_runs,
)

pytestmark = requires_oracle


def _check(reports: list[Report]) -> None:
    for report in reports:
        print(f"\n{report.summary()}")
        if report.differences:
            print(report.class_table())
    differ = sum(report.counts[DIFFER] for report in reports)
    details = "\n".join(
        f"{report.summary()}\n{report.details(limit=10)}"
        for report in reports
        if report.differences
    )
    assert differ == 0, f"{differ} cases differ from roslaunch:\n{details}"


@pytest.mark.parametrize("system", CORPUS_SYSTEMS)
def test_corpus_system(system: str) -> None:
    if not (CORPUS / system).is_dir() or not (CORPUS / "_external").is_dir():
        pytest.skip(f"corpus not found at {CORPUS}")
    _check([run.run(SAMPLES, SEED) for run in system_runs(system)])


def test_fixtures() -> None:
    assert (FIXTURES / "fixpkg" / "package.xml").is_file()
    _check([run.run(8, SEED) for run in system_runs("fixtures")])
