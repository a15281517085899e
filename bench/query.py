"""Benchmark of ``rosvar query`` on the Husky system, in process (harosvar: 70-260 ms a query).

The analysis is built once (not timed); each query is then run ``RUNS`` times on the same
:class:`QueryEngine` (elements listed by the first run, as the web UI would keep them), the
results rendered as ``--json`` renders them. Target: the 95th percentile of every query at most
``TARGET_MS``. Exits 0 always; the target prints PASS/FAIL.
"""

from __future__ import annotations

import argparse
import os
import statistics
import time

from rosvar.analyses.query.evaluator import QueryEngine
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.documents.query import result_document
from rosvar.workspace import discover

CORPUS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "corpus")
TARGET_MS = 20.0
RUNS = 50
QUERIES = (
    "nodes[self.package == 'husky_control']",
    "nodes[self.name.startswith('/husky')]",
    "for n in nodes where n.namespace == '/' return n",
    "params[self.name.startswith('/husky_velocity_controller')]",
    "topics[len(self.remapped_by) > 1]",
    "launch_files[len(self.nodes) > 5]",
    "args[self.default == 'false']",
)


def percentile(samples: list[float], fraction: float) -> float:
    ordered = sorted(samples)
    return ordered[min(len(ordered) - 1, round(fraction * (len(ordered) - 1)))]


def main() -> int:
    options = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    options.add_argument("--runs", type=int, default=RUNS, help="repetitions per query")
    options.add_argument("--corpus", default=CORPUS, help="folder holding the systems")
    arguments = options.parse_args()
    workspace = discover(
        [os.path.join(arguments.corpus, "husky")],
        deps=[os.path.join(arguments.corpus, "_external")],
        ros_package_path="",
    )
    started = time.perf_counter()
    analysis = Analysis(workspace)
    engine = QueryEngine(analysis)
    print(
        f"husky: {len(engine.models)} launch files analysed in "
        f"{time.perf_counter() - started:.1f} s (not timed below)"
    )
    worst = 0.0
    for query in QUERIES:
        samples = []
        for _ in range(arguments.runs):
            begun = time.perf_counter()
            results = engine.run(query)
            for result in results:
                result_document(engine, result)
            samples.append((time.perf_counter() - begun) * 1000)
        p95 = percentile(samples, 0.95)
        worst = max(worst, p95)
        print(
            f"  {query:<62} {len(results):>5} results  median "
            f"{statistics.median(samples):6.2f} ms  p95 {p95:6.2f} ms  first {samples[0]:6.2f} ms"
        )
    verdict = "PASS" if worst <= TARGET_MS else "FAIL"
    print(f"{verdict}: worst p95 {worst:.2f} ms (target {TARGET_MS:.0f} ms)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
