"""Exact weighted model counting on a CUDD BDD, in Python integers.

CUDD counts minterms in a ``double``: exact below 2^53 only, and past 2^1023 it
overflows (``dd`` then reports "out of memory"). Feature models pass both — Husky
has about 10^77 configurations — so counts are taken here, over the diagram's nodes
with Python's unbounded integers.

Weights let a count leave variables out of the diagram altogether: a variable
weighs ``(w_false, w_true)``, and an assignment weighs the product of its
variables' weights. The feature model counts its constrained variables this way
and folds each file's unconstrained args into the weight of the file's variable
(``features.Component``); a choice is a weight of ``(1, 0)`` or ``(0, 1)``.
"""

from __future__ import annotations

import sys
from collections.abc import Mapping

import dd.cudd as _cudd

from rosvar.interpreter.analysis import collector_paused
from rosvar.logic.conditions import BDD

Weight = tuple[int, int]  # (weight of false, weight of true)


class CountedDiagram:
    """A BDD counted exactly under some weights, then again under others.

    Each node ``u`` at level ``r`` gets ``D(u) = c(u) · P(r)``, where ``c(u)`` is its
    count over the weighted variables from ``r`` on and ``P(r)`` the total weight of
    those above: then an edge skipping levels needs no correction (``D(u) = (w₀·D(low)
    + w₁·D(high)) / (w₀ + w₁)``), a complemented edge is ``T − D`` (``T``: the total
    weight of all variables), and the count is ``D(root)``.

    The first count reads the nodes through ``dd``'s wrappers, which costs several
    times the arithmetic, and keeps them as plain lists with their values ``D``.
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


@collector_paused()  # its lists are young: the collector would rescan them as they grow
def _read(
    manager: _cudd.BDD, formula: BDD, weight_at: Mapping[int, Weight], total: int
) -> tuple[list[int], list[int], list[int], list[int], int]:
    """The nodes of ``formula``, children first after the constant TRUE (place 0): each
    one's level, low and high child (places; a complemented edge as ``~place``) and
    ``D``; and the root's place (complemented likewise).

    Nodes are told apart by ``int``, which for ``dd`` is the node's pointer plus 2; CUDD
    marks a complemented edge in the pointer's lowest bit, so ``int(~u) == int(u) ^ 1``
    (``tests/analyses/test_counting.py`` checks it) and a child's regular node needs no
    wrapper of its own. Recursive, since a stack kept by hand was half as fast (the depth
    is at most the number of variables).
    """
    true = int(manager.true)
    found = {true: 0}  # regular node → its place
    levels, lows, highs, values = [len(manager.vars)], [0], [0], [total]

    def visit(node: BDD, key: int) -> int:
        low, high = node.low, node.high  # CUDD's high edges are never complemented
        low_key, high_key = int(low), int(high)
        negated = low_key & 1
        if negated:
            low_key ^= 1
        low_place = found.get(low_key)
        if low_place is None:
            low_place = visit(low, low_key)
        high_place = found.get(high_key)
        if high_place is None:
            high_place = visit(high, high_key)
        level = node.level
        d_low = total - values[low_place] if negated else values[low_place]
        d_high = values[high_place]
        off, on = weight_at[level]  # as in ``_combine``, inlined: a call per node costs
        if off == on:
            values.append((d_low + d_high) >> 1)
        elif not off:
            values.append(d_high)
        elif not on:
            values.append(d_low)
        else:
            values.append((off * d_low + on * d_high) // (off + on))
        found[key] = place = len(levels)
        levels.append(level)
        lows.append(~low_place if negated else low_place)
        highs.append(high_place)
        return place

    key = int(formula)
    negated = key & 1
    root = found.get(key ^ negated)
    if root is None:
        limit = sys.getrecursionlimit()
        sys.setrecursionlimit(limit + len(weight_at))
        try:
            root = visit(formula, key ^ negated)
        finally:
            sys.setrecursionlimit(limit)
    return levels, lows, highs, values, ~root if negated else root
