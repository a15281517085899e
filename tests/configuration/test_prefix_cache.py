"""The prefix cache: answers come from the longest known prefix; the oldest go first."""

from __future__ import annotations

from rosvar.configuration.prefix_cache import PrefixCache


def test_longest_known_prefix_and_empty() -> None:
    cache: PrefixCache[str, str] = PrefixCache("start", capacity=8)
    assert cache.longest(("a", "b")) == (0, "start")
    cache.put(("a",), "A")
    cache.put(("a", "b", "c"), "ABC")
    assert cache.longest(("a", "b")) == (1, "A")
    assert cache.longest(("a", "b", "c", "d")) == (3, "ABC")
    assert cache.longest(("b",)) == (0, "start")
    assert cache.longest(()) == (0, "start")


def test_least_recently_used_goes_first() -> None:
    cache: PrefixCache[int, int] = PrefixCache(0, capacity=2)
    cache.put((1,), 1)
    cache.put((2,), 2)
    assert cache.longest((1, 9)) == (1, 1)  # a hit makes (1,) the most recent
    cache.put((3,), 3)
    assert cache.longest((2,)) == (0, 0)  # (2,) was the least recently used
    assert cache.longest((1,)) == (1, 1)
    assert cache.longest((3,)) == (1, 3)
