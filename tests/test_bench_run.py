"""``bench/run.py``'s whole-process commands: a run is stopped at its command's cap, and a
target may be a factor of another command's time (issue 28: ``features`` and ``check``
within twice ``analyze``)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

import bench_scripts

run = bench_scripts.load("run")


def _outcome(name: str, seconds: float | None, **limits: object) -> object:
    command = run.Command(name, lambda _scratch: None, **limits)
    wall_ms = None if seconds is None else seconds * 1000
    return run.CommandOutcome(command, wall_ms=wall_ms, peak_mb=10.0)


def test_targets_relative_to_another_command() -> None:
    outcomes = [
        _outcome("analyze", 2.0, wall_s=3.0),
        _outcome("features", 3.9, within=("analyze", 2.0)),
        _outcome("check", 4.1, within=("analyze", 2.0)),
        _outcome("query", None, within=("missing", 2.0)),
    ]
    lines = run.command_lines(outcomes)
    verdicts = lines[lines.index("") + 1 :]
    assert verdicts == [
        "PASS  analyze: wall ≤ 3 s: 2.00 s",
        "PASS  features: wall ≤ 2 × analyze: 3.90 s (limit 4.00 s)",
        "FAIL  check: wall ≤ 2 × analyze: 4.10 s (limit 4.00 s)",
        "FAIL  query: wall ≤ 2 × missing: no figure",
    ]
    assert "| `check` | 4.10 | 10 | ≤ 2 × `analyze` |" in lines


def test_a_run_stops_at_the_cap(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    sleeper = [sys.executable, "-c", "import time; time.sleep(30)"]
    quick = [sys.executable, "-c", "raise SystemExit(1)"]
    commands = [
        run.Command("sleeper", lambda _scratch: sleeper, wall_s=1.0, cap_s=1.0),
        run.Command("refused", lambda _scratch: quick),
        run.Command("accepted", lambda _scratch: quick, ok_codes=(0, 1)),
    ]
    monkeypatch.setattr(run, "COMMANDS", commands)
    sleeping, refused, accepted = run.measure_commands(tmp_path)
    assert (sleeping.wall_ms, sleeping.note) == (None, "> 1 s (cap)")
    assert refused.wall_ms is None and refused.note.startswith("run: exit 1")
    assert accepted.wall_ms is not None and accepted.note == ""
    assert run.measure_commands(tmp_path, ["accept"])[0].command is commands[2]
