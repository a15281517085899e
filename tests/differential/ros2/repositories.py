"""The real ROS 2 repositories of ``tests/data/ros2`` against the oracle, through rosvar's
command line.

For every launch file of a repository, the configurations of :mod:`.samples` are loaded by
the oracle (``tests/oracle/ros2_client.py``, lenient: packages outside the repository are
placeholders, as the oracle's README says) and by ``rosvar resolve ROOT --launch FILE
name:=value --json`` in a subprocess, so that the harness reads rosvar as a user does and
outlives its internal moves. The oracle's placeholders ``/__missing_pkg__/NAME`` stand for
packages it could not find; rosvar gets empty packages of those names (``--deps``) and the
placeholders are read as their folders, so both sides name the same paths.

Each configuration ends up as

* ``agree``: the oracle loads it, rosvar gives the same nodes (:data:`oracle.ros2_client.KEYS`)
  and reports no error beyond what the missing packages and unresolved includes explain;
* ``differ``: the oracle loads it and anything else happens, each difference with a
  :class:`Cause` (a category, and a detail naming the node and the values);
* ``oracle fails``: the oracle does not load it (a Python package the repository imports is
  not installed, a required value, a command): left out of the agreement, its reason kept.

Run from the repository root: ``PYTHONPATH=src:tests python -m differential.ros2.repositories
[--full] [--repository NAME] [--json FILE] [--oracle-cache DIR]``; it prints the agreement of
every repository and the causes of difference by the number of configurations they affect.
"""

from __future__ import annotations

import argparse
import concurrent.futures
import hashlib
import json
import os
import random
import re
import subprocess
import sys
import tempfile
from collections import Counter
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from pathlib import Path
from typing import Any

import rosvar
from oracle.ros2_client import (
    ENVIRONMENT,
    ORACLE,
    canonical_nodes,
    restored_lists,
    rosvar_nodes,
    run_oracle,
)

from ..harness import message_pattern
from .samples import Config, Origin, read, sample

DATA = Path(__file__).resolve().parents[2] / "data" / "ros2"
SOURCES = Path(rosvar.__file__).resolve().parents[1]
MISSING = "/__missing_pkg__/"
TIMEOUT_S = 120
"""rosvar's time per configuration: past it a configuration differs (issue 28 wants seconds)."""
SEED = "ros2-repositories"

# -- the repositories and their launch files ------------------------------------------------


@dataclass(frozen=True)
class Repository:
    """A folder of ``tests/data/ros2``; ``dot_launch``: its ``*.launch`` files are ROS 2 XML
    (elsewhere they are ROS 1 leftovers, which ``ros2 launch`` never loads); ``deps``: other
    folders whose packages (and Python modules) it uses, as an installed workspace has
    them (the oracle's package path, rosvar's ``--deps``)."""

    name: str
    dot_launch: bool = False
    deps: tuple[str, ...] = ()

    @property
    def root(self) -> Path:
        return DATA / self.name

    @property
    def package_paths(self) -> list[Path]:
        return [self.root, *(DATA / name for name in self.deps)]

    def launch_files(self) -> list[Path]:
        """The files ``ros2 launch`` can start: by name, or in a ``launch/`` folder with the
        frontend's mark (``generate_launch_description``, a ``<launch>`` root, ``launch:``);
        Python files without ``generate_launch_description`` are helpers or launch tests."""
        found = []
        for path in sorted(self.root.rglob("*")):
            if not path.is_file() or not _is_launch_file(path, self.dot_launch):
                continue
            found.append(path)
        return found


_NAMED = re.compile(r"(\.launch\.(py|xml|ya?ml)|_launch\.(py|xml|ya?ml))$")
_MARKS = {".py": "generate_launch_description", ".xml": "<launch", ".yaml": "launch:"}


def _is_launch_file(path: Path, dot_launch: bool) -> bool:
    if path.suffix == ".launch":
        return dot_launch
    mark = _MARKS.get(path.suffix)
    if mark is None or not (_NAMED.search(path.name) or path.parent.name == "launch"):
        return False
    return mark in path.read_text(encoding="utf-8", errors="replace")


MOVEIT_DEPS = ("launch_param_builder", "xacro")
"""What ``moveit_configs_utils`` imports (``launch_param_builder``, which imports ``xacro``)."""
XACRO = ("xacro",)
"""For repositories whose packages depend on ``xacro`` and whose launch files import it."""

REPOSITORIES = {
    r.name: r
    for r in (
        Repository("Universal_Robots_ROS2_Driver", deps=("moveit2", *MOVEIT_DEPS)),
        Repository("autoware.universe"),
        Repository("clearpath_common", deps=XACRO),
        Repository("demos"),
        Repository("husky", deps=XACRO),
        Repository("image_pipeline"),
        Repository("moveit2", deps=MOVEIT_DEPS),
        Repository("moveit2_tutorials", deps=("moveit2", *MOVEIT_DEPS)),
        Repository("realsense-ros", deps=XACRO),
        Repository("ros2_control_demos"),
        Repository("ros_gz", dot_launch=True, deps=XACRO),
        Repository("slam_toolbox"),
    )
}


@dataclass(frozen=True)
class Case:
    """One configuration of one launch file: ``config`` holds the ``name:=value`` pairs,
    ``origins`` the sampler's rules that named it."""

    repository: str
    file: Path
    config: tuple[tuple[str, str], ...]
    origins: frozenset[Origin] = field(default=frozenset(), compare=False)

    @property
    def relative(self) -> str:
        return self.file.relative_to(DATA).as_posix()

    def command_line(self) -> str:
        words = [f"{k}:={v}" if v and " " not in v else f"{k}:={v!r}" for k, v in self.config]
        return " ".join([self.relative, *words]) if words else f"{self.relative} (defaults)"

    @property
    def arguments(self) -> Config:
        return dict(self.config)


def cases(
    repository: Repository, files_limit: int | None = None, configs_limit: int | None = None
) -> list[Case]:
    """Every file × configuration of ``repository``; with limits, a spread of files (every
    k-th of the sorted list, so each folder is represented) and each file's first
    configurations (the defaults first)."""
    readings = {path: read(path) for path in repository.launch_files()}
    sampled = sample(readings, repository.root)
    files = sorted(readings)
    if files_limit is not None and len(files) > files_limit:
        step = len(files) / files_limit
        files = [files[int(index * step)] for index in range(files_limit)]
    found: list[Case] = []
    for path in files:
        configs = sampled[path]
        if configs_limit is not None and len(configs) > configs_limit:
            rest = random.Random(f"{SEED}:{path.relative_to(DATA).as_posix()}")
            configs = [configs[0], *rest.sample(configs[1:], configs_limit - 1)]
        found.extend(
            Case(repository.name, path, tuple(c.config.items()), c.origins) for c in configs
        )
    return found


# -- running both -----------------------------------------------------------------------------
class Status(StrEnum):
    AGREE = "agree"
    DIFFER = "differ"
    ORACLE_FAILS = "oracle fails"


@dataclass(frozen=True)
class Cause:
    """One difference: ``category`` groups configurations, ``detail`` is this one's."""

    category: str
    detail: str


@dataclass
class Outcome:
    case: Case
    status: Status
    causes: list[Cause] = field(default_factory=list)


class OracleCache:
    """Oracle answers on disk, keyed by everything they depend on: the oracle's version, the
    repository's files, the launch file's path and the configuration. rosvar always runs."""

    def __init__(self, directory: Path | None) -> None:
        self.directory = directory
        self._digests: dict[str, str] = {}

    def _digest(self, repository: Repository) -> str:
        if repository.name not in self._digests:
            digest = hashlib.sha256((ORACLE / "VERSION").read_bytes())
            for root in repository.package_paths:
                for path in sorted(root.rglob("*")):
                    if path.is_file():
                        digest.update(path.relative_to(DATA).as_posix().encode())
                        digest.update(path.read_bytes())
            self._digests[repository.name] = digest.hexdigest()
        return self._digests[repository.name]

    def answer(self, case: Case) -> dict[str, Any]:
        repository = REPOSITORIES[case.repository]
        if self.directory is None:
            return run_oracle(case.file, case.arguments, repository.package_paths, strict=False)
        key = json.dumps([self._digest(repository), str(case.file), case.config])
        path = self.directory / f"{hashlib.sha256(key.encode()).hexdigest()}.json"
        if path.is_file():  # kept as the client gave it (its repairs run again: idempotent)
            return restored_lists(json.loads(path.read_text(encoding="utf-8")))
        answer = run_oracle(case.file, case.arguments, repository.package_paths, strict=False)
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(answer), encoding="utf-8")
        return answer


def _stub_packages(folder: Path, names: Iterable[str]) -> None:
    """Empty ament packages named as the oracle's placeholders."""
    for name in names:
        (folder / name).mkdir(parents=True)
        (folder / name / "package.xml").write_text(
            f'<?xml version="1.0"?>\n<package format="3"><name>{name}</name>'
            "<export><build_type>ament_cmake</build_type></export></package>\n",
            encoding="utf-8",
        )


def run_rosvar(case: Case, deps: Path | None) -> tuple[dict[str, Any] | None, str]:
    """``rosvar resolve`` of the case in a clean environment: its JSON, or None and why not."""
    repository = REPOSITORIES[case.repository]
    command = [sys.executable, "-m", "rosvar", "resolve", str(repository.root)]
    command += ["--launch", str(case.file), *(f"{k}:={v}" for k, v in case.config), "--json"]
    for folder in [*repository.package_paths[1:], *([deps] if deps is not None else [])]:
        command += ["--deps", str(folder)]
    command += [f"--env={name}={value}" for name, value in sorted(ENVIRONMENT.items())]
    env = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "PYTHONPATH": str(SOURCES)}
    try:
        done = subprocess.run(command, capture_output=True, text=True, env=env, timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        return None, f"rosvar timeout: over {TIMEOUT_S} s"
    if done.returncode in (0, 1):
        try:
            return oracle_shape(json.loads(done.stdout)), ""
        except json.JSONDecodeError:
            pass
    last = (done.stderr.strip().splitlines() or [f"exit {done.returncode}, no output"])[-1]
    return None, f"rosvar crash: {last}"


def oracle_shape(document: Mapping[str, Any]) -> dict[str, Any]:
    """``rosvar resolve --json`` in the oracle's shape: its nodes as :func:`rosvar_nodes`
    makes them, an error's place as ``location``."""
    errors = [
        {**error, "location": {k: error.get(k) for k in ("file", "line", "col")}}
        for error in document.get("errors") or []
    ]
    return {**document, **rosvar_nodes(document), "errors": errors}


def run_case(case: Case, oracle: OracleCache) -> Outcome:
    try:
        expected = oracle.answer(case)
    except (RuntimeError, ValueError, subprocess.TimeoutExpired) as error:
        return Outcome(case, Status.ORACLE_FAILS, [Cause("oracle: no answer", str(error)[:300])])
    if not expected.get("ok"):
        why = f"{expected.get('error_type')}: {_cause_line(str(expected.get('error')))}"
        return Outcome(case, Status.ORACLE_FAILS, [Cause(_pattern(f"oracle: {why}"), why)])
    missing = expected.get("missing_packages") or []
    with tempfile.TemporaryDirectory(prefix="rosvar-deps-") as folder:
        deps = Path(folder) if missing else None
        if deps is not None:
            _stub_packages(deps, missing)
            text = json.dumps(expected).replace(MISSING, f"{deps}/")
            expected = json.loads(text)
        got, failure = run_rosvar(case, deps)
    if got is None:  # a traceback's last line names the exception: kept as it is
        return Outcome(case, Status.DIFFER, [Cause(failure[:120], failure)])
    causes = compare(expected, got)
    return Outcome(case, Status.DIFFER if causes else Status.AGREE, causes)


# -- comparing ---------------------------------------------------------------------------------
IDENTITY = ("kind", "package", "executable", "plugin")
"""Fields that pair an oracle node with a rosvar node; the other fields are compared."""


def _cause_line(text: str) -> str:
    """The first line of an error, or where it lists the exceptions behind it (the
    frontends' "Caught multiple exceptions"), the first of those."""
    lines = [line.strip() for line in text.strip().splitlines()]
    listed = [line[2:] for line in lines if line.startswith("- ")]
    return (listed or lines or [""])[0][:300]


def _pattern(text: str) -> str:
    """A category from a message: its names, paths and numbers made alike, its length cut."""
    return message_pattern(text)[:120]


def _explained(error: Mapping[str, Any], expected: Mapping[str, Any]) -> bool:
    """A rosvar error the oracle's lenient reading explains: a missing package or a file in
    it, an include the oracle could not resolve either (named by the message, or the file
    the error is in: a package rosvar finds where the oracle's index does not, Clearpath's
    ``project_bringup`` inside another package, whose files the oracle never reads), a
    robot description's xacro (which rosvar expands and the oracle, running no command,
    never does)."""
    message = str(error.get("message", ""))
    if error.get("code") == "launch-stops" and message.startswith("xacro fails"):
        return True  # the oracle runs no command: a robot description's xacro is rosvar's
    names = expected.get("missing_packages") or []
    if any(f"'{name}'" in message or f"/{name}/" in message for name in names):
        return True  # the package, or a file of it (rosvar's stand-in is empty)
    includes = [str(i.get("location", i)) for i in expected.get("unresolved_includes") or []]
    if any(os.path.basename(path) in message for path in includes if path):
        return True
    file = str((error.get("location") or {}).get("file") or "")
    unread = [
        path[path.index(f"/{name}/") :]
        for path in includes
        for name in names
        if f"/{name}/" in path
    ]
    return bool(file) and any(file.endswith(tail) for tail in unread)


def _label(node: Mapping[str, Any]) -> str:
    name = node.get("name") or node.get("executable") or "?"
    return f"{node.get('namespace') or ''}/{name} ({node.get('package')}/{node.get('executable')})"


def _pair(
    expected: list[dict[str, Any]], got: list[dict[str, Any]]
) -> tuple[list[tuple[dict[str, Any], dict[str, Any]]], list[dict[str, Any]], list[dict[str, Any]]]:
    """Oracle nodes matched with rosvar nodes of the same identity (most equal fields first);
    the unmatched of both sides."""
    left = list(got)
    pairs, alone = [], []
    for node in expected:
        same = [n for n in left if all(n.get(k) == node.get(k) for k in IDENTITY)]
        if not same:
            alone.append(node)
            continue
        best = max(same, key=lambda n: sum(n.get(k) == v for k, v in node.items()))
        left.remove(best)
        pairs.append((node, best))
    return pairs, alone, left


def _type(value: object) -> str:
    return "null" if value is None else type(value).__name__


def _parameter_causes(label: str, want: Mapping[str, Any], have: Mapping[str, Any]) -> list[Cause]:
    causes = []
    for key in sorted(set(want) | set(have)):
        if key not in have:
            causes.append(Cause("parameter only in the oracle", f"{label}: {key}={want[key]!r}"))
        elif key not in want:
            causes.append(Cause("parameter only in rosvar", f"{label}: {key}={have[key]!r}"))
        elif want[key] != have[key] or _type(want[key]) != _type(have[key]):
            kind = "value" if _type(want[key]) == _type(have[key]) else "type"
            category = f"parameter {kind}: oracle {_type(want[key])}, rosvar {_type(have[key])}"
            detail = f"{label}: {key}: oracle {want[key]!r}, rosvar {have[key]!r}"
            causes.append(Cause(category, detail[:400]))
    return causes


def compare(expected: Mapping[str, Any], got: Mapping[str, Any]) -> list[Cause]:
    """Why rosvar's answer differs from the oracle's (which loaded the configuration)."""
    causes = [
        Cause(f"rosvar error [{e.get('code')}]: {_pattern(str(e.get('message')))}", _where(e))
        for e in got.get("errors") or []
        if not _explained(e, expected)
    ]
    pairs, only_oracle, only_rosvar = _pair(canonical_nodes(expected), canonical_nodes(got))
    causes += [Cause("node only in the oracle", _label(n)) for n in only_oracle]
    causes += [Cause("node only in rosvar", _label(n)) for n in only_rosvar]
    for want, have in pairs:
        label = _label(want)
        for key, value in want.items():
            if key == "parameters" and isinstance(value, dict):
                causes += _parameter_causes(label, value, have.get(key) or {})
            elif key in EQUIVALENT and EQUIVALENT[key](value, have.get(key)):
                continue
            elif have.get(key) != value:
                detail = f"{label}: oracle {value!r}, rosvar {have.get(key)!r}"
                causes.append(Cause(f"{key} differs", detail[:400]))
    return causes


def _same_rules(oracle: object, rosvar: object) -> bool:
    """The same remapping rules in another order, none sharing its source with another: the
    first rule matching a name applies, so only rules of one source have an order that
    matters (a Python set literal of rules comes out in its hash order, another each run)."""
    if not isinstance(oracle, list) or not isinstance(rosvar, list):
        return False
    sources = [str(rule[0]) for rule in oracle]
    same = sorted(map(str, oracle)) == sorted(map(str, rosvar))
    return same and len(set(sources)) == len(sources)


_ANON = re.compile(r"(.+)_anon\d+")


def _anonymous(oracle: object, rosvar: object) -> bool:
    """Both an ``$(anon id)`` name: launch appends the host, pid and a random number to the
    id, rosvar a counter (docs/known-differences.md)."""
    named = _ANON.fullmatch(str(rosvar))
    return named is not None and str(oracle).startswith(f"{named.group(1)}_")


EQUIVALENT: dict[str, Callable[[object, object], bool]] = {
    "name": _anonymous,
    "remappings": _same_rules,
}
"""Fields whose values may be written differently yet mean the same, each with its test."""


def _where(error: Mapping[str, Any]) -> str:
    location = error.get("location") or {}
    file = str(location.get("file", "?"))
    if file.startswith(str(DATA)):
        file = os.path.relpath(file, DATA)
    return f"{file}:{location.get('line')}:{location.get('col')}: {error.get('message')}"


# -- the report --------------------------------------------------------------------------------
@dataclass
class Report:
    outcomes: list[Outcome]

    def count(self, status: Status, repository: str | None = None) -> int:
        return sum(
            o.status is status and (repository is None or o.case.repository == repository)
            for o in self.outcomes
        )

    def loaded(self, repository: str | None = None) -> int:
        return self.count(Status.AGREE, repository) + self.count(Status.DIFFER, repository)

    def agreeing(self, repository: str | None = None) -> int:
        return self.count(Status.AGREE, repository)

    def categories(self, status: Status) -> list[tuple[str, int, Outcome, Cause]]:
        """(category, configurations it affects, first of them, its cause), most first."""
        counts: Counter[str] = Counter()
        first: dict[str, tuple[Outcome, Cause]] = {}
        for outcome in self.outcomes:
            if outcome.status is not status:
                continue
            for cause in {c.category: c for c in outcome.causes}.values():
                counts[cause.category] += 1
                first.setdefault(cause.category, (outcome, cause))
        return [(c, n, *first[c]) for c, n in counts.most_common()]

    def summary(self) -> list[str]:
        lines = []
        for name in sorted({o.case.repository for o in self.outcomes}):
            files = len({o.case.file for o in self.outcomes if o.case.repository == name})
            lines.append(
                f"{name}: {self.agreeing(name)} of {self.loaded(name)} loaded configurations "
                f"agree ({self.count(Status.ORACLE_FAILS, name)} the oracle does not load; "
                f"{files} files)"
            )
        loaded = self.loaded()
        share = f"{100 * self.agreeing() / loaded:.1f} %" if loaded else "-"
        lines.append(f"all: {self.agreeing()} of {loaded} agree ({share})")
        return [*lines, self.origins()]

    def origins(self) -> str:
        """How many configurations each rule of the sampler named, loaded and agreeing (a
        configuration two rules name counts for both)."""
        parts = []
        for origin in Origin:
            named = [o for o in self.outcomes if origin in o.case.origins]
            loaded = [o for o in named if o.status is not Status.ORACLE_FAILS]
            agree = sum(o.status is Status.AGREE for o in loaded)
            parts.append(f"{origin} {len(named)} ({len(loaded)} loaded, {agree} agree)")
        return "sampled: " + "; ".join(parts)

    def render(self, examples: int = 1) -> str:
        lines = self.summary()
        for status in (Status.DIFFER, Status.ORACLE_FAILS):
            lines += ["", f"{status}: causes by the configurations they affect"]
            for category, count, outcome, cause in self.categories(status):
                lines.append(f"{count:5d}  {category}")
                lines.append(f"       e.g. {outcome.case.command_line()}")
                lines.append(f"            {cause.detail[:300]}")
        return "\n".join(lines)

    def to_json(self) -> list[dict[str, object]]:
        return [
            {
                "repository": o.case.repository,
                "file": o.case.relative,
                "arguments": o.case.arguments,
                "origins": sorted(o.case.origins),
                "status": str(o.status),
                "causes": [{"category": c.category, "detail": c.detail} for c in o.causes],
            }
            for o in self.outcomes
        ]


def run(
    all_cases: Sequence[Case],
    oracle: OracleCache,
    jobs: int | None = None,
    progress: Callable[[Outcome], None] | None = None,
) -> Report:
    """Every case, ``jobs`` at a time (each is two subprocesses), in the cases' order."""
    workers = jobs or max(1, min(4, os.cpu_count() or 1))
    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
        outcomes = []
        for outcome in pool.map(lambda case: run_case(case, oracle), all_cases):
            outcomes.append(outcome)
            if progress is not None:
                progress(outcome)
    return Report(outcomes)


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else "")
    parser.add_argument("--repository", action="append", choices=sorted(REPOSITORIES))
    parser.add_argument("--file", help="only launch files whose path contains this text")
    parser.add_argument("--full", action="store_true", help="every configuration of every file")
    parser.add_argument("--files", type=int, default=None, help="files per repository")
    parser.add_argument("--configs", type=int, default=None, help="configurations per file")
    parser.add_argument("--jobs", type=int, default=None)
    parser.add_argument("--json", type=Path, help="write every outcome to this file")
    parser.add_argument("--oracle-cache", type=Path, help="keep the oracle's answers here")
    parser.add_argument("-v", "--verbose", action="store_true", help="print each outcome")
    options = parser.parse_args(argv)
    chosen: list[Case] = []
    for name in options.repository or sorted(REPOSITORIES):
        limits = (None, None) if options.full else (options.files, options.configs)
        chosen += [
            c
            for c in cases(REPOSITORIES[name], *limits)
            if options.file is None or options.file in c.relative
        ]

    def show(outcome: Outcome) -> None:
        if options.verbose:
            first = outcome.causes[0].category if outcome.causes else ""
            print(f"{outcome.status:12} {outcome.case.command_line()}  {first}", flush=True)

    report = run(chosen, OracleCache(options.oracle_cache), options.jobs, show)
    print(report.render())
    if options.json is not None:
        options.json.write_text(json.dumps(report.to_json(), indent=1), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
