"""Command lines: launched files only, args that matter, shared where roslaunch allows it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from configuration.helpers import canonical, choices, configurator, product, run
from json_view import read
from rosvar.configuration.command import Launch, given, group
from rosvar.configuration.engine import ConfigurationState
from rosvar.outputs.documents.resolution import resolution_document
from rosvar.ros.version import RosVersion
from rosvar.ros1.resolve import resolve

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def launch(name: str, given: dict[str, str], reads: dict[str, str | None]) -> Launch:
    return Launch(f"/ws/{name}", name, given, {**reads, **given})


def test_files_share_a_command_while_they_read_the_same_values() -> None:
    a = launch("a", {"robot": "husky"}, {"sim": "false"})
    b = launch("b", {}, {"robot": "husky"})  # its default is what a gives
    c = launch("c", {}, {"robot": "kobuki"})  # would read robot:=husky instead of its default
    d = launch("d", {"sim": "true"}, {})  # a reads sim
    shared = group([a, b, c, d], RosVersion.ROS1)
    assert [[m.spelled for m in g] for g in shared] == [["a", "b"], ["c", "d"]]
    assert group([], RosVersion.ROS1) == []
    # ros2 launch takes one file
    apart = group([a, b], RosVersion.ROS2)
    assert [[m.spelled for m in g] for g in apart] == [["a"], ["b"]]


def test_engine_commands(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="robot" default="kobuki"/>\n  <node pkg="p" type="t" name="a_$(arg robot)"/>',
    )
    ws.launch(
        "b.launch",
        '  <arg name="robot" default="kobuki"/>\n  <node pkg="p" type="t" name="b_$(arg robot)"/>',
    )
    ws.launch("c.launch", '  <include file="$(find pkg)/launch/a.launch"/>')
    engine = configurator(ws)
    done = ["deselect c.launch", "set a.launch:robot=kobuki"]
    same = run(engine, *done, "set b.launch:robot=kobuki")
    assert same.command == "roslaunch a.launch b.launch"  # defaults are not named
    apart = run(engine, *done, "set b.launch:robot=husky")
    assert apart.command == "roslaunch pkg a.launch\nroslaunch pkg b.launch robot:=husky"
    included = run(engine, "select c.launch", "set a.launch:robot=kobuki", "deselect b.launch")
    assert included.command == "roslaunch pkg c.launch"  # a.launch comes with c.launch
    assert [launch.spelled for g in included.commands for launch in g] == ["c.launch"]


def test_choosing_a_substituted_default_leaves_the_arg_off(ws: LaunchWorkspace) -> None:
    """The default's feature reads ``<default: $(...)>``: by select or by set (as the web UI
    does), the arg stays off the command and the product is what roslaunch loads for it."""
    ws.launch(
        "a.launch",
        '  <arg name="scan" default="$(optenv LASER scan)"/>\n'
        '  <node pkg="p" type="t" name="n"><remap from="in" to="$(arg scan)"/></node>',
    )
    engine = configurator(ws)
    [default] = [f for f in engine.catalog if f.kind == "value" and f.value != "<other>"]
    assert default.value == "<default: $(optenv LASER scan)>"
    for word in (f"select {default.id}", f"set a.launch:scan={default.value}"):
        state = run(engine, word)
        assert state.command == "roslaunch pkg a.launch", word
        assert_resolves_the_same(ws, state)


def test_an_arg_set_by_value_is_never_asked_for(ws: LaunchWorkspace) -> None:
    """Husky's move_group.launch: ``--finish`` must not pick an ``<other>`` for it."""
    ws.launch(
        "a.launch",
        '  <arg name="info" default="false"/>\n'
        '  <arg unless="$(arg info)" name="c" value=""/>\n'
        '  <arg if="$(arg info)" name="c" value="--debug"/>\n'
        '  <node pkg="p" type="t" name="n" args="$(arg c)"/>\n',
    )
    engine = configurator(ws)
    chosen = choices("select a.launch")
    state = engine.state(chosen + engine.completion(chosen))
    assert state.complete and state.command == "roslaunch pkg a.launch"
    assert_resolves_the_same(ws, state)


def assert_resolves_the_same(ws: LaunchWorkspace, state: ConfigurationState) -> None:
    """Each command line of a complete product loads what the product shows."""
    assert state.commands
    for members in state.commands:
        resolution = read(
            resolution_document(resolve(ws.analysis(), [m.path for m in members], given(members)))
        )
        ours = product(state, [m.spelled for m in members])
        assert ours["ok"] == resolution["ok"], state.command
        assert canonical(ours["nodes"]) == canonical(resolution["nodes"]), state.command
        assert ours["params"] == resolution["params"], state.command
