"""Questions the feature model's solver answers: counting, core/dead features, simplest triggers."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest

from analyses.feature_model.helpers import INCLUDE, brute_force_count
from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.operations import (
    core_and_dead,
    count_configurations,
    simplest_trigger,
)
from rosvar.logic.bdd import BDD
from rosvar.logic.inputs import ArgInput, Input

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def two_files(ws: LaunchWorkspace, *, products: bool = False) -> FeatureModel:
    ws.launch(
        "a.launch",
        '  <arg name="robot" default="kobuki"/>\n'
        '  <arg name="use_x" default="true"/>\n'
        '  <node pkg="pkg" type="t" name="$(arg robot)"/>\n'
        '  <node pkg="pkg" type="t" name="x" if="$(arg use_x)"/>\n'
        + INCLUDE.format(target="b.launch", attrs=""),
    )
    ws.launch(
        "b.launch",
        '  <arg name="mode" default="slow"/>\n'
        '  <param name="speed" value="$(arg mode)"/>\n'
        '  <node pkg="pkg" type="t" name="x"/>\n',
    )
    return extract(ws.analysis(), products=products)


def test_count_by_hand_for_two_files(ws: LaunchWorkspace) -> None:
    model = two_files(ws)
    values = {a.id: [v.value for v in a.values] for f in model.files for a in f.args}
    assert values == {
        "pkg/launch/a.launch:robot": ["kobuki", "<other>"],
        "pkg/launch/a.launch:use_x": ["true", "false", "<other>"],
        "pkg/launch/b.launch:mode": ["slow", "<other>"],
    }
    # Tree: a selected picks 2 robot x 3 use_x values = 6 ways, or a is off: 7.
    #       b selected picks 2 mode values, or b is off: 3.          7 x 3 = 21.
    # a requires b (unconditional include): drop "a on, b off" = 6 x 1 -> 15.
    # a and b both declare /x when use_x holds: drop a on (use_x=true) and b on:
    #       2 robot x 1 x 2 mode = 4 -> 11. (use_x=<other> may be any string, e.g. "0":
    #       not a clash for every value, so the solver keeps it.)
    assert count_configurations(model) == 11
    assert brute_force_count(model) == 11


def test_in_products_an_included_file_takes_its_args_from_the_include(
    ws: LaunchWorkspace,
) -> None:
    """As above, but a requires b with b's args at their defaults (``products``): "a on,
    b on, mode=<other>" goes too (2 robot x 3 use_x = 6 -> 9), then the clash as above
    (2 robot x 1 x 1 mode = 2 -> 7)."""
    model = two_files(ws, products=True)
    assert count_configurations(model) == brute_force_count(model) == 7
    [requires] = model.requires
    assert requires.text.endswith("which takes no args from the command line then")


@pytest.mark.parametrize("extra_if", ["", ' if="$(arg flag)"'])
def test_count_equals_brute_force(ws: LaunchWorkspace, extra_if: str) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="flag" default="false"/>\n'
        '  <node pkg="pkg" type="t" name="n" unless="$(arg flag)"/>\n'
        + INCLUDE.format(target="b.launch", attrs=extra_if),
    )
    ws.launch(
        "b.launch",
        '  <arg name="side" default="left"/>\n'
        '  <node pkg="pkg" type="t" name="n" if="$(eval side == \'right\')"/>\n',
    )
    ws.launch("c.launch", '  <node pkg="pkg" type="t" name="n"/>')
    model = extract(ws.analysis())
    assert len(model.solver.variables) <= 16
    count = count_configurations(model)
    assert count == brute_force_count(model)
    assert count is not None and count > 1


def test_empty_selection_is_valid_so_no_feature_is_core(ws: LaunchWorkspace) -> None:
    model = two_files(ws)
    solver = model.solver
    nothing = dict.fromkeys(solver.variables, False)
    assert solver.manager.let(nothing, solver.formula) == solver.manager.true
    assert [v for v in core_and_dead(model) if v.kind == "core"] == []


def test_dead_value_and_its_explanation(ws: LaunchWorkspace) -> None:
    model = two_files(ws)
    verdicts = {v.feature: v for v in core_and_dead(model)}
    assert set(verdicts) == {"pkg/launch/a.launch:use_x=true"}
    verdict = verdicts["pkg/launch/a.launch:use_x=true"]
    assert verdict.kind == "dead"
    assert sorted(verdict.because) == [
        "pkg/launch/a.launch and pkg/launch/b.launch both declare node /x",
        "pkg/launch/a.launch includes pkg/launch/b.launch",
    ]


def test_file_including_a_file_it_clashes_with_is_dead(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <node pkg="pkg" type="t" name="n"/>\n' + INCLUDE.format(target="b.launch", attrs=""),
    )
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="n"/>')
    # unrelated constraints that an explanation must leave out
    ws.launch("c.launch", INCLUDE.format(target="d.launch", attrs=""))
    ws.launch("d.launch", '  <node pkg="pkg" type="t" name="d"/>')
    ws.launch("e.launch", '  <node pkg="pkg" type="t" name="d"/>')
    model = extract(ws.analysis())
    verdicts = {v.feature: v for v in core_and_dead(model)}
    # c is not dead: c requires d, and d only excludes e (c without e is fine)
    assert set(verdicts) == {"pkg/launch/a.launch"}
    assert verdicts["pkg/launch/a.launch"].kind == "dead"
    assert sorted(verdicts["pkg/launch/a.launch"].because) == [
        "pkg/launch/a.launch and pkg/launch/b.launch both declare node /n",
        "pkg/launch/a.launch includes pkg/launch/b.launch",
    ]
    solver = model.solver
    c, e = (
        solver.var(f.variable)
        for f in model.files
        if f.id in ("pkg/launch/c.launch", "pkg/launch/e.launch")
    )
    assert (solver.formula & c & e) == solver.manager.false


def test_no_dead_features_without_conflicts(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="x" default="true"/>\n  <node pkg="pkg" type="t" name="a" if="$(arg x)"/>\n'
        + INCLUDE.format(target="b.launch", attrs=""),
    )
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="b"/>')
    assert core_and_dead(extract(ws.analysis())) == []


# -- simplest_trigger --------------------------------------------------------------------------
def satisfied_by(
    ws: LaunchWorkspace, model: FeatureModel, condition: BDD, file: str, trigger: dict[str, str]
) -> bool:
    """Does ``name:=value`` for every entry of ``trigger`` (args of ``file``) make it true?"""
    path = str(ws.root / "pkg" / "launch" / file)
    space = model.space
    given: dict[Input, str | None] = {}
    for input_ in space.inputs():
        if isinstance(input_, ArgInput) and input_.file == path:
            domain = space.domain(input_)
            given[input_] = trigger.get(
                f"{file}:{input_.name}", domain[0] if isinstance(domain[0], str) else None
            )
    return space.evaluate(condition, space.assignment(given))


def test_simplest_trigger_of_a_name_clash(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="robot" default="r1"/>\n'
        '  <arg name="rate" default="10"/>\n'
        '  <param name="rate" value="$(arg rate)"/>\n'
        '  <node pkg="pkg" type="t" name="$(arg robot)"/>\n',
    )
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="r2"/>')
    # c passes r2 to a, so r2 is a known value of a's robot
    ws.launch(
        "c.launch",
        '  <include file="$(find pkg)/launch/a.launch"><arg name="robot" value="r2"/></include>',
    )
    model = extract(ws.analysis())
    [excludes] = [c for c in model.constraints if c.kind == "excludes"]
    assert excludes.files == ("pkg/launch/a.launch", "pkg/launch/b.launch")
    assert model.space.describe(excludes.condition) == "robot=r2"
    trigger = simplest_trigger(model.space, excludes.condition)
    assert satisfied_by(ws, model, excludes.condition, "a.launch", trigger)
    defaults = {"a.launch:rate": "10", "a.launch:robot": "r1"}
    changed = {k: v for k, v in trigger.items() if defaults.get(k) != v}
    assert changed == {"a.launch:robot": "r2"}


@pytest.mark.parametrize(
    ("declaration", "test", "wanted"),
    [
        pytest.param('<arg name="x" default="false"/>', "$(arg x)", "true", id="if"),
        pytest.param('<arg name="x" default="r1"/>', "$(eval x == 'r2')", "r2", id="eval"),
    ],
)
def test_simplest_trigger_gives_typeable_values(
    ws: LaunchWorkspace, declaration: str, test: str, wanted: str
) -> None:
    """A known literal, not ``<other>`` (no value a user can type), when one triggers it."""
    ws.launch("a.launch", f'  {declaration}\n  <node pkg="pkg" type="t" name="n" if="{test}"/>')
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="n"/>')
    model = extract(ws.analysis())
    [excludes] = [c for c in model.constraints if c.kind == "excludes"]
    assert model.space.describe(excludes.condition) in ("x", "x=r2")
    trigger = simplest_trigger(model.space, excludes.condition)
    assert trigger == {"a.launch:x": wanted}
    assert satisfied_by(ws, model, excludes.condition, "a.launch", trigger)


def test_simplest_trigger_leaves_unrelated_args_alone(ws: LaunchWorkspace) -> None:
    """Args of other files (and of the same file) that the clash does not need stay default."""
    ws.launch(
        "a.launch",
        '  <arg name="robot" default="r1"/>\n'
        '  <node pkg="pkg" type="t" name="n" if="$(eval robot == \'r2\')"/>\n',
    )
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="n"/>')
    for i in range(3):
        ws.launch(
            f"z{i}.launch",
            f'  <arg name="q{i}" default="d"/>\n  <arg name="w{i}" default="true"/>\n'
            f'  <param name="q{i}" value="$(arg q{i})"/>\n'
            f'  <node pkg="pkg" type="t" name="z{i}" if="$(arg w{i})"/>\n',
        )
    model = extract(ws.analysis())
    [excludes] = [c for c in model.constraints if c.kind == "excludes"]
    trigger = simplest_trigger(model.space, excludes.condition)
    defaults = {
        "a.launch:robot": "r1",
        **{f"z{i}.launch:q{i}": "d" for i in range(3)},
        **{f"z{i}.launch:w{i}": "true" for i in range(3)},
    }
    changed = {k: v for k, v in trigger.items() if defaults.get(k) != v}
    assert changed == {"a.launch:robot": "r2"}


def test_simplest_trigger_tells_args_of_different_files_apart(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="x" default="false"/>\n  <node pkg="pkg" type="t" name="n" if="$(arg x)"/>',
    )
    ws.launch(
        "b.launch",
        '  <arg name="x" default="true"/>\n  <node pkg="pkg" type="t" name="n" unless="$(arg x)"/>',
    )
    model = extract(ws.analysis())
    [excludes] = [c for c in model.constraints if c.kind == "excludes"]
    trigger = simplest_trigger(model.space, excludes.condition)
    # some key must say a's x is true and another that b's x is false
    assert sorted(trigger.values()) == ["false", "true"]


@pytest.mark.parametrize("system", ["examples", "lizi", "kobuki"])
def test_possible_values_match_asking_the_solver(system: str) -> None:
    """possible_values (one pass per component) agrees with two solver queries per variable."""
    from pathlib import Path

    from rosvar.analyses.feature_model.operations import possible_values
    from rosvar.interpreter.workspace_models import Analysis
    from rosvar.workspace import discover

    root = Path(__file__).resolve().parents[3]
    path = root / "examples" if system == "examples" else root.parent / "shared" / "corpus" / system
    if not path.is_dir():
        pytest.skip(f"{path} is not here")
    model = extract(Analysis(discover([str(path)], ros_package_path="")))
    solver = model.solver
    fast = possible_values(solver)
    for name in solver.variables:
        variable = solver.manager.var(name)
        slow = {
            value
            for value, part in ((True, variable), (False, ~variable))
            if (solver.formula & part) != solver.manager.false
        }
        assert fast[name] == slow, name
