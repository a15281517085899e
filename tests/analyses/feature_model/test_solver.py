"""The solver's structure: components, exclusions per name, stand-ins, its budgets."""

from __future__ import annotations

import gc
from typing import TYPE_CHECKING

import dd.cudd
import pytest

from analyses.feature_model.helpers import INCLUDE, brute_force_count
from rosvar.analyses.feature_model import extraction, operations
from rosvar.analyses.feature_model import solver as solving
from rosvar.analyses.feature_model.counting import CountedDiagram
from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.feature_model.features import ModelTooLarge
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.operations import (
    core_and_dead,
    count_configurations,
)
from rosvar.logic.bdd import BDD, Manager

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def clique_and_loner(ws: LaunchWorkspace) -> FeatureModel:
    """Three files redeclaring /n (one only under an arg, one only under an environment
    variable), two files clashing on /p or /q depending on an environment variable, a
    file one of them includes, and a file on its own."""
    ws.launch(
        "a.launch",
        '  <arg name="use" default="true"/>\n  <node pkg="pkg" type="t" name="n" if="$(arg use)"/>',
    )
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="n"/>')
    ws.launch("c.launch", '  <node pkg="pkg" type="t" name="n" if="$(optenv FLAG true)"/>')
    both = (
        '  <node pkg="pkg" type="t" name="p" if="$(optenv SIDE true)"/>\n'
        '  <node pkg="pkg" type="t" name="q" unless="$(optenv SIDE true)"/>\n'
    )
    ws.launch("d.launch", both)
    ws.launch("e.launch", both + INCLUDE.format(target="f.launch", attrs=""))
    ws.launch(
        "f.launch", '  <arg name="mode" default="slow"/>\n  <param name="m" value="$(arg mode)"/>'
    )
    ws.launch(
        "g.launch", '  <arg name="level" default="1"/>\n  <param name="l" value="$(arg level)"/>'
    )
    return extract(ws.analysis())


def test_formula_is_the_tree_and_every_constraint(ws: LaunchWorkspace) -> None:
    """Exclusions enter per clashing name, yet the formula is exactly tree ∧ constraints."""
    model = clique_and_loner(ws)
    solver = model.solver
    assert {c.kind for c in model.constraints} == {"excludes", "requires"}
    expected = solver.tree
    for constraint in solver.constraints:
        expected &= constraint
    assert solver.formula == expected
    assert count_configurations(model) == brute_force_count(model)


def test_components_are_the_linked_files(ws: LaunchWorkspace) -> None:
    model = clique_and_loner(ws)
    components = sorted(
        sorted(name.rsplit("/", 1)[1] for name in c.files) for c in model.solver.components
    )
    assert components == [
        ["a.launch", "b.launch", "c.launch"],
        ["d.launch", "e.launch", "f.launch"],
        ["g.launch"],
    ]
    variables = [v for c in model.solver.components for v in c.variables]
    assert sorted(variables) == sorted(model.solver.variables)


def test_count_under_choices_is_the_product_over_components(ws: LaunchWorkspace) -> None:
    model = clique_and_loner(ws)
    solver = model.solver
    assert solver.count() == count_configurations(model)
    b = next(f for f in model.files if f.id.endswith("/b.launch"))
    level = next(a for f in model.files for a in f.args if a.name == "level")
    choices = {str(b.variable.var): True, str(level.values[0].variable.var): True}
    restricted = solver.manager.let(choices, solver.formula)
    free = len(solver.variables) - len(choices)
    assert solver.count(choices) == int(solver.manager.count(restricted, nvars=free))
    assert 0 < solver.count(choices) < solver.count()


def unweighted_count(manager: Manager, formula: BDD, nvars: int) -> int:
    """Satisfying assignments of the ``nvars`` first levels, in Python integers: the plain
    recursion over the whole diagram, without the weights and stand-ins under test."""
    return _below(manager, {}, formula, 0, nvars)


def _below(
    manager: Manager,
    memo: dict[BDD, int],
    edge: BDD,
    level: int,
    nvars: int,
) -> int:
    """Assignments of the levels from ``level`` on that ``edge`` accepts."""
    if edge == manager.true:
        return 1 << (nvars - level)
    if edge == manager.false:
        return 0
    if edge not in memo:
        node = ~edge if edge.negated else edge
        count = sum(_below(manager, memo, c, node.level + 1, nvars) for c in (node.low, node.high))
        memo[edge] = count if not edge.negated else (1 << (nvars - edge.level)) - count
    return memo[edge] << (edge.level - level)


def stand_ins(ws: LaunchWorkspace) -> FeatureModel:
    """``side`` decides a clash on one value (``right``) and has four values no constraint
    mentions (``left``, ``up``, ``down`` and ``<other>``, which is none of the values
    known); ``speed`` is mentioned by no constraint."""
    ws.launch(
        "a.launch",
        '  <arg name="side" default="left"/>\n  <arg name="speed" default="slow"/>\n'
        '  <node pkg="pkg" type="t" name="n" if="$(eval side == \'right\')"/>\n'
        '  <param name="s" value="$(arg speed)"/>\n'
        '  <param name="t" value="$(arg side)"/>',
    )
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="n"/>')
    for value in ("up", "down"):
        ws.launch(
            f"{value}.launch",
            '  <include file="$(find pkg)/launch/a.launch">\n'
            f'    <arg name="side" value="{value}"/>\n  </include>',
        )
    return extract(ws.analysis())


def test_stand_ins_count_as_the_values_they_replace_under_any_choice(
    ws: LaunchWorkspace,
) -> None:
    model = stand_ins(ws)
    solver = model.solver
    a = next(c for c in solver.components if any(f.endswith("/a.launch") for f in c.files))
    groups = [len(names) for _stand_in, names in a.stand_ins]
    assert sorted(groups) == [2, 4]  # speed (its file stands in), side's other values
    assert len(a.counted_variables) < len(a.variables)
    everything = len(solver.variables)
    for name in solver.variables:
        for value in (False, True):
            restricted = solver.manager.let({name: value}, solver.formula)
            expected = int(solver.manager.count(restricted, nvars=everything - 1))
            assert solver.count({name: value}) == expected, (name, value)
    whole = CountedDiagram(solver.manager, solver.formula, dict.fromkeys(solver.variables, (1, 1)))
    assert operations.possible_values(solver) == whole.taken()
    pairs = [(n, m) for n in a.variables for m in a.variables if n < m]
    for first, second in pairs:
        choices = {first: True, second: False}
        restricted = solver.manager.let(choices, solver.formula)
        assert solver.count(choices) == int(solver.manager.count(restricted, nvars=everything - 2))


def test_counts_beyond_a_double_are_exact(ws: LaunchWorkspace) -> None:
    """36 args of three values each: 3^36 > 2^53 ways to configure a.launch alone."""
    flags = "".join(
        f'  <arg name="f{i}" default="true"/>\n'
        f'  <node pkg="pkg" type="t" name="n{i}" if="$(arg f{i})"/>\n'
        for i in range(36)
    )
    ws.launch("a.launch", flags + '  <node pkg="pkg" type="t" name="x" if="$(arg f0)"/>')
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="x"/>')
    model = extract(ws.analysis())
    solver = model.solver
    exact = unweighted_count(solver.manager, solver.formula, len(solver.variables))
    assert int(float(exact)) != exact  # a double could not hold it
    assert count_configurations(model) == exact


def test_restrict_touches_only_the_chosen_components(ws: LaunchWorkspace) -> None:
    model = clique_and_loner(ws)
    solver = model.solver
    level = next(a for f in model.files for a in f.args if a.name == "level")
    name = str(level.values[0].variable.var)
    home = solver.component_of[name]
    restricted = solver.restrict({name: False})
    for number, (component, formula) in enumerate(zip(solver.components, restricted, strict=True)):
        if number == home:
            assert (
                formula == solver.manager.let({name: False}, component.formula) != component.formula
            )
        else:
            assert formula == component.formula


def test_a_model_linking_too_many_files_is_listed_not_solved(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Over the link budget nothing pairwise is computed up front; the listing still is."""
    monkeypatch.setattr(extraction, "LINKS_PER_FILE", 0)
    monkeypatch.setattr(extraction, "LINK_BUDGET", 3)  # clique_and_loner: /n links 3 pairs, /p 1
    model = clique_and_loner(ws)
    assert not model.solved and count_configurations(model) is None
    assert "clashes" not in vars(model) and "constraints" not in vars(model)  # not built yet
    with pytest.raises(ModelTooLarge, match="4 pairs of files"):
        core_and_dead(model)
    assert [d.code for d in model.diagnostics] == ["model-too-large"]
    assert {c.kind for c in model.constraints} == {"excludes", "requires"}
    monkeypatch.setattr(extraction, "LINK_BUDGET", 4)  # at most the budget: solved
    assert extract(ws.analysis()).solved
    monkeypatch.setattr(extraction, "LINK_BUDGET", 0)
    monkeypatch.setattr(extraction, "LINKS_PER_FILE", 1)  # 7 files: a budget of 7 pairs
    assert extract(ws.analysis()).solved


def test_a_model_whose_order_too_many_constraints_cross_is_listed_not_solved(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The widest cut of the solver's order is told before any diagram is built; a model
    at the budget is solved, one constraint above it is not."""
    monkeypatch.setattr(solving, "CUT_BUDGET", 0)
    model = clique_and_loner(ws)
    assert not model.solved and count_configurations(model) is None
    with pytest.raises(ModelTooLarge, match="cross one point") as raised:
        core_and_dead(model)
    crossing = int(str(raised.value).split()[0])
    assert crossing >= 1
    monkeypatch.setattr(solving, "CUT_BUDGET", crossing - 1)
    assert not extract(ws.analysis()).solved
    monkeypatch.setattr(solving, "CUT_BUDGET", crossing)
    assert extract(ws.analysis()).solved


def test_the_memory_bound_grows_with_the_files(monkeypatch: pytest.MonkeyPatch) -> None:
    manager = dd.cudd.BDD()
    monkeypatch.setattr(solving, "MEMORY_BUDGET", 1 << 20)
    monkeypatch.setattr(solving, "MEMORY_PER_FILE", 1 << 20)
    with solving.memory_bound(manager, 3):
        assert manager.configure()["max_memory"] == 4 << 20
    assert manager.configure()["max_memory"] > 4 << 20  # lifted afterwards


def test_memory_bound_turns_the_refusal_of_cudd_into_model_too_large(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    manager: Manager = dd.cudd.BDD()
    names = [f"x{number}" for number in range(3000)]
    manager.declare(*names)

    def parity() -> BDD:
        result = manager.false
        for name in names:  # about two nodes per variable: many more than one node chunk
            result = manager.apply("xor", result, manager.var(name))
        return result

    monkeypatch.setattr(solving, "MEMORY_BUDGET", 1)
    with pytest.raises(ModelTooLarge), solving.memory_bound(manager, 0):
        parity()
    assert len(parity()) > len(names)  # the bound is lifted afterwards
    gc.collect()  # the failed build's nodes, held by the error's frames, go before their manager
