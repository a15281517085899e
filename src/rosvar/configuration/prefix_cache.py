"""Answers for lists of choices, each derived from the answer for its longest known prefix.

A session adds one choice at a time (and undo drops the last one), so the answer for a list
is nearly always one step from an answer already computed: the engine keeps the recent ones
and starts from the longest prefix it has, never from nothing.
"""

from __future__ import annotations

from collections import OrderedDict
from typing import Generic, TypeVar

Item = TypeVar("Item")
Value = TypeVar("Value")


class PrefixCache(Generic[Item, Value]):
    """The ``capacity`` most recently used answers, by their list; ``empty`` answers ``()``."""

    def __init__(self, empty: Value, capacity: int) -> None:
        self.empty = empty
        self._capacity = capacity
        self._items: OrderedDict[tuple[Item, ...], Value] = OrderedDict()

    def longest(self, key: tuple[Item, ...]) -> tuple[int, Value]:
        """The length of the longest prefix of ``key`` with an answer, and that answer."""
        length = len(key)
        while length and key[:length] not in self._items:
            length -= 1
        if not length:
            return 0, self.empty
        prefix = key[:length]
        self._items.move_to_end(prefix)
        return length, self._items[prefix]

    def put(self, key: tuple[Item, ...], value: Value) -> None:
        self._items[key] = value
        self._items.move_to_end(key)
        while len(self._items) > self._capacity:
            self._items.popitem(last=False)
