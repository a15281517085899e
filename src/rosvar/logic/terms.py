"""Terms: string values that analysis cannot compute yet.

A term is a pure expression over inputs whose slot is ``OTHER`` (or environment
variables analysis knows nothing about). It is kept symbolic and evaluated only
when a concrete configuration supplies the missing strings (HAROS-style
*unknown* values, but lazy instead of lost).
"""

from __future__ import annotations

import weakref
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, TypeVar, cast

from rosvar.logic.inputs import Input

if TYPE_CHECKING:
    from rosvar.workspace import Workspace


class TermError(Exception):
    """Evaluating a term failed the way roslaunch would fail at that point (``code``: the
    diagnostic a resolution reports it with)."""

    def __init__(self, message: str, code: str = "value-unknown") -> None:
        super().__init__(message)
        self.code = code


class Hole:
    """The concrete string of an input (known only once a configuration is given).

    Immutable (never assign to a term's attributes) and hash-consed as :class:`Apply`:
    ``Hole(input)`` of an input that has a hole alive is that hole.
    """

    __slots__ = ("__weakref__", "_hash", "input")

    input: Input
    _hash: int

    def __new__(cls, input: Input) -> Hole:
        known = _known(input)
        if known is not None:
            return cast("Hole", known)
        self = object.__new__(cls)
        self.input = input
        self._hash = hash(input)
        _intern(input, self)
        return self

    def __reduce__(self) -> tuple[type[Hole], tuple[Input]]:
        return Hole, (self.input,)  # unpickled through the table

    def __eq__(self, other: object) -> bool:
        return other is self or (other.__class__ is Hole and self.input == other.input)

    def __hash__(self) -> int:
        return self._hash

    def __repr__(self) -> str:
        return f"Hole(input={self.input!r})"

    def __str__(self) -> str:
        return f"⟨{self.input}⟩"


class Apply:
    """``function(*operands)`` where some operand is a term.

    ``function`` names an entry of :data:`FUNCTIONS`; ``display`` is how people see it.
    Immutable, with slots, and hash-consed: ``Apply(...)`` of a function, operands and
    display that a term alive already has is that term (:func:`_intern`), so that terms
    built again in every includer's walk are one object, a dictionary finds them by
    identity instead of comparing them level by level, and what a term caches (its hash,
    its text, its :func:`measure`) is computed once. Equality stays structural where two
    equal terms are apart (a term unpickled, a subclass). The text is made on first use:
    the ``analyze`` JSON shows the same terms in every file that includes theirs.
    """

    __slots__ = ("__weakref__", "_hash", "_measure", "_text", "display", "function", "operands")

    function: str
    operands: tuple[Operand, ...]
    display: str
    _hash: int
    _text: str | None
    _measure: tuple[int, int] | None

    def __new__(cls, function: str, operands: tuple[Operand, ...], display: str = "") -> Apply:
        key = (function, operands, display)
        known = _known(key)
        if known is not None:
            return cast("Apply", known)
        self = cls._made(function, operands, display)
        _intern(key, self)
        return self

    @classmethod
    def _made(cls, function: str, operands: tuple[Operand, ...], display: str) -> Apply:
        """A new term, not looked up (a subclass whose terms are equal only to themselves)."""
        self = object.__new__(cls)
        self.function = function
        self.operands = operands
        self.display = display
        self._hash = hash((function, operands, display))
        self._text = None
        self._measure = None
        return self

    def __reduce__(self) -> tuple[type[Apply], tuple[str, tuple[Operand, ...], str]]:
        return Apply, (self.function, self.operands, self.display)  # through the table

    def __eq__(self, other: object) -> bool:
        return other is self or (
            other.__class__ is Apply
            and self._hash == other._hash
            and self.function == other.function
            and self.operands == other.operands
            and self.display == other.display
        )

    def __hash__(self) -> int:
        return self._hash

    def __repr__(self) -> str:
        return (
            f"Apply(function={self.function!r}, operands={self.operands!r}, "
            f"display={self.display!r})"
        )

    def __str__(self) -> str:
        if self._text is None:
            self._text = self._shown()
        return self._text

    def evaluated(self, inputs: Mapping[Input, str], host: object) -> str:
        """The function applied to the operands' strings (a kind of term that computes
        otherwise overrides it: :class:`~rosvar.logic.given_up.GivenUp`)."""
        operands = [o if isinstance(o, tuple) else evaluate(o, inputs, host) for o in self.operands]
        try:
            function = FUNCTIONS[self.function]
        except KeyError:
            raise TermError(f"unknown term function {self.function}") from None
        return function(host, *operands)

    def _shown(self) -> str:
        if self.display:
            return self.display
        shown = [o if isinstance(o, str | tuple) else str(o) for o in self.operands]
        try:  # string functions applied to the operands' display show the shape of the result
            return FUNCTIONS[self.function](None, *shown)
        except Exception:
            return f"{self.function}({', '.join(str(o) for o in self.operands)})"


Term = Hole | Apply
Operand = str | Term | tuple[str, ...]
Made = TypeVar("Made", bound=Hole | Apply)

_INTERNED: dict[object, weakref.KeyedRef[object, Hole | Apply]] = {}
"""Every term alive, by what makes it (an input; a function, operands and display): weak,
so a term no value holds any more is freed as before and leaves the table."""


def _known(key: object) -> Hole | Apply | None:
    ref = _INTERNED.get(key)
    return None if ref is None else ref()


def _intern(key: object, term: Hole | Apply) -> None:
    _INTERNED[key] = weakref.KeyedRef(term, _forget, key)


def shared(key: tuple[object, ...], make: Callable[[], Made]) -> Made:
    """The term alive that ``key`` made, else ``make()``'s, entered under ``key``: for a
    kind of term hash-consed by a key of its own (whose first item is its class, so that
    it meets no other kind's key)."""
    known = _known(key)
    if known is not None:
        return cast("Made", known)
    term = make()
    _intern(key, term)
    return term


def _forget(ref: weakref.KeyedRef[object, Hole | Apply]) -> None:
    """A term was freed: its entry goes, unless the key was made again since."""
    if _INTERNED.get(ref.key) is ref:
        del _INTERNED[ref.key]


def measure(term: Term) -> tuple[int, int]:
    """The characters and nesting of ``term``'s text (shared operands counted each time, as
    showing or evaluating it would), computed once per term."""
    if isinstance(term, Hole):
        return len(str(term)), 0
    if term._measure is None:
        term._measure = measure_parts(term.operands)
    return term._measure


def measure_parts(parts: Iterable[object]) -> tuple[int, int]:
    """Characters and nesting of a concatenation of ``parts`` (tuples are not text)."""
    size, depth = 0, 0
    for part in parts:
        if isinstance(part, str):
            size += len(part)
        elif isinstance(part, Hole | Apply):
            part_size, part_depth = measure(part)
            size += part_size
            depth = max(depth, part_depth + 1)
    return size, depth


TermFunction = Callable[..., str]
FUNCTIONS: dict[str, TermFunction] = {"concat": lambda _host, *parts: "".join(parts)}


@dataclass(frozen=True)
class PackageTable:
    """Package name → path: the host a term's functions get outside an interpretation (a
    dialect's ``$(find)`` terms read it); ``workspace``, where the host has it, for what
    else a term reads (an install prefix, a file through the workspace's gate)."""

    paths: dict[str, str]
    workspace: Workspace | None = field(default=None, kw_only=True)


def register(name: str, function: TermFunction) -> None:
    """Make ``function(host, *operands)`` available to :class:`Apply` terms.

    ``host`` is whatever the evaluating analysis passes (e.g. the workspace for
    ``$(find)``); a registry keeps this module free of roslaunch knowledge.
    """
    FUNCTIONS[name] = function


def is_term(value: object) -> bool:
    return isinstance(value, Hole | Apply)


def term_inputs(value: Operand) -> set[Input]:
    """The inputs whose strings ``value`` needs before it can be evaluated."""
    if isinstance(value, Hole):
        return {value.input}
    if isinstance(value, Apply):
        found: set[Input] = set()
        for operand in value.operands:
            if not isinstance(operand, str | tuple):
                found |= term_inputs(operand)
        return found
    return set()


def concat(parts: list[str | Term]) -> str | Term:
    """Join strings; stays a string unless a part is a term."""
    merged: list[str | Term] = []
    for part in parts:
        if isinstance(part, str):
            if not part:
                continue
            if merged and isinstance(merged[-1], str):
                merged[-1] = merged[-1] + part
                continue
        merged.append(part)
    if not merged:
        return ""
    if len(merged) == 1:
        return merged[0]
    return Apply("concat", tuple(merged))


def evaluate(value: Operand, inputs: Mapping[Input, str], host: object = None) -> str:
    """The concrete string of ``value`` once every input has a concrete string."""
    if isinstance(value, str):
        return value
    if isinstance(value, tuple):
        raise TermError("a tuple is not a string value")
    if isinstance(value, Hole):
        try:
            return inputs[value.input]
        except KeyError:
            raise TermError(f"no value for {value.input}") from None
    return value.evaluated(inputs, host)
