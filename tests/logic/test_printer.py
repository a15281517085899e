"""Presence conditions in readable form (``logic/printer.py``).

The readable form is checked two ways: a few exact strings people will read (``use_teleop ∧
¬sim``, ``model∈{a, b}``, ``x≠a``), and a round trip over randomly generated conditions: the
description is parsed back into a BDD and must mean the same as the condition (modulo the
valid configurations, and with ``known_only`` modulo the ``<other>`` slots of args).
"""

from __future__ import annotations

import random
import re

from logic.spaces import (
    DOMAINS,
    HOME,
    MODEL,
    SIM,
    TELEOP,
    WORLD,
    F,
    make_space,
    random_condition,
)
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, Input
from rosvar.logic.terms import Hole


# -- readable descriptions ----------------------------------------------------------------------
def test_describe_booleans_as_literals() -> None:
    space = make_space()
    teleop, no_sim = space.slot(TELEOP, "true"), space.slot(SIM, "false")
    # conjuncts are ordered by input name
    assert space.describe(teleop & no_sim) == "¬sim ∧ use_teleop"
    assert space.describe(teleop) == "use_teleop"
    assert space.describe(space.slot(TELEOP, "false")) == "¬use_teleop"
    assert space.describe(teleop | space.slot(SIM, "true")) == "sim ∨ use_teleop"
    assert space.describe(teleop & ~space.slot(TELEOP, "false")) == "use_teleop"


def test_describe_sets_and_exclusions() -> None:
    space = make_space()
    a, b = space.slot(MODEL, "a"), space.slot(MODEL, "b")
    assert space.describe(a | b) == "model∈{a, b}"
    assert space.describe(~a) == "model≠a"
    assert space.describe(space.slot(MODEL, UNSET)) == "model=<unset>"
    assert space.describe(space.slot(HOME, "/home/r")) == "$ROBOT_HOME=/home/r"
    assert space.describe(a, qualify=True) == f"{F}:model=a"


def test_describe_true_false_and_other_values() -> None:
    space = make_space()
    a = space.slot(MODEL, "a")
    assert space.describe(space.true) == "true"
    assert space.describe(space.false) == "false"
    assert space.describe(a & space.slot(MODEL, "b")) == "false"  # invalid, not just empty
    whole = space.false
    for slot in DOMAINS[SIM]:
        whole |= space.slot(SIM, slot)
    assert space.describe(whole) == "true"
    only_other = space.slot(WORLD, OTHER)
    assert space.describe(only_other) == "only for other values"
    assert space.describe(only_other, known_only=False) == "world=<other>"
    # known_only hides <other>: "not empty" is "other" among the known values
    assert space.describe(~space.slot(WORLD, "empty")) == "only for other values"


def test_describe_predicates() -> None:
    space = make_space()
    p = space.predicate("test_nonempty", Hole(MODEL))
    assert space.describe(p) == "⟨model⟩ is set"
    assert space.describe(~p) == "¬(⟨model⟩ is set)"


def test_describe_disjunction_parenthesises_conjunctions() -> None:
    space = make_space()
    condition = (space.slot(TELEOP, "true") & space.slot(SIM, "true")) | space.slot(MODEL, "c")
    text = space.describe(condition)
    assert sorted(text.split(" ∨ ")) == ["(sim ∧ use_teleop)", "model=c"]


# -- round trip: parse a description back ------------------------------------------------------
_PART = re.compile(r"^(?P<neg>¬?)(?P<name>[$\w]+)(?:(?P<op>=|≠|∈)(?P<rest>.*))?$")


def _slot_named(space: ConditionSpace, input_: Input, text: str) -> BDD:
    for slot in space.domain(input_):
        if (slot if isinstance(slot, str) else repr(slot)) == text:
            return space.slot(input_, slot)
    raise AssertionError(f"{text!r} is no slot of {input_}")


def parse(space: ConditionSpace, text: str) -> BDD:
    """The BDD of a description (slots only), in the grammar ``describe`` produces."""
    if text == "true":
        return space.true
    if text == "false":
        return space.false
    by_name = {str(i): i for i in space.inputs()}
    result = space.false
    for cube_text in text.split(" ∨ "):
        if cube_text.startswith("("):
            assert cube_text.endswith(")"), text
            cube_text = cube_text[1:-1]
        cube = space.true
        for part in cube_text.split(" ∧ "):
            match = _PART.match(part)
            assert match is not None, (part, text)
            input_ = by_name[match["name"]]
            op, rest = match["op"], match["rest"]
            if op is None:
                word = "false" if match["neg"] else "true"
                cube &= _slot_named(space, input_, word)
            elif op == "=":
                cube &= _slot_named(space, input_, rest)
            elif op == "≠":
                cube &= ~_slot_named(space, input_, rest)
            else:
                assert rest.startswith("{") and rest.endswith("}"), part
                union = space.false
                for item in rest[1:-1].split(", "):
                    union |= _slot_named(space, input_, item)
                cube &= union
        result |= cube
    return result


def _known(space: ConditionSpace) -> BDD:
    """Valid configurations in which every arg holds a known value."""
    care = space.valid
    for input_ in space.inputs():
        if isinstance(input_, ArgInput):
            care &= ~space.slot(input_, OTHER)
    return care


def _round_trip_failures(seeds: range, sound_only: bool) -> list[str]:
    """Descriptions of random conditions that do not mean their condition.

    With ``sound_only`` only the configurations a description claims but its condition lacks
    count; otherwise also those the description leaves out.
    """
    failures = []
    for seed in seeds:
        space = make_space()
        care = _known(space)
        rng = random.Random(seed)
        for _ in range(60):
            condition = random_condition(space, rng)
            for known_only, within in ((True, care), (False, space.valid)):
                text = space.describe(condition, known_only=known_only)
                if text == "false":
                    ok = not space.satisfiable(condition)
                elif text == "only for other values":
                    ok = (condition & care) == space.false and space.satisfiable(condition)
                else:
                    described = parse(space, text) & within
                    meant = condition & within
                    extra = described & ~meant
                    ok = extra == space.false and (sound_only or described == meant)
                if not ok:
                    failures.append(f"seed {seed} known_only={known_only}: {text}")
    return failures


def test_describe_claims_nothing_its_condition_lacks() -> None:
    assert _round_trip_failures(range(12), sound_only=True) == []


def test_describe_round_trip_over_random_conditions() -> None:
    assert _round_trip_failures(range(12), sound_only=False) == []


def test_describe_keeps_every_needed_cube() -> None:
    x, y, z = ArgInput(F, "x"), ArgInput(F, "y"), ArgInput(F, "z")
    space = make_space({x: ("a", "b", "c"), y: ("a", "b", "c"), z: ("a", "b")})

    def any_of(input_: Input, *slots: str) -> BDD:
        result = space.false
        for slot in slots:
            result |= space.slot(input_, slot)
        return result

    condition = (
        (any_of(x, "a") & any_of(y, "a", "c"))
        | (any_of(x, "b") & any_of(y, "b"))
        | (any_of(y, "a", "b") & any_of(z, "a"))
    )
    text = space.describe(condition)
    # x=c ∧ y=a ∧ z=a satisfies the condition (third disjunct): its description must say so
    witness = any_of(x, "c") & any_of(y, "a") & any_of(z, "a")
    assert space.satisfiable(condition & witness)
    assert (parse(space, text) & witness & space.valid) != space.false, text


def test_describe_says_when_other_values_matter() -> None:
    space = make_space()
    only_known = space.slot(WORLD, "empty")
    assert space.describe(only_known, known_only=False) == "world=empty"
    assert space.describe(only_known) != space.describe(space.true)
