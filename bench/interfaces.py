"""Benchmark of interface extraction (``rosvar interfaces``) on the four corpus systems.

Runs in a fresh subprocess per repetition, so that tree-sitter's parse cache starts empty and
module import is excluded from the figure (it is timed apart). Target: every corpus system's
sources extracted in at most ``TARGET_S`` seconds (the median of ``RUNS``). Exits 0 always;
the target prints PASS/FAIL.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys

CORPUS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "corpus")
SYSTEMS = ("kobuki", "turtlebot2", "lizi", "husky")
TARGET_S = 2.0
RUNS = 5

_CHILD = """
import json, sys, time
started = time.perf_counter()
from rosvar.workspace import discover
from rosvar.workspace.interfaces.extraction import extract_interfaces
imported = time.perf_counter()
workspace = discover(sys.argv[1:], ros_package_path="")
interfaces = extract_interfaces(workspace.packages.values())
done = time.perf_counter()
entries = sum(len(node.entries) for node in interfaces.nodes)
print(json.dumps({"import": imported - started, "extract": done - imported,
                  "nodes": len(interfaces.nodes), "entries": entries,
                  "diagnostics": len(interfaces.diagnostics)}))
"""


def measure(paths: list[str]) -> dict[str, float]:
    source = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src")
    env = {**os.environ, "PYTHONPATH": os.path.abspath(source)}
    result = subprocess.run(
        [sys.executable, "-c", _CHILD, *paths], capture_output=True, text=True, env=env, check=True
    )
    figures: dict[str, float] = json.loads(result.stdout)
    return figures


def main() -> int:
    options = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    options.add_argument("--runs", type=int, default=RUNS, help="repetitions (median reported)")
    options.add_argument("--corpus", default=CORPUS, help="folder holding the four systems")
    arguments = options.parse_args()
    paths = [os.path.join(arguments.corpus, system) for system in SYSTEMS]
    runs = [measure(paths) for _ in range(arguments.runs)]
    extract = statistics.median(run["extract"] for run in runs)
    imported = statistics.median(run["import"] for run in runs)
    last = runs[-1]
    print(
        f"interfaces of the corpus: {int(last['nodes'])} nodes, {int(last['entries'])} entries, "
        f"{int(last['diagnostics'])} diagnostics"
    )
    print(f"extraction (discover + read + extract): median {extract:.2f} s of {len(runs)} runs")
    print(f"import of the extractor (tree-sitter included): median {imported:.2f} s")
    verdict = "PASS" if extract <= TARGET_S else "FAIL"
    print(f"{verdict}: extraction of all corpus sources <= {TARGET_S:.0f} s ({extract:.2f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
