"""The engine's answers: derived states, refusals, presence, completion (examples inline)."""

from __future__ import annotations

import gc
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from configuration.helpers import choices, configurator, present, run, same_as_resolve, states
from json_view import read
from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.feature_model.features import name_of
from rosvar.analyses.feature_model.operations import count_configurations
from rosvar.configuration.choices import Action, ChoiceError, UserChoice
from rosvar.configuration.engine import ConfigurationState, Configurator
from rosvar.configuration.sat import Sat
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.documents.state import state_document
from rosvar.outputs.web.entries import render
from rosvar.workspace import discover

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

MAIN = """  <arg name="robot" default="kobuki"/>
  <arg name="cam" default="false"/>
  <node pkg="pkg" type="drive" name="$(arg robot)"/>
  <include file="$(find pkg)/launch/camera.launch" if="$(arg cam)"/>
"""
CAMERA = """  <arg name="fps" default="30"/>
  <node pkg="pkg" type="cam" name="camera"><param name="fps" value="$(arg fps)"/></node>
"""
CLASH = '  <node pkg="pkg" type="cam" name="camera"/>\n'


@pytest.fixture
def engine(ws: LaunchWorkspace) -> Configurator:
    ws.launch("main.launch", MAIN)
    ws.launch("camera.launch", CAMERA)
    ws.launch("other_camera.launch", CLASH)
    return configurator(ws)


def test_nothing_chosen_nothing_decided(engine: Configurator) -> None:
    state = run(engine)
    assert states(state) == {}
    assert not state.complete and state.command is None
    assert state.unselected == len(state.features)
    assert set(present(state).values()) == {"undetermined"}


def test_value_selects_its_arg_and_file_and_deselects_its_siblings(engine: Configurator) -> None:
    found = states(run(engine, "set main.launch:robot=kobuki"))
    assert found["main.launch"] == "selected*"
    assert found["main.launch:robot"] == "selected"
    assert found["main.launch:robot=kobuki"] == "selected"
    assert found["main.launch:robot=<other>"] == "deselected*"


def test_include_selects_the_included_file_and_exclude_deselects_the_clash(
    engine: Configurator,
) -> None:
    found = states(run(engine, "set main.launch:cam=true"))
    assert found["camera.launch"] == "selected*"
    assert found["other_camera.launch"] == "deselected*"  # both declare /camera
    assert "camera.launch" not in states(run(engine, "set main.launch:cam=false"))


def test_refusal_names_the_earlier_choice_and_the_constraints(engine: Configurator) -> None:
    state = run(
        engine, "select other_camera.launch", "select main.launch", "set main.launch:cam=true"
    )
    [refusal] = state.refused
    assert refusal.choice.feature == "main.launch:cam"
    assert "select other_camera.launch" in refusal.reason
    assert "select main.launch" not in refusal.reason  # not needed for the contradiction
    # main.launch loads camera.launch's node: the clash is main's own (issue 30)
    assert "main.launch and pkg/launch/other_camera.launch both load node /camera" in (
        refusal.reason
    )
    assert [c.feature for c in state.choices] == ["other_camera.launch", "main.launch"]
    assert states(state)["main.launch:cam=true"] == "deselected*"


def test_unknown_feature_is_a_usage_error(engine: Configurator) -> None:
    with pytest.raises(ChoiceError):
        run(engine, "select nowhere.launch")


def test_unselect_takes_a_choice_back(engine: Configurator) -> None:
    state = run(engine, "set main.launch:cam=true", "unselect main.launch:cam")
    assert states(state) == {}


def test_set_replaces_the_earlier_value(engine: Configurator) -> None:
    state = run(engine, "set main.launch:robot=kobuki", "set main.launch:robot=husky")
    assert state.refused == []
    assert present(state)["/husky"] == "present"


def test_presence_present_absent_undetermined(engine: Configurator) -> None:
    state = run(engine, "select main.launch")
    nodes = {(n["name"], n["presence"], n["condition"]) for n in state.graph.nodes}
    assert ("/kobuki", "undetermined", "robot=kobuki") in nodes
    # the camera of main.launch's model: only when cam
    assert ("/camera", "undetermined", "cam") in nodes
    state = run(engine, "select main.launch", "set main.launch:cam=false")
    names = {
        n["name"]: n["presence"] for n in read(state.graph.nodes) if n["id"].startswith("main")
    }
    assert names["/camera"] == "absent"


def test_typed_other_value_is_evaluated(engine: Configurator) -> None:
    state = run(engine, "set main.launch:robot=r2d2")
    assert states(state)["main.launch:robot=<other>"] == "selected"
    assert present(state)["/r2d2"] == "present"


def test_included_file_is_not_launched_on_its_own(engine: Configurator) -> None:
    state = run(engine, "set main.launch:cam=true")
    cameras = [
        n for n in read(state.graph.nodes) if n["name"] == "/camera" and n["presence"] != "absent"
    ]
    assert [n["id"].split("|")[0] for n in cameras] == ["main.launch"]


def test_a_step_runs_without_the_collector_and_restores_it(
    engine: Configurator, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Were the collector running during the step, its thousands of allocations would
    start collections at a threshold of 100 (the few before and after it do not)."""
    started: list[int] = []

    def record(phase: str, info: dict[str, int]) -> None:
        if phase == "start":
            started.append(info["generation"])

    chosen = choices("set main.launch:cam=true", "set main.launch:robot=husky")
    threshold = gc.get_threshold()
    gc.collect()
    gc.callbacks.append(record)
    gc.set_threshold(100)
    try:
        assert gc.isenabled()
        state = engine.state(chosen)
        assert started == []
        assert gc.isenabled()
        gc.collect(0)  # the hook does see collections
    finally:
        gc.set_threshold(*threshold)
        gc.callbacks.remove(record)
    assert started and not state.refused and len(state.choices) == 2


def test_an_included_file_takes_no_args_from_the_command_line(engine: Configurator) -> None:
    """main.launch includes camera.launch without passing ``fps``: in that product fps is
    its default, derived, and setting it is refused with the include as the reason (it
    would change nothing: the command cannot give it)."""
    found = states(run(engine, "set main.launch:cam=true"))
    assert found["camera.launch:fps=30"] == "selected*"
    for words in (
        ["set main.launch:cam=true", "set camera.launch:fps=60"],
        ["set camera.launch:fps=60", "set main.launch:cam=true"],
    ):
        state = run(engine, *words)
        [refusal] = state.refused
        assert refusal.choice == choices(words[1])[0]
        assert "main.launch includes pkg/launch/camera.launch" in refusal.reason
        assert "no args from the command line" in refusal.reason
    alone = run(engine, "set camera.launch:fps=60", "deselect main.launch")
    chosen = alone.choices
    alone = engine.state(chosen + engine.completion(chosen))
    assert alone.command is not None and "fps:=60" in alone.command


def test_completion_reaches_a_complete_product(engine: Configurator) -> None:
    chosen = choices("set main.launch:cam=true")
    state = engine.state(chosen + engine.completion(chosen))
    assert state.complete and state.unselected == 0 and state.configurations == 1
    assert state.command == "roslaunch pkg main.launch cam:=true"


def test_conflict_certain_possible_gone(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="on" default="true"/>\n  <node pkg="p" type="t" name="n" if="$(arg on)"/>',
    )
    ws.launch("b.launch", '  <node pkg="p" type="t" name="n"/>')
    engine = configurator(ws)
    [conflict] = run(engine).conflicts
    assert (conflict.files, conflict.status, conflict.condition) == (
        ("a.launch", "b.launch"),
        "possible",
        "on",
    )
    # with b.launch in, on=true would clash and is derived out: a typed value could still
    [conflict] = run(engine, "select b.launch").conflicts
    assert (conflict.status, conflict.condition) == ("possible", "only for other values")
    assert run(engine, "set a.launch:on=false").conflicts == []
    assert run(engine, "deselect b.launch").conflicts == []
    # certain once both files are there, but the solver deselects b.launch then: a clash
    # with a file out of the product is not shown (the README's control.xml and teleop_only)
    assert states(run(engine, "set a.launch:on=true"))["b.launch"] == "deselected*"
    assert run(engine, "set a.launch:on=true").conflicts == []
    # both files in: on=true is derived out, and the clash is judged on what is left (a
    # typed value), not on the choices alone ("on", a value the product can no longer take:
    # a red ⚠ that stayed on finished products)
    both = run(engine, "select b.launch", "select a.launch")
    assert states(both)["a.launch:on=true"] == "deselected*"
    assert [c.condition for c in both.conflicts] == ["only for other values"]


def test_a_file_that_loads_a_node_twice_fails_alone(ws: LaunchWorkspace) -> None:
    """roslaunch refuses it ("multiple nodes named"): the engine's model excludes it, and
    the values that would make it happen."""
    ws.launch("a.launch", '  <node pkg="p" type="t" name="n"/>\n' * 2)
    ws.launch(
        "b.launch",
        '  <arg name="twice" default="false"/>\n  <node pkg="p" type="t" name="m"/>\n'
        '  <node pkg="p" type="t" name="m" if="$(arg twice)"/>\n',
    )
    engine = configurator(ws)
    assert states(run(engine))["a.launch"] == "deselected*"
    [refusal] = run(engine, "select a.launch").refused
    assert refusal.reason.endswith("pkg/launch/a.launch loads node /n twice")
    b = run(engine, "select b.launch")
    assert states(b)["b.launch:twice=true"] == "deselected*"
    assert [c.condition for c in b.conflicts] == ["only for other values"]  # a typed 'true'
    assert (
        "b.launch loads node /m twice" in run(engine, "set b.launch:twice=true").refused[0].reason
    )


def test_configurations_are_counted_exactly_beyond_a_double(ws: LaunchWorkspace) -> None:
    """40 args used in conditions: over 2^53 configurations, which CUDD's double rounds."""
    args = "".join(
        f'  <arg name="a{n}" default="true"/>\n'
        f'  <node pkg="p" type="t" name="n{n}" if="$(arg a{n})"/>\n'
        for n in range(40)
    )
    ws.launch("many.launch", args)
    engine = configurator(ws)
    model = engine.model
    everything = run(engine).configurations
    assert everything == count_configurations(model) and everything > 2**53
    chosen = run(engine, "set many.launch:a0=true").configurations
    [arg] = [a for a in model.files[0].args if a.name == "a0"]
    [value] = [v for v in arg.values if v.slot == "true"]
    assert chosen == model.solver.count({name_of(value.variable): True})
    assert 0 < chosen < everything


def test_an_arg_roslaunch_stops_without_is_asked_for_and_an_unused_one_left_off(
    ws: LaunchWorkspace,
) -> None:
    """A required arg the graph does not show (a node's ``output``) made complete products
    without a command and nothing to type; one never used needs no value at all."""
    ws.launch(
        "a.launch",
        '  <arg name="unused"/>\n  <arg name="out"/>\n'
        '  <node pkg="p" type="t" name="n" output="$(arg out)"/>',
    )
    engine = configurator(ws)
    assert [f.id for f in engine.catalog if f.kind == "arg"] == ["a.launch:out"]
    chosen = choices("select a.launch")
    finished = engine.state(chosen + engine.completion(chosen))
    assert finished.complete and finished.command is None
    assert finished.untyped == ["a.launch:out"]
    typed = run(engine, "select a.launch", "set a.launch:out=screen")
    assert typed.complete and typed.command == "roslaunch pkg a.launch out:=screen"
    assert typed.graph.errors == []  # absent: not listed


TYPED = """  <arg name="rate" default="5"/>
  <arg name="fast" default="false"/>
  <group if="$(arg fast)">
    <param name="rate" type="int" value="$(arg rate)"/>
    <param name="description" command="$(arg rate)"/>
  </group>
  <node pkg="pkg" type="t" name="n"/>
"""


def test_a_typed_text_every_product_left_fails_by_is_refused_with_where(
    ws: LaunchWorkspace,
) -> None:
    """issue 30: ``initial_reset:=typed8`` made a product whose command roslaunch refuses."""
    ws.launch("t.launch", TYPED)
    engine = configurator(ws)
    state = run(engine, "set t.launch:fast=true", "set t.launch:rate=abc")
    [refusal] = state.refused
    assert refusal.choice.value == "abc"
    assert "roslaunch would stop at " in refusal.reason
    assert "t.launch:5:5: invalid literal for int() with base 10: 'abc' [param-invalid]" in (
        refusal.reason
    )
    assert "t.launch:rate" not in state.untyped and typed_failures(state) == []
    assert run(engine, "set t.launch:fast=true", "set t.launch:rate=7").refused == []


def test_a_typed_text_some_products_fail_by_is_their_error_under_its_condition(
    ws: LaunchWorkspace,
) -> None:
    ws.launch("t.launch", TYPED)
    engine = configurator(ws)
    typed = run(engine, "set t.launch:rate=abc")
    assert typed.refused == []
    [error] = typed_failures(typed)
    assert (error["line"], error["presence"], error["condition"]) == (5, "undetermined", "fast")
    assert typed.summary.errors == []
    chosen = choices("set t.launch:rate=abc", "set t.launch:fast=true")
    failing = engine.state(chosen + engine.completion(chosen))
    assert failing.complete and [e["presence"] for e in typed_failures(failing)] == ["present"]
    assert [e["code"] for e in failing.summary.errors] == ["param-invalid"]
    assert same_as_resolve(ws.analysis(), failing) == 0  # rosvar resolve refuses it too
    loads = run(engine, "set t.launch:rate=abc", "set t.launch:fast=false")
    assert typed_failures(loads) == [] and loads.summary.errors == []


def typed_failures(state: ConfigurationState) -> list[dict[str, object]]:
    """The errors of texts typed for ``<other>`` values that are not absent."""
    return [e for e in state.graph.errors if e["code"] == "param-invalid"]


def test_a_command_param_shows_what_roslaunch_loads_once_typed(ws: LaunchWorkspace) -> None:
    ws.launch("t.launch", TYPED)
    engine = configurator(ws)
    chosen = choices("set t.launch:fast=true", "set t.launch:rate=12")
    state = engine.state(chosen + engine.completion(chosen))
    params = {p["name"]: p["value"] for p in state.graph.params if p["presence"] == "present"}
    assert params == {"/rate": 12, "/description": "__command__(12)"}
    assert same_as_resolve(ws.analysis(), state) == 1


def test_what_rosvar_could_not_read_is_shown_while_its_file_is_in(ws: LaunchWorkspace) -> None:
    """issue 30: a product rosvar could not read was offered as finished ("0 nodes") and the
    notice of what it could not read was gone after the next click."""
    ws.launch("a.launch", '  <include file="$(find nopkg)/launch/x.launch"/>')
    ws.launch("b.launch", '  <node pkg="p" type="t" name="n"/>')
    engine = configurator(ws)
    assert run(engine).unknown == []
    chosen = choices("select a.launch")
    for state in (run(engine, "select a.launch"), engine.state(chosen + engine.completion(chosen))):
        assert [(d.code, d.location.line) for d in state.unknown] == [
            ("package-unknown", 2),
            ("include-unknown", 2),
        ]
    finished = engine.state(chosen + engine.completion(chosen))
    assert (
        finished.complete
        and read(state_document(finished))["unknown"][0]["code"] == "package-unknown"
    )
    assert run(engine, "select b.launch", "deselect a.launch").unknown == []


def test_a_finished_product_says_whether_it_launches(ws: LaunchWorkspace) -> None:
    ws.launch("t.launch", TYPED)
    engine = configurator(ws)
    assert run(engine, "set t.launch:rate=abc").launches is None  # not finished
    chosen = choices("set t.launch:rate=abc", "set t.launch:fast=true")
    failing = engine.state(chosen + engine.completion(chosen))
    assert failing.launches is False and state_document(failing)["launches"] is False
    chosen = choices("set t.launch:rate=3", "set t.launch:fast=true")
    assert engine.state(chosen + engine.completion(chosen)).launches is True


def test_a_refusal_the_search_cannot_explain_in_its_budget_says_so(
    engine: Configurator, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(Sat, "_limited", lambda _sat, _assumptions: None)
    state = run(
        engine, "select other_camera.launch", "select main.launch", "set main.launch:cam=true"
    )
    [refusal] = state.refused
    assert refusal.reason.endswith(
        "is impossible after select other_camera.launch: not explained (finding the "
        "constraints why took too long)"
    )


def test_two_ordinary_clicks_on_husky_are_explained_at_once() -> None:
    """issue 30.5: two selections that each took a second took over 120 s together, in the
    BDD conjunctions of the refusal's explanation."""
    corpus = Path(__file__).resolve().parents[3] / "shared" / "corpus"
    if not (corpus / "husky").is_dir():
        pytest.skip(f"corpus not found at {corpus}")
    analysis = Analysis(discover([corpus / "husky"], deps=[corpus / "_external"]))
    engine = Configurator(analysis, extract(analysis, products=True), render=render)
    config = "husky_manipulation/husky_dual_gen3_moveit_config/launch/"
    [gazebo, planning] = [
        next(f.id for f in engine.catalog.files if f.path.endswith(config + name))
        for name in ("gazebo.launch", "husky_dual_gen3_moveit_planning_execution.launch")
    ]
    [refusal] = engine.state(
        [UserChoice(Action.SELECT, gazebo), UserChoice(Action.SELECT, planning)]
    ).refused
    assert refusal.reason.startswith(f"select {planning} is impossible after select {gazebo}: ")
    assert "ros_controllers.launch both declare param /controller_list" in refusal.reason
