"""Conditional values: merging of equal leaves, ite, combine and the other combinators.

Every combinator must keep the branches pairwise disjoint, keep exactly the configurations its
operands cover, and give in each configuration what the plain (non-variational) operation gives
on the values that configuration picks. The last property is checked by enumerating the
configurations of a small space.
"""

from __future__ import annotations

import itertools
import random

import pytest

from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, Fail, combine, ite
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER, ArgInput, Input, Slot

F = "/ws/pkg/launch/main.launch"
X = ArgInput(F, "x")
Y = ArgInput(F, "y")
DOMAINS: dict[Input, tuple[Slot, ...]] = {X: ("a", "b", "c", OTHER), Y: ("true", "false")}


@pytest.fixture
def space() -> ConditionSpace:
    s = ConditionSpace()
    for input_, domain in DOMAINS.items():
        s.declare_input(input_, domain)
    return s


def configurations(space: ConditionSpace) -> list[dict[str, bool]]:
    """Every valid configuration of the space as an atom assignment."""
    values = [[(i, s if isinstance(s, str) else "zzz") for s in DOMAINS[i]] for i in DOMAINS]
    result = []
    for combination in itertools.product(*values):
        assignment = space.assignment(dict(combination))
        assert space.evaluate(space.valid, assignment)
        result.append(assignment)
    return result


def value_in(space: ConditionSpace, choice: Choice[object], config: dict[str, bool]) -> object:
    """The leaf ``choice`` has in ``config`` (``KeyError`` if none, error if several)."""
    found = [leaf for condition, leaf in choice if space.evaluate(condition, config)]
    assert len(found) <= 1, f"branches overlap: {found}"
    if not found:
        raise KeyError("undefined")
    return found[0]


def assert_disjoint(space: ConditionSpace, choice: Choice[object]) -> None:
    for (c1, v1), (c2, v2) in itertools.combinations(choice.branches, 2):
        assert (c1 & c2 & space.valid) == space.false, (v1, v2)


def x_is(space: ConditionSpace, *slots: Slot) -> BDD:
    result = space.false
    for slot in slots:
        result |= space.slot(X, slot)
    return result


def y_true(space: ConditionSpace) -> BDD:
    return space.slot(Y, "true")


# -- construction and merging -------------------------------------------------------------------
def test_equal_leaves_share_one_branch(space: ConditionSpace) -> None:
    a, b, c = x_is(space, "a"), x_is(space, "b"), x_is(space, "c")
    choice = Choice.of([(a, "one"), (b, "two"), (c, "one")])
    assert len(choice) == 2
    assert sorted(choice.values()) == ["one", "two"]
    conditions = dict((v, cond) for cond, v in choice)
    assert conditions["one"] == a | c
    assert conditions["two"] == b


def test_unhashable_leaves_merge_by_value(space: ConditionSpace) -> None:
    choice = Choice.of(
        [(x_is(space, "a"), [1, 2]), (x_is(space, "b"), [1, 2]), (y_true(space), {})]
    )
    assert len(choice) == 2
    assert choice.where(lambda v: v == [1, 2]) == x_is(space, "a", "b")


def test_false_branches_are_dropped(space: ConditionSpace) -> None:
    assert len(Choice.of([(space.false, "x")])) == 0
    assert Choice.of([(space.false, "x"), (x_is(space, "a"), "y")]).values() == ["y"]
    assert Choice.of([(space.false, "x")]).single() is None


def test_leaves_of_different_types_stay_apart(space: ConditionSpace) -> None:
    choice = Choice.of([(x_is(space, "a"), 1), (x_is(space, "b"), True), (x_is(space, "c"), 1.0)])
    assert len(choice) == 3
    picked = {
        type(value_in(space, choice, config))
        for config in configurations(space)
        if space.evaluate(choice.covered(), config)
    }
    assert picked == {int, bool, float}


def test_const_single_and_covered(space: ConditionSpace) -> None:
    choice = Choice.const(space, "v")
    assert choice.single() == "v"
    assert choice.covered() == space.true
    two = Choice.of([(x_is(space, "a"), "p"), (x_is(space, "b"), "q")])
    assert two.single() is None
    assert two.covered() == x_is(space, "a", "b")
    assert "p" in repr(two) and "q" in repr(two)


# -- map, bind, restrict, where -----------------------------------------------------------------
def test_map_merges_what_becomes_equal(space: ConditionSpace) -> None:
    choice = Choice.of([(x_is(space, "a"), "A"), (x_is(space, "b"), "a"), (x_is(space, "c"), "B")])
    lowered = choice.map(str.lower)
    assert len(lowered) == 2
    assert lowered.where(lambda v: v == "a") == x_is(space, "a", "b")


def test_bind_flattens_and_drops_impossible_pairs(space: ConditionSpace) -> None:
    outer = Choice.of([(x_is(space, "a"), "A"), (~x_is(space, "a"), "notA")])

    def inner(leaf: str) -> Choice[str]:
        # the inner choice conflicts with the outer branch "A" in its first branch
        b = x_is(space, "b")
        return Choice.of([(b, leaf + "/b"), (~b & y_true(space), leaf + "/y")])

    bound = outer.bind(inner)
    assert_disjoint(space, bound)
    possible = {v for c, v in bound if space.satisfiable(c)}
    assert possible == {"notA/b", "A/y", "notA/y"}  # x=a and x=b never hold together
    for config in configurations(space):
        x_a = space.evaluate(x_is(space, "a"), config)
        x_b = space.evaluate(x_is(space, "b"), config)
        y = space.evaluate(y_true(space), config)
        prefix = "A" if x_a else "notA"
        expected: object = f"{prefix}/b" if x_b else (f"{prefix}/y" if y else KeyError)
        try:
            got: object = value_in(space, bound, config)
        except KeyError:
            got = KeyError
        assert got == expected


def test_restrict_where(space: ConditionSpace) -> None:
    choice = Choice.of([(x_is(space, "a"), "p"), (~x_is(space, "a"), "q")])
    restricted = choice.restrict(y_true(space) & x_is(space, "a"))
    assert restricted.values() == ["p"]
    assert choice.where(lambda v: v == "nothing") == space.false
    assert choice.where(lambda v: True) == space.true


# -- ite ------------------------------------------------------------------------------------------
def test_ite_constant_conditions_return_an_operand(space: ConditionSpace) -> None:
    then, otherwise = Choice.const(space, "t"), Choice.const(space, "o")
    assert ite(space, space.true, then, otherwise) is then
    assert ite(space, space.false, then, otherwise) is otherwise


def test_ite_partitions_and_merges(space: ConditionSpace) -> None:
    cond = x_is(space, "a")
    result = ite(space, cond, Choice.const(space, "t"), Choice.const(space, "o"))
    assert dict((v, c) for c, v in result) == {"t": cond, "o": ~cond}
    same = ite(space, cond, Choice.const(space, "v"), Choice.const(space, "v"))
    assert len(same) == 1 and same.branches[0][0] == space.true


def test_ite_agrees_with_per_configuration_choice(space: ConditionSpace) -> None:
    rng = random.Random(7)
    for _ in range(20):
        then = _random_choice(space, rng, "t")
        otherwise = _random_choice(space, rng, "o")
        cond = _random_condition(space, rng)
        result = ite(space, cond, then, otherwise)
        assert_disjoint(space, result)
        for config in configurations(space):
            picked = then if space.evaluate(cond, config) else otherwise
            try:
                expected: object = value_in(space, picked, config)
            except KeyError:
                expected = KeyError
            try:
                got: object = value_in(space, result, config)
            except KeyError:
                got = KeyError
            assert got == expected


def test_ite_is_the_merge_of_both_sides_conjoined(space: ConditionSpace) -> None:
    """Leaves on both sides (one if-then-else each) come out as merging the two sides'
    conjunctions gives them: the same conditions, in the same order."""
    rng = random.Random(11)
    shared = 0
    for _ in range(40):
        then = _random_choice(space, rng, "v")
        otherwise = _random_choice(space, rng, rng.choice(("v", "o")))
        cond = _random_condition(space, rng)
        expected = Choice.of(
            [(c & cond, v) for c, v in then.branches]
            + [(c & ~cond, v) for c, v in otherwise.branches],
            space.false,
        )
        assert ite(space, cond, then, otherwise).branches == expected.branches
        shared += bool(set(then.values()) & set(otherwise.values()))
    assert shared > 10  # the case the if-then-else is for was met


# -- combine --------------------------------------------------------------------------------------
def test_combine_prunes_impossible_combinations(space: ConditionSpace) -> None:
    a = x_is(space, "a")
    first = Choice.of([(a, "1"), (~a, "2")])
    second = Choice.of([(a, "p"), (~a, "q")])
    combined = combine([first, second], lambda vs: "".join(vs))
    assert sorted(combined.values()) == ["1p", "2q"]  # not the 4 of a plain cross product


def test_combine_is_the_cross_product_of_independent_choices(space: ConditionSpace) -> None:
    first = Choice.of([(x_is(space, "a"), "1"), (~x_is(space, "a"), "2")])
    second = Choice.of([(y_true(space), "p"), (~y_true(space), "q")])
    combined = combine([first, second], lambda vs: "".join(vs))
    assert sorted(combined.values()) == ["1p", "1q", "2p", "2q"]
    assert combined.where(lambda v: v == "1q") == x_is(space, "a") & ~y_true(space)


def test_combine_agrees_with_per_configuration_values(space: ConditionSpace) -> None:
    rng = random.Random(11)
    for _ in range(20):
        operands = [_random_choice(space, rng, tag) for tag in "uvw"]
        combined = combine(operands, lambda vs: "+".join(vs))
        assert_disjoint(space, combined)
        for config in configurations(space):
            try:
                expected: object = "+".join(str(value_in(space, o, config)) for o in operands)
            except KeyError:
                expected = KeyError
            try:
                got: object = value_in(space, combined, config)
            except KeyError:
                got = KeyError
            assert got == expected


def test_combine_keeps_failures_as_leaves(space: ConditionSpace) -> None:
    failing: Choice[str | Fail] = Choice.of(
        [(x_is(space, "a"), Fail("boom")), (~x_is(space, "a"), "ok")]
    )
    suffix: Choice[str | Fail] = Choice.const(space, "!")

    def joined(values: list[str | Fail]) -> str | Fail:
        first, second = values
        return first if isinstance(first, Fail) else f"{first}{second}"

    combined = combine([failing, suffix], joined)
    assert combined.where(lambda v: isinstance(v, Fail)) == x_is(space, "a")
    assert combined.where(lambda v: v == "ok!") == ~x_is(space, "a")


# -- helpers --------------------------------------------------------------------------------------
def _random_condition(space: ConditionSpace, rng: random.Random) -> BDD:
    slots = rng.sample(DOMAINS[X], rng.randint(1, 3))
    condition = x_is(space, *slots)
    if rng.random() < 0.5:
        condition &= y_true(space) if rng.random() < 0.5 else ~y_true(space)
    return condition


def _random_choice(space: ConditionSpace, rng: random.Random, tag: str) -> Choice[str]:
    """Disjoint branches over X (and sometimes Y); may leave configurations uncovered."""
    branches: list[tuple[BDD, str]] = []
    for slot in DOMAINS[X]:
        roll = rng.random()
        if roll < 0.15:
            continue  # undefined here
        leaf = f"{tag}{rng.randint(0, 2)}"
        if roll < 0.4:
            branches.append((x_is(space, slot) & y_true(space), leaf))
            branches.append((x_is(space, slot) & ~y_true(space), f"{tag}{rng.randint(0, 2)}"))
        else:
            branches.append((x_is(space, slot), leaf))
    return Choice.of(branches)


def test_constants_are_shared_within_a_space_only(space: ConditionSpace) -> None:
    other = ConditionSpace()
    text = Choice.const(space, "x")
    assert Choice.const(space, "x") is text
    assert Choice.const(space, None) is Choice.const(space, None)
    elsewhere = Choice.const(other, "x")
    assert elsewhere is not text
    assert elsewhere.branches[0][0] == other.true  # a condition of its own manager
    # 1 == True: numbers and bools are never looked up by value; lists cannot be
    assert Choice.const(space, True).single() is True
    assert Choice.const(space, 1).single() == 1 and Choice.const(space, 1).single() is not True
    listed = Choice.const(space, ["a"])
    assert listed.single() == ["a"] and Choice.const(space, ["a"]) is not listed
