"""``<include>``: conditions and namespaces flow into the included file; args are passed."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest

from rosvar.interpreter import interpretation
from rosvar.interpreter.model import LaunchModel, NodeDecl
from rosvar.ros1.tags import include as include_tag

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

SENSOR = """
  <arg name="rate" default="10"/>
  <arg name="debug" default="false"/>
  <node pkg="pkg" type="sensor" name="sensor">
    <param name="rate" value="$(arg rate)"/>
  </node>
  <node pkg="pkg" type="dbg" name="debugger" if="$(arg debug)"/>
"""

MAIN = """
  <arg name="use_sensor" default="true"/>
  <arg name="fast" default="false"/>
  <include file="$(find pkg)/launch/sensor.launch" if="$(arg use_sensor)" ns="front">
    <arg name="rate" value="50" if="$(arg fast)"/>
    <arg name="debug" value="$(arg fast)"/>
  </include>
"""


def nodes_by_name(model: LaunchModel) -> dict[str, NodeDecl]:
    return {str(n.fields["name"].single()): n for n in model.nodes}


def test_include_condition_is_conjoined_into_included_nodes(ws: LaunchWorkspace) -> None:
    ws.launch("sensor.launch", SENSOR)
    main = ws.launch("main.launch", MAIN)
    model = ws.model(main)
    space = model.space
    nodes = nodes_by_name(model)
    sensor, debugger = nodes["sensor"], nodes["debugger"]
    assert space.describe(sensor.condition) == "use_sensor"
    assert space.describe(debugger.condition) == "fast ∧ use_sensor"
    included = str(ws.root / "pkg" / "launch" / "sensor.launch")
    assert sensor.filename == included  # as roslaunch's Node
    assert sensor.location.file == included
    assert model.files == [main, included]
    [include] = model.includes
    assert include.resolved and space.describe(include.condition) == "use_sensor"


def test_include_args_and_namespace(ws: LaunchWorkspace) -> None:
    ws.launch("sensor.launch", SENSOR)
    main = ws.launch("main.launch", MAIN)
    slow = ws.resolve(main, {})
    assert slow.ok, slow.errors
    assert [n.name for n in slow.nodes] == ["/front/sensor"]
    assert slow.params == {"/front/sensor/rate": 10}
    fast = ws.resolve(main, {"fast": "true"})
    assert sorted(n.name for n in fast.nodes) == ["/front/debugger", "/front/sensor"]
    assert fast.params == {"/front/sensor/rate": 50}
    off = ws.resolve(main, {"use_sensor": "false", "fast": "true"})
    assert off.ok and off.nodes == [] and off.params == {}


@pytest.mark.oracle
def test_include_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.launch("sensor.launch", SENSOR)
    main = ws.launch("main.launch", MAIN)
    ws.assert_agrees(
        main,
        [{}, {"fast": "true"}, {"use_sensor": "false"}, {"fast": "1"}, {"rate": "99"}],
    )


SELECT = """
  <arg name="robot" default="husky"/>
  <include file="$(find pkg)/launch/robots/$(arg robot).launch"/>
"""


def test_included_file_chosen_by_an_arg(ws: LaunchWorkspace) -> None:
    ws.launch("robots/husky.launch", '<node pkg="pkg" type="t" name="husky_base"/>')
    ws.launch("robots/jackal.launch", '<node pkg="pkg" type="t" name="jackal_base"/>')
    main = ws.launch("select.launch", SELECT)
    fresh = ws.analysis(extra_values={"robot": ["jackal"]})
    model = fresh.model(main)
    space = model.space
    nodes = nodes_by_name(model)
    assert space.describe(nodes["husky_base"].condition) == "robot=husky"
    assert space.describe(nodes["jackal_base"].condition) == "robot=jackal"
    assert [n.name for n in ws.resolve(main, {"robot": "jackal"}).nodes] == ["/jackal_base"]
    missing = ws.resolve(main, {"robot": "nope"})
    assert not missing.ok


@pytest.mark.oracle
def test_included_file_chosen_by_an_arg_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.launch("robots/husky.launch", '<node pkg="pkg" type="t" name="husky_base"/>')
    ws.launch("robots/jackal.launch", '<node pkg="pkg" type="t" name="jackal_base"/>')
    main = ws.launch("select.launch", SELECT)
    ws.assert_agrees(main, [{}, {"robot": "jackal"}, {"robot": "nope"}])


PASS_ALL = """
  <arg name="rate" default="7"/>
  <arg name="debug" default="true"/>
  <include file="$(find pkg)/launch/sensor.launch" pass_all_args="true"/>
"""

UNUSED = """
  <include file="$(find pkg)/launch/sensor.launch">
    <arg name="speed" value="1"/>
  </include>
"""


def test_pass_all_args_and_unused_args(ws: LaunchWorkspace) -> None:
    ws.launch("sensor.launch", SENSOR)
    passing = ws.launch("pass.launch", PASS_ALL)
    resolution = ws.resolve(passing, {"rate": "3"})
    assert resolution.ok and resolution.params == {"/sensor/rate": 3}
    assert sorted(n.name for n in resolution.nodes) == ["/debugger", "/sensor"]
    unused = ws.launch("unused.launch", UNUSED)
    model = ws.model(unused)
    assert [e.code for e in model.errors] == ["include-arg-unused"]
    assert not ws.resolve(unused).ok


@pytest.mark.oracle
def test_pass_all_args_and_unused_args_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.launch("sensor.launch", SENSOR)
    ws.assert_agrees(ws.launch("pass.launch", PASS_ALL), [{}, {"rate": "3", "debug": "false"}])
    ws.assert_agrees(ws.launch("unused.launch", UNUSED), [{}])


TWICE = """
  <arg name="second_ns" default=""/>
  <include file="$(find pkg)/launch/sensor.launch"/>
  <include file="$(find pkg)/launch/sensor.launch" ns="$(arg second_ns)"
           if="$(eval second_ns != '')"/>
"""


def test_including_twice_conflicts_only_in_the_same_namespace(ws: LaunchWorkspace) -> None:
    ws.launch("sensor.launch", SENSOR)
    main = ws.launch("twice.launch", TWICE)
    assert ws.resolve(main, {}).ok
    renamed = ws.resolve(main, {"second_ns": "rear"})
    assert renamed.ok
    assert sorted(n.name for n in renamed.nodes) == ["/rear/sensor", "/sensor"]
    clash = ws.resolve(main, {"second_ns": "/"})
    assert [c.name for c in clash.conflicts] == ["/sensor"]


@pytest.mark.oracle
def test_including_twice_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.launch("sensor.launch", SENSOR)
    main = ws.launch("twice.launch", TWICE)
    ws.assert_agrees(main, [{}, {"second_ns": "rear"}, {"second_ns": "/"}])


def test_include_outside_the_workspace_is_not_followed(ws: LaunchWorkspace) -> None:
    outside = ws.root.parent / "evil.launch"
    outside.write_text('<launch><param name="leak" value="1"/></launch>')
    file = ws.launch(
        "top.launch",
        '<include file="$(find pkg)/../../evil.launch"/><include file="/proc/self/environ"/>',
    )
    model = ws.model(file)
    assert [d.code for d in model.diagnostics] == ["file-outside-workspace"] * 2
    assert model.params == [] and model.errors == []
    assert [i.resolved for i in model.includes] == [False, False]
    resolution = ws.resolve(file)
    assert [e.code for e in resolution.errors] == ["include-unknown"]


def test_include_diamond_is_bounded(ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(interpretation, "MAX_INCLUDES", 100)
    monkeypatch.setattr(include_tag, "MAX_INCLUDES", 100)
    for level in range(20):  # each file includes the next twice: 2^20 walks unbounded
        nxt = f"$(find pkg)/launch/d{level + 1}.launch"
        ws.launch(f"d{level}.launch", f'<include file="{nxt}"/><include file="{nxt}"/>')
    ws.launch("d20.launch", '<param name="leaf" value="1"/>')
    model = ws.model(str(ws.root / "pkg" / "launch" / "d0.launch"))
    assert "include-too-many" in [d.code for d in model.diagnostics]
    assert sum(1 for include in model.includes if include.resolved) == 100


@pytest.mark.parametrize(("groups", "includes"), [(998, 0), (120, 0), (10, 30), (0, 60)])
def test_deep_nesting_is_a_diagnostic_not_a_recursion_error(
    ws: LaunchWorkspace, groups: int, includes: int
) -> None:
    for level in range(includes):
        inner = f'<include file="$(find pkg)/launch/n{level + 1}.launch"/>'
        ws.launch(f"n{level}.launch", "<group>" * groups + inner + "</group>" * groups)
    body = '<param name="x" value="$(eval 1+((((1)))))"/><rosparam param="y">[[[1]]]</rosparam>'
    ws.launch(f"n{includes}.launch", "<group>" * groups + body + "</group>" * groups)
    file = str(ws.root / "pkg" / "launch" / "n0.launch")
    model = ws.model(file)
    nested = (groups + 1) * (includes + 1)  # levels walked: each file's own plus its groups
    deep = nested > interpretation.MAX_NESTING
    assert ("nesting-too-deep" in [d.code for d in model.diagnostics]) == deep
    assert bool(model.params) != deep
    ws.resolve(file)
    ws.analysis().all_models()
