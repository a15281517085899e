"""A map shared among forked worker processes, for work that is independent item by item.

Launch files are analysed one entry file at a time, and each entry file's analysis reads
only what every process already holds once the workspace is read (the parsed files, the
include index): a forked child inherits that state, so it is sent nothing but the places
of its items and sends back only results. Threads would not run Python in parallel, and a
fresh process (``spawn``) would read the workspace again.

Items are dealt round-robin, so each process gets a share of every region of the list
(files of one package are alike in cost); results come back in the items' order. Without
``os.fork`` (Windows) or with one job, the map runs in the calling process.
"""

from __future__ import annotations

import contextlib
import os
import pickle
import sys
import traceback
from collections.abc import Callable, Sequence
from functools import partial
from typing import TypeVar

Item = TypeVar("Item")
Result = TypeVar("Result")

Progress = Callable[[int], None]
"""Told, as this process starts on each of its items, the place of the last item under way
in all processes (the children are assumed to keep pace: they are not watched); the last
call is told the last place."""


class WorkerFailed(RuntimeError):
    """A worker process ended without sending all its results (its error is on stderr)."""


def available_jobs() -> int:
    """The processors this process may run on."""
    if hasattr(os, "sched_getaffinity"):
        return max(1, len(os.sched_getaffinity(0)))
    return os.cpu_count() or 1


def forked_map(
    items: Sequence[Item],
    work: Callable[[Item], Result],
    jobs: int,
    progress: Progress | None = None,
    prepare: Callable[[Item], object] | None = None,
) -> list[Result]:
    """``[work(item) for item in items]``, computed by ``jobs`` processes: this one and
    ``jobs - 1`` forked children. With ``prepare``, each process first runs it on every item
    of its share, then ``work``: what ``work`` reads of several items is then complete when
    it starts (every model of the share built before any is described). Progress is told
    as the first phase starts on each item. Results must pickle; neither function may write
    to the standard streams (a child's writes would interleave with this process's)."""
    jobs = min(jobs, len(items)) if hasattr(os, "fork") else 1
    if jobs <= 1:
        return _share_done(items, range(len(items)), work, prepare, progress, 1)
    for stream in (sys.stdout, sys.stderr):  # else a child would write the buffers again
        stream.flush()
    children: list[tuple[int, int, range]] = []
    try:
        for first in range(1, jobs):
            share = range(first, len(items), jobs)
            read_end, write_end = os.pipe()
            pid = os.fork()
            if pid == 0:  # pragma: no cover - the child's coverage is not collected
                os.close(read_end)
                _serve(write_end, partial(_share_done, items, share, work, prepare, None, jobs))
            os.close(write_end)
            children.append((pid, read_end, share))
        results: list[Result | None] = [None] * len(items)
        own = range(0, len(items), jobs)
        computed = _share_done(items, own, work, prepare, progress, jobs)
        for index, result in zip(own, computed, strict=True):
            results[index] = result
        for pid, read_end, share in children:
            received: list[Result] = _received(pid, read_end, len(share))
            for index, result in zip(share, received, strict=True):
                results[index] = result
        return results  # type: ignore[return-value] # every place is filled above
    finally:
        for pid, read_end, _share in children:  # after an error: let every child end
            with contextlib.suppress(OSError):  # closed already
                os.close(read_end)
            _reap(pid)


def _share_done(
    items: Sequence[Item],
    share: range,
    work: Callable[[Item], Result],
    prepare: Callable[[Item], object] | None,
    progress: Progress | None,
    jobs: int,
) -> list[Result]:
    """One process's results: its share prepared, then worked on."""
    last = len(items) - 1
    results = []
    for index in share:
        if progress is not None:
            progress(min(index + jobs - 1, last))
        if prepare is None:
            results.append(work(items[index]))
        else:
            prepare(items[index])
    if prepare is not None:
        results = [work(items[index]) for index in share]
    return results


def _serve(write_end: int, results: Callable[[], list[Result]]) -> None:
    """A child's whole life: compute, send, and end without running the parent's
    clean-up (atexit handlers, buffered streams, a test runner's teardown)."""
    code = 0
    try:
        with os.fdopen(write_end, "wb") as stream:
            pickle.dump(results(), stream, pickle.HIGHEST_PROTOCOL)
    except BaseException:  # reported here: the parent only sees the exit status
        traceback.print_exc()
        sys.stderr.flush()
        code = 1
    os._exit(code)


def _received(pid: int, read_end: int, count: int) -> list[Result]:
    with os.fdopen(os.dup(read_end), "rb") as stream:
        data = stream.read()
    status = _reap(pid)
    if status != 0 or not data:
        raise WorkerFailed(f"a worker process failed (wait status {status})")
    results: list[Result] = pickle.loads(data)
    if len(results) != count:
        raise WorkerFailed(f"a worker process sent {len(results)} results of {count}")
    return results


def _reap(pid: int) -> int:
    """The child's wait status, once it has ended; 0 if it was reaped already."""
    try:
        return os.waitpid(pid, 0)[1]
    except ChildProcessError:
        return 0
