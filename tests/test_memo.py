"""Bounded memo tables: the oldest entries go first, and nothing beyond the capacity stays."""

from __future__ import annotations

import gc

import pytest

from rosvar.memo import EVICTED, EntryMemo, Memo, memos


def test_keeps_the_newest_entries_up_to_its_capacity() -> None:
    memo: Memo[int, str] = Memo(3)
    for key in range(10):
        memo[key] = str(key)
        assert len(memo) == min(key + 1, 3)
    assert dict(memo) == {7: "7", 8: "8", 9: "9"}
    assert memo.get(2) is None


def test_a_full_memo_forgets_an_eighth_of_its_oldest_at_once() -> None:
    capacity = 4 * EVICTED
    memo: Memo[int, int] = Memo(capacity)
    for key in range(capacity + 1):
        memo[key] = key
    assert list(memo) == list(range(capacity // EVICTED, capacity + 1))
    for key in range(capacity + 1, capacity + 4):  # room again until the next overflow
        memo[key] = key
        assert len(memo) == capacity - capacity // EVICTED + 1 + key - capacity


def test_a_hit_does_not_reorder() -> None:
    memo: Memo[str, int] = Memo(2)
    memo["a"], memo["b"] = 1, 2
    assert memo["a"] == 1
    memo["c"] = 3
    assert list(memo) == ["b", "c"]  # first in, first out


def test_chained_assignments_are_bounded_too() -> None:
    memo: Memo[int, int] = Memo(1)
    first = memo[1] = 10
    second = memo[2] = 20
    assert (first, second, dict(memo)) == (10, 20, {2: 20})


def test_every_live_memo_is_listed_and_a_dropped_one_goes() -> None:
    memo: Memo[int, int] = Memo(5)
    assert any(found is memo for found in memos())
    del memo
    gc.collect()
    assert all(found.capacity != 5 for found in memos())


def test_capacity_is_at_least_one() -> None:
    with pytest.raises(ValueError):
        Memo(0)


def test_an_entry_memo_releases_the_entries_of_the_entry_file_done() -> None:
    memo: EntryMemo[str, int] = EntryMemo(4)
    memo.keep("evicted", 0, own=True)
    memo.keep("shared", 1, own=False)
    memo.keep("own", 2, own=True)
    for key in ("a", "b"):  # the oldest goes first, whoever it served
        memo.keep(key, 0, own=False)
    assert list(memo) == ["shared", "own", "a", "b"]
    memo.release()
    assert list(memo) == ["shared", "a", "b"]
    memo.keep("own", 4, own=False)  # entered again, for every entry file: released no more
    memo.release()
    assert memo["own"] == 4 and len(memo) == 4
