"""Memory of a long-running ``rosvar serve`` (issue 16): distinct values typed, click after click.

Drives the web API in-process (no HTTP: the answers are the same documents) over the given
workspace: every click types a new text into the next arg's ``<other>`` entry, so no click
meets a key seen before, and a new session opens every ``--per-session`` clicks, so sessions
are evicted too. Prints the growth of the resident set (after a garbage collection), the
largest bounded memo and the BDD nodes of both managers, at a few points of the run::

    python bench/memory.py /work/shared/corpus/husky --clicks 3000
"""

from __future__ import annotations

import argparse
import gc
import os
import sys
from pathlib import Path

from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.engine import Configurator
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.web.api import Api
from rosvar.outputs.web.entries import render
from rosvar.workspace import discover


def resident_kb() -> int:
    pages = int(Path("/proc/self/statm").read_text().split()[1])
    return pages * os.sysconf("SC_PAGE_SIZE") // 1024


def largest_memo() -> int | None:
    try:
        from rosvar.memo import memos
    except ImportError:  # a version before bounded memos
        return None
    return max((len(memo) for memo in memos()), default=0)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("paths", nargs="+")
    parser.add_argument("--clicks", type=int, default=3000)
    parser.add_argument("--per-session", type=int, default=50)
    parser.add_argument("--sessions", type=int, default=64, help="the store's capacity")
    options = parser.parse_args()
    analysis = Analysis(discover(options.paths))
    engine = Configurator(analysis, extract(analysis, products=True), render=render)
    api = Api(engine, capacity=options.sessions)
    args = [arg_id for arg_id, _values in engine.catalog.args.items()]
    gc.collect()
    base = resident_kb()
    print(f"start: {base // 1024} MB resident", flush=True)
    session = ""
    for click in range(options.clicks):
        if click % options.per_session == 0:
            session = str(api.handle("POST", "/api/session", {}, {})["session"])
        body = {
            "session": session,
            "action": "set",
            "feature": args[click % len(args)],
            "value": f"value {click}",
        }
        api.handle("POST", "/api/choose", {}, body)
        if (click + 1) % max(1, options.clicks // 6) == 0 or click + 1 == options.clicks:
            gc.collect()
            nodes = (len(engine.derivation.manager), len(analysis.space.bdd))
            print(
                f"{click + 1} clicks: +{(resident_kb() - base) // 1024} MB,"
                f" largest memo {largest_memo()}, BDD nodes (solver, analysis) {nodes}",
                flush=True,
            )
    return 0


if __name__ == "__main__":
    sys.exit(main())
