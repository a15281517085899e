"""Differential harness: rosvar's restriction to one configuration against the real roslaunch.

For every launch file of a system, a few configurations (command-line args) are chosen from the
file's variational model (:func:`configurations`). Each configuration is loaded by the roslaunch
oracle (``tests/oracle``, all jobs of a system in one batch) and restricted by rosvar in-process
(:func:`rosvar.ros1.resolve.resolve`, one
:class:`~rosvar.interpreter.workspace_models.Analysis` per system), and the two
results are compared (:func:`compare`). Each case ends up as

* ``agree``: same nodes, tests and parameters, or both refuse the configuration;
* ``differ``: anything else, including rosvar raising an exception;
* ``roslaunch-failed``: roslaunch failed for a reason outside the launch files (a package, an
  environment variable or a file that is not there; ``outside: true`` in the oracle's answer).
  rosvar may say anything in those cases (unless it crashes, which is always ``differ``).

Every line of a difference reads ``KIND: DETAIL``; :func:`difference_class` maps it to a class
so that a report can say which kinds of difference are the most common.

Run from the repository root::

    .venv/bin/python -m tests.differential.harness [--samples N] [--system husky] [--show 20]
"""

from __future__ import annotations

import argparse
import concurrent.futures
import json
import math
import os
import random
import re
import sys
import time
import traceback
from collections import Counter
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.documents.resolution import resolution_document
from rosvar.ros1.resolve import resolve
from rosvar.workspace import discover

# ``tests/`` is no package: pytest (importlib mode) imports this module as
# ``differential.harness``, ``python -m`` as ``tests.differential.harness``; either way the
# oracle's client is ``oracle.client``, with ``tests/`` on the path
if (TESTS := str(Path(__file__).resolve().parents[1])) not in sys.path:
    sys.path.insert(0, TESTS)
from oracle.client import (
    UNAVAILABLE_REASON,
    RoslaunchOracle,
    oracle_available,
    requires_oracle,
    shared_oracle,
)

__all__ = [
    "AGREE",
    "DIFFER",
    "ROSLAUNCH_FAILED",
    "Difference",
    "Report",
    "SystemRun",
    "compare",
    "configurations",
    "difference_class",
    "message_pattern",
    "requires_oracle",
    "run_system",
    "shared_oracle",
    "system_runs",
]

REPO = Path(__file__).resolve().parents[2]
CORPUS = Path(os.environ.get("ROSVAR_CORPUS", REPO.parent / "shared" / "corpus")).resolve()
FIXTURES = Path(__file__).resolve().with_name("fixtures")

CORPUS_SYSTEMS = ("kobuki", "turtlebot2", "lizi", "husky")
SEED = 20240601
SAMPLES = 4

AGREE = "agree"
DIFFER = "differ"
ROSLAUNCH_FAILED = "roslaunch-failed"
OUTCOMES = (AGREE, DIFFER, ROSLAUNCH_FAILED)

Config = dict[str, str]

#: The environment a TurtleBot2 installation sets (turtlebot_bringup's and the simulators'
#: env-hooks): every ``TURTLEBOT_*`` variable the corpus reads with ``$(env)``/``$(optenv)``.
TURTLEBOT_ENV: dict[str, str] = {
    "TURTLEBOT_BASE": "kobuki",
    "TURTLEBOT_3D_SENSOR": "kinect",
    "TURTLEBOT_STACKS": "hexagons",
    "TURTLEBOT_BATTERY": "/proc/acpi/battery/BAT0",
    "TURTLEBOT_SIMULATION": "false",
    "TURTLEBOT_SERIAL_PORT": "/dev/kobuki",
    "TURTLEBOT_TYPE": "turtlebot",
    "TURTLEBOT_NAME": "turtlebot",
    "TURTLEBOT_RAPP_PACKAGE_WHITELIST": "[]",
    "TURTLEBOT_RAPP_PACKAGE_BLACKLIST": "[]",
    "TURTLEBOT_INTERACTIONS_LIST": "[]",
    "TURTLEBOT_MAP_FILE": "/opt/ros/melodic/share/turtlebot_navigation/maps/"
    "willow-2010-02-18-0.10.yaml",
    "TURTLEBOT_GAZEBO_MAP_FILE": "/opt/ros/melodic/share/turtlebot_gazebo/maps/playground.yaml",
    "TURTLEBOT_GAZEBO_WORLD_FILE": "/opt/ros/melodic/share/turtlebot_gazebo/worlds/"
    "playground.world",
    "TURTLEBOT_STAGE_MAP_FILE": "/opt/ros/melodic/share/turtlebot_stage/maps/maze.yaml",
    "TURTLEBOT_STAGE_WORLD_FILE": "/opt/ros/melodic/share/turtlebot_stage/maps/stage/maze.world",
    "TURTLEBOT_STDR_MAP_FILE": "/opt/ros/melodic/share/turtlebot_stdr/maps/sparse_obstacles.yaml",
}

#: The second environment of the fixture workspace (``$(optenv)``/``$(env)``/eval ``env()``).
FIXTURE_ENV: dict[str, str] = {"FIXPKG_MODE": "fast", "FIXPKG_ROBOT": "r2"}


# ------------------------------------------------------------------------------------------------
# Configurations


def configurations(model: LaunchModel, rng: random.Random, samples: int) -> list[Config]:
    """Command-line args to try on ``model``'s file: defaults, boolean flips, random samples.

    1. ``{}``: every arg left at its default;
    2. for each input whose domain holds both ``true`` and ``false``: that input alone set to
       the boolean that is not its literal default (to both when it has no such default);
    3. ``samples`` random configurations, each input drawn from its literal slots (an input
       without a literal slot is not given).

    Duplicates are dropped, first occurrence kept.
    """
    names = sorted(model.inputs)
    configs: list[Config] = [{}]
    for name in names:
        domain = model.domains.get(name, ())
        if "true" in domain and "false" in domain:
            default = model.unset_defaults.get(name)
            configs.extend({name: value} for value in ("true", "false") if value != default)
    for _ in range(samples):
        config: Config = {}
        for name in names:
            literals = [slot for slot in model.domains.get(name, ()) if isinstance(slot, str)]
            if literals:
                config[name] = rng.choice(literals)
        configs.append(config)
    unique: dict[tuple[tuple[str, str], ...], Config] = {}
    for config in configs:
        unique.setdefault(tuple(sorted(config.items())), config)
    return list(unique.values())


def format_config(config: Mapping[str, str]) -> str:
    if not config:
        return "(defaults)"
    return " ".join(
        f"{name}:={value!r}" if _needs_quotes(value) else f"{name}:={value}"
        for name, value in config.items()
    )


def _needs_quotes(value: str) -> bool:
    return value == "" or any(c.isspace() for c in value) or "'" in value


# ------------------------------------------------------------------------------------------------
# Comparison

IGNORED_FIELDS = frozenset({"line", "col"})
FLOAT_FIELDS = frozenset({"respawn_delay", "time_limit"})
MAX_LINES_PER_KIND = 15
_SHORT = 160


def _short(value: object) -> str:
    text = json.dumps(value, sort_keys=True) if not isinstance(value, str) else repr(value)
    return text if len(text) <= _SHORT else text[: _SHORT - 3] + "..."


class _Lines:
    """Difference lines, at most ``MAX_LINES_PER_KIND`` per kind (the rest counted)."""

    def __init__(self) -> None:
        self.lines: list[str] = []
        self.counts: Counter[str] = Counter()

    def add(self, kind: str, detail: str) -> None:
        self.counts[kind] += 1
        if self.counts[kind] <= MAX_LINES_PER_KIND:
            self.lines.append(f"{kind}: {detail}")

    def result(self) -> list[str]:
        extra = [
            f"{kind}: ... and {count - MAX_LINES_PER_KIND} more"
            for kind, count in self.counts.items()
            if count > MAX_LINES_PER_KIND
        ]
        return self.lines + extra


def _same(ours: object, theirs: object) -> bool:
    """Equal as parameter values: same types (bool, int, float, str kept apart), floats close."""
    if isinstance(ours, bool) or isinstance(theirs, bool):
        return type(ours) is type(theirs) and ours == theirs
    if isinstance(ours, float) and isinstance(theirs, float):
        return ours == theirs or math.isclose(ours, theirs, rel_tol=1e-9, abs_tol=1e-12)
    if type(ours) is not type(theirs):
        return False
    if isinstance(ours, dict) and isinstance(theirs, dict):
        return ours.keys() == theirs.keys() and all(_same(ours[k], theirs[k]) for k in ours)
    if isinstance(ours, list) and isinstance(theirs, list):
        return len(ours) == len(theirs) and all(
            _same(a, b) for a, b in zip(ours, theirs, strict=True)
        )
    return ours == theirs


def _first_difference(ours: object, theirs: object, path: str = "") -> tuple[str, str] | None:
    """(kind, detail) of the first place where two values differ, or None."""
    if _same(ours, theirs):
        return None
    if isinstance(ours, dict) and isinstance(theirs, dict):
        for key in sorted(set(ours) | set(theirs), key=str):
            if key not in ours:
                return "value", f"{path}[{key!r}] only in roslaunch ({_short(theirs[key])})"
            if key not in theirs:
                return "value", f"{path}[{key!r}] only in rosvar ({_short(ours[key])})"
            found = _first_difference(ours[key], theirs[key], f"{path}[{key!r}]")
            if found is not None:
                return found
    if isinstance(ours, list) and isinstance(theirs, list) and len(ours) == len(theirs):
        for index, (a, b) in enumerate(zip(ours, theirs, strict=True)):
            found = _first_difference(a, b, f"{path}[{index}]")
            if found is not None:
                return found
    kind = "value" if _type_name(ours) == _type_name(theirs) else "type"
    where = f"{path} " if path else ""
    return kind, (
        f"{where}rosvar {_short(ours)} ({_type_name(ours)}) / "
        f"roslaunch {_short(theirs)} ({_type_name(theirs)})"
    )


def _type_name(value: object) -> str:
    return "null" if value is None else type(value).__name__


def _field_equal(name: str, ours: object, theirs: object) -> bool:
    if name == "filename" and isinstance(ours, str) and isinstance(theirs, str):
        return ours == theirs or os.path.realpath(ours) == os.path.realpath(theirs)
    if name in FLOAT_FIELDS:
        numeric = (int, float, str)  # what float() takes
        if not (isinstance(ours, numeric) and isinstance(theirs, numeric)):
            return ours == theirs
        try:
            a, b = float(ours), float(theirs)
        except ValueError:
            return ours == theirs
        return a == b or math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-12)
    return _same(ours, theirs)


def _by_name(entries: Sequence[Mapping[str, Any]]) -> dict[str, list[Mapping[str, Any]]]:
    grouped: dict[str, list[Mapping[str, Any]]] = {}
    for entry in entries:
        grouped.setdefault(str(entry.get("name")), []).append(entry)
    return grouped


def _label(entry: Mapping[str, Any]) -> str:
    return f"{entry.get('name')} ({entry.get('package')}/{entry.get('type')})"


def _canonical(entry: Mapping[str, Any], keys: Sequence[str]) -> str:
    return json.dumps(
        {k: entry.get(k) for k in keys if k not in IGNORED_FIELDS and k != "filename"},
        sort_keys=True,
        default=str,
    )


def _compare_entries(
    kind: str,
    ours: Sequence[Mapping[str, Any]],
    theirs: Sequence[Mapping[str, Any]],
    out: _Lines,
) -> None:
    mine, real = _by_name(ours), _by_name(theirs)
    for name in sorted(set(mine) | set(real)):
        a, b = mine.get(name, []), real.get(name, [])
        if not a:
            for entry in b:
                out.add(f"{kind} only in roslaunch", _label(entry))
            continue
        if not b:
            for entry in a:
                out.add(f"{kind} only in rosvar", _label(entry))
            continue
        if len(a) != len(b):
            out.add(f"{kind} count", f"{name}: rosvar {len(a)}, roslaunch {len(b)}")
        keys = list(b[0].keys())
        pairs = zip(
            sorted(a, key=lambda e: _canonical(e, keys)),
            sorted(b, key=lambda e: _canonical(e, keys)),
            strict=False,  # a count mismatch is reported above
        )
        for x, y in pairs:
            for key, expected in y.items():
                if key in IGNORED_FIELDS:
                    continue
                if key not in x:
                    out.add(
                        f"{kind} field {key}",
                        f"{name}: missing in rosvar (roslaunch {_short(expected)})",
                    )
                elif not _field_equal(key, x[key], expected):
                    out.add(
                        f"{kind} field {key}",
                        f"{name}: rosvar {_short(x[key])} / roslaunch {_short(expected)}",
                    )


def _compare_params(ours: Mapping[str, Any], theirs: Mapping[str, Any], out: _Lines) -> None:
    for key in sorted(set(ours) | set(theirs)):
        if key not in ours:
            out.add("param only in roslaunch", f"{key} = {_short(theirs[key])}")
        elif key not in theirs:
            out.add("param only in rosvar", f"{key} = {_short(ours[key])}")
        else:
            found = _first_difference(ours[key], theirs[key])
            if found is not None:
                kind, detail = found
                out.add(f"param {kind}", f"{key}: {detail}")


def _our_failure(ours: Mapping[str, Any]) -> tuple[str, str]:
    """(code, description) of why rosvar refused a configuration."""
    errors = ours.get("errors") or []
    if errors:
        e = errors[0]
        where = f"{e.get('file')}:{e.get('line')}"
        return str(e.get("code")), f"{e.get('message')} at {where}"
    conflicts = ours.get("conflicts") or []
    if conflicts:
        c = conflicts[0]
        return f"conflict {c.get('kind')}", f"{c.get('name')}"
    return "?", "not ok, without errors or conflicts"


def _first_line(text: str) -> str:
    line = text.strip().splitlines()[0] if text.strip() else ""
    return line if len(line) <= 300 else line[:297] + "..."


def compare(ours: Mapping[str, Any], theirs: Mapping[str, Any]) -> list[str]:
    """Differences between rosvar's resolution (its JSON document) and the oracle's result.

    Empty when they agree. When both load, nodes and tests must match on the oracle's fields
    (``filename`` up to ``realpath``, ``respawn_delay``/``time_limit`` as floats) and the
    parameters must be equal (floats compared with ``math.isclose``, types kept apart). When
    roslaunch fails, rosvar must refuse the configuration too (for a duplicate node name: with a
    conflict or an error); when roslaunch loads, rosvar must load.
    """
    out = _Lines()
    if theirs.get("ok"):
        if not ours.get("ok"):
            code, description = _our_failure(ours)
            out.add(f"rosvar failed [{code}], roslaunch ok", description)
            return out.result()
        _compare_entries("node", ours.get("nodes") or [], theirs.get("nodes") or [], out)
        _compare_entries("test", ours.get("tests") or [], theirs.get("tests") or [], out)
        _compare_params(ours.get("params") or {}, theirs.get("params") or {}, out)
        return out.result()
    error = str(theirs.get("error", ""))
    error_type = str(theirs.get("error_type", "?"))
    if ours.get("ok"):
        out.add(f"roslaunch failed [{error_type}], rosvar ok", _first_line(error))
    elif "multiple nodes named" in error and not (ours.get("conflicts") or ours.get("errors")):
        out.add("duplicate node not reported by rosvar", _first_line(error))
    return out.result()


_NORMALISE = (
    (re.compile(r"\[[^\]]*\]"), "[…]"),
    (re.compile(r"'[^']*'"), "'…'"),
    (re.compile(r'"[^"]*"'), '"…"'),
    (re.compile(r"(/[\w.+-]+)+"), "/…"),
    (re.compile(r"\d+"), "N"),
)


def message_pattern(message: str) -> str:
    """``message`` with its bracketed lists, quoted names, paths and numbers made alike."""
    for regex, replacement in _NORMALISE:
        message = regex.sub(replacement, message)
    return message


def difference_class(line: str) -> str:
    """The class of one difference line: its kind, and for failures a message pattern."""
    kind, _, detail = line.partition(": ")
    if kind.startswith(("roslaunch failed", "rosvar crashed", "rosvar failed")):
        pattern = detail
        if kind.startswith("rosvar failed"):
            pattern = re.sub(r" at \S+$", "", pattern)
        return f"{kind}: {message_pattern(pattern)[:100]}"
    return kind


# ------------------------------------------------------------------------------------------------
# Running a system


@dataclass
class Difference:
    """One case in which rosvar and roslaunch disagree (or, in ``failures``, roslaunch's error)."""

    file: str
    config: Config
    lines: list[str]

    def render(self, indent: str = "    ", max_lines: int = 12) -> str:
        head = f"{self.file}  {format_config(self.config)}"
        body = [indent + line for line in self.lines[:max_lines]]
        if len(self.lines) > max_lines:
            body.append(f"{indent}... {len(self.lines) - max_lines} more lines")
        return "\n".join([head, *body])


@dataclass
class Report:
    """Outcome counts of one system run, with every difference."""

    name: str
    counts: Counter[str] = field(default_factory=Counter)
    differences: list[Difference] = field(default_factory=list)
    failures: list[Difference] = field(default_factory=list)
    files: int = 0
    seconds: float = 0.0
    both_failed: list[Difference] = field(default_factory=list)  # agree: both refuse (why)

    @property
    def total(self) -> int:
        return sum(self.counts.values())

    def summary(self) -> str:
        return (
            f"{self.name}: {self.counts[AGREE]} agree / {self.counts[DIFFER]} differ / "
            f"{self.counts[ROSLAUNCH_FAILED]} roslaunch-failed "
            f"({self.total} cases, {self.files} files, {self.seconds:.1f}s; "
            f"{len(self.both_failed)} of the agree cases fail in both)"
        )

    def classes(self) -> list[tuple[str, int, Difference, str]]:
        """(class, number of cases, first case, its line), most common first."""
        counts: Counter[str] = Counter()
        example: dict[str, tuple[Difference, str]] = {}
        for difference in self.differences:
            seen: set[str] = set()
            for line in difference.lines:
                cls = difference_class(line)
                if cls in seen:
                    continue
                seen.add(cls)
                counts[cls] += 1
                example.setdefault(cls, (difference, line))
        return [(cls, n, *example[cls]) for cls, n in counts.most_common()]

    def class_table(self, limit: int = 10) -> str:
        rows = []
        for cls, n, difference, line in self.classes()[:limit]:
            rows.append(f"  {n:5d}  {cls}")
            rows.append(f"         e.g. {difference.file}  {format_config(difference.config)}")
            rows.append(f"              {line}")
        return "\n".join(rows)

    def details(self, limit: int = 10) -> str:
        shown = [d.render() for d in self.differences[:limit]]
        more = len(self.differences) - len(shown)
        if more > 0:
            shown.append(f"... and {more} more differences")
        return "\n".join(shown)


@dataclass
class _Case:
    file: str
    config: Config
    crash: str | None = None
    ours: dict[str, Any] | None = None


def _crash_line(error: BaseException) -> str:
    last = traceback.format_exception_only(type(error), error)[-1].strip()
    frames = traceback.extract_tb(error.__traceback__)
    if not frames:
        return last
    frame = frames[-1]
    path = frame.filename
    if path.startswith(str(REPO) + os.sep):
        path = os.path.relpath(path, REPO)
    return f"{last} (at {path}:{frame.lineno} in {frame.name})"


def _stable_name(file: str, roots: Sequence[str]) -> str:
    for root in roots:
        if file.startswith(root.rstrip(os.sep) + os.sep):
            return os.path.relpath(file, root)
    return file


def run_system(
    roots: Sequence[str | os.PathLike[str]],
    files: Sequence[str],
    env: Mapping[str, str],
    samples: int,
    seed: int,
    *,
    name: str = "",
    oracle: RoslaunchOracle | None = None,
    progress: Callable[[str], None] | None = None,
    env_domains: bool = True,
) -> Report:
    """Compare rosvar with roslaunch on every file × configuration of one system.

    ``roots`` are the package roots (for both tools), ``files`` the entry launch files, ``env``
    the whole environment of every job (plus ``ROS_PACKAGE_PATH``, which the oracle always sets
    to the roots and rosvar therefore sees as well). By default the analysis is built as the
    ``rosvar`` command line builds it (no environment values known in advance); with
    ``env_domains`` each variable of ``env`` gets its value as a literal slot of its domain.
    """
    start = time.monotonic()
    root_list = [os.path.realpath(os.fspath(r)) for r in roots]
    oracle = oracle if oracle is not None else shared_oracle()
    rosvar_env = {**env, "ROS_PACKAGE_PATH": ":".join(root_list)}
    env_values = {k: [v] for k, v in rosvar_env.items()} if env_domains else None
    analysis = Analysis(discover(root_list, ros_package_path=""), env_values=env_values)

    cases: list[_Case] = []
    for file in files:
        rng = random.Random(f"{seed}:{_stable_name(file, root_list)}")
        try:
            configs = configurations(analysis.model(file), rng, samples)
        except Exception as error:
            cases.append(_Case(file, {}, crash=_crash_line(error)))
            continue
        cases.extend(_Case(file, config) for config in configs)

    jobs = [
        {
            "id": index,
            "roots": root_list,
            "files": [case.file],
            "args": case.config,
            "env": dict(env),
        }
        for index, case in enumerate(cases)
    ]
    with concurrent.futures.ThreadPoolExecutor(max_workers=1) as pool:
        pending = pool.submit(oracle.run, jobs)  # roslaunch works while rosvar resolves
        for index, case in enumerate(cases):
            if progress is not None and (index == 0 or case.file != cases[index - 1].file):
                progress(case.file)
            if case.crash is not None:
                continue
            try:
                case.ours = resolution_document(
                    resolve(analysis, [case.file], case.config, rosvar_env)
                )
            except Exception as error:
                case.crash = _crash_line(error)
        results = pending.result()

    report = Report(name or ", ".join(root_list), files=len(files))
    for case, theirs in zip(cases, results, strict=True):
        if case.crash is not None:
            outcome, lines = DIFFER, [f"rosvar crashed: {case.crash}"]
        elif not theirs.get("ok") and theirs.get("outside"):
            outcome = ROSLAUNCH_FAILED
            why = f"{theirs.get('error_type')}: {_first_line(str(theirs.get('error', '')))}"
            report.failures.append(Difference(case.file, case.config, [why]))
            lines = []
        else:
            assert case.ours is not None
            lines = compare(case.ours, theirs)
            outcome = DIFFER if lines else AGREE
            if outcome == AGREE and not theirs.get("ok"):
                code, description = _our_failure(case.ours)
                message = _first_line(str(theirs.get("error", "")))
                report.both_failed.append(
                    Difference(
                        case.file,
                        case.config,
                        [
                            f"roslaunch: {theirs.get('error_type')}: {message}",
                            f"rosvar: [{code}] {description}",
                        ],
                    )
                )
        report.counts[outcome] += 1
        if outcome == DIFFER:
            report.differences.append(Difference(case.file, case.config, lines))
    report.seconds = time.monotonic() - start
    return report


# ------------------------------------------------------------------------------------------------
# Systems


@dataclass(frozen=True)
class SystemRun:
    """One run of the harness: the launch files under ``folder`` in one environment."""

    name: str
    system: str
    folder: Path
    roots: tuple[Path, ...]
    env: Mapping[str, str]

    def files(self) -> list[str]:
        return discover([self.folder], ros_package_path="").launch_files

    def run(
        self,
        samples: int = SAMPLES,
        seed: int = SEED,
        *,
        only: str | None = None,
        oracle: RoslaunchOracle | None = None,
        progress: Callable[[str], None] | None = None,
        env_domains: bool = True,
    ) -> Report:
        files = [f for f in self.files() if only is None or only in f]
        return run_system(
            [str(r) for r in self.roots],
            files,
            self.env,
            samples,
            seed,
            name=self.name,
            oracle=oracle,
            progress=progress,
            env_domains=env_domains,
        )


def system_runs(system: str, corpus: Path = CORPUS) -> list[SystemRun]:
    """The runs of one corpus system (``kobuki``, ...) or of ``fixtures``."""
    if system == "fixtures":
        return [
            SystemRun("fixtures", system, FIXTURES, (FIXTURES,), {}),
            SystemRun("fixtures+env", system, FIXTURES, (FIXTURES,), dict(FIXTURE_ENV)),
        ]
    folder = corpus / system
    roots: list[Path] = [folder, corpus / "_external"]
    if system == "turtlebot2":
        roots.append(corpus / "kobuki")
    runs = [SystemRun(system, system, folder, tuple(roots), {})]
    if system == "turtlebot2":
        runs.append(SystemRun("turtlebot2+env", system, folder, tuple(roots), TURTLEBOT_ENV))
    return runs


# ------------------------------------------------------------------------------------------------
# Command line


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m tests.differential.harness",
        description="Compare rosvar's resolution with the real roslaunch on the corpus.",
    )
    parser.add_argument("--samples", type=int, default=SAMPLES, help="random configs per file")
    parser.add_argument("--seed", type=int, default=SEED)
    parser.add_argument(
        "--system",
        action="append",
        choices=[*CORPUS_SYSTEMS, "fixtures"],
        help="system to run (repeatable; default: all four corpus systems and the fixtures)",
    )
    parser.add_argument("--file", help="only launch files whose path contains this text")
    parser.add_argument("--show", type=int, default=10, help="differences to print per run")
    parser.add_argument("--classes", type=int, default=10, help="difference classes to print")
    parser.add_argument("--failures", action="store_true", help="also list roslaunch-failed")
    parser.add_argument(
        "--both-failed", action="store_true", help="also list agree cases where both fail"
    )
    parser.add_argument("--corpus", type=Path, default=CORPUS)
    parser.add_argument(
        "--no-env-domains",
        dest="env_domains",
        action="store_false",
        help="analyse without the run's environment values as domain literals (as plain analyze)",
    )
    parser.add_argument("-v", "--verbose", action="store_true", help="print each file's name")
    options = parser.parse_args(argv)

    if not oracle_available():
        print(UNAVAILABLE_REASON, file=sys.stderr)
        return 2
    systems = options.system or [*CORPUS_SYSTEMS, "fixtures"]
    oracle = RoslaunchOracle()
    reports: list[Report] = []

    def progress(file: str) -> None:
        print(f"  {file}", file=sys.stderr, flush=True)

    try:
        for system in systems:
            for run in system_runs(system, options.corpus.resolve()):
                if not run.folder.is_dir():
                    print(f"{run.name}: skipped, {run.folder} is missing")
                    continue
                report = run.run(
                    options.samples,
                    options.seed,
                    only=options.file,
                    oracle=oracle,
                    progress=progress if options.verbose else None,
                    env_domains=options.env_domains,
                )
                reports.append(report)
                print(f"== {report.summary()}")
                if report.differences:
                    print(
                        f"-- most common difference classes (cases):\n"
                        f"{report.class_table(options.classes)}"
                    )
                    print(f"-- first differences:\n{report.details(options.show)}")
                if options.failures and report.failures:
                    print("-- roslaunch-failed:")
                    print("\n".join(f.render() for f in report.failures))
                if options.both_failed and report.both_failed:
                    print("-- both fail (agree):")
                    print("\n".join(f.render() for f in report.both_failed))
                print(flush=True)
    finally:
        oracle.close()
    print("== totals")
    for report in reports:
        print(f"   {report.summary()}")
    return 1 if any(r.counts[DIFFER] for r in reports) else 0


if __name__ == "__main__":
    sys.exit(main())
