"""A condition space of a few args and an environment variable, and random conditions over it,
shared by the tests of conditions and of their readable form."""

from __future__ import annotations

import random
from collections.abc import Mapping

from rosvar.logic.atoms import register_predicate
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, EnvInput, Input, Slot

F = "/ws/pkg/launch/main.launch"
TELEOP = ArgInput(F, "use_teleop")
SIM = ArgInput(F, "sim")
MODEL = ArgInput(F, "model")
WORLD = ArgInput(F, "world")
HOME = EnvInput("ROBOT_HOME")

DOMAINS: dict[Input, tuple[Slot, ...]] = {
    TELEOP: ("true", "false", OTHER),
    SIM: ("false", "true", OTHER),
    MODEL: ("a", "b", "c", UNSET, OTHER),
    WORLD: ("empty", OTHER),
    HOME: ("/home/r", UNSET, OTHER),
}

register_predicate("test_nonempty", lambda text: text != "", "{} is set")


def make_space(domains: Mapping[Input, tuple[Slot, ...]] = DOMAINS) -> ConditionSpace:
    space = ConditionSpace()
    for input_, domain in domains.items():
        space.declare_input(input_, domain)
    return space


def count(space: ConditionSpace, u: BDD) -> int:
    return int(space.bdd.count(space.valid & u, len(space.bdd.vars)))


def random_condition(space: ConditionSpace, rng: random.Random) -> BDD:
    inputs = list(DOMAINS)
    result = space.false
    for _ in range(rng.randint(1, 3)):
        cube = space.true
        for input_ in rng.sample(inputs, rng.randint(1, 3)):
            domain = DOMAINS[input_]
            chosen = rng.sample(domain, rng.randint(1, len(domain) - 1))
            union = space.false
            for slot in chosen:
                union |= space.slot(input_, slot)
            cube &= union if rng.random() < 0.8 else ~union
        result |= cube
    return ~result if rng.random() < 0.2 else result
