"""Print the figures of the regression set of real bugs (``tests/data/bugs``) for docs/checks.md.

For each bug folder: whether ``rosvar check`` of the buggy version, with the fixed version's
JSON as ``--baseline``, reports a finding naming each misconfigured name of ``bug.json`` (and
the fix, with the buggy version as baseline, none), the severities of those findings, and each
version's findings by severity without a baseline (the noise a user sees). Runs this
checkout's ``rosvar`` (``python -m rosvar``) in each version's folder, as
``tests/analyses/test_bug_regressions.py`` does:

    python tools/bug_regressions.py > /tmp/bugs.md
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
BUGS = ROOT / "tests" / "data" / "bugs"
SEVERITIES = ("error", "warning", "note")
VERSIONS = ("buggy", "fixed")


def run(folder: Path, args: list[str], baseline: str | None = None) -> str:
    """The JSON output of ``rosvar check .`` in ``folder``, outside any ROS environment."""
    command = [sys.executable, "-m", "rosvar", "check", ".", *args, "--format", "json"]
    if baseline is not None:
        command += ["--baseline", baseline]
    env = {
        k: v for k, v in os.environ.items() if k not in ("ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH")
    }
    env["PYTHONPATH"] = str(ROOT / "src")
    return subprocess.run(
        command, cwd=folder, env=env, capture_output=True, text=True, check=False
    ).stdout


def findings(output: str) -> list[dict[str, Any]]:
    found: list[dict[str, Any]] = json.loads(output)["findings"]
    return found


def new_over(bug: Path, args: list[str], version: str, other: str) -> list[dict[str, Any]]:
    """The findings of ``version`` that ``other``'s output, as its baseline, does not hold."""
    with tempfile.TemporaryDirectory() as scratch:
        baseline = Path(scratch) / "baseline.json"
        baseline.write_text(run(bug / other, args))
        return findings(run(bug / version, args, str(baseline)))


def counts(findings: list[dict[str, Any]]) -> str:
    """``errors/warnings/notes``."""
    by = Counter(finding["severity"] for finding in findings)
    return "/".join(str(by[severity]) for severity in SEVERITIES)


def row(bug: Path) -> str:
    spec = json.loads((bug / "bug.json").read_text(encoding="utf-8"))
    args, names = spec.get("check_args", []), set(spec["names"])
    brought = [f for f in new_over(bug, args, "buggy", "fixed") if f["name"] in names]
    kept = [f for f in new_over(bug, args, "fixed", "buggy") if f["name"] in names]
    found = names <= {f["name"] for f in brought} and not kept
    how = ", ".join(sorted({f"{f['severity']} `{f['check']}`" for f in brought})) or "-"
    noise = " | ".join(counts(findings(run(bug / version, args))) for version in VERSIONS)
    verdict = "yes" if found else "no"
    return f"| `{bug.name}` | {spec['dialect']} | {verdict} | {how} | {noise} |"


def main() -> None:
    print("| bug | dialect | detected | by | buggy: errors/warnings/notes | fixed |")
    print("|-----|---------|----------|----|------------------------------|-------|")
    for bug in sorted(p for p in BUGS.iterdir() if p.is_dir()):
        print(row(bug))


if __name__ == "__main__":
    main()
