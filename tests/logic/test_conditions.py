"""Presence conditions: the exactly-one constraint, assignments, supports, cofactors, sizing."""

from __future__ import annotations

import itertools
import math
import random

import pytest

from logic.spaces import (
    DOMAINS,
    HOME,
    MODEL,
    SIM,
    TELEOP,
    WORLD,
    F,
    count,
    make_space,
    random_condition,
)
from rosvar.logic import conditions as conditions_module
from rosvar.logic.atoms import PredicateAtom, register_predicate
from rosvar.logic.bdd import BDD
from rosvar.logic.cells import register_predicate_texts, spellings
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, Input, Slot
from rosvar.logic.terms import Apply, Hole


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


def test_a_fact_added_again_changes_nothing() -> None:
    """Every ``if`` testing the same value adds the same fact: the facts, and what is
    remembered under them, stay as they were."""
    space = make_space()
    fact = ~(space.slot(MODEL, "a") & space.slot(SIM, "true"))
    space.constrain(fact)
    facts, valid = space.facts(), space.valid
    name = sorted(space.support(fact))[0]
    space.constrain(fact)
    assert (space.facts(), space.valid) == (facts, valid)
    assert list(space.facts_of(name)) == [fact]
    assert not space.satisfiable(~fact)


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


def test_support_agrees_with_dd_on_random_conditions(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(conditions_module, "SUPPORT_WALK_FACTOR", 0)  # always walk the BDD
    space = make_space()
    rng = random.Random(7)
    conditions = [space.true, space.false] + [random_condition(space, rng) for _ in range(200)]
    for condition in conditions:
        assert space.support(condition) == space.bdd.support(condition)


def test_evaluate_and_cofactor_agree_with_dd_let_on_random_conditions() -> None:
    space = make_space()
    rng = random.Random(11)
    names = sorted(space.bdd.vars)
    for _ in range(200):
        condition = random_condition(space, rng)
        assignment = {name: rng.random() < 0.5 for name in names}
        expected = space.bdd.let(assignment, condition) == space.true
        assert space.evaluate(condition, assignment) is expected
        fixed = dict(rng.sample(sorted(assignment.items()), rng.randint(1, len(names))))
        assert space.cofactor(condition, fixed) == space.bdd.let(fixed, condition)


# -- sizing the manager ---------------------------------------------------------------------------
def test_memory_estimate_grows_with_files_within_bounds() -> None:
    estimate = conditions_module.memory_estimate
    assert estimate(0) == conditions_module.MIN_MEMORY
    assert estimate(10**6) == conditions_module.MAX_MEMORY
    sizes = [estimate(n) for n in (100, 400, 1000, 2000)]
    assert sizes == sorted(sizes) and len(set(sizes)) == len(sizes)


def test_a_key_varies_where_it_holds_a_condition_of_some_input() -> None:
    space = ConditionSpace()
    x = ArgInput(F, "x")
    space.declare_input(x, ("a", OTHER))
    constant = ("text", None, ((space.true, "v"),), ((space.false, Hole(x)),))
    assert not space.varies(constant) and not space.varies("text")
    assert space.varies(("text", ((space.true, "v"),), (((space.slot(x, "a"), "a"),),)))
    assert space.varies(space.slot(x, OTHER))


@pytest.mark.filterwarnings("ignore:Changed in `dd`")  # statistics()' note on its 'mem' key
def test_dead_nodes_are_collected_before_they_outgrow_the_estimate() -> None:
    """Husky with ``_external`` as a root (5,800 variables): the web server's graph build
    left a million dead nodes that CUDD kept, as it collects garbage below 90 % of its
    estimate only once there are four dead nodes per slot of its unique table (256 slots a
    variable)."""
    space = ConditionSpace(files=100)
    names = [f"v{index}" for index in range(5_800)]
    space.bdd.declare(*names)
    pairs, made = 16, 0
    for round_ in range(8):  # ⋁ x_i ∧ y_i, the xs above the ys: 2^pairs nodes, then dropped
        xs, ys = names[40 * round_ :][:pairs], names[2_900 + 40 * round_ :][:pairs]
        built = space.false
        for x, y in zip(xs, ys, strict=True):
            built |= space.bdd.var(x) & space.bdd.var(y)
        made += len(space.bdd)
        del built
    assert made * 32 > conditions_module.memory_estimate(100)  # 32 bytes a node
    assert space.bdd.statistics()["peak_nodes"] < made * 3 // 4


@pytest.mark.filterwarnings("ignore:Changed in `dd`")  # statistics()' note on its 'mem' key
def test_computed_table_stays_fixed_as_variables_grow() -> None:
    space = ConditionSpace(files=10_000)
    for index in range(3_000):  # CUDD grows the table with the unique table unless capped
        space.declare_input(ArgInput(F, f"a{index}"), ("x", OTHER))
    assert space.bdd.statistics()["cache_size"] == conditions_module.CACHE_ENTRIES


register_predicate("test_yes", lambda text: text.strip().lower() == "yes", "{} is yes")
register_predicate_texts("test_yes", spellings(("yes", "no")))
register_predicate("test_no", lambda text: text.strip().lower() == "no", "{} is no")
register_predicate_texts("test_no", spellings(("yes", "no")))
register_predicate("test_upper", lambda text: text.isupper(), "{} is in capitals")
register_predicate_texts("test_upper", ("A", "a"))


def test_predicates_of_one_inputs_text_are_related_by_their_witnesses() -> None:
    """Predicates over an input's own text (its hole) hold together for an unforeseen value
    only as some witness makes them: 'yes' in capitals is ``YES``, nothing is both yes and
    no. The nonempty test registers no texts: it joins no group (it could tell apart texts
    nobody tried), so yes and empty stay possible together."""
    space = make_space()
    other = space.slot(WORLD, OTHER)
    yes = space.predicate("test_yes", Hole(WORLD))
    upper = space.predicate("test_upper", Hole(WORLD))
    assert space.satisfiable(other & yes & upper)
    assert space.satisfiable(other & yes & ~upper)
    assert space.satisfiable(other & ~yes & upper)
    assert space.witnesses(
        {WORLD: OTHER}, {_atom(space, yes): True, _atom(space, upper): True}
    ) == {WORLD: "YES"}
    assert space.witnesses(
        {WORLD: OTHER}, {_atom(space, yes): False, _atom(space, upper): True}
    ) == {WORLD: "NO"}
    nonempty = space.predicate("test_nonempty", Hole(WORLD))
    assert space.satisfiable(other & yes & ~nonempty)  # unrelated: no texts registered
    shouted = space.predicate("test_upper", Apply("concat", (Hole(WORLD), "!")))
    assert shouted not in (yes, upper)  # concat has no cells: no fact with the group
    assert space.satisfiable(other & upper & ~shouted)


def test_an_unforeseen_value_no_witness_gives_has_none() -> None:
    space = make_space()
    yes = _atom(space, space.predicate("test_yes", Hole(WORLD)))
    upper = _atom(space, space.predicate("test_upper", Hole(WORLD)))
    assert space.witnesses({WORLD: OTHER}, {yes: True, upper: True}) == {WORLD: "YES"}
    assert space.witnesses({WORLD: OTHER}, {yes: False, upper: True}) == {WORLD: "NO"}
    lower = {yes: True, upper: False}
    assert space.witnesses({WORLD: OTHER}, lower) == {WORLD: "yes"}
    domain = {**DOMAINS, WORLD: ("yes", "Yes", " yes ", "empty", OTHER)}
    space = make_space(domain)  # every lower-case yes the witnesses know is foreseen
    yes = _atom(space, space.predicate("test_yes", Hole(WORLD)))
    upper = _atom(space, space.predicate("test_upper", Hole(WORLD)))
    assert space.witnesses({WORLD: OTHER}, {yes: True, upper: False}) is None


def _atom(space: ConditionSpace, variable: BDD) -> PredicateAtom:
    atom = space.atom_of(str(variable.var))
    assert isinstance(atom, PredicateAtom)
    return atom
