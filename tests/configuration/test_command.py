"""Command lines: launched files only, args that matter, shared where roslaunch allows it."""

from __future__ import annotations

from typing import TYPE_CHECKING

from configuration.helpers import configurator, run
from rosvar.configuration.command import Launch, group

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def launch(name: str, given: dict[str, str], reads: dict[str, str | None]) -> Launch:
    return Launch(f"/ws/{name}", name, given, {**reads, **given})


def test_files_share_a_command_while_they_read_the_same_values() -> None:
    a = launch("a", {"robot": "husky"}, {"sim": "false"})
    b = launch("b", {}, {"robot": "husky"})  # its default is what a gives
    c = launch("c", {}, {"robot": "kobuki"})  # would read robot:=husky instead of its default
    d = launch("d", {"sim": "true"}, {})  # a reads sim
    assert [[m.spelled for m in g] for g in group([a, b, c, d])] == [["a", "b"], ["c", "d"]]
    assert group([]) == []


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
