"""Cells: how predicates over one input are related by facts instead of being independent
atoms.

Two ``if``s over one arg, ``$(eval arg('dof') == 6)`` and ``$(eval arg('dof') == 7)``, are two
predicate atoms over two terms; so are ROS 2's ``IfCondition(use_composition)`` (a predicate
on the arg's own text, its *hole*) and ``IfCondition(PythonExpression(['not ',
use_composition]))``. For a value analysis did not foresee (the ``OTHER`` slot) nothing would
stop both from holding. Every predicate over the bare hole, and over a term of one input whose
function is registered here, joins its input's group; the space evaluates the group's
predicates at each *witness* (a text of the input) and adds as a fact that exactly the
combinations seen can hold for an unforeseen value
(:meth:`rosvar.logic.conditions.ConditionSpace.predicate`).

The witnesses are what the group's predicates and functions tell apart: each function's
(``witnesses`` of the constants its terms compare the input with: for roslaunch's ``$(eval)``
one text per cell, exact; for a term the text is spliced into, the constants written beside
it and the texts such code distinguishes), each predicate's :data:`PREDICATE_TEXTS` (the truth
texts launch and roslaunch accept, in their cases), and :data:`FRESH`, a text equal to none.
The same witnesses give an ``<other>`` value of an example a concrete text
(:meth:`~rosvar.logic.conditions.ConditionSpace.witness`).
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Hashable, Iterable
from dataclasses import dataclass
from typing import Final

from rosvar.logic.inputs import Input
from rosvar.logic.terms import Apply, Hole

FRESH: Final = "unforeseen_text"
"""A text no launch file compares with (a witness of every 'any other text' cell)."""


@dataclass(frozen=True)
class Cells:
    """``constants(term, input)``: what the term compares ``input``'s value with, or None
    when it does more with it (no fact is then added); ``witnesses(constants)``: a value of
    the input in every cell of those constants (more is allowed: a witness only adds a
    combination that may hold)."""

    constants: Callable[[Apply, Input], frozenset[Hashable] | None]
    witnesses: Callable[[Iterable[Hashable]], tuple[str, ...]]


CELLS: dict[str, Cells] = {}
PREDICATE_TEXTS: dict[str, tuple[str, ...]] = {}


def register_cells(function: str, cells: Cells) -> None:
    """Declare how the terms of ``function`` (a :data:`rosvar.logic.terms.FUNCTIONS` name)
    depend on one input."""
    CELLS[function] = cells


def register_predicate_texts(predicate: str, texts: Iterable[str]) -> None:
    """The texts ``predicate`` (a :data:`rosvar.logic.atoms.PREDICATES` name) tells apart:
    witnesses of every group it is tested in."""
    PREDICATE_TEXTS[predicate] = tuple(dict.fromkeys(texts))


def literal_operands(
    term: Apply, input_: Input, quoting: Collection[str] = ()
) -> frozenset[Hashable] | None:
    """The literal texts among a term's operands (through concatenations), when its only
    other operand is ``input_``'s hole (or, for a function of ``quoting``, the hole as that
    function quotes it whole: every text of the input stays one literal there): what a
    function of texts (an equality, a boolean) can compare the input's text with; None for
    any other operand (a nested function's cells would be its own)."""
    hole = Hole(input_)
    found: set[Hashable] = set()
    pending: list[object] = list(term.operands)
    while pending:
        operand = pending.pop()
        if isinstance(operand, str):
            found.add(operand)
        elif isinstance(operand, tuple):
            pending.extend(operand)
        elif isinstance(operand, Apply) and operand.function == "concat":
            pending.extend(operand.operands)
        elif isinstance(operand, Apply) and operand.function in quoting:
            if operand.operands != (hole,):
                return None
        elif operand != hole:
            return None
    return frozenset(found)


def literal_witnesses(constants: Iterable[Hashable]) -> tuple[str, ...]:
    """The literals themselves (the rest is one cell, :data:`FRESH`'s)."""
    return tuple(c for c in constants if isinstance(c, str))


LITERAL_CELLS: Final = Cells(literal_operands, literal_witnesses)
"""Cells of a function that compares the input's text with its literal operands only."""


def spellings(words: Iterable[str]) -> tuple[str, ...]:
    """Each word as people write it and as a case-insensitive, stripping test still reads
    it (``true``, ``True``, ``TRUE``, `` true ``): the texts a truth predicate tells apart,
    and that code the text is spliced into (Python's ``True``) may not."""
    found: list[str] = []
    for word in words:
        found += [word, word.capitalize(), word.upper(), f" {word} "]
    return tuple(dict.fromkeys(found))
