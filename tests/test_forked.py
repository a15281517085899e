"""The forked map: the same results as a plain map, in order, whatever the number of jobs;
a worker's failure is an error, never a silently short list; no process is left behind."""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

import pytest

from rosvar.forked import WorkerFailed, available_jobs, forked_map

PARENT = os.getpid()


def square_with_origin(item: int) -> tuple[int, bool]:
    """The item's square, and whether a forked child computed it."""
    return item * item, os.getpid() != PARENT


def children() -> set[str]:
    """This process's children (Linux; other tests' may be among them)."""
    tasks = Path(f"/proc/{os.getpid()}/task")
    if not tasks.is_dir():
        pytest.skip("no /proc")
    return {pid for task in tasks.iterdir() for pid in (task / "children").read_text().split()}


@pytest.fixture
def no_child_left() -> Callable[[], bool]:
    before = children()
    return lambda: children() <= before


@pytest.mark.parametrize("count", [0, 1, 2, 7, 30])
@pytest.mark.parametrize("jobs", [1, 2, 3, 5])
def test_results_are_the_plain_map_s_in_order(
    count: int, jobs: int, no_child_left: Callable[[], bool]
) -> None:
    items = list(range(count))
    found = forked_map(items, square_with_origin, jobs)
    assert [square for square, _child in found] == [item * item for item in items]
    children = {item for item, (_square, child) in zip(items, found, strict=True) if child}
    assert children == {item for item in items if item % min(jobs, max(count, 1)) != 0}
    assert no_child_left()


def test_children_see_the_parent_s_state() -> None:
    table = {item: f"value {item}" for item in range(10)}  # built before the fork, never sent
    assert forked_map(list(table), table.__getitem__, 3) == list(table.values())


def test_progress_ends_on_the_last_place() -> None:
    told: list[int] = []
    forked_map(list(range(11)), square_with_origin, 3, told.append)
    assert told == sorted(told) and told[-1] == 10 and len(told) == 4  # places 0, 3, 6, 9


PREPARED: list[int] = []  # the items prepared in this process (a child's copy its own)


@pytest.mark.parametrize("jobs", [1, 2, 3])
def test_a_process_prepares_its_whole_share_before_working(jobs: int) -> None:
    PREPARED.clear()
    told: list[int] = []
    items = list(range(10))
    found = forked_map(items, lambda _item: sorted(PREPARED), jobs, told.append, PREPARED.append)
    assert found == [items[item % jobs :: jobs] for item in items]  # its process's share
    assert told[-1] == 9 and len(told) == len(items[::jobs])  # told as prepare starts
    PREPARED.clear()


def fail_on_three(item: int) -> int:
    if item == 3:
        raise ValueError("three")
    return item


def test_a_child_s_error_fails_the_map(
    capfd: pytest.CaptureFixture[str], no_child_left: Callable[[], bool]
) -> None:
    with pytest.raises(WorkerFailed):
        forked_map(list(range(8)), fail_on_three, 2)  # 3 is a child's
    assert "ValueError: three" in capfd.readouterr().err
    assert no_child_left()


def test_the_parent_s_error_leaves_no_child(no_child_left: Callable[[], bool]) -> None:
    with pytest.raises(ValueError, match="three"):
        forked_map(list(range(8)), fail_on_three, 3)  # 3 is the parent's
    assert no_child_left()


def test_available_jobs_is_positive() -> None:
    assert available_jobs() >= 1
