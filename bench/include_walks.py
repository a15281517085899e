"""Where the include walks of a ROS 2 workspace go: the census behind the notes on large ROS 2
systems in docs/performance.md (issue 28).

Runs ``rosvar analyze --jobs 1`` in this process with a count wrapped around the include
memo (:mod:`rosvar.ros2.include_memo`) and the passes of each entry file, and prints:

* the CPU time of the entry files interpreted once, of the passes that were thrown away
  (an included file's arg read before its declaration makes another pass), and of the
  passes kept after one was thrown away;
* the includes replayed and walked, and how many distinct keys the walks have when keyed as
  the memo keys them and when keyed more loosely — without the path condition, by the
  leaves of what they read (conditions left out), those leaves with each input named
  without its entry file, and by the names read alone — which bounds what a memo (or a
  summary) keyed that way could replay::

    python bench/include_walks.py /tmp/rd
"""

from __future__ import annotations

import argparse
import contextlib
import io
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import Any

from rosvar.interpreter import workspace_models
from rosvar.logic.choice import Choice, leaf_key
from rosvar.logic.terms import Apply, Hole
from rosvar.outputs.cli import main
from rosvar.ros2 import include_memo
from rosvar.ros2.context import Probe

KEYS = ("as the memo", "without the path condition", "by leaves", "by leaves, inputs renamed")


@dataclass
class Census:
    """What one analysis did, counted."""

    replays: int = 0
    walks: int = 0
    keys: dict[str, set[object]] = field(default_factory=lambda: {k: set() for k in KEYS})
    names: set[object] = field(default_factory=set)
    files: set[str] = field(default_factory=set)
    pairs: set[tuple[str, str]] = field(default_factory=set)
    passes: dict[str, list[tuple[float, bool]]] = field(default_factory=dict)


def _renamed(leaf: object) -> object:
    """A leaf with each input named without its entry file."""
    if isinstance(leaf, Hole):
        return ("hole", str(leaf.input))
    if isinstance(leaf, Apply):
        return (
            "apply",
            leaf.function,
            tuple(o if isinstance(o, tuple) else _renamed(o) for o in leaf.operands),
        )
    return leaf_key(leaf)


def _leaves(value: object, renamed: bool) -> object:
    if not isinstance(value, Choice):
        return value
    return tuple(_renamed(leaf) if renamed else leaf_key(leaf) for _c, leaf in value.branches)


def _loose(fixed: tuple[Any, ...], context: Any, renamed: bool) -> tuple[object, ...]:
    """The fixed key by leaves: the file, the namespace's, remaps' and parameters' leaves."""
    remaps = tuple(
        (_leaves(r.source, renamed), _leaves(r.target, renamed)) for r in context.remaps or ()
    )
    params = tuple(
        (_leaves(p.name, renamed), _leaves(p.value, renamed)) for p in context.params or ()
    )
    return (fixed[0], fixed[1], _leaves(context.namespace, renamed), remaps, params, *fixed[6:])


@contextlib.contextmanager
def _wrapped(owner: object, name: str, wrapper: Callable[..., Any]) -> Iterator[None]:
    original = getattr(owner, name)
    setattr(owner, name, wrapper(original))
    try:
        yield
    finally:
        setattr(owner, name, original)


def census(path: str) -> tuple[Census, float]:
    """The count of ``rosvar analyze --jobs 1 path``, and its CPU seconds."""
    counted = Census()
    last: list[list[Any]] = []

    def read_before(original: Callable[..., list[Any]]) -> Callable[..., list[Any]]:
        def wrapper(*args: Any) -> list[Any]:
            reads = original(*args)
            last.append(reads)
            return reads

        return wrapper

    def record(original: Callable[..., None]) -> Callable[..., None]:
        def wrapper(it: Any, root: Any, context: Any, file: str, *args: Any) -> None:
            fixed = include_memo._fixed(root, file, it, context)
            assert isinstance(fixed, tuple)
            loose = (_loose(fixed, context, False), _loose(fixed, context, True))
            original(it, root, context, file, *args)
            reads = last.pop()
            counted.walks += 1
            exact = tuple((p, n, include_memo._answer_key(p, a)) for p, n, a in reads)
            keys = counted.keys
            keys[KEYS[0]].add((fixed, exact))
            keys[KEYS[1]].add((fixed[:2] + fixed[3:], exact))
            for renamed in (False, True):
                read = tuple(
                    (p, n, _leaves(a, renamed) if p is Probe.CONFIGURATION else a)
                    for p, n, a in reads
                )
                keys[KEYS[2 + renamed]].add((loose[renamed], read))
            counted.names.add((file, tuple((p, n) for p, n, _a in reads)))
            counted.files.add(file)
            counted.pairs.add((it.model.file, file))

        return wrapper

    def replay(original: Callable[..., None]) -> Callable[..., None]:
        def wrapper(*args: Any) -> None:
            counted.replays += 1
            original(*args)

        return wrapper

    def interpret_with(original: Callable[..., Any]) -> Callable[..., Any]:
        def wrapper(self: Any, file: str, undeclared: Any) -> Any:
            start = time.process_time()
            result = original(self, file, undeclared)
            passes = counted.passes.setdefault(file, [])
            passes.append((time.process_time() - start, bool(result[1])))
            return result

        return wrapper

    start = time.process_time()
    with (
        _wrapped(include_memo, "_read_before", read_before),
        _wrapped(include_memo, "_record", record),
        _wrapped(include_memo, "_replay", replay),
        _wrapped(workspace_models.Analysis, "_interpret_with", interpret_with),
        contextlib.redirect_stdout(io.StringIO()),
    ):
        main(["analyze", "--jobs", "1", "--json", path])
    return counted, time.process_time() - start


def report(counted: Census, cpu: float) -> list[str]:
    passes = counted.passes.values()
    once = [p for p in passes if len(p) == 1]
    again = [p for p in passes if len(p) > 1]
    thrown = sum(seconds for p in again for seconds, _late in p[:-1])
    return [
        f"CPU {cpu:.1f} s; entry files {len(counted.passes)}, "
        f"interpretations {sum(len(p) for p in passes)}",
        f"  entry files interpreted once: {len(once)}, {sum(p[0][0] for p in once):.1f} s",
        f"  passes thrown away: {sum(len(p) - 1 for p in again)}, {thrown:.1f} s",
        f"  passes kept after them: {len(again)}, {sum(p[-1][0] for p in again):.1f} s",
        f"includes replayed {counted.replays}, walked {counted.walks}",
        *(f"  distinct keys {name}: {len(keys)}" for name, keys in counted.keys.items()),
        f"  distinct keys by the names read: {len(counted.names)}",
        f"  distinct (entry file, file) pairs: {len(counted.pairs)}; files: {len(counted.files)}",
    ]


def _main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "path", help="a ROS 2 workspace (e.g. bench/generate.py --shape ros2-dense)"
    )
    counted, cpu = census(parser.parse_args().path)
    print("\n".join(report(counted, cpu)))


if __name__ == "__main__":
    _main()
