"""Exact weighted model counting, against enumeration and closed forms."""

from __future__ import annotations

import itertools
import random

import dd.cudd
import pytest

from rosvar.analyses.feature_model import counting
from rosvar.analyses.feature_model.counting import CountedDiagram, moduli
from rosvar.logic import bdd
from rosvar.logic.bdd import BDD, Manager, Weight


def declared(count: int) -> tuple[Manager, list[str]]:
    """A manager with the variables ``x0`` … ``x{count - 1}``, in that order."""
    manager = dd.cudd.BDD()
    names = [f"x{i}" for i in range(count)]
    manager.declare(*names)
    return manager, names


def enumerated(manager: Manager, formula: BDD, weights: dict[str, Weight]) -> int:
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


def random_formula(manager: Manager, rng: random.Random, names: list[str]) -> BDD:
    """A conjunction of random clauses (their negations too, for complemented edges)."""
    formula = manager.true
    for _ in range(rng.randint(0, 6)):
        clause = manager.false
        for name in rng.sample(names, rng.randint(1, 3)):
            literal = manager.var(name)
            clause |= literal if rng.random() < 0.5 else ~literal
        formula &= clause if rng.random() < 0.7 else ~clause
    return formula


@pytest.fixture(params=["one by one", "vectorised"])
def recount(request: pytest.FixtureRequest, monkeypatch: pytest.MonkeyPatch) -> str:
    """Recounts either way: node by node in Python, or by level in numpy modulo primes."""
    monkeypatch.setattr(counting, "VECTOR_FROM", 0 if request.param == "vectorised" else 10**9)
    return str(request.param)


@pytest.mark.parametrize("seed", range(40))
def test_counts_equal_enumeration(seed: int, recount: str, bdd_reader: str) -> None:
    """The first count, then counts under other weights (some zero, as choices are), each
    against listing the assignments."""
    rng = random.Random(seed)
    manager, names = declared(7)
    formula = random_formula(manager, rng, names[:5])  # x5, x6: counted, never mentioned
    first = {name: (rng.randint(1, 3), rng.randint(1, 4)) for name in names}
    diagram = CountedDiagram(manager, formula, first)
    assert diagram.first == enumerated(manager, formula, first)
    for _ in range(4):
        weights = dict(first)
        for name in rng.sample(names, rng.randint(1, 3)):
            weights[name] = (rng.randint(0, 3), rng.randint(0, 4))
        assert diagram.count(weights) == enumerated(manager, formula, weights)
    ones = dict.fromkeys(names, (1, 1))
    assert diagram.count(ones) == int(manager.count(formula, nvars=7))


def test_a_count_recomputes_the_levels_above_the_deepest_change(recount: str) -> None:
    """Changing only the top variable's weight leaves the nodes below as they were: their
    values are reused, rescaled to the new total weight."""
    manager, names = declared(6)
    x0, x2, x3, x5 = (manager.var(name) for name in ("x0", "x2", "x3", "x5"))
    formula = (x0 | x3) & ((x2 & ~x5) | (~x2 & x5))
    diagram = CountedDiagram(manager, formula, dict.fromkeys(names, (1, 1)))
    for top in ((0, 1), (1, 0), (2, 5)):
        weights = {**dict.fromkeys(names, (1, 1)), "x0": top}
        assert diagram.count(weights) == enumerated(manager, formula, weights)


def test_counts_beyond_a_double_are_exact() -> None:
    """3^40 ways minus those with x0 and x1 both off: not representable in a double."""
    manager, names = declared(40)
    formula = manager.var("x0") | manager.var("x1")
    exact = 3**40 - 3**38
    assert int(float(exact)) != exact
    assert CountedDiagram(manager, formula, dict.fromkeys(names, (1, 2))).first == exact


def test_constants_and_zero_weights() -> None:
    manager = dd.cudd.BDD()
    manager.declare("a", "b")
    weights = {"a": (2, 3), "b": (1, 4)}
    assert CountedDiagram(manager, manager.true, weights).first == 5 * 5
    assert CountedDiagram(manager, manager.false, weights).first == 0
    assert CountedDiagram(manager, ~manager.var("a"), weights).first == 2 * 5
    diagram = CountedDiagram(manager, manager.var("a"), weights)
    assert diagram.count({"a": (0, 0), "b": (1, 1)}) == 0
    with pytest.raises(ValueError):
        CountedDiagram(manager, manager.var("a"), {"a": (0, 0), "b": (1, 1)})


@pytest.mark.parametrize("seed", range(6))
def test_vectorised_recounts_of_large_counts_equal_the_exact_ones(
    seed: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Counts of hundreds of bits, under choices (bounded by the first count) and under
    larger weights (bounded by the total): both ways of recounting agree."""
    rng = random.Random(seed)
    manager, names = declared(160)
    formula = manager.true
    for _ in range(60):
        a, b, c = rng.sample(names, 3)
        formula &= (
            manager.var(a) | ~manager.var(b) | (manager.var(c) if seed % 2 else manager.false)
        )
    first = {name: (rng.randint(1, 5), rng.randint(1, 5)) for name in names}
    diagram = CountedDiagram(manager, formula, first)
    assert diagram.first.bit_length() > 100
    for changed in (
        first,
        {**first, names[-1]: (0, 1), names[3]: (1, 0)},
        {**first, names[-2]: (7, 9)},
    ):
        monkeypatch.setattr(counting, "VECTOR_FROM", 10**9)
        exact = diagram.count(changed)
        monkeypatch.setattr(counting, "VECTOR_FROM", 0)
        assert diagram.count(changed) == exact


def test_a_level_weight_no_modulus_can_divide_is_counted_one_by_one(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """A level whose total weight is a multiple of a modulus has no inverse modulo it: the
    recount falls back to Python integers and stays exact."""
    monkeypatch.setattr(counting, "VECTOR_FROM", 0)
    manager = dd.cudd.BDD()
    names = ["a", "b", "c"]
    manager.declare(*names)
    formula = (manager.var("a") & ~manager.var("b")) | manager.var("c")
    diagram = CountedDiagram(manager, formula, dict.fromkeys(names, (1, 1)))
    weights = {**dict.fromkeys(names, (1, 1)), "b": (1, moduli()[0] - 1)}
    assert diagram.count(weights) == enumerated(manager, formula, weights)


@pytest.mark.parametrize("seed", range(20))
def test_taken_values_equal_enumeration(seed: int, bdd_reader: str) -> None:
    """A variable takes a value when some satisfying assignment gives it that value."""
    rng = random.Random(seed)
    manager, names = declared(6)
    formula = random_formula(manager, rng, names[:5])
    expected: dict[str, set[bool]] = {name: set() for name in names}
    for bits in itertools.product((False, True), repeat=len(names)):
        assignment = dict(zip(names, bits, strict=True))
        if manager.let(assignment, formula) == manager.true:
            for name, bit in assignment.items():
                expected[name].add(bit)
    taken = CountedDiagram(manager, formula, dict.fromkeys(names, (1, 1))).taken()
    assert taken == expected


def test_a_prepared_diagram_recounts_with_what_it_built(monkeypatch: pytest.MonkeyPatch) -> None:
    """``prepare`` builds the vectorised recount's levels of a large diagram once, ahead of
    the first recount, which then uses them; a small diagram, recounted one by one, gets
    nothing built."""
    manager, names = declared(12)
    formula = random_formula(manager, random.Random(3), names) | manager.var("x0")
    weights = dict.fromkeys(names, (1, 1))
    diagram = CountedDiagram(manager, formula, weights)
    monkeypatch.setattr(counting, "VECTOR_FROM", len(diagram))
    diagram.prepare()
    assert "_residues" not in vars(diagram)  # a cached_property not computed yet
    monkeypatch.setattr(counting, "VECTOR_FROM", len(diagram) - 1)
    diagram.prepare()
    built = vars(diagram)["_residues"]
    assert built.size == len(diagram)
    chosen = {**weights, names[-1]: (0, 1)}
    assert diagram.count(chosen) == enumerated(manager, formula, chosen)
    assert vars(diagram)["_residues"] is built


@pytest.mark.parametrize("seed", range(8))
def test_values_below_a_quick_recount_are_let_go_and_counted_anew(
    seed: int, monkeypatch: pytest.MonkeyPatch, bdd_reader: str
) -> None:
    """Only the first values a quick recount reads are kept; a recount in Python that
    reaches below them (numpy kept away) counts the whole diagram again, exactly."""
    rng = random.Random(seed)
    manager, names = declared(10)
    formula = manager.false  # a disjunction of cubes: a diagram of some size
    for _ in range(6):
        cube = manager.true
        for name in rng.sample(names, 3):
            cube &= manager.var(name) if rng.random() < 0.5 else ~manager.var(name)
        formula |= cube
    first = {name: (rng.randint(1, 3), rng.randint(1, 4)) for name in names}
    monkeypatch.setattr(counting, "VECTOR_FROM", 4)
    diagram = CountedDiagram(manager, formula, first)
    assert diagram.first == enumerated(manager, formula, first)
    assert len(diagram._values) < len(diagram)
    monkeypatch.setattr(counting, "VECTOR_FROM", 10**9)
    for name in names:
        weights = {**first, name: (rng.randint(0, 3), rng.randint(0, 4))}
        assert diagram.count(weights) == enumerated(manager, formula, weights)


@pytest.mark.parametrize("seed", range(12))
def test_counts_by_levels_equal_those_node_by_node(
    seed: int, recount: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Diagrams too large to enumerate, with many nodes a level: read and counted a level
    at a time in numpy, their first count, recounts and values taken are those of the
    reading and count node by node."""
    rng = random.Random(seed)
    manager, names = declared(18)
    formula = manager.false
    for _ in range(5):
        formula = manager.apply("xor", formula, random_formula(manager, rng, names))
    first = {name: (rng.randint(1, 3), rng.randint(1, 4)) for name in names}
    others = [
        {**first, **{n: (rng.randint(0, 3), rng.randint(0, 4)) for n in rng.sample(names, 2)}}
        for _ in range(4)
    ]
    found = []
    for threshold in (0, 10**9):  # by levels, then node by node
        monkeypatch.setattr(bdd, "READ_BY_LEVELS_FROM", threshold)
        diagram = CountedDiagram(manager, formula, first)
        found.append((diagram.first, [diagram.count(w) for w in others], diagram.taken()))
    assert found[0] == found[1]
    assert found[0][0] == counted_exactly(manager, formula, first)


def counted_exactly(manager: Manager, formula: BDD, weights: dict[str, Weight]) -> int:
    """The weighted count by Shannon expansion over the variables in order (each function
    and variable once): another computation than ``CountedDiagram``'s."""
    order = sorted(weights, key=manager.level_of_var)
    known: dict[tuple[BDD, int], int] = {}

    def expand(u: BDD, index: int) -> int:
        if u == manager.false:
            return 0
        if index == len(order):
            return 1
        if (u, index) not in known:
            name = order[index]
            off, on = weights[name]
            low, high = (manager.let({name: value}, u) for value in (False, True))
            known[u, index] = off * expand(low, index + 1) + on * expand(high, index + 1)
        return known[u, index]

    return expand(formula, 0)


def test_combine_weighs_the_children() -> None:
    assert counting.combine((1, 1), 4, 6) == 5
    assert counting.combine((0, 3), 4, 6) == 6
    assert counting.combine((2, 0), 4, 6) == 4
    assert counting.combine((1, 3), 4, 8) == 7
