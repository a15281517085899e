"""ROS 2 command lines: ``ros2 launch PKG FILE name:=value``, checked with ros2/launch."""

from __future__ import annotations

import json
import shlex
from pathlib import Path
from typing import Any

import pytest

from oracle.ros2_client import requires_ros2_oracle, run_oracle
from rosvar.outputs.cli import main

pytestmark = requires_ros2_oracle


ROS2_MANIFEST = """<package format="3"><name>pkg</name>
<export><build_type>ament_cmake</build_type></export></package>"""
ROS2_LAUNCH = """<launch>
  <arg name="on" default="true"/>
  <arg name="mode" default="fast"><choice value="fast"/><choice value="slow"/></arg>
  <node pkg="pkg" exec="a" name="a_$(var mode)" if="$(var on)"/>
  <node pkg="pkg" exec="b" name="b_$(var mode)" unless="$(var on)"/>
</launch>"""


def ros2_workspace(root: Path) -> Path:
    file = _launch_folder(root) / "main.launch.xml"
    file.write_text(ROS2_LAUNCH)
    return file


def _launch_folder(root: Path) -> Path:
    """The launch folder of a ROS 2 package ``pkg`` in ``root``."""
    launch = root / "pkg" / "launch"
    launch.mkdir(parents=True)
    (launch.parent / "package.xml").write_text(ROS2_MANIFEST)
    return launch


@pytest.mark.parametrize("on", ["true", "false"])
def test_a_ros2_product_is_a_ros2_launch_command_the_oracle_loads(
    on: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    file = ros2_workspace(tmp_path)
    feature = "pkg/launch/main.launch.xml"
    words = ["configure", str(tmp_path), "--select", feature, "--set", f"{feature}:on={on}"]
    assert main([*words, "--set", f"{feature}:mode=slow", "--finish", "--json"]) == 0
    state = json.loads(capsys.readouterr().out)
    program, launch, package, name, *arguments = shlex.split(state["command"])
    assert (program, launch, package, name) == ("ros2", "launch", "pkg", "main.launch.xml")
    given = dict(word.split(":=", 1) for word in arguments)
    expected = run_oracle(file, given, [tmp_path])
    assert expected["ok"]
    present = {n["name"] for n in state["graph"]["nodes"] if n["presence"] == "present"}
    assert present == {n["fqn"] for n in expected["nodes"]} == {f"/{'ab'[on == 'false']}_slow"}


def test_the_graph_marks_the_nodes_event_handlers_start(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from differential.ros2.names_cases import CASES

    _launch_folder(tmp_path).joinpath("main.launch.py").write_text(
        CASES["event-handlers"][0]["main.launch.py"]
    )
    feature = "pkg/launch/main.launch.py"
    assert main(["configure", str(tmp_path), "--select", feature, "--json"]) == 0
    state = json.loads(capsys.readouterr().out)
    triggers = {n["name"]: n["trigger"].partition("(")[0] for n in state["graph"]["nodes"]}
    assert triggers == {
        "/first": "launch",
        "/after_first": "on_process_start",
        "/late": "timer@2s",
        "/after_late": "on_process_start",
        "/on_exit": "on_process_exit",
    }


def test_a_product_that_does_not_launch_names_ros2_launch(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The issue 28 audit: what ``ros2 launch`` refuses was said of roslaunch."""
    file = _launch_folder(tmp_path) / "main.launch.xml"
    file.write_text(
        '<launch><arg name="on" default="true"/>\n'
        '<node pkg="pkg" exec="a" name="a" if="$(var on)"/></launch>'
    )
    feature = "pkg/launch/main.launch.xml"
    words = ["configure", str(tmp_path), "--select", feature, "--set", f"{feature}:on=abc"]
    assert main(words) == 1
    out = capsys.readouterr().out
    assert "ros2 launch pkg main.launch.xml on:=abc\n" in out
    assert "this product does not launch: ros2 launch stops at the errors" in out
    assert not run_oracle(file, {"on": "abc"}, [tmp_path])["ok"]


TYPED_NAMES = """<launch>
  <arg name="n" default="talker"/>
  <arg name="ns" default="a"/>
  <arg name="p" default="a"/>
  <group>
    <push-ros-namespace namespace="$(var p)"/>
    <node pkg="pkg" exec="n" name="$(var n)" namespace="$(var ns)"/>
  </group>
</launch>"""


@pytest.mark.parametrize(
    ("arg", "typed"),
    [
        *(("n", typed) for typed in ("a/b", "9lives", "", "ok")),
        *(("ns", typed) for typed in ("x y", "x//y", "/abs/", "x/y")),
        *(("p", typed) for typed in ("p q", "/", "x/y/")),
    ],
)
def test_a_typed_name_launch_ros_refuses_is_refused_or_the_products_failure(
    arg: str, typed: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A text typed for a node's name or namespace or a pushed namespace is checked as
    launch_ros checks them: where the oracle fails with it, the text is refused with
    launch_ros's reason once the node is in every product left (the other args chosen), and
    is the failure of the finished product otherwise; where it loads, the product is its
    nodes."""
    file = _launch_folder(tmp_path) / "main.launch.xml"
    file.write_text(TYPED_NAMES)
    feature = "pkg/launch/main.launch.xml"
    typing = ["--set", f"{feature}:{arg}={typed}"]
    defaults = {"n": "talker", "ns": "a", "p": "a"}
    others = [
        w for a, v in defaults.items() if a != arg for w in ("--select", f"{feature}:{a}={v}")
    ]
    expected = run_oracle(file, {arg: typed}, [tmp_path])
    problem = str(expected.get("error", "")).split(":\n")[0]  # rmw's words, then where
    for words in ([*others, *typing], typing):
        main(["configure", str(tmp_path), "--select", feature, *words, "--finish", "--json"])
        state = json.loads(capsys.readouterr().out)
        errors = [e["message"] for e in state["graph"]["errors"] if e["presence"] == "present"]
        if expected["ok"]:
            assert state["refused"] == [] and errors == [] and state["launches"]
            present = {n["name"] for n in state["graph"]["nodes"] if n["presence"] == "present"}
            assert present == {n["fqn"] for n in expected["nodes"]}
        elif words == typing:
            assert not state["launches"] and any(problem in error for error in errors), errors
        else:
            [refusal] = state["refused"]
            assert "ros2 launch would stop at " in refusal["reason"]
            assert problem in refusal["reason"], (refusal["reason"], expected["error"])


TYPED_PARAM = """<launch>
  <arg name="rate" default="5"/>
  <arg name="fast" default="false"/>
  <node pkg="pkg" exec="a" name="a" if="$(var fast)">
    <param name="rate" type="int" value="$(var rate)"/>
  </node>
</launch>"""


def test_a_typed_text_a_typed_parameter_refuses_fails_as_in_ros2_launch(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """issue 30's "no finished command that does not launch", for ROS 2: ``<param
    type="int">`` of a typed ``abc`` stops ``ros2 launch`` (the oracle), so the text is refused
    where every product left has the node, and the product's failure where some have it; the
    configuration called it complete and loadable."""
    file = _launch_folder(tmp_path) / "typed.launch.xml"
    file.write_text(TYPED_PARAM)
    feature = "pkg/launch/typed.launch.xml"
    start = ["configure", str(tmp_path), "--select", feature]

    def configured(*words: str) -> dict[str, Any]:
        main([*start, *words, "--finish", "--json"])
        state: dict[str, Any] = json.loads(capsys.readouterr().out)
        return state

    refused = configured("--set", f"{feature}:fast=true", "--set", f"{feature}:rate=abc")
    [refusal] = refused["refused"]
    assert "ros2 launch would stop at " in refusal["reason"]
    assert "invalid literal for int() with base 10: 'abc' [param-invalid]" in refusal["reason"]
    assert run_oracle(file, {"fast": "true", "rate": "abc"}, [tmp_path])["ok"] is False
    failing = configured("--set", f"{feature}:rate=abc", "--set", f"{feature}:fast=true")
    assert failing["refused"] == [] and failing["launches"] is False  # its failure, struck
    loads = configured("--set", f"{feature}:rate=abc")  # fast stays false: no node, no param
    assert loads["refused"] == [] and loads["launches"] is True
    assert run_oracle(file, {"rate": "abc"}, [tmp_path])["ok"] is True
    typed = configured("--set", f"{feature}:fast=true", "--set", f"{feature}:rate=7")
    assert typed["refused"] == [] and typed["launches"] is True
    assert run_oracle(file, {"fast": "true", "rate": "7"}, [tmp_path])["ok"] is True
