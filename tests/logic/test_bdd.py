"""The door to ``dd``: each function against what ``dd``'s own (slower) operations give.

Random formulas with complemented edges; copies go into a manager with another variable
order and many more variables, and must equal ``dd.cudd.copy_bdd`` of ``exist``.
"""

from __future__ import annotations

import gc
import itertools
import random

import dd.cudd
import pytest

from rosvar.logic import bdd
from rosvar.logic.bdd import BDD, Manager

NAMES = [f"x{number}" for number in range(12)]
OPERATORS = ("and", "or", "xor")


def random_formula(manager: Manager, rng: random.Random, names: list[str] = NAMES) -> BDD:
    formula = manager.true if rng.random() < 0.5 else manager.false
    for _ in range(rng.randint(0, 10)):
        left, right = (manager.var(rng.choice(names)) for _ in range(2))
        if rng.random() < 0.5:
            left = ~left
        term = manager.apply(rng.choice(OPERATORS), left, right)
        formula = manager.apply(rng.choice(OPERATORS), formula, term)
    return ~formula if rng.random() < 0.3 else formula


def fresh(names: list[str] = NAMES) -> Manager:
    manager: Manager = dd.cudd.BDD()
    manager.declare(*names)
    return manager


def assignments(names: list[str]) -> list[dict[str, bool]]:
    return [
        dict(zip(names, bits, strict=True))
        for bits in itertools.product((False, True), repeat=len(names))
    ]


def nodes(u: BDD) -> list[BDD]:
    """Every function under ``u`` (with complement marks, as ``cofactors`` gives them)."""
    found: list[BDD] = []
    stack = [u]
    while stack:
        v = stack.pop()
        if v in found:
            continue
        found.append(v)
        if v.var is not None:
            stack.extend(bdd.cofactors(v))
    return found


def test_a_new_manager_does_not_reorder_and_bounds_its_cache() -> None:
    manager = bdd.new_manager(64 << 20, 1 << 12, 1 << 10)
    settings = manager.configure()
    assert settings["reordering"] is False
    assert settings["max_cache_hard"] == 1 << 12


@pytest.mark.parametrize("seed", range(20))
def test_cofactors_regular_and_complemented(seed: int) -> None:
    manager = fresh()
    for u in nodes(random_formula(manager, random.Random(seed))):
        assert bdd.regular(u) == (~u if bdd.complemented(u) else u)
        assert not bdd.complemented(bdd.regular(u))
        if u.var is not None:
            expected = (manager.let({u.var: False}, u), manager.let({u.var: True}, u))
            assert bdd.cofactors(u) == expected


@pytest.mark.parametrize("seed", range(20))
def test_cofactor_fixes_values_as_let_does(seed: int) -> None:
    rng = random.Random(seed)
    manager = fresh()
    u = random_formula(manager, rng)
    values = {name: rng.random() < 0.5 for name in rng.sample(NAMES, rng.randint(0, 5))}
    assert bdd.cofactor(u, values) == (manager.let(values, u) if values else u)


@pytest.mark.parametrize("seed", range(10))
def test_cube_is_dd_cube(seed: int) -> None:
    rng = random.Random(seed)
    manager = fresh()
    values = {name: rng.random() < 0.5 for name in rng.sample(NAMES, rng.randint(0, 8))}
    assert bdd.cube(manager, values) == manager.cube(values)


def test_cubes_remember_each_set_of_literals_and_cofactor_by_it() -> None:
    rng = random.Random(4)
    manager = fresh()
    cubes = bdd.Cubes(manager, capacity=4)
    for _ in range(40):
        u = random_formula(manager, rng)
        values = {name: rng.random() < 0.5 for name in rng.sample(NAMES[:3], rng.randint(0, 3))}
        literals = frozenset(values.items())
        assert cubes.cofactor(u, literals) == bdd.cofactor(u, values)
        assert cubes.of(literals) is cubes.of(literals)  # built once while remembered


@pytest.mark.parametrize("seed", range(10))
def test_evaluate_is_let_under_a_full_assignment(seed: int) -> None:
    manager = fresh(NAMES[:6])
    u = random_formula(manager, random.Random(seed), NAMES[:6])
    position = {name: 5 - number for number, name in enumerate(NAMES[:6])}
    for values in assignments(NAMES[:6]):
        expected = manager.let(values, u) == manager.true
        assert bdd.evaluate(u, values.__getitem__) == expected
        assert bdd.evaluate(~u, values.__getitem__) != expected
        # as the configuration engine gives it: a bit mask, read as truthy integers
        bits = sum(1 << position[name] for name, value in values.items() if value)

        def bit(name: str, bits: int = bits) -> int:
            return bits >> position[name] & 1

        assert bdd.evaluate(u, bit) == expected


@pytest.mark.parametrize("seed", range(20))
def test_walked_support_is_dd_support(seed: int) -> None:
    manager = fresh()
    u = random_formula(manager, random.Random(seed))
    assert bdd.walked_support(u) == manager.support(u)


@pytest.mark.parametrize("seed", range(10))
def test_children_first_gives_each_node_after_its_children(seed: int) -> None:
    manager = fresh()
    u = random_formula(manager, random.Random(seed))
    done: set[BDD] = {manager.true, manager.false}
    for node in bdd.children_first(u, bdd.cofactors, done):
        assert node not in done
        assert all(child in done for child in bdd.cofactors(node))
        done.add(node)
    assert set(nodes(u)) <= done


@pytest.mark.parametrize("seed", range(10))
def test_conjoin_restrict_and_meets(seed: int) -> None:
    rng = random.Random(seed)
    manager = fresh()
    parts = [random_formula(manager, rng) for _ in range(4)] + [manager.true]
    expected = manager.true
    for part in parts:
        expected &= part
    assert bdd.conjoin(manager, parts) == expected
    u, care = parts[0], parts[1]
    assert (bdd.restrict(u, care) & care) == (u & care)
    for v in (care, ~u, u & ~care, manager.false, manager.true):
        assert bdd.meets(u, v) == ((u & v) != manager.false)
    with pytest.raises(ValueError):
        bdd.meets(u, fresh().true)


def test_the_memory_bound_refuses_growth_and_is_lifted() -> None:
    manager = fresh([f"x{number}" for number in range(3000)])

    def parity() -> BDD:
        result = manager.false
        for number in range(3000):  # about two nodes per variable: beyond one node chunk
            result = manager.apply("xor", result, manager.var(f"x{number}"))
        return result

    with pytest.raises(bdd.OutOfMemory), bdd.memory_bound(manager, 1):
        assert manager.configure()["max_memory"] == 1
        parity()
    assert manager.configure()["max_memory"] > 1
    assert len(parity()) > 3000
    gc.collect()  # the failed build's nodes, held by the error's frames, go before their manager


def test_collected_garbage_is_the_nodes_nothing_holds() -> None:
    manager = fresh([f"x{number}" for number in range(64)])
    kept = manager.var("x0") & manager.var("x1")
    before = bdd.held_nodes(manager)
    dropped = manager.false
    for number in range(2, 64):  # a chain, no part of which ``kept`` holds
        dropped = manager.apply("xor", dropped, manager.var(f"x{number}") & manager.var("x0"))
    del dropped
    assert bdd.held_nodes(manager) > before  # CUDD keeps dead nodes until it collects them
    bdd.collect_garbage(manager)
    assert bdd.held_nodes(manager) == before
    assert kept == manager.var("x1") & manager.var("x0") and len(kept) == 3


@pytest.mark.parametrize("seed", range(100))
def test_copies_and_quantifies_as_dd_does(seed: int) -> None:
    rng = random.Random(seed)
    source, target = dd.cudd.BDD(), dd.cudd.BDD()
    source.declare(*NAMES)
    target.declare(*[f"pad{number}" for number in range(50)], *reversed(NAMES))
    formula = random_formula(source, rng)
    hidden = set(rng.sample(NAMES, rng.randint(0, 4)))
    expected = dd.cudd.copy_bdd(source.exist(hidden, formula) if hidden else formula, target)
    assert bdd.transfer(formula, target, hidden) == expected


def test_transfer_of_constants() -> None:
    source, target = dd.cudd.BDD(), dd.cudd.BDD()
    assert bdd.transfer(source.true, target) == target.true
    assert bdd.transfer(source.false, target) == target.false


# -- the raw reader ---------------------------------------------------------------------------
def test_complemented_edges_flip_the_lowest_bit_of_int() -> None:
    """``read`` tells a complemented child's node by ``int(u) ^ 1``."""
    manager = fresh(["a", "b", "c"])
    u = (manager.var("a") & manager.var("b")) | ~manager.var("c")
    for node in (u, u.low, u.high, manager.true, manager.var("c")):
        assert int(~node) == int(node) ^ 1


@pytest.mark.parametrize("seed", range(20))
def test_nodes_read_in_memory_are_those_dd_shows(seed: int, bdd_reader: str) -> None:
    """Each node ``read`` found in CUDD's memory has the level and children that ``dd``'s
    wrappers give (a complemented low edge as ``~place``), every node is reached, and
    children come before their parents."""
    rng = random.Random(seed)
    names = NAMES[:8] if seed < 10 else NAMES  # then many nodes a level, several levels down
    manager = fresh(names)
    formula = random_formula(manager, rng, names)
    if seed >= 10:
        for _ in range(6):
            formula = manager.apply("xor", formula, random_formula(manager, rng, names))
    levels, lows, highs, root, _ = bdd.read(
        manager, formula, [manager.level_of_var(name) for name in names]
    )
    function_at: dict[int, BDD] = {}  # place → its function (never complemented), from the root
    pending = [(~root if root < 0 else root, ~formula if root < 0 else formula)]
    while pending:
        place, function = pending.pop()
        assert function_at.setdefault(place, function) == function
        if place == 0:
            assert function == manager.true
            continue
        assert levels[place] == function.level
        low, high = lows[place], highs[place]
        assert 0 <= high < place and 0 <= (~low if low < 0 else low) < place
        pending.append((high, function.high))
        pending.append((~low, ~function.low) if low < 0 else (low, function.low))
    assert len(function_at) == len(levels)
    assert levels[0] == len(manager.vars)  # TRUE, below every variable


@pytest.mark.parametrize("seed", range(30))
def test_taken_is_what_some_model_sets(seed: int, bdd_reader: str) -> None:
    """The values ``taken`` finds are those of the satisfying assignments."""
    names = NAMES[:6]
    manager = fresh(names)
    formula = random_formula(manager, random.Random(seed), names)
    level_of = {name: manager.level_of_var(name) for name in names}
    levels, lows, highs, root, arrays = bdd.read(manager, formula, level_of.values())
    models = [v for v in assignments(names) if manager.let(v, formula) == manager.true]
    expected = {name: {model[name] for model in models} for name in names}
    assert bdd.taken(levels, lows, highs, root, level_of, arrays) == expected
