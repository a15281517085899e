"""Exact weighted model counting on a CUDD BDD, in Python integers.

CUDD counts minterms in a ``double``: exact below 2^53 only, and past 2^1023 it
overflows (``dd`` then reports "out of memory"). Feature models of real systems pass
both, so counts are taken here, over the diagram's nodes
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

from array import array
from collections import Counter
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass
from functools import cache, cached_property
from itertools import compress
from typing import TYPE_CHECKING, TypeAlias

from rosvar.interpreter.workspace_models import collector_paused
from rosvar.logic.bdd import BDD, Manager, Weight, read, taken, without_blas_threads

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt

    Array: TypeAlias = npt.NDArray[np.int64]
    Bools: TypeAlias = npt.NDArray[np.bool_]

VECTOR_FROM = 2_000
"""A recount over at least this many nodes runs in numpy; fewer are cheaper one by one."""


class CountedDiagram:
    """A BDD counted exactly under some weights, then again under others.

    Each node ``u`` at level ``r`` gets ``D(u) = c(u) · P(r)``, where ``c(u)`` is its
    count over the weighted variables from ``r`` on and ``P(r)`` the total weight of
    those above: then an edge skipping levels needs no correction (``D(u) = (w₀·D(low)
    + w₁·D(high)) / (w₀ + w₁)``), a complemented edge is ``T − D`` (``T``: the total
    weight of all variables), and the count is ``D(root)``.

    The nodes are read out of CUDD's memory (``bdd.read``) once, as plain lists (a large
    diagram by numpy, which also gives them as arrays: counted and gone down by levels).
    ``D(u) / T`` depends only on the weights of ``u``'s level and those below, so a
    later count whose weights differ on some levels recomputes only the nodes down to
    the deepest of them and rescales the first count's values of the nodes below: the
    configuration engine counts this way after every click. Only a recount of fewer than
    ``VECTOR_FROM`` nodes is done so, the others run in numpy (``_Residues``); so only the
    first values of the nodes such a recount visits, and of their children, are kept: the
    others, most of a large diagram's and each as long as the total weight, are let go as
    soon as their parents have been counted.
    """

    def __init__(self, manager: Manager, formula: BDD, weights: Mapping[str, Weight]) -> None:
        """Count ``formula`` under ``weights``, which give every weighted variable's weight
        and must be positive (``formula``'s support lies within them)."""
        self._level_of = {name: manager.level_of_var(name) for name in weights}
        self._weights = _by_level(self._level_of, weights)
        self._total = _total(self._weights)
        if self._total == 0:
            raise ValueError("the first weights of a diagram must not be zero")
        self._levels: Sequence[int]
        self._lows: Sequence[int]
        self._highs: Sequence[int]
        with collector_paused():  # its lists are young: the collector would rescan them
            self._levels, self._lows, self._highs, self._root, self._arrays = read(
                manager, formula, self._weights
            )
            above = self._above
            self._kept_down_to = max(
                (level for level in above if above[level] < VECTOR_FROM), default=-1
            )
            self._top = list(  # children before parents, as all places (TRUE's level is last)
                compress(range(len(self._levels)), map(self._kept_down_to.__ge__, self._levels))
            )
            kept = {self._root if self._root >= 0 else ~self._root, *self._top}
            for place in self._top:
                low = self._lows[place]
                kept.update((~low if low < 0 else low, self._highs[place]))
            self._values = _evaluated(
                self._levels,
                self._lows,
                self._highs,
                self._weights,
                self._total,
                kept,
                self._arrays,
            )
            # kept for recounts, compact: a server holds them all its life, and a list of
            # 200,000 places holds 7 MB where an array holds 1.6 (Husky + ``_external``)
            self._levels, self._lows, self._highs = (
                array("q", self._levels),
                array("q", self._lows),
                array("q", self._highs),
            )
        self.first = self._value(self._values, self._total)  # under the weights read with

    def __len__(self) -> int:
        """Nodes, the constant included."""
        return len(self._levels)

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
        deepest = max(changed)
        if self._above[deepest] >= VECTOR_FROM:
            dominated = all(
                off <= self._weights[level][0] and on <= self._weights[level][1]
                for level, (off, on) in weight_at.items()
            )  # then every assignment weighs at most as before: the first count bounds it
            found = self._residues.count(weight_at, total, self.first if dominated else total)
            if found is not None:
                return found
        if deepest > self._kept_down_to:  # the values below were let go: count them anew
            root = self._root if self._root >= 0 else ~self._root
            values = _evaluated(
                self._levels, self._lows, self._highs, weight_at, total, {root}, self._arrays
            )
            return self._value(values, total)
        times = over = 1  # T / T of the first count: the weights differ on ``changed`` only
        for level in changed:
            times *= sum(weight_at[level])
            over *= sum(self._weights[level])
        old = self._values
        values = {}
        levels, lows, highs = self._levels, self._lows, self._highs
        for place in self._top:
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
            values[place] = combine(weight_at[level], d_low, d_high)
        root = ~self._root if self._root < 0 else self._root
        if levels[root] > deepest:
            return self._value(old, total, times, over)
        return self._value(values, total)

    def prepare(self) -> None:
        """Make ready now what the first recount over many nodes would build: numpy's
        import, the levels and the moduli (once per process, which a server counting after
        every click would otherwise charge to one click)."""
        if len(self) > VECTOR_FROM:
            _ = self._residues
            moduli()

    @cached_property
    def _above(self) -> dict[int, int]:
        """Per weighted level, the nodes at it or above: what a recount down to it visits."""
        at = Counter(self._levels)
        above, running = {}, 0
        for level in sorted(self._weights):
            running += at[level]
            above[level] = running
        return above

    @cached_property
    def _residues(self) -> _Residues:
        levels, lows, highs = self._arrays or (self._levels, self._lows, self._highs)
        return _Residues.of(levels, lows, highs, self._root)

    def taken(self) -> dict[str, set[bool]]:
        """For each weighted variable, the values it takes in some assignment satisfying the
        formula (``bdd.taken``)."""
        return taken(
            self._levels, self._lows, self._highs, self._root, self._level_of, self._arrays
        )

    def _value(self, values: Mapping[int, int], total: int, times: int = 1, over: int = 1) -> int:
        root = self._root
        if root < 0:
            return total - values[~root] * times // over
        return values[root] * times // over


def combine(weight: Weight, d_low: int, d_high: int) -> int:
    """``D`` of a node at a level of ``weight`` from its children's."""
    off, on = weight
    if off == on:  # most variables: a shift, not a long division
        return (d_low + d_high) >> 1
    if not off:
        return d_high
    if not on:
        return d_low
    return (off * d_low + on * d_high) // (off + on)


def _evaluated(
    levels: Sequence[int],
    lows: Sequence[int],
    highs: Sequence[int],
    weight_at: Mapping[int, Weight],
    total: int,
    kept: Collection[int],
    arrays: tuple[Array, Array, Array] | None = None,
) -> dict[int, int]:
    """The values ``D`` under ``weight_at`` (``total``: their total weight) of the places
    ``kept``. Each other value is dropped once its last parent has been counted: live at
    once are only those of the nodes whose parents are partly counted. A diagram numpy
    read (``arrays``, as ``read`` gives them; a level after the other) is counted a level
    at a time (``_evaluated_by_levels``)."""
    if arrays is not None:
        return _evaluated_by_levels(levels, lows, highs, arrays, weight_at, total, kept)
    size = len(levels)
    last = array("q", bytes(8 * size))  # a place → its last parent's place
    for place in range(1, size):
        low = lows[place]
        last[~low if low < 0 else low] = place
        last[highs[place]] = place
    for place in kept:
        last[place] = size  # never dropped
    values = [0] * size  # a dropped value is 0 again
    values[0] = total
    for place in range(1, size):
        low, high = lows[place], highs[place]
        negated = low < 0
        if negated:
            low = ~low
        d_low, d_high = values[low], values[high]
        off, on = weight_at[levels[place]]
        if negated:
            d_low = total - d_low
        if off == on:  # as in ``combine``, inlined: a call per node costs
            values[place] = (d_low + d_high) >> 1
        elif not off:
            values[place] = d_high
        elif not on:
            values[place] = d_low
        else:
            values[place] = (off * d_low + on * d_high) // (off + on)
        if last[low] == place:
            values[low] = 0
        if last[high] == place:
            values[high] = 0
    return {place: values[place] for place in kept}


def _evaluated_by_levels(
    levels: Sequence[int],
    lows: Sequence[int],
    highs: Sequence[int],
    arrays: tuple[Array, Array, Array],
    weight_at: Mapping[int, Weight],
    total: int,
    kept: Collection[int],
) -> dict[int, int]:
    """``_evaluated`` a run of places at one level at a time: the arithmetic of a run in
    one comprehension, with the run's weight, and the values whose last parent is in the
    run dropped after it. No node of a run is a child of another, so any order of the
    places with children first is counted right; runs are long in ``read``'s order of a
    large diagram."""
    import numpy as np  # imported by ``read``, which gave ``arrays``

    size = len(levels)
    level_at, low_at, high_at = arrays
    runs = (np.flatnonzero(level_at[2:] != level_at[1:-1]) + 2).tolist()
    places = np.arange(size, dtype=np.int64)
    last = np.zeros(size, dtype=np.int64)  # a place → its last parent's place
    np.maximum.at(last, np.where(low_at < 0, ~low_at, low_at), places)
    np.maximum.at(last, high_at, places)
    last[np.fromiter(kept, dtype=np.int64, count=len(kept))] = size  # never dropped
    last[0] = size
    dropped = np.argsort(last, kind="stable")  # places by their last parent
    ends = [*runs, size] if size > 1 else []  # a constant has no run
    drops = np.searchsorted(last[dropped], ends).tolist()
    values = [0] * size  # a dropped value is 0 again
    values[0] = top = total
    start, done = 1, 0
    for end, drop in zip(ends, drops, strict=True):
        off, on = weight_at[levels[start]]
        run_lows, run_highs = lows[start:end], highs[start:end]
        if off == on:  # as in ``combine``
            values[start:end] = [
                (top - values[~low] if low < 0 else values[low]) + values[high] >> 1
                for low, high in zip(run_lows, run_highs, strict=True)
            ]
        elif not off:
            values[start:end] = [values[high] for high in run_highs]
        elif not on:
            values[start:end] = [top - values[~low] if low < 0 else values[low] for low in run_lows]
        else:
            values[start:end] = [
                (off * (top - values[~low] if low < 0 else values[low]) + on * values[high])
                // (off + on)
                for low, high in zip(run_lows, run_highs, strict=True)
            ]
        for place in dropped[done:drop].tolist():
            values[place] = 0
        start, done = end, drop
    return {place: values[place] for place in kept}


def _by_level(level_of: Mapping[str, int], weights: Mapping[str, Weight]) -> dict[int, Weight]:
    return {level_of[name]: weight for name, weight in weights.items()}


def _total(weights: Mapping[int, Weight]) -> int:
    total = 1
    for off, on in weights.values():
        total *= off + on
    return total


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
    """The nodes of one level, places ``start`` to ``end`` of ``_Residues``' numbering:
    their children's places (``children``: the low ones, then the high ones) and
    ``negated``, a column true where the low edge is complemented (None: no low edge of
    the level is).

    Not a dataclass: its field types name numpy's, and numpy is only imported on first
    use."""

    __slots__ = ("children", "end", "level", "negated", "start")

    def __init__(
        self, level: int, start: int, end: int, children: Array, negated: Bools | None
    ) -> None:
        self.level = level
        self.start = start
        self.end = end
        self.children = children
        self.negated = negated


@dataclass(frozen=True)
class _Residues:
    """``CountedDiagram``'s nodes by level, deepest first, for counting modulo primes.

    The nodes are numbered anew, a level's contiguous and after its children's: a recount
    runs a few numpy calls per level (its 400 levels, not its 49,000 nodes, set the time of
    a click's count on Husky), the children's values gathered at once and the level's
    written in place: a weighted sum of them times the inverse of the level's total weight,
    each residue kept in ``[0, p)`` and every intermediate below 2^63."""

    size: int
    levels: Sequence[_Level]
    root: int

    @classmethod
    def of(
        cls,
        levels: Sequence[int] | Array,
        lows: Sequence[int] | Array,
        highs: Sequence[int] | Array,
        root: int,
    ) -> _Residues:
        """The levels of a diagram read by ``CountedDiagram`` (numpy imported on first need,
        ``bdd.without_blas_threads``)."""
        without_blas_threads()
        import numpy as np

        level_of = np.asarray(levels, dtype=np.int64)
        low = np.asarray(lows, dtype=np.int64)
        negated = low < 0
        low = np.where(negated, ~low, low)
        high = np.asarray(highs, dtype=np.int64)
        order = np.argsort(-level_of[1:], kind="stable") + 1  # children before parents
        place = np.zeros(len(level_of), dtype=np.int64)  # the old place → the new
        place[order] = np.arange(1, len(level_of))
        ends = [*(np.flatnonzero(np.diff(level_of[order])) + 2).tolist(), len(level_of)]
        runs = []
        for start, end in zip([1, *ends], ends, strict=False):
            if start == end:  # a constant has no level
                continue
            old = order[start - 1 : end - 1]
            flipped = negated[old]
            runs.append(
                _Level(
                    int(level_of[old[0]]),
                    start,
                    end,
                    np.concatenate((place[low[old]], place[high[old]])),
                    flipped[:, None] if flipped.any() else None,
                )
            )
        found = int(place[~root if root < 0 else root])
        return cls(len(levels), runs, ~found if root < 0 else found)

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
        factors: dict[Weight, tuple[Array, Array, Array]] = {}  # off, on, 1 / their sum
        for off, on in set(weight_at.values()):
            if off and on:
                if off != on and any((off + on) % m == 0 for m in taken):
                    return None
                divisor = 2 if off == on else off + on  # (d_low + d_high) / 2 if equal
                factors[off, on] = (
                    np.asarray([off % m for m in taken], dtype=np.int64),
                    np.asarray([on % m for m in taken], dtype=np.int64),
                    np.asarray([pow(divisor, -1, m) for m in taken], dtype=np.int64),
                )
        p = np.asarray(taken, dtype=np.int64)
        everything = np.asarray([total % m for m in taken], dtype=np.int64)
        # residues below 2^31 are kept in half the memory, widened level by level to compute
        values = np.empty((self.size, len(taken)), dtype=np.int32)
        values[0] = everything
        for level in self.levels:
            off, on = weight_at[level.level]
            out = values[level.start : level.end]
            found = values.take(level.children, axis=0)
            d_low, d_high = found[: len(out)], found[len(out) :]  # d_low in [0, p)
            if not off:
                out[:] = d_high
                continue
            if level.negated is not None:  # everything − d_low: in (−p, p)
                d_low = np.where(level.negated, everything - d_low, d_low)
            if not on:
                np.remainder(d_low, p, out=out)
                continue
            weight_off, weight_on, inverse = factors[off, on]
            if off == on:  # (d_low + d_high) / 2: below 2p · 2^31
                mixed = np.add(d_low, d_high, dtype=np.int64)
            else:  # each product below 2^62, their sum's remainder times the inverse too
                mixed = weight_off * d_low + weight_on * d_high
                mixed %= p
            mixed *= inverse
            np.remainder(mixed, p, out=out)
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
