"""The paper's metrics as ``rosvar metrics --json`` writes them: one number per column."""

from __future__ import annotations

from dataclasses import asdict

from rosvar.analyses.metrics import Metrics


def metrics_document(metrics: Metrics) -> dict[str, int]:
    return asdict(metrics)
