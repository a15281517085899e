"""Memo tables of bounded size, for the long-lived engine behind ``rosvar serve``.

A server answers clicks for hours, and every distinct value typed or chosen makes new keys
(conditions, strings, rendered entries): a memo that only grows holds them all, and the BDD
nodes they reference, for ever. A :class:`Memo` forgets its oldest entries beyond its
capacity instead; what it forgot is computed again when asked (to an equal value), and the
BDD nodes nobody references any more are freed by CUDD's next garbage collection.

The eviction is first in, first out: a hit costs a plain lookup (no reordering), and a hot
entry that was evicted is one recomputation away.
"""

from __future__ import annotations

import weakref
from collections import OrderedDict
from typing import TypeVar

Key = TypeVar("Key")
Value = TypeVar("Value")

CAPACITY = 20_000
"""Entries a memo keeps unless told otherwise: enough that a session's working set (one
workspace's conditions and entries under a few dozen choices) stays; an entry with the
diagrams it keeps alive takes about 2 KB, so a few tens of MB for all memos at worst
(docs/performance.md, "Server memory")."""

_ALL: weakref.WeakValueDictionary[int, Memo[object, object]] = weakref.WeakValueDictionary()


class Memo(OrderedDict[Key, Value]):
    """A dict that keeps at most ``capacity`` entries, forgetting the oldest first."""

    def __init__(self, capacity: int | None = None) -> None:
        super().__init__()
        self.capacity = CAPACITY if capacity is None else capacity
        if self.capacity < 1:
            raise ValueError("a memo keeps at least one entry")
        _ALL[id(self)] = self  # type: ignore[assignment]

    def __setitem__(self, key: Key, value: Value) -> None:
        super().__setitem__(key, value)
        while len(self) > self.capacity:
            self.popitem(last=False)


def memos() -> list[Memo[object, object]]:
    """Every memo alive, for tests and diagnostics of memory."""
    return list(_ALL.values())
