"""Exact weighted model counting, against enumeration and closed forms."""

from __future__ import annotations

import itertools
import random

import dd.cudd
import pytest

from rosvar.analyses.counting import Weight, weighted_count
from rosvar.logic.conditions import BDD


def enumerated(manager: dd.cudd.BDD, formula: BDD, weights: dict[str, Weight]) -> int:
    """The weighted count by listing every assignment of ``weights``' variables."""
    names = sorted(weights)
    total = 0
    for bits in itertools.product((False, True), repeat=len(names)):
        assignment = dict(zip(names, bits, strict=True))
        if manager.let(assignment, formula) == manager.true:
            weight = 1
            for name, bit in assignment.items():
                weight *= weights[name][bit]
            total += weight
    return total


def random_formula(manager: dd.cudd.BDD, rng: random.Random, names: list[str]) -> BDD:
    """A conjunction of random clauses (their negations too, for complemented edges)."""
    formula = manager.true
    for _ in range(rng.randint(0, 6)):
        clause = manager.false
        for name in rng.sample(names, rng.randint(1, 3)):
            literal = manager.var(name)
            clause |= literal if rng.random() < 0.5 else ~literal
        formula &= clause if rng.random() < 0.7 else ~clause
    return formula


@pytest.mark.parametrize("seed", range(40))
def test_weighted_count_equals_enumeration(seed: int) -> None:
    rng = random.Random(seed)
    manager = dd.cudd.BDD()
    names = [f"x{i}" for i in range(7)]
    manager.declare(*names)
    formula = random_formula(manager, rng, names[:5])  # x5, x6: counted, never mentioned
    weights = {name: (rng.randint(0, 3), rng.randint(0, 4)) for name in names}
    assert weighted_count(manager, formula, weights) == enumerated(manager, formula, weights)
    ones = dict.fromkeys(names, (1, 1))
    assert weighted_count(manager, formula, ones) == int(manager.count(formula, nvars=7))


def test_counts_beyond_a_double_are_exact() -> None:
    """3^40 ways minus those with x0 and x1 both off: not representable in a double."""
    manager = dd.cudd.BDD()
    names = [f"x{i}" for i in range(40)]
    manager.declare(*names)
    formula = manager.var("x0") | manager.var("x1")
    exact = 3**40 - 3**38
    assert int(float(exact)) != exact
    assert weighted_count(manager, formula, dict.fromkeys(names, (1, 2))) == exact


def test_constants_and_zero_weights() -> None:
    manager = dd.cudd.BDD()
    manager.declare("a", "b")
    weights = {"a": (2, 3), "b": (1, 4)}
    assert weighted_count(manager, manager.true, weights) == 5 * 5
    assert weighted_count(manager, manager.false, weights) == 0
    assert weighted_count(manager, ~manager.var("a"), weights) == 2 * 5
    assert weighted_count(manager, manager.var("a"), {"a": (0, 0), "b": (1, 1)}) == 0
