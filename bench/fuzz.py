"""Seeded mutation fuzzing: corpus launch files, mutated, must never break rosvar.

Each mutant is a corpus launch file changed by a few random edits (text cut, duplicated or
garbled, hostile snippets spliced in: the inputs of issue 16), written into a throw-away
package and analysed as ``analyze --json`` and ``resolve`` would. A mutant fails when rosvar
raises, runs past the time limit, or the process's peak memory grows past the limit; failing
mutants are saved for replay. The test suite runs a short campaign
(``tests/test_fuzz.py``); the long one is::

    PYTHONPATH=src python bench/fuzz.py --mutants 100000 [--seed 1] [--out DIR]

Its figures go into docs/performance.md.
"""

from __future__ import annotations

import argparse
import json
import random
import resource
import shutil
import signal
import sys
import tempfile
import time
import traceback
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from types import FrameType

from rosvar.frontends import xml
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.describe import describe_model
from rosvar.outputs.documents.resolution import resolution_document
from rosvar.ros1.resolve import resolve
from rosvar.ros2.resolve import resolve as resolve_ros2
from rosvar.workspace import discover

ROOT = Path(__file__).resolve().parent.parent
CORPUS = (ROOT.parent / "shared" / "corpus").resolve()
PACKAGE_XML = "<package><name>fuzz</name></package>\n"
ROS2_DATA = ROOT / "tests" / "data" / "ros2"
ROS2_PACKAGE_XML = (
    '<package format="3"><name>fuzz</name><version>0.0.0</version><description>d</description>'
    '<maintainer email="a@b.c">m</maintainer><license>BSD</license>'
    "<export><build_type>ament_cmake</build_type></export></package>\n"
)
ROS2_SUFFIXES = (".launch.xml", ".launch.yaml", ".launch.py")

HOSTILE = (
    '<param name="h" type="yaml" value="&amp;a [*a]"/>',
    '<param name="h" type="yaml" value="a: b: c"/>',
    "<rosparam>a: rad(1/0)</rosparam>",
    "<rosparam>&amp;a {b: *a}</rosparam>",
    "<rosparam>a0: &amp;a0 [x,x,x,x,x,x,x,x,x,x]\na1: &amp;a1 [*a0,*a0,*a0,*a0,*a0,*a0,*a0,"
    "*a0,*a0,*a0]\na2: [*a1,*a1,*a1,*a1,*a1,*a1,*a1,*a1,*a1,*a1]</rosparam>",
    '<param name="h" textfile="/dev/zero"/>',
    '<param name="h" binfile="/dev/urandom"/>',
    '<param name="h" textfile="/etc/passwd"/>',
    '<param name="h" textfile="/proc/self/environ"/>',
    '<include file="$(find fuzz)/../../../etc/x.launch"/>',
    '<include file="$(dirname)/m.launch"/>',
    '<param name="h" value="$(eval max([9999]*1000000, key=factorial))"/>',
    '<param name="h" value="$(eval 9**9**9)"/>',
    '<arg name="z0" default="ab"/>'
    + "".join(f'<arg name="z{i}" default="$(arg z{i - 1})$(arg z{i - 1})"/>' for i in range(1, 40)),
    "".join(f'<arg name="y{i}" default="x"/>' for i in range(20))
    + '<param name="h" value="'
    + "".join(f"$(arg y{i})" for i in range(20))
    + '"/>',
    "<group>" * 300 + '<param name="h" value="1"/>' + "</group>" * 300,
    '<param name="h" value="$(env HOME)$(optenv PATH)"/>',
    '<node pkg="fuzz" type="t" name="n" if="$(eval ' + "(" * 200 + "1" + ")" * 200 + ')"/>',
    "<!DOCTYPE launch [<!ENTITY a 'aaaa'>]>",
    '<param name="h" value="$(arg' + " " * 1000 + ')"/>',
    "&#0;\x00\ufffe",
)
"""Snippets spliced into mutants: the reported inputs of issue 16 and their neighbours."""

_DOUBLING = 40
HOSTILE_ROS2 = {
    ".launch.xml": (
        '<let name="v0" value="ab"/>'
        + "".join(
            f'<let name="v{i}" value="$(var v{i - 1})$(var v{i - 1})"/>'
            for i in range(1, _DOUBLING)
        ),
        '<arg name="w0" default="ab"/>'
        + "".join(
            f'<arg name="w{i}" default="$(var w{i - 1})$(var w{i - 1})"/>'
            for i in range(1, _DOUBLING)
        ),
        "<group>" * 990 + '<node pkg="fuzz" exec="n"/>' + "</group>" * 990,
        '<node pkg="fuzz" exec="n"><param from="/etc/passwd"/></node>',
        '<set_parameters_from_file filename="$(find-pkg-share fuzz)/../../../etc/x.yaml"/>',
        '<include file="/etc/x.launch.xml"/>',
    ),
    ".launch.yaml": (
        "- let: {name: v0, value: ab}\n"
        + "".join(
            f"- let: {{name: v{i}, value: '$(var v{i - 1})$(var v{i - 1})'}}\n"
            for i in range(1, _DOUBLING)
        ),
        "- node: {pkg: fuzz, exec: n, param: [{from: /etc/passwd}]}",
        "- group: " + "[" * 200 + "]" * 200,
    ),
    ".launch.py": (
        "    s = 'x' * 1000\n    l = [[s] * 99999] * 99999",
        "    d = {'a': 1}\n    for i in range(40):\n        d = {'x': d, 'y': d}",
        "    l = list(range(99999))\n    for i in range(99999):\n        m = l == l[:]",
        "    g = GroupAction([])\n    for i in range(30):\n        g = GroupAction([g, g])",
        "    import os\n    os.system('touch /tmp/rosvar-fuzz-ran')",
        "    open('/etc/passwd').read()",
    ),
}
"""Snippets spliced into ROS 2 mutants, by format: the inputs of issue 28's item 8."""


def _lines(text: str, rng: random.Random) -> tuple[list[str], int]:
    lines = text.splitlines(keepends=True) or [""]
    return lines, rng.randrange(len(lines))


def _splice_hostile(text: str, rng: random.Random) -> str:
    lines, at = _lines(text, rng)
    lines.insert(at, rng.choice(HOSTILE) + "\n")
    return "".join(lines)


def _duplicate_lines(text: str, rng: random.Random) -> str:
    lines, at = _lines(text, rng)
    end = min(len(lines), at + rng.randint(1, 8))
    return "".join(lines[:end] + lines[at:end] * rng.randint(1, 4) + lines[end:])


def _delete_span(text: str, rng: random.Random) -> str:
    if not text:
        return text
    start = rng.randrange(len(text))
    return text[:start] + text[start + rng.randint(1, 200) :]


def _garble(text: str, rng: random.Random) -> str:
    if not text:
        return text
    at = rng.randrange(len(text))
    return text[:at] + rng.choice("<>/$()&;\"'=[]{}*!:\n \\") + text[at + rng.randint(0, 1) :]


def _swap_values(text: str, rng: random.Random) -> str:
    """One attribute value replaced by another one of the file (``$(arg)``s reach new args)."""
    values = [part for index, part in enumerate(text.split('"')) if index % 2]
    if len(values) < 2:
        return text
    old, new = rng.choice(values), rng.choice(values)
    return text.replace(f'"{old}"', f'"{new}"', 1)


MUTATIONS: tuple[Callable[[str, random.Random], str], ...] = (
    _splice_hostile,
    _duplicate_lines,
    _delete_span,
    _garble,
    _swap_values,
)


def mutate(text: str, rng: random.Random, suffix: str = "") -> str:
    for _ in range(rng.randint(1, 4)):
        if suffix and rng.random() < 0.2:
            lines, at = _lines(text, rng)
            lines.insert(at, rng.choice(HOSTILE_ROS2[suffix]) + "\n")
            text = "".join(lines)
        elif suffix:
            text = rng.choice(MUTATIONS[1:])(text, rng)
        else:
            text = rng.choice(MUTATIONS)(text, rng)
    return text


YAML_SEED = """launch:
- arg: {name: a, default: x}
- let: {name: b, value: '$(var a)'}
- node: {pkg: fuzz, exec: n, name: '$(var b)', param: [{name: p, value: 1}]}
- group:
  - push_ros_namespace: {namespace: '$(var a)'}
  - node: {pkg: fuzz, exec: m, if: '$(var a)'}
"""
"""The test data holds no YAML launch file: this one stands for the format."""


def ros2_seeds() -> list[tuple[str, str]]:
    """The ROS 2 launch files of the test data, (suffix, text), sorted, and a YAML one."""
    found: list[tuple[str, str]] = [(".launch.yaml", YAML_SEED)]
    for path in sorted(ROS2_DATA.rglob("*")):
        suffix = next((s for s in ROS2_SUFFIXES if path.name.endswith(s)), None)
        if suffix is None and path.name.endswith("_launch.py"):
            suffix = ".launch.py"
        if suffix is not None and path.is_file() and path.stat().st_size < 100_000:
            found.append((suffix, path.read_text(errors="replace")))
    return found


def seeds(limit: int | None = None) -> list[str]:
    """Corpus launch files (sorted, so that a seed reproduces a campaign)."""
    files = sorted(CORPUS.rglob("*.launch"))
    texts = [path.read_text(errors="replace") for path in files[:limit]]
    return [text for text in texts if len(text) < 100_000]


@dataclass
class Report:
    mutants: int = 0
    failures: list[tuple[str, str]] = field(default_factory=list)  # (mutant, traceback)
    slowest: float = 0.0
    seconds: float = 0.0
    peak_rss_mb: float = 0.0


class _TimeOut(Exception):
    pass


def _alarm(_signum: int, _frame: FrameType | None) -> None:
    raise _TimeOut


def _check(text: str, directory: Path, index: int) -> None:
    """Analyse and resolve one mutant as the CLI would (``ros_package_path`` empty)."""
    launch = directory / "fuzz" / "launch" / f"m{index}.launch"
    launch.write_text(text, errors="replace")
    try:
        analysis = Analysis(discover([directory / "fuzz"], ros_package_path=""))
        json.dumps(describe_model(analysis.model(str(launch))), ensure_ascii=False)
        json.dumps(
            resolution_document(resolve(analysis, [str(launch)], {}, {})), ensure_ascii=False
        )
    finally:
        launch.unlink()
        xml.clear_cache()


def _check_ros2(text: str, suffix: str, directory: Path, index: int) -> None:
    """Analyse and resolve one ROS 2 mutant as the CLI would."""
    launch = directory / "fuzz" / "launch" / f"m{index}{suffix}"
    launch.write_text(text, errors="replace")
    try:
        analysis = Analysis(discover([directory / "fuzz"], ros_package_path=""))
        json.dumps(describe_model(analysis.model(str(launch))), ensure_ascii=False)
        resolved = resolve_ros2(analysis, [str(launch)], {}, {})
        json.dumps(resolution_document(resolved), ensure_ascii=False)
    finally:
        launch.unlink()
        xml.clear_cache()


def campaign(
    count: int,
    seed: int,
    time_limit: float = 20.0,
    texts: Sequence[str] | None = None,
    ros2: bool = False,
) -> Report:
    """Run ``count`` mutants from ``seed`` (of the ROS 2 test data's launch files, XML, YAML
    and Python, if ``ros2``); failures are collected, never raised."""
    rng = random.Random(seed)
    pool: list[tuple[str, str]] = (
        ros2_seeds() if ros2 else [("", t) for t in (texts if texts is not None else seeds())]
    )
    report = Report()
    directory = Path(tempfile.mkdtemp(prefix="rosvar-fuzz-"))
    (directory / "fuzz" / "launch").mkdir(parents=True)
    (directory / "fuzz" / "package.xml").write_text(ROS2_PACKAGE_XML if ros2 else PACKAGE_XML)
    previous = signal.signal(signal.SIGALRM, _alarm)
    start = time.perf_counter()
    try:
        for index in range(count):
            suffix, seed_text = rng.choice(pool)
            text = mutate(seed_text, rng, suffix)
            began = time.perf_counter()
            signal.setitimer(signal.ITIMER_REAL, time_limit)
            try:
                if suffix:
                    _check_ros2(text, suffix, directory, index)
                else:
                    _check(text, directory, index)
            except _TimeOut:
                report.failures.append((text, f"time-out after {time_limit} s"))
            except Exception:
                report.failures.append((text, traceback.format_exc()))
            finally:
                signal.setitimer(signal.ITIMER_REAL, 0)
            report.slowest = max(report.slowest, time.perf_counter() - began)
            report.mutants += 1
    finally:
        signal.signal(signal.SIGALRM, previous)
        shutil.rmtree(directory, ignore_errors=True)
    report.seconds = time.perf_counter() - start
    report.peak_rss_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return report


def _batches(total: int, size: int) -> Iterator[int]:
    while total > 0:
        yield min(size, total)
        total -= size


def main(argv: Sequence[str] | None = None) -> int:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--mutants", type=int, default=100_000)
    options.add_argument("--seed", type=int, default=1)
    options.add_argument("--time-limit", type=float, default=20.0, help="seconds per mutant")
    options.add_argument("--out", type=Path, default=Path("fuzz-failures"))
    options.add_argument("--ros2", action="store_true", help="mutate the ROS 2 test data")
    args = options.parse_args(argv)
    texts = seeds()
    total = Report()
    for batch, size in enumerate(_batches(args.mutants, 1000)):
        report = campaign(size, args.seed * 1_000_003 + batch, args.time_limit, texts, args.ros2)
        total.mutants += report.mutants
        total.failures += report.failures
        total.slowest = max(total.slowest, report.slowest)
        total.seconds += report.seconds
        total.peak_rss_mb = report.peak_rss_mb
        print(
            f"{total.mutants} mutants, {len(total.failures)} failures, "
            f"slowest {total.slowest:.2f} s, {total.seconds:.0f} s, "
            f"peak RSS {total.peak_rss_mb:.0f} MB",
            flush=True,
        )
    if total.failures:
        args.out.mkdir(parents=True, exist_ok=True)
        for index, (text, why) in enumerate(total.failures):
            (args.out / f"{index}.launch").write_text(text, errors="replace")
            (args.out / f"{index}.txt").write_text(why)
    return 1 if total.failures else 0


if __name__ == "__main__":
    sys.exit(main())
