"""Terms: strings known only once a configuration supplies its inputs' texts."""

from __future__ import annotations

import copy
import gc
import pickle
from collections.abc import Mapping

import pytest

from rosvar.logic.inputs import ArgInput, Input
from rosvar.logic.terms import (
    _INTERNED,
    Apply,
    Hole,
    TermError,
    concat,
    evaluate,
    is_term,
    measure,
    measure_parts,
    term_inputs,
)

ROBOT = ArgInput("a.launch", "robot")
NAME = ArgInput("a.launch", "name")


def test_concat_stays_a_string_without_terms_and_merges_neighbours() -> None:
    assert concat(["a", "", "b"]) == "ab"
    assert concat([]) == ""
    joined = concat(["/", "ns", Hole(ROBOT), "_", "x"])
    assert isinstance(joined, Apply)
    assert joined.operands == ("/ns", Hole(ROBOT), "_x")
    assert concat([Hole(ROBOT)]) == Hole(ROBOT)


@pytest.mark.parametrize(
    ("parts", "texts"),
    [
        (["/", Hole(ROBOT), "/", Hole(NAME)], {ROBOT: "husky", NAME: "base"}),
        ([Hole(ROBOT), Hole(ROBOT), ""], {ROBOT: "r"}),
        (["plain"], {}),
    ],
)
def test_a_concatenation_evaluates_to_its_parts_filled_in(
    parts: list[str | Hole], texts: Mapping[Input, str]
) -> None:
    term = concat(list(parts))
    filled = "".join(p if isinstance(p, str) else texts[p.input] for p in parts)
    assert evaluate(term, texts) == filled
    assert term_inputs(term) == {p.input for p in parts if isinstance(p, Hole)}
    assert is_term(term) == bool(texts)


def test_a_missing_input_or_function_is_a_term_error() -> None:
    with pytest.raises(TermError, match="no value"):
        evaluate(concat(["x", Hole(ROBOT)]), {NAME: "n"})
    with pytest.raises(TermError, match="unknown term function"):
        evaluate(Apply("no-such-function", (Hole(ROBOT),)), {ROBOT: "r"})


def test_terms_are_values_and_show_their_holes() -> None:
    assert Hole(ROBOT) == Hole(ArgInput("a.launch", "robot"))
    assert hash(Apply("concat", ("a", Hole(ROBOT)))) == hash(Apply("concat", ("a", Hole(ROBOT))))
    assert Apply("concat", ("a", Hole(ROBOT))) != Apply("concat", ("a", Hole(NAME)))
    assert str(concat(["/", Hole(ROBOT)])) == f"/{Hole(ROBOT)}"
    assert str(Apply("concat", (Hole(ROBOT),), display="shown")) == "shown"


def test_equal_terms_are_one_object_until_freed_and_come_back_through_pickle() -> None:
    built = concat(["/", Hole(ROBOT), "/", concat([Hole(NAME), "_x"])])
    again = concat(["/", Hole(ROBOT), "/", concat([Hole(NAME), "_x"])])
    assert built is again and Hole(ROBOT) is Hole(ArgInput("a.launch", "robot"))
    assert pickle.loads(pickle.dumps(built)) is built
    assert copy.deepcopy(built) is built
    assert Apply("concat", ("a", Hole(ROBOT)), display="d") is not Apply(
        "concat", ("a", Hole(ROBOT))
    )
    shown, entries = str(built), len(_INTERNED)
    del built, again
    gc.collect()
    assert len(_INTERNED) < entries  # a freed term leaves the table
    rebuilt = concat(["/", Hole(ROBOT), "/", concat([Hole(NAME), "_x"])])
    assert str(rebuilt) == shown
    assert all(ref() is not None for ref in _INTERNED.values())


def test_a_terms_measure_counts_shared_operands_each_time() -> None:
    inner = Apply("concat", ("ab", Hole(ROBOT)))
    twice = Apply("concat", (inner, "-", inner))
    assert measure(inner) == (2 + len(str(Hole(ROBOT))), 1)
    assert measure(twice) == (2 * measure(inner)[0] + 1, 2)
    assert measure_parts(["xyz", twice, ("not", "text")]) == (3 + measure(twice)[0], 3)
