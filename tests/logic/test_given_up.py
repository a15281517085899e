"""Values over the work limits, computed again in one configuration (``GivenUp``, ``Bindings``)."""

from __future__ import annotations

import functools
import gc
from collections.abc import Iterator

import pytest

from rosvar.logic.choice import Choice, Fail
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.given_up import Bindings, GivenUp, terms_merged
from rosvar.logic.inputs import OTHER, ArgInput, Input, Slot
from rosvar.logic.terms import Apply, Hole, TermError, concat, evaluate

F = "/ws/pkg/launch/main.launch"
X = ArgInput(F, "x")
Y = ArgInput(F, "y")
DOMAINS: dict[Input, tuple[Slot, ...]] = {X: ("a", "b", OTHER), Y: ("true", "false")}


@pytest.fixture
def space() -> Iterator[ConditionSpace]:
    s = ConditionSpace()
    for input_, domain in DOMAINS.items():
        s.declare_input(input_, domain)
    yield s
    gc.collect()  # the raised errors' frames hold terms, and their BDDs, in cycles


def _choices(space: ConditionSpace) -> list[Choice[object]]:
    x = Choice.of(
        [(space.slot(X, "a"), "a"), (space.slot(X, "b"), "b"), (space.slot(X, OTHER), Hole(X))]
    )
    y = Choice.of([(space.slot(Y, "true"), "!"), (space.slot(Y, "false"), Fail("no", "y-no"))])
    return [x, y]


def _joined(leaves: list[object]) -> object:
    for leaf in leaves:
        if isinstance(leaf, Fail):
            return leaf
    return concat(["<", *leaves, ">"])  # type: ignore[list-item]


def _bindings(space: ConditionSpace, values: dict[Input, str | None]) -> Bindings:
    assignment = space.assignment(values)
    return Bindings({}, lambda condition: space.evaluate(condition, assignment))


def test_a_configuration_combines_the_leaves_that_hold_there(space: ConditionSpace) -> None:
    term = GivenUp("$(arg x)$(arg y)", "⟨…⟩", _choices(space), _joined)  # type: ignore[arg-type]
    bindings = _bindings(space, {X: "b", Y: "true"})
    assert evaluate(term, {X: "b", Y: "true"}, bindings) == "<b!>"
    # a leaf that is itself a term is evaluated with the configuration's strings
    other = _bindings(space, {X: "zzz", Y: "true"})
    assert evaluate(concat(["[", term, "]"]), {X: "zzz", Y: "true"}, other) == "[<zzz!>]"


def test_a_failing_leaf_is_the_launch_tools_failure(space: ConditionSpace) -> None:
    term = GivenUp("t", "⟨t⟩", _choices(space), _joined)  # type: ignore[arg-type]
    with pytest.raises(TermError) as raised:
        evaluate(term, {X: "a", Y: "false"}, _bindings(space, {X: "a", Y: "false"}))
    assert (str(raised.value), raised.value.code) == ("no", "y-no")


def test_without_a_configuration_it_stays_over_the_work_limits(space: ConditionSpace) -> None:
    # importing the interpreter registers the too_complex function all give-ups share
    from rosvar.interpreter import substitution_args

    term = GivenUp("t", "⟨t⟩", _choices(space), _joined)  # type: ignore[arg-type]
    with pytest.raises(TermError, match="work limits"):
        evaluate(term, {X: "a", Y: "true"}, None)
    assert substitution_args.too_complex("t") == Apply("too_complex", ("t",), display="⟨t⟩")


def test_an_operand_undefined_in_the_configuration_is_reported(space: ConditionSpace) -> None:
    only_a = Choice.of([(space.slot(X, "a"), "a")])
    term = GivenUp("t", "⟨t⟩", [only_a], _joined)  # type: ignore[arg-type]
    with pytest.raises(TermError, match="no value in this configuration"):
        evaluate(term, {X: "b"}, _bindings(space, {X: "b", Y: None}))


def test_one_computation_given_up_twice_is_one_term(space: ConditionSpace) -> None:
    """The same text, display, choices (conditions and leaves) and combination: one term,
    hence one set of predicates in the space, however often the computation is given up."""
    one = GivenUp("t", "⟨t⟩", _choices(space), _joined)  # type: ignore[arg-type]
    again = GivenUp("t", "⟨t⟩", _choices(space), _joined)  # type: ignore[arg-type]
    assert again is one
    assert space.predicate("true", again) is space.predicate("true", one)
    # a combination that is the same function of the same arguments is the same one
    bound = GivenUp("t", "⟨t⟩", _choices(space), functools.partial(_wrapped, left="["))  # type: ignore[arg-type]
    assert GivenUp("t", "⟨t⟩", _choices(space), functools.partial(_wrapped, left="[")) is bound  # type: ignore[arg-type]
    assert GivenUp("t", "⟨t⟩", _choices(space), functools.partial(_wrapped, left="(")) is not bound  # type: ignore[arg-type]


def test_give_ups_of_other_computations_are_equal_only_to_themselves(
    space: ConditionSpace,
) -> None:
    x, y = _choices(space)
    one = GivenUp("t", "⟨t⟩", [x, y], _joined)  # type: ignore[arg-type]
    others = [
        GivenUp("t", "⟨t⟩", [x], _joined),  # type: ignore[arg-type]
        GivenUp("t", "⟨t⟩", [y, x], _joined),  # type: ignore[arg-type]
        GivenUp("t", "⟨t⟩", [x, y], _wrapped),  # type: ignore[arg-type]
        GivenUp("u", "⟨t⟩", [x, y], _joined),  # type: ignore[arg-type]
        GivenUp("t", "⟨u⟩", [x, y], _joined),  # type: ignore[arg-type]
        GivenUp("t", "⟨t⟩", [x.map(lambda leaf: f"{leaf}!"), y], _joined),  # type: ignore[arg-type]
        GivenUp("t", "⟨t⟩", [Choice.of([(space.slot(X, "a"), "a")]), y], _joined),  # type: ignore[arg-type]
    ]
    assert all(other != one for other in others)
    assert len(set(others)) == len(others)
    assert one != Apply("too_complex", ("t",), display="⟨t⟩")
    assert len(Choice.of([(space.slot(X, "a"), one), (space.slot(X, "b"), others[0])])) == 2


def test_give_ups_of_two_spaces_are_apart() -> None:
    """Conditions of two managers cannot be compared: their give-ups are not looked up
    against each other's."""
    spaces = [ConditionSpace(), ConditionSpace()]
    for each in spaces:
        for input_, domain in DOMAINS.items():
            each.declare_input(input_, domain)
    one, two = (GivenUp("t", "⟨t⟩", _choices(s), _joined) for s in spaces)  # type: ignore[arg-type]
    assert one is not two and one.choices[0].false == spaces[0].false


def test_give_ups_of_one_text_are_hashed_apart(space: ConditionSpace) -> None:
    made = [
        GivenUp("t", "⟨t⟩", [Choice.const(space, str(i))], _joined)  # type: ignore[arg-type]
        for i in range(64)
    ]
    assert len({hash(g) for g in made}) == len(made)
    assert len(set(made)) == len(made) and all(g in set(made) for g in made)


def _wrapped(leaves: list[object], left: str = "<") -> object:
    return concat([left, *leaves])  # type: ignore[list-item]


def test_terms_merged_are_one_branch_that_a_configuration_evaluates(space: ConditionSpace) -> None:
    """Strings and failures stay as they are; the terms become one value whose condition
    covers theirs, and which a configuration evaluates as the term that holds there."""
    x, y = _choices(space)
    crossed = Choice.of(
        [
            (space.slot(X, "a") & space.slot(Y, "true"), "a!"),
            (space.slot(X, "b") & space.slot(Y, "true"), concat(["b", Hole(Y)])),
            (space.slot(X, OTHER) & space.slot(Y, "true"), concat([Hole(X), "!"])),
            (space.slot(Y, "false"), Fail("no", "y-no")),
        ]
    )
    merged = terms_merged(crossed, "$(arg x)$(arg y)", "⟨x and y⟩")
    assert merged.values()[:2] == ["a!", Fail("no", "y-no")]
    assert str(merged.values()[2]) == "⟨x and y⟩" and len(merged) == 3
    (where, term), *_ = [(c, v) for c, v in merged if isinstance(v, GivenUp)]
    assert where == space.slot(Y, "true") & (space.slot(X, "b") | space.slot(X, OTHER))
    configurations: list[tuple[dict[Input, str], str]] = [
        ({X: "b", Y: "true"}, "btrue"),
        ({X: "zz", Y: "true"}, "zz!"),
    ]
    for values, text in configurations:
        assert evaluate(term, values, _bindings(space, dict(values))) == text
    one = Choice.of([(space.true, concat([Hole(X), "!"]))])
    assert terms_merged(one, "t", "⟨t⟩") is one  # a single term is merged with nothing
    assert terms_merged(x, "t", "⟨t⟩") is x and terms_merged(y, "t", "⟨t⟩") is y
