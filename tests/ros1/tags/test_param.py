"""``<param>``: typed values per configuration; ``command=`` is never run."""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from rosvar.interpreter.model import DeferredValue, ParamDecl
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

TYPED = """
  <arg name="v" default="1"/>
  <param name="auto" value="$(arg v)"/>
  <param name="as_str" value="$(arg v)" type="str"/>
  <param name="as_int" value="$(arg v)" type="int"/>
  <param name="yaml" value="[$(arg v), 2]" type="yaml"/>
  <param name="fixed" value=" 3.5 "/>
"""


def test_values_are_typed_per_configuration(ws: LaunchWorkspace) -> None:
    file = ws.launch("typed.launch", TYPED)
    model = ws.model(file)
    params = {str(p.name.single()): p for p in model.params if isinstance(p, ParamDecl)}
    auto = params["/auto"].value.values()
    assert 1 in auto and any(isinstance(v, DeferredValue) for v in auto)
    assert params["/fixed"].value.values() == [3.5]
    resolution = ws.resolve(file, {"v": "7"})
    assert resolution.ok
    assert resolution.params == {
        "/auto": 7,
        "/as_str": "7",
        "/as_int": 7,
        "/yaml": [7, 2],
        "/fixed": 3.5,
    }
    wrong = ws.resolve(file, {"v": "x"})
    assert not wrong.ok and wrong.errors[0].code == "param-invalid"
    assert wrong.errors[0].location.line == 6  # the int param


@pytest.mark.oracle
def test_typed_values_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("typed.launch", TYPED)
    ws.assert_agrees(file, [{}, {"v": "7"}, {"v": "2.5"}, {"v": "x"}, {"v": "true"}])


BOOL_OR_INT = """
  <arg name="debug" default="0"/>
  <param name="debug" value="$(arg debug)"/>
  <node pkg="pkg" type="t" name="dbg" if="$(arg debug)"/>
"""


def test_bool_and_int_values_stay_apart(ws: LaunchWorkspace) -> None:
    file = ws.launch("bool_int.launch", BOOL_OR_INT)
    # compare types too: 0 == False and 1 == True in Python
    picked = {
        given: ws.resolve(file, {"debug": given} if given else {}).params["/debug"]
        for given in ("", "0", "false", "true", "1")
    }
    assert {k: (type(v).__name__, v) for k, v in picked.items()} == {
        "": ("int", 0),
        "0": ("int", 0),
        "false": ("bool", False),
        "true": ("bool", True),
        "1": ("int", 1),
    }


@pytest.mark.oracle
def test_bool_and_int_values_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("bool_int.launch", BOOL_OR_INT)
    ws.assert_agrees(file, [{}, {"debug": "false"}, {"debug": "true"}, {"debug": "1"}])


def test_command_is_not_run(ws: LaunchWorkspace, tmp_path: Path) -> None:
    marker = tmp_path / "created_by_command"
    file = ws.launch(
        "command.launch",
        f'  <arg name="target" default="{marker}"/>\n'
        '  <param name="robot_description" command="touch $(arg target)"/>',
    )
    model = ws.model(file)
    assert not marker.exists()
    resolution = ws.resolve(file, {})
    assert resolution.ok
    assert resolution.params == {"/robot_description": f"__command__(touch {marker})"}
    assert not marker.exists()
    assert model.errors == []


COMMAND_FROM_ARG = """
  <arg name="model" default="base"/>
  <param name="robot_description" command="xacro $(find pkg)/urdf/$(arg model).xacro"/>
"""


def test_command_with_a_known_arg_value(ws: LaunchWorkspace) -> None:
    file = ws.launch("xacro.launch", COMMAND_FROM_ARG)
    urdf = ws.root / "pkg" / "urdf"
    assert ws.resolve(file, {}).params == {
        "/robot_description": f"__command__(xacro {urdf}/base.xacro)"
    }
    assert ws.resolve_fresh(file, {"model": "arm"}).params == {
        "/robot_description": f"__command__(xacro {urdf}/arm.xacro)"
    }


def test_command_with_an_other_arg_value(ws: LaunchWorkspace, tmp_path: Path) -> None:
    file = ws.launch("xacro.launch", COMMAND_FROM_ARG)
    urdf = ws.root / "pkg" / "urdf"
    assert ws.resolve(file, {"model": "arm"}).params == {
        "/robot_description": f"__command__(xacro {urdf}/arm.xacro)"
    }


@pytest.mark.oracle
def test_command_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.assert_agrees(ws.launch("xacro.launch", COMMAND_FROM_ARG), [{}, {"model": "arm"}])


def test_textfile_and_binfile(ws: LaunchWorkspace) -> None:
    ws.write("config/text.txt", "hello\n")
    ws.write("config/blob.bin", b"\x00\x01\xff")
    file = ws.launch(
        "files.launch",
        '  <param name="text" textfile="$(find pkg)/config/text.txt"/>\n'
        '  <param name="blob" binfile="$(find pkg)/config/blob.bin"/>\n'
        '  <param name="gone" textfile="$(find pkg)/config/missing.txt" if="$(eval 1 == 2)"/>',
    )
    resolution = ws.resolve(file)
    assert resolution.ok, resolution.errors
    assert resolution.params == {"/text": "hello\n", "/blob": {"__binary__": "AAH/"}}


@pytest.mark.oracle
def test_param_files_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.write("config/text.txt", "hello\n")
    ws.write("config/blob.bin", b"\x00\x01\xff")
    file = ws.launch(
        "files.launch",
        '  <arg name="name" default="text"/>\n'
        '  <param name="text" textfile="$(find pkg)/config/$(arg name).txt"/>\n'
        '  <param name="blob" binfile="$(find pkg)/config/blob.bin"/>',
    )
    ws.assert_agrees(file, [{}, {"name": "missing"}])


NAMES = """
  <arg name="ns" default="robot"/>
  <param name="relative" value="1"/>
  <param name="/global/name" value="2"/>
  <group ns="$(arg ns)">
    <param name="inner//slashes/" value="3"/>
    <param name="~private" value="4"/>
    <node pkg="pkg" type="t" name="n">
      <param name="own" value="5"/>
      <param name="~also_own" value="6"/>
    </node>
  </group>
"""


def test_param_names(ws: LaunchWorkspace) -> None:
    file = ws.launch("names.launch", NAMES)
    assert ws.resolve(file, {"ns": "r2"}).params == {
        "/relative": 1,
        "/global/name": 2,
        "/r2/inner/slashes": 3,
        "/r2/n/private": 4,
        "/r2/n/own": 5,
        "/r2/n/also_own": 6,
    }


@pytest.mark.oracle
def test_param_names_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.assert_agrees(ws.launch("names.launch", NAMES), [{}, {"ns": "/abs"}, {"ns": "a/b"}])


def test_exactly_one_value_source(ws: LaunchWorkspace) -> None:
    file = ws.launch("sources.launch", '  <param name="p" value="1" command="echo"/>')
    model = ws.model(file)
    assert [e.code for e in model.errors] == ["param-invalid"]
    assert model.errors[0].location.line == 2


@pytest.mark.parametrize(
    "value", ["&amp;a [*a]", "&amp;a {b: *a}", "a: b: c", "[[[[", "a: rad(1/0)"]
)
def test_hostile_yaml_value_is_an_error_event(ws: LaunchWorkspace, value: str) -> None:
    file = ws.launch("hostile.launch", f'<param name="x" type="yaml" value="{value}"/>')
    model = ws.model(file)
    assert [e.code for e in model.errors] == ["param-invalid"]


def _outside(ws: LaunchWorkspace) -> str:
    secret = ws.root.parent / "secret.txt"
    secret.write_text("password=hunter2\n")
    return str(secret)


@pytest.mark.parametrize("kind", ["textfile", "binfile"])
def test_files_outside_the_workspace_are_not_read(ws: LaunchWorkspace, kind: str) -> None:
    secret = _outside(ws)
    ws.write("link.txt", "")
    os.remove(ws.root / "pkg" / "link.txt")
    os.symlink(secret, ws.root / "pkg" / "link.txt")
    paths = [secret, "$(find pkg)/../../secret.txt", "$(find pkg)/link.txt", "/etc/passwd"]
    body = "".join(f'<param name="p{i}" {kind}="{p}"/>' for i, p in enumerate(paths))
    file = ws.launch("outside.launch", body)
    model = ws.model(file)
    assert model.errors == []
    codes = [d.code for d in model.diagnostics]
    assert codes == ["file-outside-workspace"] * len(paths)
    shown = repr([p.value for p in model.params if isinstance(p, ParamDecl)])
    assert "hunter2" not in shown and "root:" not in shown
    resolution = ws.resolve(file)
    [error] = resolution.errors
    assert error.code == "value-unknown" and "outside the workspace" in str(error)


def test_allow_outside_reads_them_but_never_system_trees(tmp_path: Path) -> None:
    secret = tmp_path / "secret.txt"
    secret.write_text("visible")
    package = tmp_path / "ws" / "pkg"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>pkg</name></package>")
    launch = package / "launch" / "x.launch"
    launch.write_text(
        f'<launch><param name="a" textfile="{secret}"/>'
        '<param name="b" textfile="/proc/self/environ"/></launch>'
    )
    workspace = discover([tmp_path / "ws"], ros_package_path="", allow_outside=True)
    model = Analysis(workspace).model(str(launch))
    values = {p.name.single(): p.value.single() for p in model.params if isinstance(p, ParamDecl)}
    assert values["/a"] == "visible"
    assert "below /proc" in str([d.message for d in model.diagnostics])


@pytest.mark.parametrize("target", ["/dev/zero", "/dev/urandom", "/proc/self/environ", "fifo"])
def test_devices_and_fifos_are_never_read(ws: LaunchWorkspace, target: str) -> None:
    if target == "fifo":
        ws.package()
        target = str(ws.root / "pkg" / "fifo")
        os.mkfifo(target)
    file = ws.launch(
        "dev.launch", f'<param name="t" textfile="{target}"/><param name="b" binfile="{target}"/>'
    )
    model = ws.model(file)  # returns: nothing read, nothing waited for
    found = [*(e.code for e in model.errors), *(d.code for d in model.diagnostics)]
    assert len(found) == 2 and set(found) <= {"file-outside-workspace", "file-unreadable"}
