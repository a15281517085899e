"""Questions the feature model's solver answers: counting, core/dead features, simplest triggers."""

from __future__ import annotations

import gc
import itertools
from typing import TYPE_CHECKING

import dd.cudd
import pytest

from rosvar.analyses import features
from rosvar.analyses.features import (
    FeatureModel,
    ModelTooLarge,
    core_and_dead,
    count_configurations,
    extract,
    simplest_trigger,
)
from rosvar.logic.inputs import ArgInput

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

INCLUDE = '  <include file="$(find pkg)/launch/{target}"{attrs}/>\n'


def brute_force_count(model: FeatureModel) -> int:
    """Valid configurations by enumeration: the tree checked by hand, constraints via ``let``."""
    solver = model.solver
    names = solver.variables
    assert len(names) <= 16, "too many variables to enumerate"
    manager = solver.manager
    files = [
        (str(f.variable.var), [[str(v.variable.var) for v in arg.values] for arg in f.args])
        for f in model.files
    ]
    assert sorted(n for f, args in files for n in [f, *itertools.chain(*args)]) == sorted(names)
    total = 0
    for bits in itertools.product((False, True), repeat=len(names)):
        values = dict(zip(names, bits, strict=True))
        tree_ok = all(
            all(sum(values[v] for v in group) == (1 if values[file] else 0) for group in args)
            for file, args in files
        )
        if not tree_ok:
            continue
        if all(manager.let(values, c) == manager.true for c in solver.constraints):
            total += 1
    return total


def two_files(ws: LaunchWorkspace) -> FeatureModel:
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
    return extract(ws.analysis())


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
    two_files(ws)
    model = extract(ws.analysis(), products=True)
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
    assert count_configurations(model) == brute_force_count(model)
    assert count_configurations(model) > 1


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
    ws: LaunchWorkspace, model: FeatureModel, condition: object, file: str, trigger: dict[str, str]
) -> bool:
    """Does ``name:=value`` for every entry of ``trigger`` (args of ``file``) make it true?"""
    path = str(ws.root / "pkg" / "launch" / file)
    space = model.space
    given: dict[ArgInput, str | None] = {}
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
def test_one_pass_possible_values_match_asking_the_solver(system: str) -> None:
    """possible_values (one BDD traversal) agrees with two solver queries per variable."""
    from pathlib import Path

    from rosvar.analyses.features import possible_values
    from rosvar.interpreter.analysis import Analysis
    from rosvar.workspace import discover

    root = Path(__file__).resolve().parents[2]
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


# -- the solver's structure: components, exclusions per name ---------------------------------
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


def unweighted_count(manager: dd.cudd.BDD, formula: dd.cudd.Function, nvars: int) -> int:
    """Satisfying assignments of the ``nvars`` first levels, in Python integers: the plain
    recursion over the whole diagram, without the weights and stand-ins under test."""
    return _below(manager, {}, formula, 0, nvars)


def _below(
    manager: dd.cudd.BDD,
    memo: dict[dd.cudd.Function, int],
    edge: dd.cudd.Function,
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
    assert features.possible_values(solver) == features.possible_values(solver, solver.formula)
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
    monkeypatch.setattr(features, "LINKS_PER_FILE", 0)
    monkeypatch.setattr(features, "LINK_BUDGET", 3)  # clique_and_loner: /n links 3 pairs, /p 1
    model = clique_and_loner(ws)
    assert not model.solved and count_configurations(model) is None
    assert "clashes" not in vars(model) and "constraints" not in vars(model)  # not built yet
    with pytest.raises(ModelTooLarge, match="4 pairs of files"):
        core_and_dead(model)
    assert [d.code for d in model.diagnostics] == ["model-too-large"]
    assert {c.kind for c in model.constraints} == {"excludes", "requires"}
    monkeypatch.setattr(features, "LINK_BUDGET", 4)  # at most the budget: solved
    assert extract(ws.analysis()).solved
    monkeypatch.setattr(features, "LINK_BUDGET", 0)
    monkeypatch.setattr(features, "LINKS_PER_FILE", 1)  # 7 files: a budget of 7 pairs
    assert extract(ws.analysis()).solved


def test_the_memory_bound_grows_with_the_files(monkeypatch: pytest.MonkeyPatch) -> None:
    manager = dd.cudd.BDD()
    monkeypatch.setattr(features, "MEMORY_BUDGET", 1 << 20)
    monkeypatch.setattr(features, "MEMORY_PER_FILE", 1 << 20)
    with features._memory_bound(manager, 3):
        assert manager.configure()["max_memory"] == 4 << 20
    assert manager.configure()["max_memory"] > 4 << 20  # lifted afterwards


def test_memory_bound_turns_the_refusal_of_cudd_into_model_too_large(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    manager = dd.cudd.BDD()
    names = [f"x{number}" for number in range(3000)]
    manager.declare(*names)

    def parity() -> dd.cudd.Function:
        result = manager.false
        for name in names:  # about two nodes per variable: many more than one node chunk
            result = manager.apply("xor", result, manager.var(name))
        return result

    monkeypatch.setattr(features, "MEMORY_BUDGET", 1)
    with pytest.raises(ModelTooLarge), features._memory_bound(manager, 0):
        parity()
    assert len(parity()) > len(names)  # the bound is lifted afterwards
    gc.collect()  # the failed build's nodes, held by the error's frames, go before their manager
