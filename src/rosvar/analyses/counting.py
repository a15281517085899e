"""Exact weighted model counting on a CUDD BDD, in Python integers.

CUDD counts minterms in a ``double``: exact below 2^53 only, and past 2^1023 it
overflows (``dd`` then reports "out of memory"). Feature models pass both — Husky
has about 10^77 configurations — so counts are taken here, one pass over the
diagram with Python's unbounded integers.

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

from rosvar.logic.conditions import BDD

Weight = tuple[int, int]  # (weight of false, weight of true)


def weighted_count(manager: _cudd.BDD, formula: BDD, weights: Mapping[str, Weight]) -> int:
    """Σ over the assignments of ``weights``' variables satisfying ``formula`` of their weight.

    ``formula``'s support must lie within ``weights``. With every weight ``(1, 1)``
    this is the number of satisfying assignments.

    Each node ``u`` at position ``r`` (among the weighted variables, by level) gets
    ``D(u) = c(u) · P(r)``, where ``c(u)`` is its count over the variables from ``r``
    on and ``P(r)`` the total weight of those above: then an edge skipping levels
    needs no correction (``D(u) = (w₀·D(low) + w₁·D(high)) / (w₀ + w₁)``), a
    complemented edge is ``P(0) − D``, and the count is ``D(formula)``.
    """
    weight_at: dict[int, Weight] = {}
    total = 1
    for name, (off, on) in weights.items():
        weight_at[manager.level_of_var(name)] = (off, on)
        total *= off + on
    true, false = manager.true, manager.false
    if formula == false or total == 0:
        return 0
    # regular nodes by their pointer (hashing a ``Function`` calls back into ``dd``)
    values: dict[int, int] = {int(true): total}

    def d(node: BDD, key: int) -> int:
        """D of a regular node; recursive, since a loop keeping the stack by hand was
        half as fast (the depth is at most the number of variables)."""
        low, high = node.low, node.high  # CUDD's high edges are never complemented
        if low.negated:
            low = ~low
            low_key = int(low)
            found = values.get(low_key)
            d_low = total - (d(low, low_key) if found is None else found)
        else:
            low_key = int(low)
            found = values.get(low_key)
            d_low = d(low, low_key) if found is None else found
        high_key = int(high)
        found = values.get(high_key)
        d_high = d(high, high_key) if found is None else found
        off, on = weight_at[node.level]
        if off == on == 1:  # most variables: a shift, not a long division
            value = values[key] = (d_low + d_high) >> 1
        else:
            value = values[key] = (off * d_low + on * d_high) // (off + on)
        return value

    negated = formula.negated
    root = ~formula if negated else formula
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(limit + len(weights))
    try:
        found = values.get(int(root))
        value = d(root, int(root)) if found is None else found
    finally:
        sys.setrecursionlimit(limit)
    return total - value if negated else value
