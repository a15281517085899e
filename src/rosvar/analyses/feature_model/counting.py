"""Exact weighted model counting on a CUDD BDD, in Python integers.

CUDD counts minterms in a ``double``: exact below 2^53 only, and past 2^1023 it
overflows (``dd`` then reports "out of memory"). Feature models pass both — Husky
has about 10^77 configurations — so counts are taken here, over the diagram's nodes
with Python's unbounded integers.

Weights let a count leave variables out of the diagram altogether: a variable
weighs ``(w_false, w_true)``, and an assignment weighs the product of its
variables' weights. The feature model counts its constrained variables this way
and folds each file's unconstrained args into the weight of the file's variable
(``solver.Component``); a choice is a weight of ``(1, 0)`` or ``(0, 1)``.

A recount that touches many nodes runs level by level in numpy, modulo a few primes
below 2^31 (products stay within ``int64``), and the exact integer is put back
together by the Chinese remainder theorem: enough primes are taken for their product
to exceed a bound of the count, so the residues determine it.
"""

from __future__ import annotations

import ctypes
import os
import sys
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cache, cached_property
from typing import TYPE_CHECKING, TypeAlias

import dd.cudd as _cudd

from rosvar.interpreter.analysis import collector_paused
from rosvar.logic.conditions import BDD

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    Array: TypeAlias = npt.NDArray[np.int64]

Weight = tuple[int, int]  # (weight of false, weight of true)

VECTOR_FROM = 2_000
"""A recount over at least this many nodes runs in numpy; fewer are cheaper one by one."""


class CountedDiagram:
    """A BDD counted exactly under some weights, then again under others.

    Each node ``u`` at level ``r`` gets ``D(u) = c(u) · P(r)``, where ``c(u)`` is its
    count over the weighted variables from ``r`` on and ``P(r)`` the total weight of
    those above: then an edge skipping levels needs no correction (``D(u) = (w₀·D(low)
    + w₁·D(high)) / (w₀ + w₁)``), a complemented edge is ``T − D`` (``T``: the total
    weight of all variables), and the count is ``D(root)``.

    The first count reads the nodes in CUDD's memory (``_read``) and keeps them as
    plain lists with their values ``D``.
    ``D(u) / T`` depends only on the weights of ``u``'s level and those below, so a
    later count whose weights differ on some levels recomputes only the nodes down to
    the deepest of them and rescales the first count's values of the nodes below: the
    configuration engine counts this way after every click.
    """

    def __init__(self, manager: _cudd.BDD, formula: BDD, weights: Mapping[str, Weight]) -> None:
        """Count ``formula`` under ``weights``, which give every weighted variable's weight
        and must be positive (``formula``'s support lies within them)."""
        self._level_of = {name: manager.level_of_var(name) for name in weights}
        self._weights = _by_level(self._level_of, weights)
        self._total = _total(self._weights)
        if self._total == 0:
            raise ValueError("the first weights of a diagram must not be zero")
        self._levels, self._lows, self._highs, self._values, self._root = _read(
            manager, formula, self._weights, self._total
        )

    def __len__(self) -> int:
        """Nodes, the constant included."""
        return len(self._levels)

    @property
    def first(self) -> int:
        """The count under the weights the diagram was read with."""
        return self._value(self._values, self._total)

    def count(self, weights: Mapping[str, Weight]) -> int:
        """Σ over the assignments of the variables satisfying the formula of their weight
        (``weights`` gives every variable's; with all ``(1, 1)``, the number of models)."""
        weight_at = _by_level(self._level_of, weights)
        total = _total(weight_at)
        if total == 0:
            return 0
        changed = [level for level, weight in weight_at.items() if self._weights[level] != weight]
        if not changed:
            return self.first
        times = over = 1  # T / T of the first count: the weights differ on ``changed`` only
        for level in changed:
            times *= sum(weight_at[level])
            over *= sum(self._weights[level])
        deepest = max(changed)
        if self._above[deepest] >= VECTOR_FROM:
            dominated = all(
                off <= self._weights[level][0] and on <= self._weights[level][1]
                for level, (off, on) in weight_at.items()
            )  # then every assignment weighs at most as before: the first count bounds it
            found = self._residues.count(weight_at, total, self.first if dominated else total)
            if found is not None:
                return found
        old = self._values
        values = list(old)
        levels, lows, highs = self._levels, self._lows, self._highs
        for place in range(1, len(levels)):
            level = levels[place]
            if level > deepest:
                continue
            low, high = lows[place], highs[place]
            negated = low < 0
            if negated:
                low = ~low
            d_low = old[low] * times // over if levels[low] > deepest else values[low]
            if negated:
                d_low = total - d_low
            d_high = old[high] * times // over if levels[high] > deepest else values[high]
            values[place] = _combine(weight_at[level], d_low, d_high)
        root = ~self._root if self._root < 0 else self._root
        if levels[root] > deepest:
            return self._value(old, total, times, over)
        return self._value(values, total)

    def prepare(self) -> None:
        """Make ready now what the first recount over many nodes would build: numpy's
        import, the levels and the moduli (about 100 ms once per process, which a server
        counting after every click would otherwise charge to one click)."""
        if len(self) > VECTOR_FROM:
            _ = self._residues
            moduli()

    @cached_property
    def _above(self) -> dict[int, int]:
        """Per weighted level, the nodes at it or above: what a recount down to it visits."""
        at: dict[int, int] = dict.fromkeys(self._weights, 0)
        for level in self._levels[1:]:
            at[level] += 1
        above, running = {}, 0
        for level in sorted(at):
            running += at[level]
            above[level] = running
        return above

    @cached_property
    def _residues(self) -> _Residues:
        return _Residues.of(self._levels, self._lows, self._highs, self._root)

    def taken(self) -> dict[str, set[bool]]:
        """For each weighted variable, the values it takes in some assignment satisfying the
        formula: those of the edges from its nodes to anything but FALSE, and both where a
        path to TRUE skips its level. One pass over the lists."""
        if not self._level_of:
            return {}
        top = min(self._level_of.values())
        bottom = max(self._level_of.values()) + 1
        falses: set[int] = set()  # levels with an edge of that value to a satisfiable child
        trues: set[int] = set()
        free = [0] * (bottom - top + 1)  # difference array over the levels some edge skips
        levels, lows, highs = self._levels, self._lows, self._highs
        root = self._root
        if root == ~0:  # FALSE: nothing satisfies it
            return {name: set() for name in self._level_of}
        free[0] += 1  # the levels above the root are free
        free[(levels[root if root >= 0 else ~root] if root else bottom) - top] -= 1
        seen: set[int] = set()
        stack = [root]  # functions: a place, or ``~place`` for the negated node
        while stack:
            function = stack.pop()
            if function in seen or function == 0:
                continue
            seen.add(function)
            flipped = function < 0
            place = ~function if flipped else function
            here = levels[place]
            low, high = lows[place], highs[place]
            if flipped:
                low, high = ~low, ~high
            for taking, child in ((falses, low), (trues, high)):
                if child == ~0:  # FALSE
                    continue
                taking.add(here)
                free[here + 1 - top] += 1
                free[(levels[child if child >= 0 else ~child] if child else bottom) - top] -= 1
                stack.append(child)
        values: dict[int, set[bool]] = {}
        running = 0
        for level in range(top, bottom):
            running += free[level - top]
            values[level] = {False, True} if running > 0 else set()
            values[level].update(
                v for v, found in ((False, falses), (True, trues)) if level in found
            )
        return {name: values[level] for name, level in self._level_of.items()}

    def _value(self, values: list[int], total: int, times: int = 1, over: int = 1) -> int:
        root = self._root
        if root < 0:
            return total - values[~root] * times // over
        return values[root] * times // over


def _by_level(level_of: Mapping[str, int], weights: Mapping[str, Weight]) -> dict[int, Weight]:
    return {level_of[name]: weight for name, weight in weights.items()}


def _total(weights: Mapping[int, Weight]) -> int:
    total = 1
    for off, on in weights.values():
        total *= off + on
    return total


def _combine(weight: Weight, d_low: int, d_high: int) -> int:
    """``D`` of a node from its children's."""
    off, on = weight
    if off == on:  # most variables: a shift, not a long division
        return (d_low + d_high) >> 1
    if not off:
        return d_high
    if not on:
        return d_low
    return (off * d_low + on * d_high) // (off + on)


@cache
def _memory() -> memoryview:
    """The process's memory as 64-bit words, for reading CUDD's nodes where they lie.

    Only the words of live nodes are ever read (``_read``): the view maps no memory
    of its own, it only spares a ``ctypes`` call per read.
    """
    everything = (ctypes.c_uint64 * (sys.maxsize // 8)).from_address(0)
    return memoryview(everything).cast("B").cast("Q")


def _indices(manager: _cudd.BDD, weight_at: Mapping[int, Weight]) -> dict[int, int]:
    """CUDD's index of each weighted level's variable, read off its node ``x ? TRUE :
    FALSE``, which also checks the layout ``_read`` relies on: a CUDD node is its
    variable's index (32 bits, then the reference count's), the next node in its
    hash chain, then its ``then`` and ``else`` children (64-bit pointers)."""
    words = _memory()
    true = int(manager.true) - 2
    found = {}
    for level in weight_at:
        node = (int(manager.var(manager.var_at_level(level))) - 2) >> 3
        if (words[node + 2], words[node + 3]) != (true, true ^ 1):
            raise RuntimeError("dd's CUDD lays its nodes out otherwise than counting expects")
        found[words[node] & 0xFFFFFFFF] = level
    return found


@collector_paused()  # its lists are young: the collector would rescan them as they grow
def _read(
    manager: _cudd.BDD, formula: BDD, weight_at: Mapping[int, Weight], total: int
) -> tuple[list[int], list[int], list[int], list[int], int]:
    """The nodes of ``formula``, children first after the constant TRUE (place 0): each
    one's level, low and high child (places; a complemented edge as ``~place``) and
    ``D``; and the root's place (complemented likewise).

    The nodes are read in CUDD's memory (``_memory``, layout checked by ``_indices``),
    not through ``dd``'s wrappers: a wrapper per child (a Python object, a reference
    taken and dropped) made reading a node cost twice its arithmetic. Safe while
    ``formula`` is referenced, since nothing runs in CUDD meanwhile: its nodes can be
    neither freed nor moved. ``int`` of a ``dd`` function is its pointer plus 2, and
    CUDD marks a complemented edge in the pointer's lowest bit (``then`` edges never
    are).
    """
    weight_of = {
        index: (level, *weight_at[level]) for index, level in _indices(manager, weight_at).items()
    }
    reader = _Reader(weight_of, total, int(manager.true) - 2, len(manager.vars))
    pointer = int(formula) - 2
    negated = pointer & 1
    root = reader.found.get(pointer ^ negated)
    if root is None:
        limit = sys.getrecursionlimit()
        sys.setrecursionlimit(limit + len(weight_at))
        try:
            root = reader.visit(pointer ^ negated)
        finally:
            sys.setrecursionlimit(limit)
    return reader.levels, reader.lows, reader.highs, reader.values, ~root if negated else root


class _Reader:
    """``_read``'s lists as they grow. A class, not a closure over ``_read``'s locals:
    compiled (mypyc), a recursive closure keeps them in a cycle only the collector
    frees, the manager included."""

    __slots__ = ("found", "highs", "levels", "lows", "total", "values", "weight_of", "words")

    def __init__(
        self, weight_of: dict[int, tuple[int, int, int]], total: int, true: int, bottom: int
    ) -> None:
        self.words = _memory()
        self.weight_of = weight_of  # a variable's index → its level and weight
        self.total = total
        self.found = {true: 0}  # regular node's address → its place
        self.levels, self.lows, self.highs, self.values = [bottom], [0], [0], [total]

    def visit(self, node: int) -> int:
        """Place the node at address ``node`` after its children. Recursive, since a stack
        kept by hand was half as fast (the depth is at most the number of variables)."""
        words, found, values = self.words, self.found, self.values
        at = node >> 3
        low, high = words[at + 3], words[at + 2]
        negated = low & 1
        if negated:
            low ^= 1
        low_place = found.get(low)
        if low_place is None:
            low_place = self.visit(low)
        high_place = found.get(high)
        if high_place is None:
            high_place = self.visit(high)
        level, off, on = self.weight_of[words[at] & 0xFFFFFFFF]
        d_low = self.total - values[low_place] if negated else values[low_place]
        d_high = values[high_place]
        if off == on:  # as in ``_combine``, inlined: a call per node costs
            values.append((d_low + d_high) >> 1)
        elif not off:
            values.append(d_high)
        elif not on:
            values.append(d_low)
        else:
            values.append((off * d_low + on * d_high) // (off + on))
        found[node] = place = len(self.levels)
        self.levels.append(level)
        self.lows.append(~low_place if negated else low_place)
        self.highs.append(high_place)
        return place


def _primes(count: int) -> list[int]:
    """The ``count`` largest primes below 2^31 (Miller–Rabin with the bases 2, 7 and 61
    decides every number below 2^32)."""
    found: list[int] = []
    candidate = 2**31 - 1
    while len(found) < count:
        if _is_prime(candidate):
            found.append(candidate)
        candidate -= 2
    return found


def _is_prime(n: int) -> bool:
    odd, twos = n - 1, 0
    while not odd & 1:
        odd, twos = odd >> 1, twos + 1
    for base in (2, 7, 61):
        x = pow(base, odd, n)
        if x in (1, n - 1):
            continue
        for _ in range(twos - 1):
            x = x * x % n
            if x == n - 1:
                break
        else:
            return False
    return True


@cache
def moduli() -> list[int]:
    """Moduli of the vectorised recount, found on first use: 64 of them bound counts up
    to about 2^1980."""
    return _primes(64)


class _Level:
    """The nodes of one level: their places, and their children's (``negated``: the low
    edge is complemented; None: no low edge of the level is).

    Not a dataclass: a compiled dataclass needs its field types at run time, and numpy is
    only imported on first use."""

    __slots__ = ("highs", "level", "lows", "negated", "places")

    def __init__(
        self,
        level: int,
        places: Array,
        lows: Array,
        highs: Array,
        negated: npt.NDArray[np.bool_] | None,
    ) -> None:
        self.level = level
        self.places = places
        self.lows = lows
        self.highs = highs
        self.negated = negated


@dataclass(frozen=True)
class _Residues:
    """``CountedDiagram``'s nodes by level, deepest first, for counting modulo primes."""

    size: int
    levels: Sequence[_Level]
    root: int

    @classmethod
    def of(cls, levels: list[int], lows: list[int], highs: list[int], root: int) -> _Residues:
        """The levels of a diagram read by ``CountedDiagram``.

        numpy is imported here, on first need: it costs about 100 ms, which every rosvar
        command would otherwise pay at start-up. Only its element-wise integer operations
        are used, so its BLAS is kept from starting a worker thread per core.
        """
        os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
        import numpy as np

        level_of = np.asarray(levels, dtype=np.int64)
        low = np.asarray(lows, dtype=np.int64)
        negated = low < 0
        low = np.where(negated, ~low, low)
        high = np.asarray(highs, dtype=np.int64)
        order = np.argsort(-level_of[1:], kind="stable") + 1  # children before parents
        groups = np.split(order, np.flatnonzero(np.diff(level_of[order])) + 1)
        return cls(
            len(levels),
            [
                _Level(
                    int(level_of[places[0]]),
                    places,
                    low[places],
                    high[places],
                    negated[places] if negated[places].any() else None,
                )
                for places in groups
                if len(places)
            ],
            root,
        )

    def count(self, weight_at: Mapping[int, Weight], total: int, bound: int) -> int | None:
        """The count under ``weight_at`` (``total``: their total weight), known to be at
        most ``bound``; None when a level's total weight is a multiple of a modulus (its
        division has no inverse there) or the bound needs more moduli than there are."""
        import numpy as np  # imported by ``of``

        taken, product = [], 1
        for prime in moduli():
            if product > bound:
                break
            taken.append(prime)
            product *= prime
        if product <= bound:
            return None
        inverse: dict[int, list[int]] = {}  # total weight of a level → its inverses
        for off, on in set(weight_at.values()):
            if off and on and off != on:
                if any((off + on) % m == 0 for m in taken):
                    return None
                inverse[off + on] = [pow(off + on, -1, m) for m in taken]
        p = np.asarray(taken, dtype=np.int64)
        everything = np.asarray([total % m for m in taken], dtype=np.int64)
        values = np.empty((self.size, len(taken)), dtype=np.int64)
        values[0] = everything
        for level in self.levels:
            off, on = weight_at[level.level]
            d_low = values[level.lows]
            if level.negated is not None:
                flipped = everything - d_low
                d_low = np.where(level.negated[:, None], flipped + (flipped < 0) * p, d_low)
            d_high = values[level.highs]
            if off == on:  # (d_low + d_high) / 2 modulo odd primes: add p to make it even
                both = d_low + d_high
                both = (both + (both & 1) * p) >> 1
                values[level.places] = both - (both >= p) * p
            elif not off:
                values[level.places] = d_high
            elif not on:
                values[level.places] = d_low
            else:
                weights = np.asarray([[off % m, on % m] for m in taken], dtype=np.int64)
                mixed = (weights[:, 0] * d_low % p + weights[:, 1] * d_high % p) % p
                values[level.places] = mixed * np.asarray(inverse[off + on], dtype=np.int64) % p
        root = self.root
        residues = values[~root if root < 0 else root]
        if root < 0:
            residues = (everything - residues) % p
        return _restored(residues.tolist(), taken, product)


def _restored(residues: list[int], primes: list[int], product: int) -> int:
    """The number below ``product`` with these residues (Chinese remainder theorem)."""
    found = 0
    for residue, modulus in zip(residues, primes, strict=True):
        rest = product // modulus
        found += residue * rest * pow(rest, -1, modulus)
    return found % product
