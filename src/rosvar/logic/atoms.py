"""What the variables of a condition space mean: an input holding a slot, a predicate of a
term not known yet, a launch file in the product; and the registry of those predicates.

Apart from the space so that what reads conditions (the printer, the lowering into the
solver) knows the atoms without knowing the space that declares them."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from rosvar.logic.inputs import Input, Slot
from rosvar.logic.terms import Term


@dataclass(frozen=True)
class SlotAtom:
    """Input ``input`` holds ``slot``."""

    input: Input
    slot: Slot


@dataclass(frozen=True)
class PredicateAtom:
    """``test(term)`` holds; ``test`` names an entry of :data:`PREDICATES`."""

    test: str
    term: Term


@dataclass(frozen=True)
class FileAtom:
    """Launch file ``file`` is part of the product (a feature of the feature model)."""

    file: str
    label: str


Atom = SlotAtom | PredicateAtom | FileAtom
Predicate = Callable[[str], bool]
PREDICATES: dict[str, tuple[Predicate, str]] = {}


def register_predicate(name: str, test: Predicate, display: str) -> None:
    """Register a predicate over strings; ``display`` is a format with ``{}`` for the term."""
    PREDICATES[name] = (test, display)
