"""Presence: whether a condition holds in every valid configuration a step leaves, in none,
or in some, and the verdict that says so with what it depended on (``derivation`` judges
them, ``judgement`` carries the graph's from one step to the next)."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from enum import StrEnum


class Presence(StrEnum):
    """Whether a condition holds in every valid configuration left, in none, or in some."""

    PRESENT = "present"
    ABSENT = "absent"
    UNDETERMINED = "undetermined"


@dataclass(frozen=True)
class PresenceVerdict:
    """Presence of a condition at one step, and what it depended on.

    ``values`` are the decided variables of its support. When restriction by them was not
    enough, ``components`` are those whose literals the judgement read; an undetermined
    one keeps ``witnesses`` (a valid configuration without it, one that may have it):
    it stays undetermined while both agree with the user literals, or their repairs
    (``repaired``) still show it so.
    """

    presence: Presence
    values: Mapping[str, bool]
    components: frozenset[int] = frozenset()
    witnesses: tuple[int, int] | None = None
