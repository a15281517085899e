"""Cells: how a term function's result depends on one input, so that predicates over terms
of that input are related by facts instead of being independent atoms.

Two ``if``s over one arg, ``$(eval arg('dof') == 6)`` and ``$(eval arg('dof') == 7)``, are two
predicate atoms over two terms. For a value analysis did not foresee (the ``OTHER`` slot)
nothing would stop both from holding. A function registered here says which constants its
result depends on; the space then evaluates every predicate over that input at one value of
each cell of all their constants together, and adds as a fact that exactly the combinations
seen can hold (:meth:`rosvar.logic.conditions.ConditionSpace.predicate`).
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterable
from dataclasses import dataclass

from rosvar.logic.inputs import Input
from rosvar.logic.terms import Apply


@dataclass(frozen=True)
class Cells:
    """``constants(term, input)``: what the term compares ``input``'s value with, or None
    when it does more with it (no fact is then added); ``witnesses(constants)``: a value of
    the input in every cell of those constants (more is allowed: a witness only adds a
    combination that may hold)."""

    constants: Callable[[Apply, Input], frozenset[Hashable] | None]
    witnesses: Callable[[Iterable[Hashable]], tuple[str, ...]]


CELLS: dict[str, Cells] = {}


def register_cells(function: str, cells: Cells) -> None:
    """Declare how the terms of ``function`` (a :data:`rosvar.logic.terms.FUNCTIONS` name)
    depend on one input."""
    CELLS[function] = cells
