"""Copying BDDs between managers: the same functions as ``dd``'s own (slow) copy and ``exist``.

Random formulas, random complemented roots and random quantified sets, copied into a manager
with another variable order and many more variables; the result must equal what
``dd.cudd.copy_bdd`` of ``exist`` gives.
"""

from __future__ import annotations

import random

import dd.cudd
import pytest

from rosvar.logic.bdd import transfer

NAMES = [f"x{number}" for number in range(12)]
OPERATORS = ("and", "or", "xor")


def random_formula(manager: dd.cudd.BDD, rng: random.Random) -> dd.cudd.Function:
    formula = manager.true if rng.random() < 0.5 else manager.false
    for _ in range(rng.randint(0, 10)):
        left, right = (manager.var(rng.choice(NAMES)) for _ in range(2))
        if rng.random() < 0.5:
            left = ~left
        term = manager.apply(rng.choice(OPERATORS), left, right)
        formula = manager.apply(rng.choice(OPERATORS), formula, term)
    return ~formula if rng.random() < 0.3 else formula


@pytest.mark.parametrize("seed", range(100))
def test_copies_and_quantifies_as_dd_does(seed: int) -> None:
    rng = random.Random(seed)
    source, target = dd.cudd.BDD(), dd.cudd.BDD()
    source.declare(*NAMES)
    target.declare(*[f"pad{number}" for number in range(50)], *reversed(NAMES))
    formula = random_formula(source, rng)
    hidden = set(rng.sample(NAMES, rng.randint(0, 4)))
    expected = dd.cudd.copy_bdd(source.exist(hidden, formula) if hidden else formula, target)
    assert transfer(formula, target, hidden) == expected


def test_constants() -> None:
    source, target = dd.cudd.BDD(), dd.cudd.BDD()
    assert transfer(source.true, target) == target.true
    assert transfer(source.false, target) == target.false
