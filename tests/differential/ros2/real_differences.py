"""List, for each real file of ``tests/data/ros2`` the oracle loads, the first difference
between rosvar's variational model restricted to a sampled configuration and the oracle.

Run from the repository root: ``PYTHONPATH=src:tests python -m differential.ros2.real_differences
[REPOSITORY ...]``. Files the oracle fails on for every sample are left out (its limits); the
last line counts the agreeing configurations and files, as ``test_variational.py`` keeps them.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from oracle.ros2_client import canonical_nodes, resolution_nodes, run_oracle
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover

from .test_variational import DATA, configurations


def first_difference(expected: list[dict[str, object]], got: list[dict[str, object]]) -> str:
    """The first node (in the canonical order) that differs, field by field."""
    for index in range(max(len(expected), len(got))):
        want = expected[index] if index < len(expected) else None
        have = got[index] if index < len(got) else None
        if want != have:
            if want is None or have is None:
                return f"node {index}: oracle {want}, rosvar {have}"
            keys = [k for k in want if want[k] != have.get(k)]
            return "; ".join(f"{k}: oracle {want[k]!r}, rosvar {have.get(k)!r}" for k in keys)
    return ""


def main(repositories: list[str]) -> None:
    agreeing_files, configurations_total, agreeing = [], 0, 0
    files_loaded = 0
    for repository in repositories or sorted(p.name for p in DATA.iterdir() if p.is_dir()):
        root = DATA / repository
        workspace = discover([str(root)])
        analysis = Analysis(workspace)
        for file in sorted(workspace.launch_files):
            relative = Path(file).relative_to(DATA)
            differences = []
            loaded = 0
            for arguments in configurations(analysis, file, []):
                expected = run_oracle(file, arguments, [root], strict=False)
                if not expected["ok"]:
                    continue
                loaded += 1
                result = analysis.resolve([file], arguments)
                if not result.ok:
                    differences.append(f"{arguments}: rosvar fails: {result.errors[0]}")
                    continue
                difference = first_difference(
                    canonical_nodes(expected),
                    canonical_nodes(resolution_nodes(result)),
                )
                if difference:
                    differences.append(f"{arguments}: {difference}")
            if not loaded:
                continue
            files_loaded += 1
            configurations_total += loaded
            agreeing += loaded - len(differences)
            if differences:
                print(f"{relative}: {len(differences)}/{loaded} differ; {differences[0]}")
            else:
                agreeing_files.append(str(relative))
                print(f"{relative}: all {loaded} agree")
    print(json.dumps(agreeing_files, indent=1))
    print(
        f"{agreeing} of {configurations_total} configurations agree; "
        f"{len(agreeing_files)} of {files_loaded} files agree entirely"
    )


if __name__ == "__main__":
    main(sys.argv[1:])
