"""The command line: ``rosvar analyze`` and ``rosvar resolve``, their output and exit codes.

Exit codes (``rosvar.outputs.commands.exit_codes``): 0 success, 1 the configuration fails
(errors or conflicts), 2 usage error, 3 nothing to analyse / a ``--launch`` file missing.
"""

from __future__ import annotations

import argparse
import json
import os
import shlex
import signal
import subprocess
import sys
import urllib.request
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

import rosvar
from outputs.schemas import schema_check
from rosvar.analyses.feature_model import extraction
from rosvar.outputs.cli import main, parser
from rosvar.outputs.commands.exit_codes import (
    EXIT_FAILS,
    EXIT_INPUT,
    EXIT_OK,
    EXIT_TOO_LARGE,
    EXIT_USAGE,
)
from rosvar.outputs.commands.terminal import shown_path
from workspace.interfaces.ros2_packages import MANIFEST, write_ros2_packages

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


GOOD = """<launch>
  <arg name="use_teleop" default="true"/>
  <arg name="two" default="false"/>
  <node pkg="pkg" type="teleop_node" name="teleop" if="$(arg use_teleop)"/>
  <node pkg="pkg" type="teleop_node" name="teleop" if="$(arg two)"/>
  <node pkg="pkg" type="planner_node" name="planner" unless="$(arg use_teleop)"/>
  <param name="home" value="$(optenv ROBOT_HOME /nowhere)"/>
</launch>
"""
BAD: dict[str, str | bytes] = {
    "malformed.launch": '<launch>\n  <node pkg="p" type="t" name="a"\n</launch>\n',
    "tag.launch": "<launch>\n  <bogus/>\n</launch>\n",
    "dtd.launch": '<?xml version="1.0"?>\n<!DOCTYPE launch [<!ENTITY a "b">]>\n<launch/>\n',
    "latin1.launch": b'<launch>\n  <param name="p" value="caf\xe9"/>\n</launch>\n',
}


CORPUS = Path(__file__).resolve().parents[3] / "shared" / "corpus"


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


@pytest.fixture
def workspace(ws: LaunchWorkspace) -> LaunchWorkspace:
    ws.write("launch/good.launch", GOOD)
    for name, content in BAD.items():
        ws.write(f"launch/{name}", content)
    return ws


# -- analyze ------------------------------------------------------------------------------------
def test_analyze_survives_bad_files_and_prints_positions(
    workspace: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, _err = run(capsys, "analyze", str(workspace.root))
    assert code == EXIT_OK

    def launch(name: str) -> str:  # as the output spells it, wherever the checkout is
        return shown_path(str(workspace.root / "pkg" / "launch" / name))

    assert f"{launch('malformed.launch')}:3:1: error: " in out
    assert "[xml-malformed]" in out
    assert f"{launch('tag.launch')}:2:3: warning: unrecognized tag <bogus> [tag-unknown]" in out
    assert f"{launch('dtd.launch')}:2:1: error: " in out and "[xml-dtd-forbidden]" in out
    assert f"{launch('latin1.launch')}:2:29: error: " in out and "[xml-encoding]" in out
    assert "5 launch files, 1 packages" in out
    rows = {line.split()[0]: line.split()[1:] for line in out.splitlines() if "good.launch" in line}
    [(_name, counts)] = rows.items()
    # args, nodes, params, errors: a non-boolean value fails each of the 3 if/unless tests
    assert counts == ["2", "3", "1", "3"]


def test_analyze_json(workspace: LaunchWorkspace, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _err = run(capsys, "analyze", "--json", str(workspace.root))
    assert code == EXIT_OK
    document = json.loads(out)
    files = {Path(f["file"]).name: f for f in document["files"]}
    assert set(files) == {"good.launch", *BAD}
    good = files["good.launch"]
    conditions = {(n["name"], n["condition"]) for n in good["nodes"]}
    assert ("planner", "use_teleop≠true") in conditions or ("planner", "¬use_teleop") in conditions
    assert ("teleop", "use_teleop") in conditions and ("teleop", "two") in conditions
    [diagnostic] = files["malformed.launch"]["diagnostics"]
    assert diagnostic["code"] == "xml-malformed" and diagnostic["severity"] == "error"
    assert (diagnostic["line"], diagnostic["col"]) == (3, 1)
    assert files["malformed.launch"]["loads"] == "false"
    schema_check(document, "analyze.schema.json")


LOOP = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(context):
    return [Node(package='pkg', executable='each', name=name)
            for name in LaunchConfiguration('names').perform(context).split(',')]


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('names', default_value='x,y'),
                              OpaqueFunction(function=setup)])
"""


def test_analyze_shows_no_error_no_configuration_raises(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A loop over a launch-time ``split``: the errors of its items past the list's end are
    recorded before the facts that rule them out are known; ``analyze`` neither lists nor
    counts them."""
    package = tmp_path / "pkg"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST.format(name="pkg", build="ament_python"))
    (package / "launch" / "loop.launch.py").write_text(LOOP)
    code, out, _err = run(capsys, "analyze", "--json", str(tmp_path))
    assert code == EXIT_OK
    [file] = json.loads(out)["files"]
    assert [e["condition"] for e in file["errors"]] == []
    code, out, _err = run(capsys, "analyze", str(tmp_path))
    row = out.splitlines()[2].split()
    assert (row[1], row[-1]) == ("1", "0"), out


def test_analyze_without_launch_files(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "empty").mkdir()
    code, _out, err = run(capsys, "analyze", str(tmp_path / "empty"))
    assert code == EXIT_INPUT and "no launch files" in err
    code, _out, err = run(capsys, "analyze", str(tmp_path / "missing"))
    assert code == EXIT_INPUT and "no such file or directory" in err


@pytest.mark.parametrize("json_output", [False, True])
def test_analyze_prints_the_same_with_any_number_of_jobs(
    json_output: bool, capsys: pytest.CaptureFixture[str]
) -> None:
    """Each process describes the conditions of its own files in its own BDD manager, with
    the variables declared in another order: the output must not show it."""
    husky, external = CORPUS / "husky", CORPUS / "_external"
    if not husky.is_dir():
        pytest.skip(f"corpus not found at {CORPUS}")
    argv = ["analyze", str(husky), "--deps", str(external), *(["--json"] if json_output else [])]
    alone = run(capsys, *argv, "--jobs", "1")
    assert alone[0] == EXIT_OK and len(alone[1]) > 10_000
    for jobs in ("2", "3"):
        assert run(capsys, *argv, "--jobs", jobs) == alone


# -- resolve ------------------------------------------------------------------------------------
def good_file(workspace: LaunchWorkspace) -> str:
    return str(workspace.root / "pkg" / "launch" / "good.launch")


def test_resolve_ok(workspace: LaunchWorkspace, capsys: pytest.CaptureFixture[str]) -> None:
    file = good_file(workspace)
    code, out, _err = run(capsys, "resolve", str(workspace.root), "--launch", file)
    assert code == EXIT_OK
    assert out.splitlines() == ["node  /teleop  (pkg/teleop_node)", "param /home = '/nowhere'"]
    code, out, _err = run(
        capsys,
        "resolve",
        str(workspace.root),
        "use_teleop:=false",
        "_private:=ignored",
        "--launch",
        file,
        "--env",
        "ROBOT_HOME=/home/robot",
    )
    assert code == EXIT_OK
    assert out.splitlines() == ["node  /planner  (pkg/planner_node)", "param /home = '/home/robot'"]
    assert "warning" not in _err


def ament_package(package: Path) -> Path:
    """An empty ROS 2 package ``p`` (ament_cmake) at ``package``."""
    package.mkdir()
    (package / "package.xml").write_text(
        "<package format='3'><name>p</name>"
        "<export><build_type>ament_cmake</build_type></export></package>"
    )
    return package


def test_resolve_prints_a_ros2_error_at_its_place(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    package = ament_package(tmp_path / "p")
    (package / "a.launch.xml").write_text(
        '<launch>\n  <node pkg="p" exec="e" name="n">\n    <param from="$(var f)"/>\n'
        "  </node>\n</launch>\n"
    )
    monkeypatch.chdir(tmp_path)
    code, out, _err = run(capsys, "resolve", str(tmp_path), "--launch", "p", "a.launch.xml")
    assert code == EXIT_FAILS
    assert out.splitlines()[-1] == (
        "error: p/a.launch.xml:3:5: <param> attribute 'from': "
        "launch configuration 'f' does not exist"
    )


def test_resolve_a_ros2_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    package = ament_package(tmp_path / "p")
    (package / "a.launch.xml").write_text(
        """<launch><arg name="ns" default="r"/>
        <node pkg="p" exec="e" name="n" namespace="$(var ns)"><param name="k" value="1"/></node>
        <node pkg="p" exec="anonymous" namespace="$(var ns)"/>
        </launch>"""
    )
    code, out, _err = run(capsys, "resolve", str(tmp_path), "--launch", "p", "a.launch.xml")
    assert code == EXIT_OK
    # a node with no name is named by its executable at run time
    assert out.splitlines() == [
        "node  /r/n  (p/e)",
        "  param k = 1",
        "node  /r/⟨anonymous⟩  (p/anonymous)",
    ]
    code, out, _err = run(
        capsys, "resolve", "--launch", str(package / "a.launch.xml"), "ns:=/s", "--json"
    )
    resolved = json.loads(out)
    schema_check(resolved, "resolve.schema.json")  # one shape for ROS 1 and ROS 2
    node, unnamed = resolved["nodes"]
    assert (node["name"], node["fqn"], node["parameters"]) == ("/s/n", "/s/n", {"k": 1})
    assert (unnamed["name"], unnamed["fqn"], unnamed["namespace"]) == ("/s/⟨anonymous⟩", None, "/s")
    # the configured product's graph has the same nodes, drawn with ROS 2's fields
    file = str(package / "a.launch.xml")
    code, out, _err = run(
        capsys, "configure", str(tmp_path), "--select", file, "--set", f"{file}:ns=r", "--json"
    )
    document = json.loads(out)
    assert document["command"] == "ros2 launch p a.launch.xml"
    shown = [
        (n["name"], n["fqn"], n["namespace"], n["parameters"])
        for n in document["graph"]["nodes"]
        if n["presence"] == "present"
    ]
    assert shown == [("/r/n", "/r/n", "/r", {"k": 1}), ("/r/⟨anonymous⟩", None, "/r", {})]
    schema_check(document, "configure.schema.json")
    _code, out, _err = run(
        capsys, "configure", str(tmp_path), "--select", file, "--set", f"{file}:ns=r"
    )
    assert "nodes: 2 present, 0 undetermined" in out.splitlines()
    assert "params: 1 on the present nodes (a ROS 2 node holds its own)" in out.splitlines()


def test_query_and_check_on_a_ros2_workspace(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A ROS 2 node's executable is its ``exec``; the ROS 2 catalogue, not ROS 1's, gives
    its interface (ROS 2's joy publishes ``joy``, its feedback input a boundary use)."""
    package = ament_package(tmp_path / "p")
    (package / "a.launch.xml").write_text(
        """<launch><arg name="joy" default="true"/>
        <node pkg="joy" exec="joy_node" name="joy" if="$(var joy)"/></launch>"""
    )
    code, out, _err = run(
        capsys, "query", str(tmp_path), "nodes[self.type == 'joy_node']", "--json"
    )
    assert code == EXIT_OK
    [result] = json.loads(out)["results"]
    assert result["name"] == "/joy" and result["example"] == {"a.launch.xml:joy": "true"}
    code, out, _err = run(capsys, "check", str(tmp_path), "--format", "json")
    assert code == EXIT_OK
    findings = json.loads(out)["findings"]
    assert {(f["check"], f["severity"], f["name"]) for f in findings} == {
        ("no-provider", "note", "/joy/set_feedback"),
        ("no-subscriber", "note", "/joy"),
    }


def test_resolve_warns_of_an_arg_no_file_reads(
    workspace: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    """roslaunch ignores it silently: the output is that of no such arg, and stderr says so."""
    file = good_file(workspace)
    plain = run(capsys, "resolve", str(workspace.root), "--launch", file)
    code, out, err = run(
        capsys, "resolve", str(workspace.root), "use_telop:=false", "--launch", file
    )
    assert (code, out) == plain[:2]
    assert "no launched file has an arg 'use_telop'" in err
    assert "did you mean 'use_teleop'?" in err and "(args: two, use_teleop)" in err


def test_resolve_conflict_and_error_exit_1(
    workspace: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    file = good_file(workspace)
    code, out, _err = run(capsys, "resolve", str(workspace.root), "two:=true", "--launch", file)
    assert code == EXIT_FAILS
    at = shown_path(file)  # as the output spells it, wherever the checkout is
    assert f"conflict: node-name /teleop at {at}:4:3, {at}:5:3" in out
    code, out, _err = run(
        capsys, "resolve", str(workspace.root), "use_teleop:=maybe", "--launch", file
    )
    assert code == EXIT_FAILS
    assert out.startswith(f"error: {at}:4:3: ") and "not a 'bool' type" in out
    bad = str(workspace.root / "pkg" / "launch" / "malformed.launch")
    code, out, _err = run(capsys, "resolve", str(workspace.root), "--launch", bad)
    assert code == EXIT_FAILS and "malformed XML" in out


def test_resolve_json(workspace: LaunchWorkspace, capsys: pytest.CaptureFixture[str]) -> None:
    file = good_file(workspace)
    for extra, ok in (([], True), (["two:=true"], False), (["use_teleop:=maybe"], False)):
        code, out, _err = run(
            capsys, "resolve", str(workspace.root), *extra, "--launch", file, "--json"
        )
        document = json.loads(out)
        assert set(document) == {
            *("ok", "nodes", "tests", "params", "conflicts", "errors"),
            *("topics", "services", "actions"),
        }
        assert document["ok"] is ok and code == (EXIT_OK if ok else EXIT_FAILS)
        schema_check(document, "resolve.schema.json")
    assert document["errors"][0]["code"] == "bool-invalid"
    assert (document["errors"][0]["line"], document["errors"][0]["col"]) == (4, 3)


def test_resolve_json_special_values(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    """Values JSON has no type for keep a tagged form that the schema documents."""
    file = ws.launch(
        "special.launch",
        "<rosparam>\n  day: 2001-12-14\n  blob: !!binary aGVsbG8=\n  big: .inf\n</rosparam>",
    )
    code, out, _err = run(capsys, "resolve", str(ws.root), "--launch", file, "--json")
    document = json.loads(out)
    assert code == EXIT_OK
    assert document["params"] == {
        "/day": {"__datetime__": "2001-12-14"},
        "/blob": {"__binary__": "aGVsbG8="},
        "/big": "inf",
    }
    schema_check(document, "resolve.schema.json")


def test_resolve_package_and_file_name(
    workspace: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    """``--launch PKG FILE`` names the same file as its path, as ``roslaunch PKG FILE`` does."""
    root = str(workspace.root)
    for extra in ([], ["use_teleop:=false"]):
        code, by_name, _err = run(capsys, "resolve", root, "--launch", "pkg", "good.launch", *extra)
        assert (code, by_name) == run(
            capsys, "resolve", root, "--launch", good_file(workspace), *extra
        )[:2]
    assert code == EXIT_OK and "/planner" in by_name
    workspace.write("other/good.launch", GOOD)
    code, _out, err = run(capsys, "resolve", root, "--launch", "pkg", "good.launch")
    assert code == EXIT_INPUT and "multiple files named [good.launch]" in err
    code, _out, err = run(capsys, "resolve", root, "--launch", "nopkg", "good.launch")
    assert code == EXIT_INPUT and "package 'nopkg' is not in the workspace" in err
    with pytest.raises(SystemExit) as exit_info:
        main(["resolve", root, "--launch", "pkg", "good.launch", "extra"])
    assert exit_info.value.code == EXIT_USAGE


def test_resolve_input_and_usage_errors(
    workspace: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    root = str(workspace.root)
    code, _out, err = run(capsys, "resolve", root, "--launch", str(workspace.root / "no.launch"))
    assert code == EXIT_INPUT and "launch file not found" in err
    for bad_env in ("NOEQUALS", "=value"):
        code, _out, err = run(
            capsys, "resolve", root, "--launch", good_file(workspace), "--env", bad_env
        )
        assert code == EXIT_USAGE and "--env expects NAME=VALUE" in err
    with pytest.raises(SystemExit) as exit_info:
        main(["resolve", root])  # --launch is required
    assert exit_info.value.code == EXIT_USAGE
    with pytest.raises(SystemExit) as exit_info:
        main([])
    assert exit_info.value.code == EXIT_USAGE


def test_resolve_args_after_options(
    workspace: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, _err = run(
        capsys,
        "resolve",
        str(workspace.root),
        "--launch",
        good_file(workspace),
        "use_teleop:=false",
    )
    assert code == EXIT_OK and "/planner" in out


def test_real_process_exit_codes(workspace: LaunchWorkspace) -> None:
    file = good_file(workspace)
    base = [sys.executable, "-m", "rosvar", "resolve", str(workspace.root)]
    ok = subprocess.run([*base, "--launch", file], capture_output=True, text=True, check=False)
    assert ok.returncode == EXIT_OK, ok.stderr
    clash = subprocess.run(
        [*base, "two:=true", "--launch", file, "--json"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert clash.returncode == EXIT_FAILS
    assert json.loads(clash.stdout)["conflicts"][0]["name"] == "/teleop"


# -- configure ----------------------------------------------------------------------------------
ROBOT = """  <arg name="model" default="kobuki"/>
  <arg name="speed"/>
  <node pkg="pkg" type="drive" name="$(arg model)"><param name="speed" value="$(arg speed)"/></node>
"""


@pytest.fixture
def robot(ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch) -> str:
    ws.launch("robot.launch", ROBOT)
    ws.launch("other.launch", '  <node pkg="pkg" type="t" name="kobuki"/>')
    monkeypatch.chdir(ws.root)
    return "pkg/launch/robot.launch"


def test_json_has_the_agreed_fields_and_validates(
    robot: str, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, _err = run(capsys, "configure", ".", "--select", robot, "--json")
    assert code == EXIT_OK
    document = json.loads(out)
    assert {"features", "conflicts", "graph", "complete", "command", "refused"} <= set(document)
    assert document["features"][f"{robot}:model"]["state"] == "selected"
    assert document["features"][f"{robot}:model"]["derived"] is True
    assert document["features"][robot]["derived"] is False
    assert set(document["graph"]) >= {"nodes", "params", "topics"}
    assert document["complete"] is False and document["command"] is None
    schema_check(document, "configure.schema.json")


def test_complete_with_a_typed_value(robot: str, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _err = run(
        capsys, "configure", ".", "--set", f"{robot}:speed=0.5", "--deselect",
        "pkg/launch/other.launch", "--set", f"{robot}:model=kobuki", "--json",
    )  # fmt: skip
    assert code == EXIT_OK
    document = json.loads(out)
    assert document["complete"] is True
    # a required arg is always named, a default one only when it differs
    assert document["command"] == "roslaunch pkg robot.launch speed:=0.5"
    params = [p for p in document["graph"]["params"] if p["presence"] == "present"]
    assert [(p["name"], p["value"]) for p in params] == [("/kobuki/speed", 0.5)]
    schema_check(document, "configure.schema.json")


def test_refused_choice_exits_1_and_is_listed(
    robot: str, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, _err = run(
        capsys, "configure", ".", "--set", f"{robot}:model=kobuki", "--select",
        "pkg/launch/other.launch",
    )  # fmt: skip
    assert code == EXIT_FAILS
    assert "refused: select pkg/launch/other.launch is impossible after set" in out
    assert "both declare node /kobuki" in out


def test_text_summary_tells_what_is_left(robot: str, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _err = run(capsys, "configure", ".", "--select", robot)
    assert code == EXIT_OK
    assert "selected files: pkg/launch/robot.launch" in out
    assert f"--set {robot}:speed=..." in out
    code, out, _err = run(capsys, "configure", ".", "--select", robot, "--set",
                          f"{robot}:speed=1", "--finish")  # fmt: skip
    assert code == EXIT_OK and out.splitlines()[-1] == "roslaunch pkg robot.launch speed:=1"


def test_a_product_that_does_not_launch_exits_1_and_says_so(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """issue 30: a finished product whose command roslaunch refuses, offered as any other."""
    ws.launch(
        "t.launch",
        '  <arg name="rate" default="5"/>\n  <arg name="fast" default="false"/>\n'
        '  <param name="rate" type="int" value="$(arg rate)" if="$(arg fast)"/>',
    )
    monkeypatch.chdir(ws.root)
    file = "pkg/launch/t.launch"
    code, out, _err = run(capsys, "configure", ".", "--set", f"{file}:rate=abc", "--finish")
    assert code == EXIT_OK and out.splitlines()[-1] == "roslaunch pkg t.launch rate:=abc"
    code, out, _err = run(
        capsys, "configure", ".", "--set", f"{file}:rate=abc", "--set", f"{file}:fast=true",
        "--finish",
    )  # fmt: skip
    assert code == EXIT_FAILS
    assert "error: " in out and "invalid literal for int() with base 10: 'abc'" in out
    assert out.splitlines()[-2] == "roslaunch pkg t.launch rate:=abc fast:=true"
    assert out.splitlines()[-1].startswith("this product does not launch")


def test_a_ros2_product_that_does_not_launch_names_ros2_launch(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    package = ament_package(tmp_path / "p")
    (package / "a.launch.xml").write_text(
        '<launch>\n  <arg name="f" default="x.yaml"/>\n  <node pkg="p" exec="e" name="n">\n'
        '    <param from="$(var g)"/>\n  </node>\n</launch>\n'
    )
    monkeypatch.chdir(tmp_path)
    code, out, _err = run(capsys, "configure", ".", "--select", "p/a.launch.xml", "--finish")
    assert code == EXIT_FAILS
    assert out.splitlines()[-2] == "ros2 launch p a.launch.xml"
    assert out.splitlines()[-1] == (
        "this product does not launch: ros2 launch stops at the errors or conflicts above"
    )


def test_what_rosvar_could_not_read_is_listed_at_every_step(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    ws.launch("a.launch", '  <include file="$(find nopkg)/launch/x.launch"/>')
    monkeypatch.chdir(ws.root)
    for extra in ([], ["--finish"]):
        code, out, _err = run(capsys, "configure", ".", "--select", "pkg/launch/a.launch", *extra)
        assert code == EXIT_FAILS  # roslaunch cannot load the include: the product fails
        assert "not known: 2 places of the selected files that rosvar could not read" in out
        assert "  pkg/launch/a.launch:2:3: warning: package 'nopkg' is not in" in out


def test_usage_errors(robot: str, capsys: pytest.CaptureFixture[str]) -> None:
    code, _out, err = run(capsys, "configure", ".", "--select", "nowhere.launch")
    assert code == EXIT_USAGE and "no feature 'nowhere.launch'" in err
    code, _out, err = run(capsys, "configure", ".", "--set", robot)
    assert code == EXIT_USAGE and "FILE:ARG=VALUE" in err
    code, _out, err = run(capsys, "configure", ".", "--env", "NOVALUE")
    assert code == EXIT_USAGE


def test_nothing_to_configure(tmp_path: object, capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["configure", str(tmp_path)])
    assert code == EXIT_INPUT


# -- serve --------------------------------------------------------------------------------------
def test_serve_prints_its_url_answers_and_stops_on_ctrl_c(robot: str) -> None:
    source = str(Path(rosvar.__file__).resolve().parents[1])  # these sources, from any cwd
    server = subprocess.Popen(
        [sys.executable, "-m", "rosvar", "serve", ".", "--port", "0"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "PYTHONPATH": source},
        # a test run started in the background inherits SIGINT ignored, and so would the
        # server: give it Ctrl-C as a terminal would
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    try:
        assert server.stdout is not None
        line = server.stdout.readline()  # printed once the model is loaded
        assert line.startswith("rosvar: serving http://127.0.0.1:"), line
        url = line.split()[2]
        request = urllib.request.Request(
            f"{url}api/session", b"{}", {"Content-Type": "application/json"}
        )
        with urllib.request.urlopen(request, timeout=60) as reply:
            state = json.load(reply)
        assert robot in state["features"] and state["session"]
    finally:
        server.send_signal(signal.SIGINT)
        _out, err = server.communicate(timeout=60)
    assert server.returncode == EXIT_OK
    assert "analysing 2 launch files" in err


def test_serve_usage_errors(robot: str, capsys: pytest.CaptureFixture[str]) -> None:
    code, _out, err = run(capsys, "serve", ".", "--env", "NOVALUE")
    assert code == EXIT_USAGE and "NAME=VALUE" in err
    code, _out, err = run(capsys, "serve", ".", "--host", "203.0.113.1", "--port", "0")
    assert code == EXIT_USAGE and "cannot listen" in err


def test_a_model_too_large_to_solve(
    workspace: LaunchWorkspace, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Listed by the formats that need no solver; the others exit 4 with the reason."""
    workspace.write("launch/clone.launch", GOOD)  # clashes with good.launch: one linked pair
    monkeypatch.setattr(extraction, "LINK_BUDGET", 0)
    monkeypatch.setattr(extraction, "LINKS_PER_FILE", 0)
    root = str(workspace.root)
    code, out, _err = run(capsys, "features", root)
    assert code == EXIT_OK and "unknown number of valid configurations" in out
    for argv in (("features", root, "--format", "uvl"), ("configure", root)):
        code, _out, err = run(capsys, *argv)
        assert code == EXIT_TOO_LARGE
        assert err.startswith("rosvar: the feature model is too large to solve: ")


def test_a_model_too_large_says_its_largest_parts_and_a_narrower_command(
    ws: LaunchWorkspace,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """issue 30.6: on a whole repository configure stopped after seconds with the reason
    only; it names the packages the largest groups of linked files are in, and the
    narrower command that works (one package, the rest as dependencies)."""
    for package, files in (("big", 3), ("small", 1)):
        for number in range(files):
            ws.launch(f"f{number}.launch", '  <node pkg="p" type="t" name="same"/>', package)
    ws.launch("alone.launch", '  <node pkg="p" type="t" name="other"/>', "lone")
    monkeypatch.setattr(extraction, "LINK_BUDGET", 0)
    monkeypatch.setattr(extraction, "LINKS_PER_FILE", 0)
    monkeypatch.chdir(ws.root)
    code, _out, err = run(capsys, "configure", ".")
    assert code == EXIT_TOO_LARGE
    lines = err.splitlines()
    assert lines[0].startswith("rosvar: the feature model is too large to solve: 6 pairs")
    assert lines[1:4] == [
        "rosvar: its largest parts (files linked by includes and shared names):",
        "  4 files of 2 packages: big (3), small (1)",
        "  1 file of 1 package: lone (1)",
    ]
    assert lines[4].endswith("e.g. rosvar configure big --deps .")


# -- readable summaries -------------------------------------------------------------------------
REPO = Path(__file__).resolve().parents[2]


def test_metrics_table_has_a_row_per_path_as_in_json(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    ws.launch("robot.launch", ROBOT)
    examples = str(REPO / "examples")
    rows = {}
    for path in (examples, str(ws.root)):
        code, out, _err = run(capsys, "metrics", path, "--json")
        rows[path] = json.loads(out)
    code, out, _err = run(capsys, "metrics", examples, str(ws.root))
    assert code == EXIT_OK
    header, *lines = out.splitlines()
    assert header.split() == ["system", *rows[examples]]
    for path, line in zip(rows, lines, strict=False):
        assert line.split() == [path, *map(str, rows[path].values())]
    assert "LF launch files" in out and "docs/features.md#metrics" in out
    code, out, _err = run(capsys, "metrics", examples, str(ws.root), "--json")
    assert json.loads(out) == rows


def test_counts_for_people_are_short_and_json_exact(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    """30 independent Boolean args (three values each) and a file: over 10^14 configurations."""
    ws.launch(
        "many.launch",
        "".join(
            f'  <arg name="a{n}" default="true"/>\n  <node pkg="p" type="t" name="n{n}" '
            f'if="$(arg a{n})"/>\n'
            for n in range(30)
        )
        + '  <arg name="port"/>\n  <param name="port" value="$(arg port)"/>\n',
    )
    _code, out, _err = run(capsys, "features", str(ws.root), "--format", "json")
    exact = json.loads(out)["configurations"]
    exponent = len(str(exact)) - 1
    superscript = str(exponent).translate(str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹"))
    _code, out, err = run(capsys, "features", str(ws.root))
    shown = f"  ≈ {round(exact / 10**exponent, 1)} × 10{superscript} valid configurations"
    assert exponent > 9 and out.splitlines()[3] == shown
    assert "1 note [values-unknown]" in out and "[values-unknown]" in err
    assert "arg 'port'" in err and "arg 'port'" not in out


def test_analyze_marks_a_cut_path(ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]) -> None:
    path = ws.launch("a" * 70 + ".launch", '  <node pkg="p" type="t" name="n"/>')
    _code, out, _err = run(capsys, "analyze", str(ws.root))
    [row] = [line for line in out.splitlines() if ".launch" in line]
    shown = row.split()[0]
    assert shown.startswith("…") and os.path.relpath(path).endswith(shown[1:])


def test_analyze_reports_a_shared_file_s_problem_once(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    shared = ws.launch("shared.launch", "  <bogus/>")
    for name in ("a.launch", "b.launch"):
        ws.launch(name, '  <include file="$(find pkg)/launch/shared.launch"/>')
    _code, out, _err = run(capsys, "analyze", str(ws.root))
    shown = [line for line in out.splitlines() if "[tag-unknown]" in line]
    assert len(shown) == 1 and shown_path(shared) in shown[0]
    assert "\n1 diagnostics (0 errors)" in out


def test_configure_summarises_a_clash_of_many_params(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    params = "".join(f'<param name="p{n}" value="1"/>' for n in range(12))
    for name in ("a.launch", "b.launch"):
        ws.launch(name, f'  <node pkg="p" type="t" name="n">{params}</node>')
    _code, out, _err = run(capsys, "configure", str(ws.root), "--json")
    [conflict] = json.loads(out)["conflicts"]
    assert len(conflict["names"]) == 13
    _code, out, _err = run(capsys, "configure", str(ws.root))
    [line] = [line for line in out.splitlines() if line.startswith("conflict")]
    assert line.endswith(": node /n, param /n/p0, param /n/p1 and 10 params")


def test_every_option_is_described_with_an_example_that_parses() -> None:
    top = parser()
    [commands] = [a for a in top._actions if isinstance(a, argparse._SubParsersAction)]
    for name, command in commands.choices.items():
        for action in command._actions:
            assert action.help, f"{name} {action.dest}"
        assert command.epilog and "docs/cli.md" in command.epilog
        example = command.epilog.split("example:\n")[1].split("\n\n")[0]
        for line in example.replace("\\\n", " ").splitlines():
            words = shlex.split(line.split("|")[0])
            assert words[:2] == ["rosvar", name]
            top.parse_known_args(words[1:])  # exits (SystemExit) on a usage error


# -- dependencies and start-up ------------------------------------------------------------------
def test_every_command_takes_deps(
    tmp_path: Path, ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    """Packages under --deps resolve $(find) and executables, yet are no features."""
    import conftest

    underlay = conftest.LaunchWorkspace(tmp_path / "opt")  # a sourced installation's share/
    underlay.launch("driver.launch", '  <node pkg="base" type="drive" name="driver"/>', "base")
    (underlay.package("base") / ".executables").write_text("drive\n")
    main_file = ws.launch(
        "robot.launch", '  <include file="$(find base)/launch/driver.launch"/>', "robot"
    )
    root, deps = str(ws.root), str(underlay.root)

    code, out, _err = run(capsys, "analyze", root, "--deps", deps, "--json")
    (model,) = json.loads(out)["files"]
    assert code == EXIT_OK and model["file"] == main_file
    assert [i["resolved"] for i in model["includes"]] == [True]
    assert [n["name"] for n in model["nodes"]] == ["driver"]
    assert model["errors"] == [] and model["diagnostics"] == []
    code, out, _err = run(capsys, "analyze", root, "--json")
    (alone,) = json.loads(out)["files"]
    assert [i["resolved"] for i in alone["includes"]] == [False]

    code, out, _err = run(capsys, "resolve", root, "--deps", deps, "--launch", main_file)
    assert code == EXIT_OK and "node  /driver  (base/drive)" in out
    code, out, _err = run(capsys, "features", root, "--deps", deps, "--format", "json")
    assert code == EXIT_OK
    files = [f["path"] for f in json.loads(out)["features"] if f["kind"] == "file"]
    assert files == [main_file]
    for argv in (("metrics",), ("configure", "--finish")):
        code, _out, err = run(capsys, argv[0], root, "--deps", deps, *argv[1:])
        assert code == EXIT_OK, err
    code, _out, err = run(capsys, "analyze", root, "--deps", str(tmp_path / "nowhere"))
    assert code == EXIT_OK and "[path-missing]" in err
    code, _out, err = run(capsys, "serve", root, "--deps", deps, "--host", "203.0.113.1")
    assert code == EXIT_USAGE and "cannot listen" in err  # got past the analysis


def test_version_and_help_import_no_analysis() -> None:
    """`--version`, `--help` and a command's `--help` import neither `dd` (nor `networkx`
    through it), numpy, the interpreter nor the web server (the registry of dialects, typing
    only, comes with the package)."""
    heavy = (
        "dd",
        "networkx",
        "numpy",
        "rosvar.interpreter.",
        "rosvar.outputs.web",
        "rosvar.ros1",
        "rosvar.ros2",
    )
    probe = (
        "import sys\n"
        "from rosvar.outputs.cli import main\n"
        "for argv in (['--version'], ['--help'], ['features', '--help']):\n"
        "    try:\n"
        "        main(argv)\n"
        "    except SystemExit:\n"
        "        pass\n"
        f"print(sorted(m for m in sys.modules if m.split('.')[0] in {heavy!r}\n"
        f"             or m.startswith({heavy!r}) and m != 'rosvar.interpreter.dialect'))\n"
    )
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert done.stdout.strip().splitlines()[-1] == "[]"


def test_allow_outside_workspace_option(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "secret.txt").write_text("hunter2")
    package = tmp_path / "ws" / "pkg"
    package.mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>pkg</name></package>")
    (package / "x.launch").write_text(
        f'<launch><param name="s" textfile="{tmp_path / "secret.txt"}"/></launch>'
    )
    assert main(["analyze", str(tmp_path / "ws"), "--json"]) == 0
    confined = capsys.readouterr().out
    assert "hunter2" not in confined and "file-outside-workspace" in confined
    assert main(["analyze", str(tmp_path / "ws"), "--json", "--allow-outside-workspace"]) == 0
    assert "hunter2" in capsys.readouterr().out


def test_resolve_shows_the_communication_graph(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    ws.write(
        "scripts/talker.py",
        'import rospy\nfrom std_msgs.msg import String\nrospy.Publisher("~chatter", String)\n',
    )
    file = ws.launch(
        "talk.launch",
        '<group ns="robot"><node pkg="pkg" type="talker.py" name="talker">'
        '<remap from="~chatter" to="/out"/></node></group>',
    )
    code, out, _err = run(capsys, "resolve", str(ws.root), "--launch", file, "--json")
    document = json.loads(out)
    assert code == EXIT_OK
    schema_check(document, "resolve.schema.json")
    assert document["topics"] == [
        {"name": "/out", "types": ["std_msgs/String"], "publishers": ["/robot/talker"],
         "subscribers": []}
    ]  # fmt: skip
    _code, out, _err = run(capsys, "resolve", str(ws.root), "--launch", file)
    assert "topic   /out [std_msgs/String]: /robot/talker → -" in out.splitlines()


def test_ros2_communication_graph_in_resolve_and_configure(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """ROS 2 nodes' interfaces give ``resolve`` its topics, services and actions, and the
    configuration graph the same names (and the targets of remaps, as for ROS 1)."""
    write_ros2_packages(tmp_path)
    bringup = tmp_path / "demo_bringup"
    bringup.mkdir()
    (bringup / "package.xml").write_text(MANIFEST.format(name="demo_bringup", build="ament_cmake"))
    (bringup / "demo.launch.xml").write_text(
        """<launch><arg name="ns" default="r1"/>
        <push_ros_namespace namespace="$(var ns)"/>
        <node pkg="demo_cpp" exec="talker"><remap from="/reset" to="/robot_reset"/></node>
        <node pkg="demo_py" exec="listener" namespace="/"/></launch>"""
    )
    launch = ("--launch", "demo_bringup", "demo.launch.xml")
    code, out, _err = run(capsys, "resolve", str(tmp_path), *launch, "--json")
    assert code == EXIT_OK
    document = json.loads(out)
    topics = {t["name"]: (t["publishers"], t["subscribers"]) for t in document["topics"]}
    assert topics == {
        "/chatter": ([], ["/listener"]),
        "/listener/echo": (["/listener"], []),
        "/r1/chatter": (["/r1/talker"], []),
        "/r1/talker/control": ([], ["/r1/talker"]),
    }
    assert [(s["name"], s["clients"]) for s in document["services"]] == [
        ("/reset", []),
        ("/robot_reset", ["/r1/talker"]),
    ]
    assert [a["name"] for a in document["actions"]] == ["/fibonacci", "/r1/fibonacci"]
    code, out, _err = run(
        capsys,
        "configure",
        str(tmp_path),
        "--select",
        "demo_bringup/demo.launch.xml",
        "--finish",
        "--json",
    )
    assert code == EXIT_OK
    graph = json.loads(out)["graph"]
    configured = {t["name"] for t in graph["topics"] if t["presence"] == "present"}
    assert configured - set(topics) == {"/robot_reset"}  # a remap's target
    assert set(topics) <= configured
    assert {s["name"] for s in graph["services"]} == {"/reset", "/robot_reset"}


def test_ros2_hints_give_interfaces(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A ROS 2 node no source defines gets its interface from the hints' ``nodes:``, as in
    ROS 1, a component by its class."""
    package = tmp_path / "p"
    package.mkdir()
    (package / "package.xml").write_text(MANIFEST.format(name="p", build="ament_cmake"))
    (package / "a.launch.xml").write_text(
        """<launch><push_ros_namespace namespace="r1"/>
        <node pkg="joy" exec="joy_node" name="joy"><remap from="joy" to="/joy_in"/></node>
        <node_container pkg="rclcpp_components" exec="component_container" name="c">
          <composable_node pkg="teleop" plugin="teleop::Joy" name="teleop"/>
        </node_container></launch>"""
    )
    hints = tmp_path / "hints.yaml"
    hints.write_text(
        "nodes:\n"
        "  joy/joy_node:\n"
        "    publishes: [{name: joy, type: sensor_msgs/msg/Joy}]\n"
        "  teleop/teleop::Joy:\n"
        "    subscribes: [{name: /joy_in, type: sensor_msgs/msg/Joy}]\n"
    )
    query = "topics[len(self.publishers) == 1 and len(self.subscribers) == 1]"
    code, out, _err = run(capsys, "query", str(tmp_path), query, "--json", "--hints", str(hints))
    assert code == EXIT_OK
    assert [result["name"] for result in json.loads(out)["results"]] == ["/joy_in"]


def test_resolve_reads_the_hints_when(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    """A hinted entry is in ``resolve``'s graph only where its ``when:`` holds with the
    node's parameters (set here, else the source's default)."""
    ws.write(
        "scripts/talker.py",
        "import rospy\nfrom std_msgs.msg import String\n"
        'rospy.get_param("~loud", False)\nrospy.Publisher("chatter", String)\n',
    )
    hints = ws.write(
        "hints.yaml",
        "nodes:\n  pkg/talker.py:\n    publishes:\n"
        "      - {name: chatter, type: std_msgs/String, when: \"param('~loud')\"}\n",
    )
    file = ws.launch(
        "talk.launch",
        '<arg name="loud" default=""/><node pkg="pkg" type="talker.py" name="talker">'
        '<param name="loud" value="$(arg loud)" type="bool" unless="$(eval loud == \'\')"/>'
        "</node>",
    )
    topics = {}
    for loud in ("true", "false", ""):
        argv = ["resolve", str(ws.root), "--launch", file, "--hints", hints, "--json"]
        code, out, _err = run(capsys, *argv, f"loud:={loud}")
        assert code == EXIT_OK
        topics[loud] = [topic["name"] for topic in json.loads(out)["topics"]]
    assert topics == {"true": ["/chatter"], "false": [], "": []}  # unset: the default, false
    _code, out, _err = run(capsys, "resolve", str(ws.root), "--launch", file, "loud:=true")
    assert "/chatter" in out  # without hints: the source's publisher


def test_resolve_prints_a_ros2_process_and_the_warnings(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """One printer for both ROS versions: a process is listed as its program names it, and
    what ``ros2 launch`` warns of is printed where it is written."""
    package = ament_package(tmp_path / "p")
    file = package / "a.launch.xml"
    file.write_text(
        """<launch>
        <node pkg="p" exec="e" name="n"><param from="/nonexistent.yaml"/></node>
        <executable cmd="/usr/bin/sleep 5"/>
        </launch>"""
    )
    code, out, _err = run(capsys, "resolve", str(tmp_path), "--launch", str(file))
    assert code == EXIT_OK
    assert out.splitlines() == [
        "node  /n  (p/e)",
        "node  /⟨sleep⟩  (-//usr/bin/sleep)",
        f"warning: {shown_path(str(file))}:2:9: Parameter file path is not a file: "
        "/nonexistent.yaml",
    ]
