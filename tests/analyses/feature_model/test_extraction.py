"""The feature model (paper sec. IV, Algorithm 1): its tree, AFFECTSCG and cross-tree constraints.

Tree: root → launch files → args that affect the computation graph → an xor-group of values.
Constraints: an ``<include>`` *requires* its target (under the include's condition); files whose
nodes or params share a name *exclude* each other (under the arg values where both are present);
clashes inside one file are listed in :attr:`FeatureModel.internal`.
"""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

import pytest

from rosvar.analyses.feature_model.exclusions import declaring, excluding
from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.feature_model.features import ArgFeature, Constraint, FileFeature
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.operations import count_configurations
from rosvar.logic.bdd import BDD
from rosvar.logic.inputs import OTHER, ArgInput, Input

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

X = '  <arg name="x" default="v"/>\n'
TOGGLE = '  <arg name="x" default="true"/>\n'
INCLUDE_B = '  <include file="$(find pkg)/launch/b.launch"{attrs}>{body}</include>\n'
B_USES_Y = '  <arg name="y" default="w"/>\n  <node pkg="pkg" type="t" name="$(arg y)"/>\n'


def model_of(ws: LaunchWorkspace) -> FeatureModel:
    return extract(ws.analysis())


def file_feature(model: FeatureModel, name: str) -> FileFeature:
    [found] = [f for f in model.files if f.id == f"pkg/launch/{name}"]
    return found


def arg_names(model: FeatureModel, name: str) -> list[str]:
    return sorted(arg.name for arg in file_feature(model, name).args)


def arg_feature(model: FeatureModel, file: str, name: str) -> ArgFeature:
    [found] = [a for a in file_feature(model, file).args if a.name == name]
    return found


def constraints(model: FeatureModel, kind: str) -> list[Constraint]:
    return [c for c in model.constraints if c.kind == kind]


def holds(ws: LaunchWorkspace, model: FeatureModel, condition: BDD, **values: str) -> bool:
    """Truth of ``condition`` when each ``FILE__ARG=value`` is given (other args not given)."""
    given: dict[Input, str | None] = {}
    for key, value in values.items():
        file, name = key.split("__")
        given[ArgInput(str(ws.root / "pkg" / "launch" / f"{file}.launch"), name)] = value
    space = model.space
    return space.evaluate(condition, space.assignment(given))


# -- the tree ------------------------------------------------------------------------------
def test_tree_of_files_args_and_value_groups(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="robot" default="kobuki"/>\n'
        '  <arg name="use_cam" default="false"/>\n'
        '  <arg name="frame"/>\n'
        '  <node pkg="pkg" type="t" name="$(arg robot)"/>\n'
        '  <node pkg="pkg" type="t" name="cam" if="$(arg use_cam)"/>\n'
        '  <node pkg="pkg" type="t" name="tf" ns="$(arg frame)"/>\n',
    )
    model = model_of(ws)
    [feature] = model.files
    assert feature.id == "pkg/launch/a.launch"
    assert [a.name for a in feature.args] == ["robot", "use_cam", "frame"]
    robot, use_cam, frame = feature.args
    assert robot.id == "pkg/launch/a.launch:robot"
    assert [v.value for v in robot.values] == ["kobuki", "<other>"]
    assert [v.default for v in robot.values] == [True, False]
    assert robot.default == "kobuki" and not robot.boolean
    # the default first, then the other Boolean word (tested by if=), then <other>
    assert [v.value for v in use_cam.values] == ["false", "true", "<other>"]
    assert use_cam.boolean and use_cam.default == "false"
    # A required arg has no "not given" value: a product must give it.
    assert [v.slot for v in frame.values] == [OTHER]
    assert frame.default is None
    assert model.feature_ids() == [
        "pkg/launch/a.launch",
        "pkg/launch/a.launch:robot",
        "pkg/launch/a.launch:robot=kobuki",
        "pkg/launch/a.launch:robot=<other>",
        "pkg/launch/a.launch:use_cam",
        *(v.id for v in use_cam.values),
        "pkg/launch/a.launch:frame",
        "pkg/launch/a.launch:frame=<other>",
    ]


def test_tree_semantics_child_implies_parent_and_one_value_per_arg(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", TOGGLE + '  <node pkg="pkg" type="t" name="n" if="$(arg x)"/>\n')
    model = model_of(ws)
    solver = model.solver
    [feature] = model.files
    [arg] = feature.args
    present = solver.var(feature.variable)
    values = [solver.var(v.variable) for v in arg.values]
    false = solver.manager.false
    assert len(values) == 3  # true, false, <other>
    for value in values:
        assert (solver.tree & value & ~present) == false  # child ⇒ parent
        assert (solver.tree & value) != false
    for first, second in itertools.combinations(values, 2):
        assert (solver.tree & first & second) == false  # no two values of one arg
    none = solver.manager.true
    for value in values:
        none &= ~value
    # a selected file picks exactly one value; a deselected one picks none
    assert (solver.tree & present & none) == false
    assert (solver.tree & ~present & ~none) == false
    assert (solver.tree & ~present) != false


# -- AFFECTSCG: which args are features ---------------------------------------------------------
@pytest.mark.parametrize(
    "body",
    [
        pytest.param('  <node pkg="pkg" type="t" name="$(arg x)"/>', id="node-name"),
        pytest.param('  <node pkg="pkg" type="t" name="n" ns="$(arg x)"/>', id="node-ns"),
        pytest.param(
            '  <group ns="$(arg x)"><node pkg="pkg" type="t" name="n"/></group>', id="group-ns"
        ),
        pytest.param('  <node pkg="$(arg x)" type="t" name="n"/>', id="node-pkg"),
        pytest.param('  <node pkg="pkg" type="$(arg x)" name="n"/>', id="node-type"),
        pytest.param('  <param name="p" value="$(arg x)"/>', id="param-value"),
        pytest.param('  <param name="$(arg x)" value="1"/>', id="param-name"),
        pytest.param(
            '  <node pkg="pkg" type="t" name="n"><param name="p" value="$(arg x)"/></node>',
            id="private-param",
        ),
        pytest.param(
            '  <node pkg="pkg" type="t" name="n"><remap from="a" to="$(arg x)"/></node>',
            id="remap",
        ),
        pytest.param('  <rosparam ns="$(arg x)">{a: 1}</rosparam>', id="rosparam-ns"),
        pytest.param(
            '  <node pkg="pkg" type="t" name="n" if="$(eval x == \'on\')"/>', id="eval-condition"
        ),
        pytest.param(
            '  <arg name="derived" value="$(arg x)_link"/>\n'
            '  <node pkg="pkg" type="t" name="$(arg derived)"/>',
            id="through-value-arg",
        ),
    ],
)
def test_an_arg_used_by_the_graph_is_a_feature(ws: LaunchWorkspace, body: str) -> None:
    ws.launch("a.launch", X + body)
    assert arg_names(model_of(ws), "a.launch") == ["x"]


@pytest.mark.parametrize(
    "body",
    [
        pytest.param('  <node pkg="pkg" type="t" name="n" if="$(arg x)"/>', id="if"),
        pytest.param('  <node pkg="pkg" type="t" name="n" unless="$(arg x)"/>', id="unless"),
        pytest.param('  <group if="$(arg x)"><param name="p" value="1"/></group>', id="group-if"),
    ],
)
def test_an_arg_deciding_a_condition_is_a_feature(ws: LaunchWorkspace, body: str) -> None:
    ws.launch("a.launch", TOGGLE + body)
    assert arg_names(model_of(ws), "a.launch") == ["x"]


@pytest.mark.parametrize(
    "body",
    [
        pytest.param("", id="unused"),
        pytest.param('  <arg name="y" default="1" doc="$(arg x)"/>', id="only-in-doc"),
        pytest.param('  <arg name="y" value="$(arg x)"/>', id="value-arg-unused"),
        pytest.param(
            '  <node pkg="pkg" type="t" name="n" output="$(arg x)"/>', id="node-output-only"
        ),
    ],
)
def test_an_arg_the_graph_does_not_see_is_not_a_feature(ws: LaunchWorkspace, body: str) -> None:
    ws.launch("a.launch", X + body + '\n  <node pkg="pkg" type="t" name="fixed"/>')
    assert arg_names(model_of(ws), "a.launch") == []


def test_an_arg_only_set_by_value_is_not_a_feature(ws: LaunchWorkspace) -> None:
    """Husky's move_group.launch: ``command_args`` has a ``value=`` under ``if`` and under
    ``unless``; the command line cannot set it (roslaunch refuses to override it)."""
    ws.launch(
        "a.launch",
        TOGGLE + '  <arg unless="$(arg x)" name="c" value=""/>\n'
        '  <arg if="$(arg x)" name="c" value="--debug"/>\n'
        '  <node pkg="pkg" type="t" name="n" args="$(arg c)"/>\n',
    )
    assert arg_names(model_of(ws), "a.launch") == ["x"]


def test_include_arg_passing_makes_the_includers_arg_a_feature(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", X + INCLUDE_B.format(attrs="", body='<arg name="y" value="$(arg x)"/>'))
    ws.launch("b.launch", B_USES_Y)
    model = model_of(ws)
    assert arg_names(model, "a.launch") == ["x"]
    assert arg_names(model, "b.launch") == ["y"]


def test_include_arg_passing_through_a_value_arg(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        X
        + '  <arg name="z" value="$(arg x)_suffix"/>\n'
        + INCLUDE_B.format(attrs="", body='<arg name="y" value="$(arg z)"/>'),
    )
    ws.launch("b.launch", B_USES_Y)
    assert arg_names(model_of(ws), "a.launch") == ["x"]


def test_pass_all_args_makes_the_includers_arg_a_feature(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="y" default="v"/>\n'
        + INCLUDE_B.format(attrs=' pass_all_args="true"', body=""),
    )
    ws.launch("b.launch", B_USES_Y)
    assert arg_names(model_of(ws), "a.launch") == ["y"]


def test_arg_passed_through_two_levels_of_include(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", X + INCLUDE_B.format(attrs="", body='<arg name="y" value="$(arg x)"/>'))
    ws.launch(
        "b.launch",
        '  <arg name="y" default="w"/>\n'
        '  <include file="$(find pkg)/launch/c.launch"><arg name="q" value="$(arg y)"/></include>',
    )
    ws.launch("c.launch", '  <arg name="q" default="k"/>\n  <param name="p" value="$(arg q)"/>')
    model = model_of(ws)
    assert arg_names(model, "a.launch") == ["x"]
    assert arg_names(model, "b.launch") == ["y"]
    assert arg_names(model, "c.launch") == ["q"]


def test_arg_deciding_an_include_is_a_feature(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", TOGGLE + INCLUDE_B.format(attrs=' if="$(arg x)"', body=""))
    ws.launch("b.launch", B_USES_Y)
    assert arg_names(model_of(ws), "a.launch") == ["x"]


@pytest.mark.parametrize("attrs", ["", ' pass_all_args="true"'])
def test_passing_an_arg_that_the_included_file_ignores(ws: LaunchWorkspace, attrs: str) -> None:
    body = "" if attrs else '<arg name="y" value="$(arg y)"/>'
    ws.launch(
        "a.launch", '  <arg name="y" default="v"/>\n' + INCLUDE_B.format(attrs=attrs, body=body)
    )
    ws.launch(
        "b.launch",
        '  <arg name="y" default="w"/>\n  <arg name="z" default="1" doc="$(arg y)"/>\n'
        '  <node pkg="pkg" type="t" name="fixed"/>',
    )
    model = model_of(ws)
    assert arg_names(model, "a.launch") == []
    assert arg_names(model, "b.launch") == []


def test_an_arg_in_a_param_textfile_path_is_a_feature(ws: LaunchWorkspace) -> None:
    ws.write("config/a.yaml", "k: 1\n")
    ws.write("config/b.yaml", "k: 2\n")
    file = ws.launch(
        "a.launch",
        '  <arg name="x" default="a"/>\n'
        '  <param name="p" textfile="$(find pkg)/config/$(arg x).yaml"/>\n',
    )
    # The arg changes the graph: /p is "k: 1" or "k: 2" depending on it.
    assert ws.resolve_fresh(file, {"x": "a"}).params == {"/p": "k: 1\n"}
    assert ws.resolve_fresh(file, {"x": "b"}).params == {"/p": "k: 2\n"}
    assert arg_names(model_of(ws), "a.launch") == ["x"]


def test_a_required_arg_used_as_a_param_value_is_a_feature(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", '  <arg name="frame"/>\n  <param name="frame" value="$(arg frame)"/>')
    assert arg_names(model_of(ws), "a.launch") == ["frame"]


# -- requires --------------------------------------------------------------------------------
def test_include_requires_the_included_file(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", INCLUDE_B.format(attrs="", body=""))
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="n"/>')
    model = model_of(ws)
    [requires] = constraints(model, "requires")
    assert requires.files == ("pkg/launch/a.launch", "pkg/launch/b.launch")
    assert requires.unconditional
    assert model.space.describe(requires.condition) == "true"
    a, b = (file_feature(model, n) for n in ("a.launch", "b.launch"))
    solver = model.solver
    a_var, b_var = solver.var(a.variable), solver.var(b.variable)
    assert (solver.formula & a_var & ~b_var) == solver.manager.false
    assert (solver.formula & ~a_var & b_var) != solver.manager.false  # b alone is fine
    assert requires.locations[0].file.endswith("a.launch")


def test_conditional_include_gives_a_conditional_requirement(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="sim" default="false"/>\n'
        + INCLUDE_B.format(attrs=' if="$(arg sim)"', body=""),
    )
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="n"/>')
    model = model_of(ws)
    [requires] = constraints(model, "requires")
    assert not requires.unconditional
    assert model.space.describe(requires.condition) == "sim"
    assert holds(ws, model, requires.condition, a__sim="true")
    assert not holds(ws, model, requires.condition, a__sim="false")
    assert not holds(ws, model, requires.condition)  # default false
    solver = model.solver
    a, b = (file_feature(model, n) for n in ("a.launch", "b.launch"))
    [sim] = file_feature(model, "a.launch").args
    value = {v.value: solver.var(v.variable) for v in sim.values}
    a_var, b_var = solver.var(a.variable), solver.var(b.variable)
    false = solver.manager.false
    assert (solver.formula & a_var & value["true"] & ~b_var) == false
    assert (solver.formula & a_var & value["false"] & ~b_var) != false


def test_include_by_file_pattern_requires_each_target_under_its_value(
    ws: LaunchWorkspace,
) -> None:
    ws.launch("robots/r1.launch", '  <node pkg="pkg" type="t" name="r1"/>')
    ws.launch("robots/r2.launch", '  <node pkg="pkg" type="t" name="r2"/>')
    ws.launch(
        "a.launch",
        '  <arg name="robot" default="r1"/>\n'
        '  <include file="$(find pkg)/launch/robots/$(arg robot).launch"/>',
    )
    model = model_of(ws)
    found = {c.files[1]: model.space.describe(c.condition) for c in constraints(model, "requires")}
    assert found == {
        "pkg/launch/robots/r1.launch": "robot=r1",
        "pkg/launch/robots/r2.launch": "robot=r2",
    }


# -- excludes --------------------------------------------------------------------------------
def test_unconditional_clash_between_files_excludes_them(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        X + '  <node pkg="pkg" type="t" name="n"/>\n  <param name="p" value="$(arg x)"/>',
    )
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="n"/>')
    model = model_of(ws)
    [excludes] = constraints(model, "excludes")
    assert excludes.files == ("pkg/launch/a.launch", "pkg/launch/b.launch")
    assert excludes.unconditional
    assert model.space.describe(excludes.condition) == "true"
    assert "node /n" in excludes.text
    assert sorted(loc.file.rsplit("/", 1)[1] for loc in excludes.locations) == [
        "a.launch",
        "b.launch",
    ]
    solver = model.solver
    a, b = (solver.var(file_feature(model, n).variable) for n in ("a.launch", "b.launch"))
    false = solver.manager.false
    assert (solver.formula & a & b) == false
    assert (solver.formula & a & ~b) != false
    assert (solver.formula & ~a & b) != false


def test_param_clash_between_files_excludes_them(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", '  <param name="rate" value="1"/>')
    ws.launch("b.launch", '  <group ns="/"><param name="/rate" value="2"/></group>')
    ws.launch("c.launch", '  <group ns="other"><param name="rate" value="3"/></group>')
    model = model_of(ws)
    [excludes] = constraints(model, "excludes")
    assert excludes.files == ("pkg/launch/a.launch", "pkg/launch/b.launch")
    assert excludes.unconditional and "param /rate" in excludes.text


def test_conditional_clash_is_a_formula_over_both_files_args(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="x" default="false"/>\n  <node pkg="pkg" type="t" name="n" if="$(arg x)"/>',
    )
    ws.launch(
        "b.launch",
        '  <arg name="y" default="false"/>\n'
        '  <node pkg="pkg" type="t" name="n" unless="$(arg y)"/>',
    )
    model = model_of(ws)
    [excludes] = constraints(model, "excludes")
    assert not excludes.unconditional
    assert model.space.describe(excludes.condition) == "x ∧ ¬y"
    described = model.space.describe(excludes.condition, qualify=True)
    assert "a.launch:x" in described and "b.launch:y" in described
    assert holds(ws, model, excludes.condition, a__x="true", b__y="false")
    assert not holds(ws, model, excludes.condition, a__x="false", b__y="false")
    assert not holds(ws, model, excludes.condition, a__x="true", b__y="true")
    # In the solver: both files together are fine unless x=true and y=false.
    solver = model.solver
    a, b = (file_feature(model, n) for n in ("a.launch", "b.launch"))
    x = {v.value: solver.var(v.variable) for v in a.args[0].values}
    y = {v.value: solver.var(v.variable) for v in b.args[0].values}
    both = solver.formula & solver.var(a.variable) & solver.var(b.variable)
    false = solver.manager.false
    assert (both & x["true"] & y["false"]) == false
    assert (both & x["true"] & y["true"]) != false
    assert (both & x["false"] & y["false"]) != false


def test_files_with_disjoint_names_do_not_exclude_each_other(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", '  <node pkg="pkg" type="t" name="a"/>\n  <param name="pa" value="1"/>')
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="b"/>\n  <param name="pb" value="1"/>')
    ws.launch("c.launch", '  <node pkg="pkg" type="t" name="a" ns="c"/>')
    model = model_of(ws)
    assert constraints(model, "excludes") == []
    assert model.clashes == [] and model.internal == []


def test_the_solver_links_the_files_excludes_pair_without_building_them(
    ws: LaunchWorkspace,
) -> None:
    """The solver finds the pairs of clashing files per name (``excluding``): the files of
    the ``excludes`` constraints, which are built only when asked for. a and c declare
    /n under conditions that never hold together: no pair."""
    ws.launch(
        "a.launch",
        '  <node pkg="pkg" type="t" name="n" if="$(optenv USE_A false)"/>\n'
        '  <param name="p" value="1"/>',
    )
    ws.launch("b.launch", '  <param name="p" value="2"/>\n  <node pkg="pkg" type="t" name="n"/>')
    ws.launch("c.launch", '  <node pkg="pkg" type="t" name="n" unless="$(optenv USE_A false)"/>')
    model = model_of(ws)
    count_configurations(model)
    assert "clashes" not in vars(model) and "constraints" not in vars(model)
    files = {f.file: f for f in model.files}
    found = {
        (files[a].id, files[b].id)
        for a, b in excluding(declaring(model.space, files, model.declarations))
    }
    assert found == {c.files for c in constraints(model, "excludes")}
    assert found == {
        ("pkg/launch/a.launch", "pkg/launch/b.launch"),
        ("pkg/launch/b.launch", "pkg/launch/c.launch"),
    }


def test_clash_inside_one_file_is_reported_as_internal(ws: LaunchWorkspace) -> None:
    file = ws.launch(
        "a.launch",
        '  <arg name="robot" default="r1"/>\n'
        '  <arg name="two" default="false"/>\n'
        '  <node pkg="pkg" type="t" name="$(arg robot)" ns="x"/>\n'
        '  <node pkg="pkg" type="t" name="r2" ns="x"/>\n'
        '  <node pkg="pkg" type="t" name="n" if="$(arg two)"/>\n'
        '  <node pkg="pkg" type="t" name="n"/>\n'
        '  <node pkg="pkg" type="t" name="m" if="$(arg two)"/>\n'
        '  <node pkg="pkg" type="t" name="m" unless="$(arg two)"/>\n',
    )
    ws.launch(
        "b.launch",
        '  <include file="$(find pkg)/launch/a.launch"><arg name="robot" value="r2"/></include>',
    )
    model = model_of(ws)
    internal = {c.name: c for c in model.internal}
    assert set(internal) == {"/x/r2", "/n"}  # /m: if and unless never hold together
    assert model.space.describe(internal["/x/r2"].condition) == "robot=r2"
    assert model.space.describe(internal["/n"].condition) == "two"
    assert all(c.first.file == c.second.file == file for c in model.internal)
    assert [
        loc.line for loc in (internal["/n"].first.location, internal["/n"].second.location)
    ] == [
        6,
        7,
    ]
    assert constraints(model, "excludes") == []


def test_including_one_file_twice_reports_the_clash(ws: LaunchWorkspace) -> None:
    file = ws.launch(
        "a.launch",
        '  <arg name="twice" default="false"/>\n'
        + INCLUDE_B.format(attrs="", body="")
        + INCLUDE_B.format(attrs=' if="$(arg twice)"', body=""),
    )
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="n"/>')
    # roslaunch (as rosvar's own resolve says) refuses the duplicate node
    assert [c.name for c in ws.resolve(file, {"twice": "true"}).conflicts] == ["/n"]
    assert ws.resolve(file, {"twice": "false"}).ok
    model = model_of(ws)
    assert [model.space.describe(c.condition) for c in model.internal] == ["twice"]


def test_an_arg_without_inferable_values_gets_a_diagnostic(ws: LaunchWorkspace) -> None:
    """Unresolvable values stay in the <other> slot, and the model says so where."""
    ws.launch("a.launch", '  <arg name="robot"/>\n  <node pkg="pkg" type="t" name="$(arg robot)"/>')
    model = extract(ws.analysis())
    [diagnostic] = model.diagnostics
    assert diagnostic.code == "values-unknown"
    assert "'robot'" in diagnostic.message
    assert diagnostic.location.file.endswith("a.launch") and diagnostic.location.line == 2
    [arg] = model.files[0].args
    assert [v.value for v in arg.values] == ["<other>"]


def test_the_files_own_problems_are_the_models_diagnostics_once_each(ws: LaunchWorkspace) -> None:
    """A file the interpreter could not read is still a feature, and the model says why:
    ``rosvar features`` must not show a broken file as a file without args."""
    ws.launch("broken.launch", '  <node pkg="pkg" type="t" name="n">\n')  # never closed
    ws.write("launch/latin1.launch", b'<launch><node pkg="pkg" type="t" name="caf\xe9"/></launch>')
    ws.launch("a.launch", INCLUDE_B.format(attrs="", body=""))
    ws.launch("c.launch", INCLUDE_B.format(attrs="", body=""))
    ws.launch("b.launch", "  <bogus/>\n")
    model = extract(ws.analysis())
    by_code = {d.code: d for d in model.diagnostics}
    assert {"xml-malformed", "xml-encoding", "tag-unknown"} <= set(by_code), by_code
    assert by_code["xml-malformed"].location.file.endswith("broken.launch")
    assert by_code["tag-unknown"].location.line == 2
    # b.launch is read from a, from c and on its own: its tag is reported once
    assert [d.code for d in model.diagnostics].count("tag-unknown") == 1
    assert {f.id for f in model.files} >= {"pkg/launch/broken.launch", "pkg/launch/latin1.launch"}
