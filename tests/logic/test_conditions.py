"""Presence conditions: the exactly-one constraint, assignments, readable descriptions.

The readable form is checked two ways: a few exact strings people will read (``use_teleop ∧
¬sim``, ``model∈{a, b}``, ``x≠a``), and a round trip over randomly generated conditions: the
description is parsed back into a BDD and must mean the same as the condition (modulo the
valid configurations, and with ``known_only`` modulo the ``<other>`` slots of args).
"""

from __future__ import annotations

import itertools
import math
import random
import re

import pytest

from rosvar.logic import conditions as conditions_module
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace, register_predicate
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, EnvInput, Input, Slot
from rosvar.logic.terms import Apply, Hole

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


def make_space(domains: dict[Input, tuple[Slot, ...]] = DOMAINS) -> ConditionSpace:
    space = ConditionSpace()
    for input_, domain in domains.items():
        space.declare_input(input_, domain)
    return space


def count(space: ConditionSpace, u: BDD) -> int:
    return int(space.bdd.count(space.valid & u, len(space.bdd.vars)))


# -- exactly one slot per input -----------------------------------------------------------------
def test_model_count_is_product_of_domain_sizes() -> None:
    space = make_space()
    sizes = [len(d) for d in DOMAINS.values()]
    assert count(space, space.true) == math.prod(sizes) == 3 * 3 * 5 * 2 * 3
    for input_, domain in DOMAINS.items():
        total = 0
        for slot in domain:
            n = count(space, space.slot(input_, slot))
            assert n == math.prod(sizes) // len(domain), (input_, slot)
            total += n
        assert total == math.prod(sizes)
        for a, b in itertools.combinations(domain, 2):
            assert count(space, space.slot(input_, a) & space.slot(input_, b)) == 0


def test_exactly_one_by_enumerating_every_assignment() -> None:
    domains: dict[Input, tuple[Slot, ...]] = {MODEL: ("a", "b", OTHER), HOME: (UNSET, OTHER)}
    space = make_space(domains)
    variables = sorted(space.bdd.vars)
    assert len(variables) == 5
    slot_vars = {
        input_: [space.bdd.support(space.slot(input_, s)) for s in domain]
        for input_, domain in domains.items()
    }
    valid_seen = 0
    for bits in itertools.product((False, True), repeat=len(variables)):
        assignment = dict(zip(variables, bits, strict=True))
        expected = all(
            sum(assignment[next(iter(support))] for support in supports) == 1
            for supports in slot_vars.values()
        )
        assert space.evaluate(space.valid, assignment) is expected
        valid_seen += expected
    assert valid_seen == 3 * 2


def test_declaring_an_input_twice_or_with_repeated_slots() -> None:
    space = ConditionSpace()
    space.declare_input(MODEL, ("a", "a", "b", OTHER))
    assert space.domain(MODEL) == ("a", "b", OTHER)
    space.declare_input(MODEL, ("z", OTHER))  # ignored: the first declaration stands
    assert space.domain(MODEL) == ("a", "b", OTHER)
    assert len(space.bdd.vars) == 3
    assert count(space, space.true) == 3
    assert space.slot(MODEL, "z") == space.false
    assert space.slot(SIM, "true") == space.false  # undeclared input


def test_satisfiable_and_valid_implies_respect_validity() -> None:
    space = make_space()
    a, b = space.slot(MODEL, "a"), space.slot(MODEL, "b")
    assert not space.satisfiable(a & b)  # not valid, although a & b != false as a BDD
    assert (a & b) != space.false
    assert space.satisfiable(a & space.slot(SIM, "true"))
    every_model = space.false
    for slot in DOMAINS[MODEL]:
        every_model |= space.slot(MODEL, slot)
    assert space.valid_implies(every_model)
    assert not space.valid_implies(a | b)
    assert space.valid_implies(~(a & b))


# -- assignments --------------------------------------------------------------------------------
def _holding(space: ConditionSpace, assignment: dict[str, bool], input_: Input) -> list[Slot]:
    return [s for s in space.domain(input_) if space.evaluate(space.slot(input_, s), assignment)]


def test_assignment_picks_one_slot_per_input() -> None:
    space = make_space()
    assignment = space.assignment(
        {TELEOP: "true", SIM: "yes", MODEL: None, WORLD: "empty", HOME: "/elsewhere"}
    )
    assert _holding(space, assignment, TELEOP) == ["true"]
    assert _holding(space, assignment, SIM) == [OTHER]  # outside the domain
    assert _holding(space, assignment, MODEL) == [UNSET]  # not given
    assert _holding(space, assignment, WORLD) == ["empty"]
    assert _holding(space, assignment, HOME) == [OTHER]
    assert space.evaluate(space.valid, assignment)


def test_assignment_of_special_looking_strings_is_other() -> None:
    """A user typing ``<unset>`` or ``<other>`` gives a value, not the special slot."""
    space = make_space()
    assignment = space.assignment({MODEL: "<unset>", HOME: "<other>"})
    assert _holding(space, assignment, MODEL) == [OTHER]
    assert _holding(space, assignment, HOME) == [OTHER]
    assert _holding(space, assignment, TELEOP) == []  # no UNSET slot: nothing holds
    assert not space.evaluate(space.valid, assignment)


def test_assignment_decides_predicates_on_concrete_values() -> None:
    space = make_space()
    hole = Hole(MODEL)
    is_set = space.predicate("test_nonempty", hole)
    assert space.predicate("test_nonempty", Hole(MODEL)) == is_set  # one atom per (test, term)
    joined = space.predicate("test_nonempty", Apply("concat", (hole, Hole(HOME))))
    assert joined != is_set
    condition = space.slot(MODEL, OTHER) & is_set

    given = space.assignment({MODEL: "x"})
    assert space.evaluate(condition, given)
    empty = space.assignment({MODEL: ""})
    assert not space.evaluate(condition, empty)
    assert space.evaluate(space.slot(MODEL, OTHER), empty)
    # a term that cannot be evaluated (HOME not given) satisfies no predicate
    assert not space.evaluate(joined, space.assignment({MODEL: "x"}))
    assert space.evaluate(joined, space.assignment({MODEL: "", HOME: "h"}))


def test_evaluate_constant_conditions() -> None:
    space = make_space()
    assignment = space.assignment({})
    assert space.evaluate(space.true, assignment)
    assert not space.evaluate(space.false, assignment)


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


def _random_condition(space: ConditionSpace, rng: random.Random) -> BDD:
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


def test_support_agrees_with_dd_on_random_conditions(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(conditions_module, "SUPPORT_WALK_FACTOR", 0)  # always walk the BDD
    space = make_space()
    rng = random.Random(7)
    conditions = [space.true, space.false] + [_random_condition(space, rng) for _ in range(200)]
    for condition in conditions:
        assert space.support(condition) == space.bdd.support(condition)


def test_evaluate_and_cofactor_agree_with_dd_let_on_random_conditions() -> None:
    space = make_space()
    rng = random.Random(11)
    names = sorted(space.bdd.vars)
    for _ in range(200):
        condition = _random_condition(space, rng)
        assignment = {name: rng.random() < 0.5 for name in names}
        expected = space.bdd.let(assignment, condition) == space.true
        assert space.evaluate(condition, assignment) is expected
        fixed = dict(rng.sample(sorted(assignment.items()), rng.randint(1, len(names))))
        assert space.cofactor(condition, fixed) == space.bdd.let(fixed, condition)


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
            condition = _random_condition(space, rng)
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


# -- sizing the manager ---------------------------------------------------------------------------
def test_memory_estimate_grows_with_files_within_bounds() -> None:
    estimate = conditions_module.memory_estimate
    assert estimate(0) == conditions_module.MIN_MEMORY
    assert estimate(10**6) == conditions_module.MAX_MEMORY
    sizes = [estimate(n) for n in (100, 400, 1000, 2000)]
    assert sizes == sorted(sizes) and len(set(sizes)) == len(sizes)


@pytest.mark.filterwarnings("ignore:Changed in `dd`")  # statistics()' note on its 'mem' key
def test_computed_table_stays_fixed_as_variables_grow() -> None:
    space = ConditionSpace(files=10_000)
    for index in range(3_000):  # CUDD grows the table with the unique table unless capped
        space.declare_input(ArgInput(F, f"a{index}"), ("x", OTHER))
    assert space.bdd.statistics()["cache_size"] == conditions_module.CACHE_ENTRIES
