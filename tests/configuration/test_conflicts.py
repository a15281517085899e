"""Blocks of ``tree ∧ requires`` that clashes are judged on, and their size bound."""

from __future__ import annotations

import os
import random
from typing import TYPE_CHECKING

import pytest

from configuration.helpers import configurator, run, states
from configuration.test_judgement import FILES as PRESENCE_FILES
from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration import conflicts
from rosvar.configuration.conflicts import _blocks

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

MAIN = """  <arg name="cam" default="false"/>
  <include file="$(find pkg)/launch/camera.launch" if="$(arg cam)"/>
"""
CAMERA = '  <arg name="fps" default="30"/>\n  <node pkg="pkg" type="cam" name="camera"/>\n'
CLASH = '  <node pkg="pkg" type="cam" name="camera"/>\n'


@pytest.fixture
def workspace(ws: LaunchWorkspace) -> LaunchWorkspace:
    ws.launch("main.launch", MAIN)
    ws.launch("camera.launch", CAMERA)
    ws.launch("other_camera.launch", CLASH)
    return ws


def block_files(ws: LaunchWorkspace) -> list[set[str]]:
    """Each block as the base names of the files whose variables it holds."""
    model = extract(ws.analysis())
    solver = model.solver
    component_of = {f: i for i, c in enumerate(solver.components) for f in c.files}
    owner = {v: os.path.basename(f.file) for f in model.files for v in f.variable_names()}
    return sorted(
        ({owner[v] for v in variables} for variables, _ in _blocks(model, component_of)), key=sorted
    )


def test_requires_link_files_into_one_block(workspace: LaunchWorkspace) -> None:
    assert block_files(workspace) == [{"camera.launch", "main.launch"}, {"other_camera.launch"}]


def test_a_block_over_the_limit_goes_back_to_one_block_per_file(
    workspace: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(conflicts, "BLOCK_LIMIT", 1)
    assert block_files(workspace) == [{"camera.launch"}, {"main.launch"}, {"other_camera.launch"}]
    engine = configurator(workspace)  # the clashes are still judged, on the tree alone
    # camera.launch's node is main.launch's when main includes it (issue 30)
    shown = {c.files: (c.status, c.condition) for c in run(engine).conflicts}
    assert shown == {
        ("camera.launch", "other_camera.launch"): ("possible", "¬cam ∨ ¬pkg/launch/main.launch"),
        ("main.launch", "other_camera.launch"): ("possible", "cam"),
    }
    judged_all = engine.conflicts.judge(engine.derivation.initial, {}, engine.views.describe)
    assert [judged.files for judged in filter(None, judged_all)] == list(shown)
    assert run(engine, "deselect other_camera.launch").conflicts == []


def test_the_satisfiability_tests_agree_with_the_conjunctions(ws: LaunchWorkspace) -> None:
    """``_meets`` asks ``∃ variables. u ∧ cube`` instead of building ``u ∧ cube``."""
    for name, body in PRESENCE_FILES.items():
        ws.launch(name, body)
    engine = configurator(ws)
    derivation, judged = engine.derivation, engine.conflicts
    variables = list(derivation.variables)
    false = judged.manager.false
    assert judged.pairs
    rng = random.Random(11)
    outcomes: list[bool] = []
    for _ in range(40):
        decisions = derivation.initial
        for variable in rng.sample(variables, rng.randint(0, 4)):
            decisions = derivation.add(decisions, variable, rng.random() < 0.5) or decisions
        for pair in judged.pairs:
            cube = judged._decided(pair, decisions)
            for u in (pair.possible, pair.escapes):
                expected = (pair.within & u & cube) != false
                assert judged._meets(u, pair, cube) == expected
                outcomes.append(expected)
    assert len(outcomes) >= 80 and set(outcomes) == {True, False}


def test_a_typed_text_that_cannot_clash_rules_the_clash_out(ws: LaunchWorkspace) -> None:
    """A clash on an ``<other>`` value is judged on the text typed for it: one that makes no
    clash left a ⚠ on a finished product (Husky's demo.launch, ``use_gui:=typed3``)."""
    ws.launch(
        "a.launch",
        '  <arg name="on" default="false"/>\n'
        '  <node pkg="p" type="t" name="n" if="$(eval on == \'yes\' or on == \'true\')"/>',
    )
    ws.launch("b.launch", '  <node pkg="p" type="t" name="n"/>')
    engine = configurator(ws)
    [open_] = run(engine, "select a.launch:on=<other>").conflicts
    assert open_.status == "possible"
    assert run(engine, "set a.launch:on=no").conflicts == []


def test_a_clash_an_unset_environment_makes_excludes_the_pair(ws: LaunchWorkspace) -> None:
    """turtlebot_world.launch includes ``$(optenv TURTLEBOT_BASE kobuki).launch.xml``: with
    the variable unset (the product's command sets none) it loads kobuki's nodes, which
    create's file loads too, so the two files are never one product (the engine's solver
    once quantified the environment out: a value of it that nobody sets avoided the clash)."""
    ws.launch(
        "world.launch", '  <include file="$(find pkg)/launch/$(optenv BASE kobuki).launch"/>\n'
    )
    ws.launch("kobuki.launch", '  <node pkg="pkg" type="mux" name="mux"/>\n')
    ws.launch("create.launch", '  <node pkg="pkg" type="mux" name="mux"/>\n')
    state = run(configurator(ws), "select world.launch")
    assert states(state)["create.launch"] == "deselected*"
    # with BASE=create, world.launch loads create's file itself: no clash, and create.launch
    # is no product of its own next to it
    state = run(
        configurator(ws, env={"BASE": "create"}), "select world.launch", "select create.launch"
    )
    assert state.refused == []
