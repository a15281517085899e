"""Memo tables of bounded size, for the long-lived engine behind ``rosvar serve``.

A server answers clicks for hours, and every distinct value typed or chosen makes new keys
(conditions, strings, rendered entries): a memo that only grows holds them all, and the BDD
nodes they reference, for ever. A :class:`Memo` forgets its oldest entries beyond its
capacity instead; what it forgot is computed again when asked (to an equal value), and the
BDD nodes nobody references any more are freed by CUDD's next garbage collection.

The eviction is first in, first out: a hit costs a plain lookup (no reordering), and a hot
entry that was evicted is one recomputation away. A memo is a plain dict (insertion ordered),
half the memory of an ``OrderedDict``; its oldest entries go an eighth of its capacity at a
time, because a dict walks the holes its deletions left at its front on each walk from there.
"""

from __future__ import annotations

import weakref
from itertools import islice
from typing import TypeVar

Key = TypeVar("Key")
Value = TypeVar("Value")

CAPACITY = 20_000
"""Entries a memo keeps unless told otherwise: enough that a session's working set (one
workspace's conditions and entries under a few dozen choices) stays; an entry with the
diagrams it keeps alive takes about 2 KB, so a few tens of MB for all memos at worst
(docs/performance.md, "Server memory")."""

_ALL: weakref.WeakValueDictionary[int, Memo[object, object]] = weakref.WeakValueDictionary()


EVICTED = 8
"""A full memo forgets the oldest ``capacity // EVICTED`` entries (at least one) at once."""


class Memo(dict[Key, Value]):
    """A dict that keeps at most ``capacity`` entries, forgetting the oldest first."""

    def __init__(self, capacity: int | None = None) -> None:
        super().__init__()
        self.capacity = CAPACITY if capacity is None else capacity
        if self.capacity < 1:
            raise ValueError("a memo keeps at least one entry")
        _ALL[id(self)] = self  # type: ignore[assignment]

    def __setitem__(self, key: Key, value: Value) -> None:
        super().__setitem__(key, value)
        if len(self) > self.capacity:
            for oldest in list(islice(self, max(1, self.capacity // EVICTED))):
                del self[oldest]


def memos() -> list[Memo[object, object]]:
    """Every memo alive, for tests and diagnostics of memory."""
    return list(_ALL.values())


class EntryMemo(Memo[Key, Value]):
    """A memo of an analysis some of whose entries serve one entry file only (their keys
    are values over its inputs): those are dropped at once when the analysis goes on to
    another entry file (:meth:`release`), the others kept for every entry file."""

    def __init__(self, capacity: int | None = None) -> None:
        super().__init__(capacity)
        self._own: list[Key] = []

    def keep(self, key: Key, value: Value, own: bool) -> None:
        """Enter ``value`` under ``key``; ``own``: for the entry file under way only."""
        self[key] = value
        if own:
            self._own.append(key)

    def release(self) -> None:
        """Drop the entries of the entry file done."""
        for key in self._own:
            self.pop(key, None)
        self._own.clear()
