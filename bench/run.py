"""Scaling benchmarks of ``rosvar analyze`` (``make bench``).

Each workload (a corpus system, or a generated workspace of N launch files) is measured in
fresh subprocesses, so peak RSS belongs to that workload alone and a hang cannot stall the
run (every subprocess is bounded by ``TIMEOUT_S``; a timeout is reported, never raised):

* ``isolated``: ``run.py --one PATH...`` times discover + Analysis + all_models in-process
  (median of several runs, fresh Analysis and cleared parser cache each time), reports
  ``ru_maxrss``, and times the baseline in the same process: parsing the same launch files
  with ``xml.dom.minidom``, which is what roslaunch itself does;
* ``whole-process``: wall time of ``rosvar analyze PATH... --json > /dev/null``.

Workloads, measurements, table columns and targets are registries: a new benchmark is one
more entry, not one more branch. The script always exits 0; targets print PASS/FAIL.
"""

from __future__ import annotations

import argparse
import compileall
import cProfile
import datetime
import gc
import importlib.util
import io
import itertools
import json
import math
import os
import platform
import pstats
import random
import resource
import shutil
import signal
import statistics
import subprocess
import sys
import sysconfig
import tempfile
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any
from xml.dom import minidom

BENCH = Path(__file__).resolve().parent
REPO = BENCH.parent
CORPUS = REPO.parent / "shared" / "corpus"
EXTERNAL = CORPUS / "_external"
ROS2_DATA = REPO / "tests" / "data" / "ros2"  # real ROS 2 repositories (their README.md)
DOC = REPO / "docs" / "performance.md"

TIMEOUT_S = 600.0
"""Bound on every subprocess; a workload that needs longer is reported as a timeout."""
MEMORY_LIMIT_MB = 8192
"""Address-space cap of every subprocess, so a blow-up fails alone instead of starving the host."""
REPEATS = 3
SINGLE_RUN_FROM = 2_000  # workloads this large are timed once: one run is minutes
GENERATED_SIZES = (100, 400, 2_000, 10_000)
GENERATED_PREFIXES = {"corpus": "gen", "uniform": "uni", "ros2": "ros2", "ros2-dense": "ros2dense"}
ROS2_FILES = 120  # bench/generate.py's ROS 2 workspace: 1,500 args, include trees 8 deep
QUICK_SIZES = (100, 400)
UNIFORM_SIZES = (400, 2_000)  # the shape: 5 args, 5 conditional nodes, group, include
GROWTH_KEY = "analyze_cpu_ms"  # CPU time: robust to other load on a shared machine
LINEAR_EXPONENT = math.log2(2.3)  # "x2 files => at most x2.3 time", as a power of n
PROFILE_TOP = 15

Metrics = dict[str, float]


# -- workloads -------------------------------------------------------------------------------
@dataclass(frozen=True)
class Workload:
    """Something to analyse: ``prepare(scratch)`` returns its roots (writing them if needed).

    ``package_path`` plays ROS_PACKAGE_PATH: its packages resolve ``$(find)`` and includes
    but contribute no launch files, so a system is measured on its own files only.
    """

    name: str
    family: str  # growth is computed between consecutive sizes of one family
    prepare: Callable[[Path], list[str]]
    package_path: str = ""
    size: int = 0  # nominal launch-file count (generated workloads); orders a family
    repeats: int = REPEATS
    in_table: bool = True  # False: measured only by COMMANDS (or when named by --only)


WORKLOADS: dict[str, Workload] = {}


def register_workload(workload: Workload) -> None:
    WORKLOADS[workload.name] = workload


def _corpus(system: str) -> Workload:
    def prepare(_scratch: Path) -> list[str]:
        return [str(CORPUS / system)]

    return Workload(system, "corpus", prepare, package_path=str(EXTERNAL))


def _ros2_repository(name: str) -> Workload:
    """A real ROS 2 repository of the tests' data (``tests/data/ros2/NAME``)."""

    def prepare(_scratch: Path) -> list[str]:
        return [str(ROS2_DATA / name)]

    return Workload(name, "ros2-real", prepare, in_table=False)


def _generated(n_files: int, shape: str = "corpus") -> Workload:
    """A workspace of ``bench/generate.py``: ``gen-N`` shaped like the corpus, ``uni-N`` the
    uniform shape of the workspace-scale issue (every file alike), ``ros2-N`` ROS 2's,
    ``ros2dense-N`` the slow ROS 2 system of issue 28 (denser includes, ``$(eval)``)."""
    prefix = GENERATED_PREFIXES[shape]

    def prepare(scratch: Path) -> list[str]:
        from generate import SHAPES  # bench/ is sys.path[0] for this script

        root = scratch / f"{prefix}{n_files}"
        if not root.exists():
            started = time.perf_counter()
            SHAPES[shape](root, n_files, 0)
            took = time.perf_counter() - started
            print(f"  generated {n_files} launch files in {took:.1f} s", file=sys.stderr)
        return [str(root)]

    repeats = 1 if n_files >= SINGLE_RUN_FROM else REPEATS
    family = "generated" if shape == "corpus" else shape
    return Workload(f"{prefix}-{n_files}", family, prepare, size=n_files, repeats=repeats)


for _system in ("kobuki", "turtlebot2", "lizi", "husky"):
    register_workload(_corpus(_system))
for _size in GENERATED_SIZES:
    register_workload(_generated(_size))
for _size in UNIFORM_SIZES:
    register_workload(_generated(_size, "uniform"))


# One size, measured in every run like a corpus system (size 0: not one of --sizes).
register_workload(replace(_generated(ROS2_FILES, "ros2"), size=0))
# Issue 28's large ROS 2 systems, measured as whole processes (COMMANDS) only: one run of
# each took minutes in-process when they were added.
ROS2_DENSE = f"ros2dense-{ROS2_FILES}"
register_workload(replace(_generated(ROS2_FILES, "ros2-dense"), size=0, in_table=False))
AUTOWARE = "autoware.universe"
register_workload(_ros2_repository(AUTOWARE))


# -- measurements inside the isolated process (run.py --one) -------------------------------
@dataclass
class Job:
    """What an isolated process measures: the roots, and how hard to try."""

    roots: list[str]
    package_path: str
    repeats: int
    budget_s: float  # stop repeating once another run would likely overrun this
    files: list[str] = field(default_factory=list)
    analysis: object = None  # the last run's interpreted Analysis, for the feature model
    analysis_ms: float = 0.0  # what interpreting it took
    # Whether the feature model was solved (within its budget, see feature_model/extraction.py):
    # the engine measurements build it again and need its solver; generated workspaces
    # whose clashes link most files are listed but not solved.
    feature_model_built: bool = False


def _timed_runs(
    job: Job, run: Callable[[], object], reset: Callable[[], object] = lambda: None
) -> tuple[float, float, int]:
    """Median wall and CPU ms of up to ``job.repeats`` runs (fewer rather than overrun).

    CPU time is kept beside wall time because the machine may be shared: other load
    stretches wall time but barely CPU time, and must not pass for non-linear growth.
    ``reset`` runs before each run, untimed: dropping the previous run's results is
    not part of the next one (freeing Husky's models took 9-17 ms, in runs 2 and 3).
    """
    walls: list[float] = []
    cpus: list[float] = []
    for _ in range(job.repeats):
        reset()
        wall, cpu = time.perf_counter(), time.process_time()
        run()
        walls.append((time.perf_counter() - wall) * 1000)
        cpus.append((time.process_time() - cpu) * 1000)
        if (sum(walls) + walls[-1]) / 1000 > job.budget_s:
            break
    return statistics.median(walls), statistics.median(cpus), len(walls)


def _expire(_signum: int, _frame: object) -> None:
    raise TimeoutError


def _arm(seconds: float) -> object:
    """Raise TimeoutError in this process after ``seconds``; returns what ``_disarm`` restores."""
    previous = signal.signal(signal.SIGALRM, _expire)
    signal.alarm(int(seconds))
    return previous


def _disarm(previous: object) -> None:
    signal.alarm(0)
    signal.signal(signal.SIGALRM, previous)  # type: ignore[arg-type]


def measure_analyze(job: Job) -> Metrics:
    """What ``rosvar analyze`` does before printing, with nothing cached from a prior run."""
    from rosvar.frontends.xml import clear_cache
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.workspace import discover

    def reset() -> None:
        job.analysis = None  # the previous run's models must not inflate this one's heap
        clear_cache()

    def run() -> None:
        started = time.perf_counter()
        workspace = discover(job.roots, ros_package_path=job.package_path)
        analysis = Analysis(workspace)
        analysis.all_models()
        job.analysis, job.analysis_ms = analysis, (time.perf_counter() - started) * 1000
        job.files = workspace.launch_files

    wall, cpu, runs = _timed_runs(job, run, reset)
    peak_kib = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss  # KiB on Linux
    clear_cache()
    gc.collect()
    return {
        "files": len(job.files),
        "analyze_ms": wall,
        "analyze_cpu_ms": cpu,
        "runs": runs,
        "peak_mb": peak_kib / 1024,
    }


def measure_minidom(job: Job) -> Metrics:
    """The baseline: parse the same launch files with minidom, as roslaunch does."""

    def run() -> None:
        for file in job.files:
            minidom.parse(file).unlink()

    wall, cpu, _runs = _timed_runs(job, run)
    return {"minidom_ms": wall, "minidom_cpu_ms": cpu}


FEATURES_BUDGET_S = 120.0  # the feature model of a large workload may not finish: bound it


QUESTIONS_MAX_FILES = 137
"""The solver questions are timed up to Husky's size: on 400 generated files one question
outlasted the budget by minutes."""


def measure_features(job: Job) -> Metrics:
    """``rosvar features``' work on the models ``measure_analyze`` interpreted, timed apart.

    Interpretation is the analyze measurement's (and another module's cost); what is
    timed here is the feature model proper: extraction (Algorithm 1, conflicts through
    the name index, the solver's BDDs) and the valid-configuration count, then, apart,
    the solver questions ``rosvar features`` answers on top (core/dead features with
    explanations, the simplest trigger of every conflict). Bounded by an alarm: a
    timeout is a figure too. The models are dropped afterwards, so the baseline that
    follows finds a small heap.
    """
    from rosvar.analyses.feature_model.extraction import extract
    from rosvar.analyses.feature_model.operations import (
        core_and_dead,
        count_configurations,
        simplest_trigger,
    )
    from rosvar.interpreter.workspace_models import Analysis

    analysis, job.analysis = job.analysis, None
    if not isinstance(analysis, Analysis):
        return {}

    metrics: Metrics = {"features_interpret_ms": job.analysis_ms}
    previous = _arm(FEATURES_BUDGET_S)
    try:
        wall, cpu = time.perf_counter(), time.process_time()
        model = extract(analysis)
        count_configurations(model)
        metrics["features_ms"] = (time.perf_counter() - wall) * 1000
        job.feature_model_built = model.solved
        metrics["features_cpu_ms"] = (time.process_time() - cpu) * 1000
        if not model.solved:  # over the solver's budget: listed, count unknown, no questions
            metrics["features_unsolved"] = 1
            return metrics
        if len(analysis.workspace.launch_files) > QUESTIONS_MAX_FILES:
            return metrics
        metrics["conflict_pairs"] = len(model.clashes)
        metrics["constraints"] = len(model.constraints)
        wall = time.perf_counter()
        core_and_dead(model)
        for condition in {c.condition for c in model.constraints if c.kind == "excludes"}:
            simplest_trigger(model.space, condition)
        metrics["features_questions_ms"] = (time.perf_counter() - wall) * 1000
    except TimeoutError:
        metrics["features_timeout_s"] = FEATURES_BUDGET_S
    finally:
        _disarm(previous)
        del analysis
        gc.collect()
    return metrics


def random_click(
    rng: random.Random, features: Mapping[str, Mapping[str, Any]]
) -> tuple[str, str] | None:
    """A seeded user's next click, on features as JSON: a random open feature (not an
    ``<other>`` slot, which wants a typed text), a value selected, a file or an arg selected
    or deselected; None once nothing is open (the product is complete)."""
    open_ = [
        k for k, f in features.items() if f["state"] == "unselected" and f["value"] != "<other>"
    ]
    if not open_:
        return None
    feature = rng.choice(open_)
    kind = features[feature]["kind"]
    return ("select" if kind == "value" else rng.choice(("select", "deselect"))), feature


WEB_BUDGET_S = 300.0  # engine construction plus the clicks, bounded
WEB_MAX_FILES = 150  # the corpus (Husky: 137 files) and gen-100; larger ones not through HTTP
WEB_CLICKS = 60
WEB_SEED = 7


SELECTIONS = {"u": "unselected", "s": "selected", "d": "deselected"}
"""A feature's state as an overview state spells it (``overview.SELECTIONS``; upper case:
derived)."""


def measure_web(job: Job) -> Metrics:
    """Click-to-data latency of ``rosvar serve``: ``POST /api/choose`` round trips over HTTP.

    The server runs in a thread of this process on a free loopback port; one keep-alive
    connection plays the browser. A seeded random sequence of clicks (a random open feature,
    not an ``<other>`` slot, selected or deselected; a new session once the product is
    complete) is timed from sending each request to the last byte of its answer: the engine
    step, the JSON and the transfer. Refused choices count as well, being round trips too.
    As the page does, each click names the version of the state held, is answered with a
    delta and patched in; the patched state is checked against the server's whole one.
    Twice, on one engine: with whole states (the API for scripts), then in overview mode
    as the page asks (its features read through the catalog, its graph in summaries).
    """
    import http.client
    import threading

    from rosvar.analyses.feature_model.extraction import extract
    from rosvar.configuration.engine import Configurator
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.outputs.web.delta import patch
    from rosvar.outputs.web.entries import render
    from rosvar.outputs.web.server import make_server
    from rosvar.workspace import discover

    if len(job.files) > WEB_MAX_FILES or not job.feature_model_built:
        return {}

    previous = _arm(WEB_BUDGET_S)
    metrics: Metrics = {}
    server = None
    try:
        analysis = Analysis(discover(job.roots, ros_package_path=job.package_path))
        server = make_server(
            Configurator(analysis, extract(analysis, products=True), render=render), port=0
        )
        threading.Thread(target=server.serve_forever, daemon=True).start()
        connection = http.client.HTTPConnection("127.0.0.1", server.server_address[1])

        def clicks(opening: Mapping[str, object]) -> tuple[list[float], list[int]]:
            """The sequence of clicks in sessions opened with ``opening``: each click's
            milliseconds and bytes."""
            rounds: list[float] = []
            sizes: list[int] = []
            rows: list[list[Any]] = []
            if opening:
                connection.request("GET", "/api/catalog")
                rows = json.loads(connection.getresponse().read())["features"]

            def call(path: str, body: dict[str, object], held: dict[str, Any]) -> dict[str, Any]:
                """The state after the request: ``held`` patched with the answer."""
                wall = time.perf_counter()
                connection.request(
                    "POST", path, json.dumps(body), {"Content-Type": "application/json"}
                )
                answer = connection.getresponse().read()
                if path == "/api/choose":
                    rounds.append((time.perf_counter() - wall) * 1000)
                    sizes.append(len(answer))
                return patch(held, json.loads(answer))

            def features(state: dict[str, Any]) -> dict[str, Any]:
                if not opening:
                    found: dict[str, Any] = state["features"]
                    return found
                return {
                    row[0]: {"state": SELECTIONS[mark.lower()], "kind": row[1], "value": row[4]}
                    for row, mark in zip(rows, state["features"], strict=True)
                }

            state = call("/api/session", dict(opening), {})
            rng = random.Random(WEB_SEED)
            while len(rounds) < WEB_CLICKS:
                click = random_click(rng, features(state))
                if click is None:
                    state = call("/api/session", dict(opening), state)
                    continue
                action, feature = click
                body = {
                    "session": state["session"],
                    "version": state["version"],
                    "action": action,
                    "feature": feature,
                }
                state = call("/api/choose", body, state)
            connection.request("GET", f"/api/state?session={state['session']}")
            whole = json.loads(connection.getresponse().read())
            if {**state, "version": 0, "refused": []} != {**whole, "version": 0}:
                raise AssertionError("the state patched from the answers is not the server's")
            return rounds, sizes

        for prefix, opening in (("web_choose", {}), ("web_overview", {"overview": "package"})):
            rounds, sizes = clicks(opening)
            metrics[f"{prefix}_p50_ms"] = statistics.median(rounds)
            metrics[f"{prefix}_p95_ms"] = statistics.quantiles(rounds, n=20)[-1]
            metrics[f"{prefix}_answer_kb"] = statistics.median(sizes) / 1024
        metrics["web_clicks"] = WEB_CLICKS
    except TimeoutError:
        if not metrics:
            return {"web_timeout_s": WEB_BUDGET_S}
    finally:
        _disarm(previous)
        if server is not None:
            server.shutdown()
            server.server_close()
    return metrics


CONFIGURE_BUDGET_S = 300.0  # engine construction plus the selection sequences, bounded
CONFIGURE_SEQUENCES = 5
CONFIGURE_MAX_FILES = 2_000  # the issue measures the engine up to the 2,000-file workspace
CONFIGURE_SEED = 4


def measure_configure(job: Job) -> Metrics:
    """Per-step latency of the configuration engine, in-process, over random sequences.

    A step is what a session does for one click: ``Configurator.state(choices + [one])``,
    the answer for the shorter list being cached. Each seeded sequence selects or deselects
    a random unselected feature (not an ``<other>`` value) until the product is complete.
    ``state_document`` of each state is timed apart (what the web server then serialises).
    """

    from rosvar.analyses.feature_model.extraction import extract
    from rosvar.configuration.choices import UserChoice
    from rosvar.configuration.engine import Configurator
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.outputs.documents.state import feature_document, state_document
    from rosvar.outputs.web.entries import render
    from rosvar.workspace import discover

    if len(job.files) > CONFIGURE_MAX_FILES or not job.feature_model_built:
        return {}
    previous = _arm(CONFIGURE_BUDGET_S)
    steps: list[float] = []
    documents: list[float] = []
    built_ms = 0.0
    try:
        analysis = Analysis(discover(job.roots, ros_package_path=job.package_path))
        started = time.perf_counter()
        engine = Configurator(analysis, extract(analysis, products=True), render=render)
        built_ms = (time.perf_counter() - started) * 1000
        rng = random.Random(CONFIGURE_SEED)
        for _sequence in range(CONFIGURE_SEQUENCES):
            choices: list[UserChoice] = []
            while True:
                wall = time.perf_counter()
                state = engine.state(choices)
                steps.append((time.perf_counter() - wall) * 1000)
                wall = time.perf_counter()
                state_document(state)
                documents.append((time.perf_counter() - wall) * 1000)
                click = random_click(
                    rng, {k: feature_document(f) for k, f in state.features.items()}
                )
                if click is None:
                    break
                choices.append(UserChoice.parse(*click))
    except TimeoutError:
        if len(steps) < 2:
            return {"configure_timeout_s": CONFIGURE_BUDGET_S}
    finally:
        _disarm(previous)
    return {
        "configure_build_ms": built_ms,
        "configure_steps": len(steps),
        "configure_step_p50_ms": statistics.median(steps),
        "configure_step_p95_ms": statistics.quantiles(steps, n=20)[-1],
        "configure_json_p95_ms": statistics.quantiles(documents, n=20)[-1],
    }


# Run in this order: peak RSS is read right after the analysis, the feature model reuses
# its models (and frees them), the baseline parses the files the analysis found.
ISOLATED_MEASUREMENTS: dict[str, Callable[[Job], Metrics]] = {
    "analyze": measure_analyze,
    "features": measure_features,
    "minidom": measure_minidom,
    "web": measure_web,
    "configure": measure_configure,
}


def run_one(options: argparse.Namespace) -> None:
    """The ``--one`` mode: import cost recorded apart, then every isolated measurement."""
    import rosvar.interpreter.workspace_models  # noqa: F401 - imported before measuring

    metrics: Metrics = {"import_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}
    job = Job(options.paths, options.package_path, options.repeats, options.budget)
    for name, measure in ISOLATED_MEASUREMENTS.items():
        metrics.update(measure(job))
        # the figures so far, each time: a later measurement that fails keeps them
        sys.stdout.write(json.dumps({**metrics, "measured": name}) + "\n")
        sys.stdout.flush()
    os._exit(0)  # the BDD manager's teardown is not part of any measurement


# -- measurements in the driver, each a subprocess -----------------------------------------
@dataclass
class Outcome:
    """One workload's figures; ``notes`` say why some are missing."""

    workload: Workload
    metrics: Metrics = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)

    def get(self, key: str) -> float | None:
        return self.metrics.get(key)


@dataclass
class Finished:
    returncode: int | None  # None: killed at the timeout
    wall_ms: float
    peak_mb: float
    stdout: str
    stderr: str


def _limit_memory() -> None:
    limit = MEMORY_LIMIT_MB * 1024 * 1024
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def run_bounded(
    command: Sequence[str], env: dict[str, str], stdout: bool = True, timeout: float = TIMEOUT_S
) -> Finished:
    """Run ``command`` for at most ``timeout`` seconds, keeping its own rusage (os.wait4) for
    peak RSS."""
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err:
        started = time.perf_counter()
        process = subprocess.Popen(
            command,
            stdout=out if stdout else subprocess.DEVNULL,
            stderr=err,
            env=env,
            preexec_fn=_limit_memory,
        )
        deadline = started + timeout
        status: int | None = None
        maxrss = 0
        while time.perf_counter() < deadline:
            pid, wait_status, usage = os.wait4(process.pid, os.WNOHANG)
            if pid:
                status, maxrss = os.waitstatus_to_exitcode(wait_status), usage.ru_maxrss
                break
            time.sleep(0.02)
        wall = (time.perf_counter() - started) * 1000
        if status is None:
            process.kill()
            process.wait()
        else:
            process.returncode = status  # reaped by wait4 already; Popen must not wait again
        out.seek(0)
        err.seek(0)
        text = out.read().decode(errors="replace")
        return Finished(status, wall, maxrss / 1024, text, err.read().decode(errors="replace"))


def _env(workload: Workload) -> dict[str, str]:
    return {**os.environ, "ROS_PACKAGE_PATH": workload.package_path}


def _failure(finished: Finished, what: str, timeout: float = TIMEOUT_S) -> str:
    if finished.returncode is None:
        return f"{what}: timeout after {timeout:.0f} s"
    tail = finished.stderr.strip().splitlines()[-1:] or ["no output"]
    return f"{what}: exit {finished.returncode} ({tail[0][:120]})"


def measure_isolated(workload: Workload, roots: list[str], outcome: Outcome) -> bool:
    command = [
        sys.executable, str(Path(__file__).resolve()), "--one",
        "--repeats", str(workload.repeats), "--budget", str(TIMEOUT_S * 0.5),
        "--package-path", workload.package_path, *roots,
    ]  # fmt: skip
    finished = run_bounded(command, _env(workload))
    lines = finished.stdout.strip().splitlines()
    measured = json.loads(lines[-1]) if lines else {}
    last = measured.pop("measured", None)  # the last measurement whose figures came
    outcome.metrics.update(measured)
    if finished.returncode == 0 and lines:
        return True
    after = f"after {last}" if last else "before any figure"
    outcome.notes.append(_failure(finished, f"in-process ({after})"))
    return "analyze_ms" in outcome.metrics


def _rosvar_command() -> list[str]:
    script = Path(sys.executable).parent / "rosvar"
    return [str(script)] if script.exists() else [sys.executable, "-m", "rosvar"]


def measure_whole_process(workload: Workload, roots: list[str], outcome: Outcome) -> bool:
    if "analyze_ms" not in outcome.metrics:
        outcome.notes.append("whole-process: skipped (in-process run failed)")
        return False
    command = [*_rosvar_command(), "analyze", *roots, "--json"]
    finished = run_bounded(command, _env(workload), stdout=False)
    if finished.returncode == 0:
        outcome.metrics["whole_ms"] = finished.wall_ms
        outcome.metrics["whole_peak_mb"] = finished.peak_mb
        return True
    outcome.notes.append(_failure(finished, "whole-process"))
    return False


# -- whole processes as a user runs them -----------------------------------------------------
COMMAND_REPEATS = 3
SLOW_COMMAND_S = 20.0  # a command this slow is timed once: more runs would say nothing new
LONG_COMMAND_CAP_S = 150.0  # the cap of issue 28's commands (67 s when the issue was filed)
HAROSVAR = "harosvar"  # the paper's prototype (github.com/git-afsanos/harosvar), if installed


@dataclass(frozen=True)
class Command:
    """A command line measured as a whole process: wall time (median of ``COMMAND_REPEATS``,
    one run from ``SLOW_COMMAND_S``) and peak RSS (the largest), with the targets of the
    issue: ``wall_s``/``peak_mb``, or ``within`` a factor of another command's wall time.
    A run is stopped at ``cap_s`` (reported as over it); ``ok_codes`` are the exit codes of a
    finished run (``check`` exits with 1 when it finds errors)."""

    name: str
    argv: Callable[[Path], list[str] | None]  # None: not available on this machine
    wall_s: float | None = None
    peak_mb: float | None = None
    within: tuple[str, float] | None = None  # (another command's name, factor)
    cap_s: float = TIMEOUT_S
    ok_codes: tuple[int, ...] = (0,)


def _rosvar(*words: str, workload: str | None = None) -> Callable[[Path], list[str]]:
    def argv(scratch: Path) -> list[str]:
        roots = WORKLOADS[workload].prepare(scratch) if workload else []
        return [*_rosvar_command(), *words[:1], *roots, *words[1:]]

    return argv


def _harosvar(scratch: Path) -> list[str] | None:
    found = shutil.which(HAROSVAR)
    return None if found is None else [found, *WORKLOADS["uni-400"].prepare(scratch)]


COMMANDS: list[Command] = [
    Command("rosvar --version", _rosvar("--version"), wall_s=0.15),
    Command("rosvar analyze uni-400", _rosvar("analyze", workload="uni-400")),
    Command(
        "rosvar analyze uni-400 --json",
        _rosvar("analyze", "--json", workload="uni-400"),
        wall_s=1.0,
        peak_mb=150,
    ),
    Command(
        "rosvar analyze uni-400 --json -j 1 (one process)",
        _rosvar("analyze", "--json", "--jobs", "1", workload="uni-400"),
    ),
    Command(
        "rosvar analyze uni-2000 --json", _rosvar("analyze", "--json", workload="uni-2000"), 5.0
    ),
    Command(
        "rosvar features husky _external",
        lambda _scratch: [*_rosvar_command(), "features", str(CORPUS / "husky"), str(EXTERNAL)],
        wall_s=2.0,
    ),
    Command(
        f"rosvar analyze ros2-{ROS2_FILES}",
        _rosvar("analyze", workload=f"ros2-{ROS2_FILES}"),
        wall_s=2.0,
    ),
    # issue 28: the large ROS 2 systems
    Command(
        f"rosvar analyze {ROS2_DENSE}",
        _rosvar("analyze", workload=ROS2_DENSE),
        wall_s=3.0,
        peak_mb=300,
        cap_s=LONG_COMMAND_CAP_S,
    ),
    *(
        Command(
            f"rosvar {name} {ROS2_DENSE}",
            _rosvar(name, workload=ROS2_DENSE),
            within=(f"rosvar analyze {ROS2_DENSE}", 2.0),
            cap_s=LONG_COMMAND_CAP_S,
            ok_codes=codes,
        )
        for name, codes in (("features", (0,)), ("check", (0, 1)))
    ),
    Command(
        f"rosvar analyze {AUTOWARE}",
        _rosvar("analyze", workload=AUTOWARE),
        wall_s=10.0,
        cap_s=LONG_COMMAND_CAP_S,
    ),
    Command("harosvar uni-400 (the paper's prototype)", _harosvar),
]


@dataclass
class CommandOutcome:
    command: Command
    wall_ms: float | None = None
    peak_mb: float | None = None
    note: str = ""


def measure_commands(scratch: Path, only: Sequence[str] = ()) -> list[CommandOutcome]:
    """Each command of :data:`COMMANDS` in fresh processes, output to /dev/null, with an
    empty ROS_PACKAGE_PATH (the command line says everything)."""
    outcomes = []
    for command in [c for c in COMMANDS if not only or any(t in c.name for t in only)]:
        print(f"{command.name} ...", file=sys.stderr, flush=True)
        outcome = CommandOutcome(command)
        outcomes.append(outcome)
        argv = command.argv(scratch)
        if argv is None:
            outcome.note = "not installed"
            continue
        walls, peaks = [], []
        for _ in range(COMMAND_REPEATS):
            env = {**os.environ, "ROS_PACKAGE_PATH": ""}
            finished = run_bounded(argv, env, stdout=False, timeout=command.cap_s)
            if finished.returncode is None:
                outcome.note = f"> {command.cap_s:.0f} s (cap)"
                break
            if finished.returncode not in command.ok_codes:
                outcome.note = _failure(finished, "run")
                break
            walls.append(finished.wall_ms)
            peaks.append(finished.peak_mb)
            if finished.wall_ms >= SLOW_COMMAND_S * 1000:
                break
        if walls:
            outcome.wall_ms, outcome.peak_mb = statistics.median(walls), max(peaks)
    return outcomes


def command_lines(outcomes: Sequence[CommandOutcome]) -> list[str]:
    """The commands' figures as a Markdown table, then a PASS/FAIL line per target."""
    lines = ["| command | wall s | peak MB | target |", "|---|---:|---:|---|"]
    verdicts = []
    walls = {o.command.name: o.wall_ms for o in outcomes}
    for outcome in outcomes:
        command = outcome.command
        wall = None if outcome.wall_ms is None else outcome.wall_ms / 1000
        limits = []
        if command.wall_s is not None:
            limits.append(f"≤ {command.wall_s:g} s")
            verdicts.append(_verdict(command.name, "wall", wall, command.wall_s, "s", outcome))
        if command.within is not None:
            other, factor = command.within
            limits.append(f"≤ {factor:g} × `{other}`")
            verdicts.append(_relative_verdict(command.name, wall, other, factor, walls, outcome))
        if command.peak_mb is not None:
            limits.append(f"≤ {command.peak_mb:g} MB")
            verdicts.append(
                _verdict(command.name, "peak", outcome.peak_mb, command.peak_mb, "MB", outcome)
            )
        shown = outcome.note or _number(wall, 2)
        lines.append(
            f"| `{command.name}` | {shown} | {_number(outcome.peak_mb)} | {', '.join(limits)} |"
        )
    return [*lines, "", *verdicts]


def _relative_verdict(
    name: str,
    wall: float | None,
    other: str,
    factor: float,
    walls: Mapping[str, float | None],
    outcome: CommandOutcome,
) -> str:
    """PASS when ``wall`` is at most ``factor`` times the wall time of command ``other``."""
    label = f"{name}: wall ≤ {factor:g} × {other}"
    base = walls.get(other)
    if wall is None or base is None:
        why = outcome.note if wall is None else f"{other}: no figure"
        return f"FAIL  {label}: {why or 'no figure'}"
    limit = factor * base / 1000
    status = "PASS" if wall <= limit else "FAIL"
    return f"{status}  {label}: {wall:,.2f} s (limit {limit:,.2f} s)"


def _verdict(
    name: str, what: str, value: float | None, limit: float, unit: str, outcome: CommandOutcome
) -> str:
    label = f"{name}: {what} ≤ {limit:g} {unit}"
    if value is None:
        return f"FAIL  {label}: {outcome.note or 'no figure'}"
    status = "PASS" if value <= limit else "FAIL"
    return f"{status}  {label}: {value:,.2f} {unit}"


ENGINE_START_WORKLOAD = "husky"  # measured with the third-party packages as launch files too
SERVE_GROUPING = "package"  # the page's first session is in overview mode, grouped so


def _serve(roots: list[str]) -> tuple[subprocess.Popen[bytes], str] | None:
    """``rosvar serve`` on ``roots`` started, and its address once it listens (None: it
    stopped before)."""
    command = [*_rosvar_command(), "serve", *roots, "--port", "0"]
    process = subprocess.Popen(
        command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, preexec_fn=_limit_memory
    )
    assert process.stdout is not None
    line = process.stdout.readline().decode()  # "serving URL" once ready, "" if it stopped
    address = next((word for word in line.split() if word.startswith("http://")), None)
    if address is None:
        process.terminate()
        process.wait(timeout=30)
        return None
    return process, address


def _peak_mb(process: subprocess.Popen[bytes]) -> float:
    status = Path(f"/proc/{process.pid}/status").read_text(encoding="utf-8")
    return (
        next(int(row.split()[1]) for row in status.splitlines() if row.startswith("VmHWM")) / 1024
    )


def _serve_first_answers(roots: list[str]) -> tuple[float, float, float] | None:
    """``rosvar serve`` on ``roots`` as the page meets it: seconds from the start until it
    listens, and until it has answered the page's first requests (``GET /api/catalog``,
    then ``POST /api/session`` in overview mode); the peak RSS (MB) by then."""
    import http.client

    started = time.perf_counter()
    served = _serve(roots)
    if served is None:
        return None
    process, address = served
    try:
        ready = time.perf_counter() - started
        host, port = address.removeprefix("http://").rstrip("/").split(":")
        connection = http.client.HTTPConnection(host, int(port), timeout=TIMEOUT_S)
        connection.request("GET", "/api/catalog")
        connection.getresponse().read()
        body = json.dumps({"overview": SERVE_GROUPING})
        connection.request("POST", "/api/session", body, {"Content-Type": "application/json"})
        connection.getresponse().read()
        return ready, time.perf_counter() - started, _peak_mb(process)
    finally:
        process.terminate()
        process.wait(timeout=30)


def minidom_baseline_ms(roots: list[str], package_path: str = "") -> float:
    """The baseline of a whole-process figure, taken in this process just before it: parsing
    the launch files below ``roots`` with minidom, as roslaunch does (a shared machine's
    speed changes from minute to minute; a figure is read against this)."""
    from rosvar.workspace import discover

    files = discover(roots, ros_package_path=package_path).launch_files
    started = time.perf_counter()
    for file in files:
        minidom.parse(file).unlink()
    return (time.perf_counter() - started) * 1000


def measure_engine_start(workload: Workload, roots: list[str], outcome: Outcome) -> bool:
    """The configuration engine's start on a real workspace, Husky with every third-party
    package as launch files too (issue 17): ``configure`` to its answer, ``serve`` until
    the page's first requests are answered (issue 30), a baseline beside them."""
    if workload.name != ENGINE_START_WORKLOAD:
        return True
    paths = [*roots, str(EXTERNAL)]
    outcome.metrics["engine_baseline_ms"] = minidom_baseline_ms(paths)
    finished = run_bounded([*_rosvar_command(), "configure", *paths], _env(workload), False)
    if finished.returncode != 0:
        outcome.notes.append(_failure(finished, "engine start (configure)"))
        return False
    outcome.metrics["engine_configure_s"] = finished.wall_ms / 1000
    outcome.metrics["engine_configure_mb"] = finished.peak_mb
    served = _serve_first_answers(paths)
    if served is None:
        outcome.notes.append("engine start (serve): stopped before it was ready")
        return False
    ready, answered, peak = served
    outcome.metrics["engine_serve_ready_s"] = ready
    outcome.metrics["engine_serve_s"], outcome.metrics["engine_serve_mb"] = answered, peak
    return True


BROWSER_WAIT_S = 300.0  # the page's first view on a busy machine, bounded
BROWSER_CHOICE = "husky_gazebo/launch/husky_playpen.launch"


SHOWN = """() => {
  const step = document.body.dataset.step;
  const shown = () => document.body.dataset.step !== step
    && document.getElementById("graph").dataset.layout === "done";
  window.rosvarShown = new Promise((resolve) => {
    const observer = new MutationObserver(() => {
      if (shown()) { observer.disconnect(); resolve(true); }
    });
    observer.observe(document.body, { attributes: true, subtree: true,
                                      attributeFilter: ["data-step", "data-layout"] });
  });
}"""
"""Installed before the click: a promise the page resolves once it shows the next state with
its graph laid out. Told by the page's own mutations, where Playwright's waiting for a
selector queried the whole page at every frame, on the processors the server needs."""


def _cpu_s(process: subprocess.Popen[bytes]) -> float:
    """The CPU seconds (user and system) ``process`` has used: the machine may be busy,
    which stretches wall time, hardly CPU time."""
    fields = Path(f"/proc/{process.pid}/stat").read_text(encoding="utf-8").rsplit(")", 1)[1]
    user, system = fields.split()[11:13]
    return (int(user) + int(system)) / os.sysconf("SC_CLK_TCK")


def measure_browser_choice(workload: Workload, roots: list[str], outcome: Outcome) -> bool:
    """A choice in the browser on Husky with ``_external`` as a second root (issue 30): the
    page of ``rosvar serve`` in headless Chromium (Debian's, through Playwright, as the
    browser tests), ``husky_playpen.launch`` selected in the tree once the page is at rest
    (its first view drawn, its checks listed and answered); seconds from the click
    until the page shows the new state and its graph is laid out, the server's CPU seconds
    meanwhile (a busy machine stretches the wall time), and the bytes of the answers it
    fetched for it. Skipped (with a note) without Playwright or Chromium."""
    if workload.name != ENGINE_START_WORKLOAD:
        return True
    chromium = "/usr/bin/chromium"
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        outcome.notes.append("browser choice: skipped (Playwright is not installed)")
        return True
    if not os.access(chromium, os.X_OK):
        outcome.notes.append(f"browser choice: skipped ({chromium} not found)")
        return True
    served = _serve([*roots, str(EXTERNAL)])
    if served is None:
        outcome.notes.append("browser choice: the server stopped before it was ready")
        return False
    process, address = served
    try:
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=chromium)
            page = browser.new_page(viewport={"width": 1600, "height": 1000})
            page.set_default_timeout(BROWSER_WAIT_S * 1000)
            page.goto(address)
            page.wait_for_selector('body[data-step] #graph[data-layout="done"]')
            page.wait_for_selector("body[data-checks]")  # at rest: the findings listed
            features = page.evaluate("window.rosvar.state.features")
            file = next(k for k, f in features.items() if k.endswith(BROWSER_CHOICE))
            row = page.locator(f'.feature[data-id="{file}"]').first
            button = row.locator(":scope > summary, :scope > .row").first
            sizes: list[int] = []
            page.on("response", lambda response: sizes.append(len(response.body())))
            page.evaluate(SHOWN)
            cpu = _cpu_s(process)
            started = time.perf_counter()
            button.locator('.choose button[data-action="select"]').click()
            page.evaluate("window.rosvarShown")
            outcome.metrics["browser_choice_s"] = time.perf_counter() - started
            outcome.metrics["browser_choice_server_cpu_s"] = _cpu_s(process) - cpu
            outcome.metrics["browser_choice_kb"] = sum(sizes) / 1024
            outcome.notes.append(
                f"browser choice: {outcome.metrics['browser_choice_s']:.2f} s wall, of which "
                f"{outcome.metrics['browser_choice_server_cpu_s']:.2f} s of the server's CPU"
            )
            browser.close()
    finally:
        process.terminate()
        process.wait(timeout=30)
    return True


# Each returns whether it got its figures; a failure skips it for larger sizes of the family.
DRIVER_MEASUREMENTS: dict[str, Callable[[Workload, list[str], Outcome], bool]] = {
    "isolated": measure_isolated,
    "whole-process": measure_whole_process,
    "engine-start": measure_engine_start,
    "browser-choice": measure_browser_choice,
}


# -- derived figures, table and targets -----------------------------------------------------
def per_file_ms(outcome: Outcome) -> float | None:
    time_ms, files = outcome.get("analyze_ms"), outcome.get("files")
    return time_ms / files if time_ms is not None and files else None


def growth_steps(outcomes: Sequence[Outcome]) -> dict[str, tuple[Outcome, Outcome]]:
    """For each sized workload, the next smaller size of its family."""
    by_family: dict[str, list[Outcome]] = {}
    for outcome in outcomes:
        if outcome.workload.size:
            by_family.setdefault(outcome.workload.family, []).append(outcome)
    steps: dict[str, tuple[Outcome, Outcome]] = {}
    for members in by_family.values():
        members.sort(key=lambda o: o.workload.size)
        for small, large in itertools.pairwise(members):
            steps[large.workload.name] = (small, large)
    return steps


@dataclass(frozen=True)
class Growth:
    files_ratio: float
    time_ratio: float

    @property
    def per_file_ratio(self) -> float:
        return self.time_ratio / self.files_ratio

    @property
    def exponent(self) -> float:
        return math.log(self.time_ratio) / math.log(self.files_ratio)


def growth(step: tuple[Outcome, Outcome]) -> Growth | None:
    small, large = step
    times = (small.get(GROWTH_KEY), large.get(GROWTH_KEY))
    files = (small.get("files"), large.get("files"))
    if None in times or None in files:
        return None
    return Growth(files[1] / files[0], times[1] / times[0])  # type: ignore[operator]


def _number(value: float | None, digits: int = 0) -> str:
    return "—" if value is None else f"{value:,.{digits}f}"


@dataclass(frozen=True)
class Column:
    header: str
    cell: Callable[[Outcome, dict[str, tuple[Outcome, Outcome]]], str]
    align: str = ">"


def _ratio(outcome: Outcome) -> str:
    time_ms, base = outcome.get("analyze_ms"), outcome.get("minidom_ms")
    return "—" if time_ms is None or not base else f"{time_ms / base:,.1f} ×"


def _growth_cell(outcome: Outcome, steps: dict[str, tuple[Outcome, Outcome]]) -> str:
    step = steps.get(outcome.workload.name)
    found = growth(step) if step else None
    if found is None:
        return ""
    return (
        f"×{found.files_ratio:.1f} files → ×{found.time_ratio:.1f} CPU time "
        f"(per file ×{found.per_file_ratio:.2f}, ~n^{found.exponent:.2f})"
    )


def _in_process_cell(outcome: Outcome, _steps: object) -> str:
    runs = outcome.get("runs")
    suffix = f" ({runs:.0f})" if runs is not None else ""
    return _number(outcome.get("analyze_ms")) + suffix


def _features_cell(outcome: Outcome, _steps: object) -> str:
    if outcome.get("features_timeout_s") is not None and outcome.get("features_ms") is None:
        return f"> {FEATURES_BUDGET_S:,.0f} s"
    unsolved = " (too large: count unknown)" if outcome.get("features_unsolved") else ""
    return _number(outcome.get("features_ms")) + unsolved


def _questions_cell(outcome: Outcome, _steps: object) -> str:
    return _number(outcome.get("features_questions_ms"))


def _web_cell(outcome: Outcome, _steps: object) -> str:
    if outcome.get("web_timeout_s") is not None:
        return "timeout"
    cells = []
    for prefix in ("web_choose", "web_overview"):
        p50, p95 = outcome.get(f"{prefix}_p50_ms"), outcome.get(f"{prefix}_p95_ms")
        size = outcome.get(f"{prefix}_answer_kb")
        cells.append("—" if p50 is None else f"{p50:,.1f} / {_number(p95, 1)} ({_number(size)})")
    return " · ".join(cells)


def _configure_cell(outcome: Outcome, _steps: object) -> str:
    if outcome.get("configure_timeout_s") is not None:
        return f"> {CONFIGURE_BUDGET_S:,.0f} s"
    p50, p95 = outcome.get("configure_step_p50_ms"), outcome.get("configure_step_p95_ms")
    return "—" if p50 is None else f"{p50:,.1f} / {_number(p95, 1)}"


COLUMNS: list[Column] = [
    Column("workload", lambda o, _s: o.workload.name, "<"),
    Column("files", lambda o, _s: _number(o.get("files"))),
    Column("in-process ms (runs)", _in_process_cell),
    Column("CPU ms", lambda o, _s: _number(o.get("analyze_cpu_ms"))),
    Column("ms/file", lambda o, _s: _number(per_file_ms(o), 1)),
    Column("whole-process ms", lambda o, _s: _number(o.get("whole_ms"))),
    Column("peak MB", lambda o, _s: _number(o.get("peak_mb"))),
    Column("minidom ms", lambda o, _s: _number(o.get("minidom_ms"), 1)),
    Column("× minidom parse", lambda o, _s: _ratio(o)),
    Column("growth vs previous size", _growth_cell, "<"),
    Column("features: interpretation ms", lambda o, _s: _number(o.get("features_interpret_ms"))),
    Column("features: model ms", _features_cell),
    Column("features: core/dead + triggers ms", _questions_cell),
    Column("web click p50/p95 ms (answer KB): whole · overview", _web_cell),
    Column("configure step p50/p95 ms", _configure_cell),
]


def table_rows(outcomes: Sequence[Outcome]) -> list[list[str]]:
    steps = growth_steps(outcomes)
    return [[column.cell(outcome, steps) for column in COLUMNS] for outcome in outcomes]


def text_table(outcomes: Sequence[Outcome]) -> str:
    rows = [[c.header for c in COLUMNS], *table_rows(outcomes)]
    widths = [max(len(row[i]) for row in rows) for i in range(len(COLUMNS))]
    lines = [
        "  ".join(f"{cell:{c.align}{w}}" for cell, c, w in zip(row, COLUMNS, widths, strict=True))
        for row in rows
    ]
    return "\n".join(line.rstrip() for line in lines)


def markdown_table(outcomes: Sequence[Outcome]) -> str:
    header = "| " + " | ".join(c.header for c in COLUMNS) + " |"
    rule = "|" + "|".join("---:" if c.align == ">" else "---" for c in COLUMNS) + "|"
    body = ["| " + " | ".join(row) + " |" for row in table_rows(outcomes)]
    return "\n".join([header, rule, *body])


@dataclass(frozen=True)
class Verdict:
    status: str  # PASS, FAIL, or SKIP (workload not in this run)
    detail: str


@dataclass(frozen=True)
class Target:
    label: str
    check: Callable[[dict[str, Outcome]], Verdict]


def _why_missing(outcome: Outcome | None) -> Verdict:
    if outcome is None:
        return Verdict("SKIP", "workload not in this run")
    return Verdict("FAIL", "; ".join(outcome.notes) or "no figure")


BASELINES = {
    "minidom_ms": "minidom parse of its files in the same process",
    "engine_baseline_ms": "minidom parse of its files in the bench's process just before",
}
"""What a figure is read against, by metric: the machine is shared, and its speed changes from
minute to minute; a baseline taken beside the figure says how fast it was then."""


def at_most(
    workload: str,
    key: str,
    limit: float,
    unit: str,
    scale: float = 1.0,
    baseline: str | None = "minidom_ms",
) -> Target:
    """Target: ``key`` of ``workload`` (divided by ``scale`` for display) ≤ ``limit``, shown
    beside ``baseline`` (a metric of :data:`BASELINES`, in ms) and their ratio."""

    def check(outcomes: dict[str, Outcome]) -> Verdict:
        outcome = outcomes.get(workload)
        value = outcome.get(key) if outcome else None
        if value is None:
            return _why_missing(outcome)
        shown = value / scale
        status = "PASS" if shown <= limit else "FAIL"
        detail = f"{shown:,.2f} {unit} (limit {limit:,} {unit}"
        base = outcome.get(baseline) if outcome is not None and baseline else None
        if baseline is not None and base:
            in_ms = value / scale * UNIT_MS.get(unit, 1.0)
            detail += f"; baseline {base:,.1f} ms, {BASELINES[baseline]}: ×{in_ms / base:,.1f}"
        return Verdict(status, detail + ")")

    return Target(f"{workload}: {key} ≤ {limit:,} {unit}", check)


UNIT_MS = {"ms": 1.0, "s": 1000.0}
"""Milliseconds per unit of time (a ratio to the baseline needs the figure in ms)."""


def near_linear(outcomes: dict[str, Outcome]) -> Verdict:
    steps = growth_steps(list(outcomes.values()))
    if not steps:
        return Verdict("SKIP", "fewer than two generated sizes in this run")
    failed, parts = False, []
    for name, step in steps.items():
        found = growth(step)
        if found is None:
            failed = True
            parts.append(f"{step[0].workload.name}→{name}: no figure")
            continue
        failed |= found.exponent > LINEAR_EXPONENT
        parts.append(f"{step[0].workload.name}→{name}: ~n^{found.exponent:.2f}")
    return Verdict("FAIL" if failed else "PASS", ", ".join(parts))


def features_within(workload: str, limit_s: float) -> Target:
    """Target on the feature model (interpretation apart); a timeout of it is a FAIL."""
    inner = at_most(workload, "features_ms", limit_s * 1000, "ms")

    def check(outcomes: dict[str, Outcome]) -> Verdict:
        outcome = outcomes.get(workload)
        timed_out = outcome is not None and outcome.get("features_timeout_s") is not None
        if timed_out and outcome is not None and outcome.get("features_ms") is None:
            return Verdict("FAIL", f"not done within {FEATURES_BUDGET_S:.0f} s")
        if outcome is not None and outcome.get("features_unsolved"):
            listed = inner.check(outcomes).detail
            return Verdict("FAIL", f"{listed}, but too large to solve: count unknown")
        return inner.check(outcomes)

    label = f"{workload}: feature model (after interpretation) ≤ {limit_s * 1000:,.0f} ms"
    return Target(label, check)


TARGETS: list[Target] = [
    *(features_within(system, 0.2) for system in ("kobuki", "turtlebot2", "lizi", "husky")),
    features_within("gen-10000", 30),
    at_most("husky", "analyze_ms", 100, "ms"),
    at_most("husky", "web_choose_p95_ms", 50, "ms"),
    at_most("husky", "web_overview_p95_ms", 50, "ms"),
    at_most("husky", "configure_step_p95_ms", 10, "ms"),
    *(
        at_most(
            ENGINE_START_WORKLOAD,
            f"engine_{command}_{key}",
            limit,
            unit,
            baseline="engine_baseline_ms" if unit == "s" else None,
        )
        for command in ("configure", "serve")
        for key, limit, unit in (("s", 10, "s"), ("mb", 400, "MB"))
    ),
    at_most(ENGINE_START_WORKLOAD, "browser_choice_s", 1, "s", baseline="engine_baseline_ms"),
    at_most("gen-400", "analyze_ms", 1, "s", scale=1000),
    at_most("gen-400", "peak_mb", 150, "MB", baseline=None),
    at_most("gen-10000", "analyze_ms", 25, "s", scale=1000),
    at_most("gen-10000", "peak_mb", 1.5, "GB", scale=1000, baseline=None),
    Target(
        f"near-linear growth: CPU time ~ n^k, k ≤ {LINEAR_EXPONENT:.2f} (×2 files ⇒ ≤ ×2.3 time)",
        near_linear,
    ),
]


def target_lines(outcomes: Sequence[Outcome]) -> list[str]:
    by_name = {o.workload.name: o for o in outcomes}
    lines = []
    for target in TARGETS:
        verdict = target.check(by_name)
        lines.append(f"{verdict.status}  {target.label}: {verdict.detail}")
    return lines


# -- profile, document, driver ----------------------------------------------------------------
def profile_one(options: argparse.Namespace) -> None:
    """The ``--one --profile-one`` mode: cProfile of one analyze run, top functions printed."""
    from rosvar.frontends.xml import clear_cache
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.workspace import discover

    clear_cache()
    profiler = cProfile.Profile()
    profiler.enable()
    Analysis(discover(options.paths, ros_package_path=options.package_path)).all_models()
    profiler.disable()
    stream = io.StringIO()
    stats = pstats.Stats(profiler, stream=stream)
    stats.sort_stats("cumulative").print_stats(PROFILE_TOP)
    text = stream.getvalue()
    start = text.find("   ncalls")
    sys.stdout.write((text[start:] if start >= 0 else text).rstrip() + "\n")
    sys.stdout.flush()
    os._exit(0)


def profile(workload: Workload, scratch: Path) -> str:
    """Where rosvar's time goes on ``workload``, profiled in a fresh process."""
    command = [
        sys.executable, str(Path(__file__).resolve()), "--one", "--profile-one",
        "--package-path", workload.package_path, *workload.prepare(scratch),
    ]  # fmt: skip
    finished = run_bounded(command, _env(workload))
    if finished.returncode != 0:
        return _failure(finished, "profile")
    text = finished.stdout.rstrip()
    for prefix in {sysconfig.get_paths()["purelib"], sysconfig.get_paths()["platlib"], str(REPO)}:
        text = text.replace(prefix + os.sep, "")  # shorter, machine-independent paths
    return text


def _machine() -> str:
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return (
        f"{os.cpu_count()} CPUs (nproc {len(os.sched_getaffinity(0))}), {cpu}; "
        f"Python {platform.python_version()} ({platform.python_implementation()}); "
        f"{platform.system()} {platform.release()}; rosvar {_build()}"
    )


def _build() -> str:
    """Where the measured rosvar's sources are."""
    spec = importlib.util.find_spec("rosvar")
    origin = spec.origin if spec is not None else None
    return "not found" if origin is None else f"plain Python ({Path(origin).parent})"


def _revision() -> str:
    try:
        result = subprocess.run(
            ["git", "-C", str(REPO), "describe", "--always", "--dirty"],
            capture_output=True, text=True, timeout=30, check=False,
        )  # fmt: skip
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    return result.stdout.strip() or "unknown"


KEEP_MARKER = "<!-- Hand-written notes below this line are kept by bench/run.py --write-doc. -->"


def _kept_notes() -> str:
    """The hand-written tail of the current document: findings outlive regeneration."""
    try:
        text = DOC.read_text(encoding="utf-8")
    except OSError:
        return ""
    _, found, tail = text.partition(KEEP_MARKER)
    return tail.strip("\n") if found else ""


def write_doc(
    outcomes: Sequence[Outcome],
    targets: list[str],
    commands: list[str],
    profiled: str | None,
    context: str,
) -> None:
    sizes = ", ".join(f"{w.size:,}" for w in WORKLOADS.values() if w.family == "generated")
    imports = [mb for o in outcomes if (mb := o.get("import_mb")) is not None]
    import_note = f" (about {min(imports):.0f} MB of it is Python and imports)" if imports else ""
    parts = [
        "# Performance of `rosvar analyze`",
        "",
        f"Measured {datetime.date.today().isoformat()} with `bench/run.py --write-doc`. "
        f"Machine: {_machine()}. {context}",
        "",
        "## Method",
        "",
        "- Workloads: the four corpus systems (`../shared/corpus/<system>`, with `_external` "
        "as the ROS_PACKAGE_PATH so its packages resolve but its launch files are not "
        "analysed) and synthetic workspaces from `bench/generate.py` (seed 0) of "
        f"{sizes} launch files: packages of 20 files in systems of 5 packages (includes "
        "stay within a system), 2–5 args, conditional nodes, groups and includes, parameter "
        "names shared within a package, inline `<rosparam>` YAML, include depth ≤ 4. "
        f"`ros2-{ROS2_FILES}` is `bench/generate.py --shape ros2`: a ROS 2 workspace of "
        f"{ROS2_FILES} XML launch files with 1,500 args and include trees 8 deep.",
        "- *in-process*: discover + `Analysis` + `all_models()` — what `rosvar analyze` does "
        "before printing — in a fresh subprocess (`bench/run.py --one`), parser cache "
        f"cleared and a new `Analysis` each run; median of {REPEATS} runs "
        f"(1 run from {SINGLE_RUN_FROM:,} files, fewer when runs would overrun the "
        "time-out). The number of runs is in brackets.",
        f"- *peak MB*: `ru_maxrss` of that subprocess after the analysis{import_note}.",
        "- *whole-process*: wall time of `rosvar analyze PATH --json > /dev/null` "
        "(start-up, analysis, JSON output, exit).",
        "- *× minidom parse*: in-process time divided by the time to parse the same launch "
        "files with `xml.dom.minidom` in the same subprocess — what roslaunch itself does.",
        "- *CPU ms*: the process CPU time of the same runs (median). Other load on a shared "
        "machine stretches wall time, hardly CPU time.",
        "- *features*: `rosvar features`' work on the models of the last in-process run, "
        "timed once: *interpretation* is what interpreting them took (another module's "
        "cost), *model* is the feature model proper (`extract`: Algorithm 1, conflicts "
        "through the name index, the solver's BDDs; then `count_configurations`), and "
        "*core/dead + triggers* the solver questions answered on top (`core_and_dead` with "
        "explanations, `simplest_trigger` of every conflict). The feature-model targets are "
        f"on *model*; it is bounded by {FEATURES_BUDGET_S:.0f} s.",
        "- *growth*: CPU-time ratio between consecutive generated sizes; near-linear means "
        f"time ~ n^k with k ≤ log2(2.3) ≈ {LINEAR_EXPONENT:.2f}.",
        f"- Every subprocess is bounded by {TIMEOUT_S:.0f} s and {MEMORY_LIMIT_MB:,} MB of "
        "address space; hitting a bound counts as FAIL, and a measurement that failed is not "
        "attempted again at larger generated sizes.",
        "",
        "## Results",
        "",
        markdown_table(outcomes),
        "",
    ]
    notes = [f"- {o.workload.name}: {note}" for o in outcomes for note in o.notes]
    if notes:
        parts += ["Notes:", "", *notes, ""]
    parts += ["## Targets", "", "```", *targets, "```", ""]
    if commands:
        table, verdicts = commands[: commands.index("")], commands[commands.index("") + 1 :]
        parts += [
            "## Whole processes, as a user runs them",
            "",
            f"Wall time (median of {COMMAND_REPEATS}; one run from {SLOW_COMMAND_S:.0f} s) "
            "and peak RSS (`wait4`'s `ru_maxrss`) of each command in a fresh process, output "
            "to `/dev/null`, ROS_PACKAGE_PATH empty; the targets are those of the "
            "workspace-scale issue and of issue 28. `uni-N` is `bench/generate.py --shape "
            "uniform` (5 args, 5 conditional nodes, a group and an include per file); the "
            f"paper's prototype (`{HAROSVAR}`) runs on the same workspace where it is "
            f"installed. `{ROS2_DENSE}` is `bench/generate.py --shape ros2-dense` (issue 28's "
            "slow system: 120 XML files, 1,500 args, 340 includes, 180 `$(eval)`s), "
            f"`{AUTOWARE}` the launch files of `tests/data/ros2/{AUTOWARE}`; their runs stop "
            f"at {LONG_COMMAND_CAP_S:.0f} s.",
            "",
            *table,
            "",
            "```",
            *verdicts,
            "```",
            "",
        ]
    if profiled:
        parts += [
            f"## Profile (top {PROFILE_TOP} by cumulative time)",
            "",
            "```",
            profiled,
            "```",
            "",
        ]
    parts += [KEEP_MARKER, "", _kept_notes(), ""]
    DOC.parent.mkdir(parents=True, exist_ok=True)
    DOC.write_text("\n".join(parts).rstrip("\n") + "\n", encoding="utf-8")
    print(f"wrote {DOC}")


def selected(options: argparse.Namespace) -> list[Workload]:
    """The workloads of the table: those of the sizes asked for, or those named by --only
    (also those otherwise measured as whole processes only)."""
    sizes = QUICK_SIZES if options.quick else options.sizes or GENERATED_SIZES
    chosen = [w for w in WORKLOADS.values() if w.in_table and (not w.size or w.size in sizes)]
    if options.only:
        chosen = [w for w in WORKLOADS.values() if w.name in options.only]
    chosen.sort(key=lambda w: (w.size > 0, w.family, w.size))  # a family smallest first
    return chosen


def run_all(options: argparse.Namespace) -> None:
    # rosvar's bytecode up to date, as an install leaves it (``make setup`` does the same):
    # where PYTHONDONTWRITEBYTECODE is set, each measured process would compile it again
    compileall.compile_dir(REPO / "src", quiet=1)
    outcomes: list[Outcome] = []
    failed: set[tuple[str, str]] = set()  # (family, measurement) that failed at a smaller size
    load_before, revision_before = os.getloadavg()[1], _revision()
    with tempfile.TemporaryDirectory(prefix="rosvar-bench-") as scratch_dir:
        scratch = Path(scratch_dir)
        for workload in [] if options.commands_only else selected(options):
            outcome = Outcome(workload)
            outcomes.append(outcome)
            print(f"{workload.name} ...", file=sys.stderr, flush=True)
            roots: list[str] | None = None
            for name, measure in DRIVER_MEASUREMENTS.items():
                key = (workload.family, name)
                if key in failed and not options.no_skip:
                    outcome.notes.append(f"{name}: skipped, it failed at a smaller size")
                    continue
                roots = roots if roots is not None else workload.prepare(scratch)
                if not measure(workload, roots, outcome) and workload.size:
                    failed.add(key)
        profiled = profile(WORKLOADS[options.profile], scratch) if options.profile else None
        measured = [] if options.no_commands else measure_commands(scratch, options.command or ())
        commands = command_lines(measured) if measured else []
    print()
    print(text_table(outcomes))
    for outcome in outcomes:
        for note in outcome.notes:
            print(f"  note: {outcome.workload.name}: {note}")
    print()
    targets = target_lines(outcomes)
    print("\n".join(targets))
    if commands:
        print("\nwhole processes, as a user runs them:")
        print("\n".join(commands))
    if profiled:
        print(f"\nprofile of {options.profile} (top {PROFILE_TOP} by cumulative time):")
        print(profiled)
    if options.write_doc:
        revision = _revision()
        if revision == revision_before:
            revision_note = f"Revision `{revision}`."
        else:  # others may commit while a long run goes on
            revision_note = f"Revision `{revision_before}` at the start, `{revision}` at the end."
        context = (
            f"{revision_note} Load average (5 min) {load_before:.1f} at the start, "
            f"{os.getloadavg()[1]:.1f} at the end: other work on the machine stretches wall "
            "times."
        )
        write_doc(outcomes, targets, commands, profiled, context)


def parse_options(argv: Sequence[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description="Scaling benchmarks of rosvar analyze.")
    parser.add_argument("--quick", action="store_true", help="corpus + 100 + 400 files only")
    parser.add_argument(
        "--sizes", type=int, nargs="+", metavar="N", help="generated workspace sizes to run"
    )
    parser.add_argument("--only", nargs="+", metavar="NAME", help="workloads to run, by name")
    parser.add_argument("--no-skip", action="store_true", help="attempt sizes after a failure")
    parser.add_argument(
        "--no-commands", action="store_true", help="skip the whole-process command rows"
    )
    parser.add_argument(
        "--commands-only", action="store_true", help="only the whole-process command rows"
    )
    parser.add_argument(
        "--command",
        action="append",
        metavar="TEXT",
        help="only the whole-process commands whose name holds TEXT (repeatable)",
    )
    parser.add_argument("--profile", metavar="NAME", choices=sorted(WORKLOADS))
    parser.add_argument("--write-doc", action="store_true", help=f"write {DOC.relative_to(REPO)}")
    # Internal: the isolated measurement process.
    parser.add_argument("--one", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--profile-one", action="store_true", help=argparse.SUPPRESS)
    parser.add_argument("--repeats", type=int, default=REPEATS, help=argparse.SUPPRESS)
    parser.add_argument("--budget", type=float, default=TIMEOUT_S, help=argparse.SUPPRESS)
    parser.add_argument("--package-path", default="", help=argparse.SUPPRESS)
    parser.add_argument("paths", nargs="*", help=argparse.SUPPRESS)
    options = parser.parse_args(argv)
    if options.sizes:
        unknown = sorted(set(options.sizes) - set(GENERATED_SIZES))
        for size in unknown:  # any size may be asked for; register it on the fly
            register_workload(_generated(size))
    unknown_names = sorted(set(options.only or ()) - set(WORKLOADS))
    if unknown_names:
        parser.error(f"unknown workload {', '.join(unknown_names)}; known: {', '.join(WORKLOADS)}")
    return options


def main() -> int:
    options = parse_options()
    if options.one:
        (profile_one if options.profile_one else run_one)(options)
    else:
        run_all(options)
    return 0


if __name__ == "__main__":
    sys.exit(main())
