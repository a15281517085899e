"""The SAT solver's models against the feature model's BDDs."""

from __future__ import annotations

import random
from typing import TYPE_CHECKING

import pytest

from configuration.test_derivation import FILES
from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration import sat as sat_module
from rosvar.configuration.sat import PATHS, Sat
from rosvar.logic.bdd import BDD, conjoin

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def test_tree_and_constraints_make_the_components(ws: LaunchWorkspace) -> None:
    for name, body in FILES.items():
        ws.launch(name, body)
    solver = extract(ws.analysis()).solver
    assert conjoin(solver.manager, [solver.tree, *solver.constraints]) == solver.formula


@pytest.mark.parametrize("paths", [PATHS, 0])  # 0: every diagram by Tseitin's encoding
def test_models_are_valid_and_satisfy_what_was_asked(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch, paths: int
) -> None:
    monkeypatch.setattr(sat_module, "PATHS", paths)
    for name, body in FILES.items():
        ws.launch(name, body)
    model = extract(ws.analysis())
    solver = model.solver
    manager, formula, variables = solver.manager, solver.formula, solver.variables
    sat = Sat.whole(model)
    rng = random.Random(5)
    for _ in range(60):
        literals = {v: rng.random() < 0.5 for v in rng.sample(variables, rng.randint(0, 3))}
        a, b = (manager.var(rng.choice(variables)) for _ in range(2))
        goal = (a & ~b) | (~a & b)
        some = [sat.atom(v, rng.random() < 0.5) for v in rng.sample(variables, 2)]
        found = sat.model([sat.atom(v, b) for v, b in literals.items()], goal, some)
        wanted = formula & manager.cube(literals) & goal
        alternatives = manager.false
        for literal in some:
            atom = manager.var(variables[abs(literal) - 1])
            alternatives |= atom if literal > 0 else ~atom
        wanted &= alternatives
        assert (found is None) == (wanted == manager.false)
        if found is not None:
            values = {v: bool(found >> i & 1) for i, v in enumerate(variables)}
            assert manager.let(values, wanted) == manager.true


def test_each_component_has_a_solver_whose_models_are_its_valid_configurations(
    ws: LaunchWorkspace,
) -> None:
    for name, body in FILES.items():
        ws.launch(name, body)
    model = extract(ws.analysis())
    solver = model.solver
    manager, variables = solver.manager, solver.variables
    sats = Sat.per_component(model)
    assert len(sats) == len(solver.components) > 1
    rng = random.Random(8)
    for sat, component in zip(sats, solver.components, strict=True):
        mine = component.variables
        for _ in range(20):
            literals = {v: rng.random() < 0.5 for v in rng.sample(mine, min(2, len(mine)))}
            found = sat.model([sat.atom(v, b) for v, b in literals.items()])
            wanted = component.formula & manager.cube(literals)
            assert (found is None) == (wanted == manager.false)
            if found is not None:
                values = {v: bool(found >> i & 1) for i, v in enumerate(variables)}
                assert not {v for v, b in values.items() if b} - set(mine)  # its bits only
                assert manager.let({v: values[v] for v in mine}, wanted) == manager.true


@pytest.mark.parametrize("paths", [PATHS, 0])
def test_a_core_is_a_minimal_set_of_constraints_that_rules_literals_out(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch, paths: int
) -> None:
    """Checked against the BDDs: without the core's constraints the literals are possible,
    with them (and the tree) they are not, and without any one of them they are again."""
    monkeypatch.setattr(sat_module, "PATHS", paths)
    for name, body in FILES.items():
        ws.launch(name, body)
    model = extract(ws.analysis(), products=True)
    solver = model.solver
    manager = solver.manager
    rng = random.Random(7)
    explained = 0
    for _ in range(40):
        literals = {v: rng.random() < 0.5 for v in rng.sample(solver.variables, 2)}
        components = {solver.component_of[v] for v in literals}
        if len(components) > 1:
            continue
        [component] = components
        sat, numbers = Sat.explaining(model, component)
        core = sat.core([sat.atom(v, value) for v, value in literals.items()])
        cube = manager.cube(literals)

        def possible(chosen: list[int], cube: BDD = cube, numbers: list[int] = numbers) -> bool:
            parts = [solver.tree, cube, *(solver.constraints[numbers[i]] for i in chosen)]
            return bool(conjoin(manager, parts) != manager.false)

        if possible(list(range(len(numbers)))):
            assert core is None
            continue
        assert core is not None and not possible(core)
        assert all(possible([i for i in core if i != dropped]) for dropped in core)
        explained += 1
    assert explained > 0
