"""Copying BDDs from one ``dd.cudd`` manager to another in time linear in their size.

The feature model's solver and the configuration engine have managers of their own (their
own variable orders) and copy many small formulas into them, some with variables the target
does not hold quantified out. ``dd.cudd.copy_bdd`` checks each support variable against
``target.vars``, a set it rebuilds from every declared variable on each access, and ``dd``'s
``exist`` builds a cube over every variable of the manager: both cost the managers' whole
variable counts per call, which made building the solver quadratic in the workspace (about
6 ms per copy, 41 s of the 68 s of 2,000 launch files). Here a copy visits each node of
the source BDD once, quantifying as it goes.
"""

from __future__ import annotations

from collections.abc import Collection

import dd.cudd as _cudd

from rosvar.logic.conditions import BDD, children_first, cofactors


def transfer(u: BDD, target: _cudd.BDD, hidden: Collection[str] = ()) -> BDD:
    """``∃ hidden. u`` rebuilt in ``target``, which declares the rest of its support.

    Functions are rebuilt before the functions above them, so a node on a ``hidden``
    variable becomes the disjunction of its cofactors' copies, which no longer depend on
    it. Quantification does not commute with negation, so a complemented edge is its own
    function here, with its own cofactors.
    """
    source = u.bdd
    copies: dict[BDD, BDD] = {source.true: target.true, source.false: target.false}
    for function in children_first(u, cofactors, copies):
        low, high = cofactors(function)
        name = function.var
        copies[function] = (
            copies[high] | copies[low]
            if name in hidden
            else target.ite(target.var(name), copies[high], copies[low])
        )
    return copies[u]
