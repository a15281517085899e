"""ROS 2 entry files interpreted over every command line: declared arguments are inputs."""

from __future__ import annotations

import os
from pathlib import Path

from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.inputs import OTHER, UNSET
from rosvar.ros.version import RosVersion
from rosvar.workspace import discover

MANIFEST = """<package format="3"><name>p</name>
<export><build_type>ament_cmake</build_type></export></package>"""


def analysis(tmp_path: Path, text: str) -> tuple[Analysis, str]:
    (tmp_path / "package.xml").write_text(MANIFEST)
    (tmp_path / "launch").mkdir()
    file = tmp_path / "launch" / "a.launch.xml"
    file.write_text(text)
    workspace = discover([str(tmp_path)])
    assert workspace.ros_version is RosVersion.ROS2
    return Analysis(workspace), str(file)


def test_arguments_are_inputs_and_nodes_get_presence_conditions(tmp_path: Path) -> None:
    it, file = analysis(
        tmp_path,
        """<launch>
          <arg name="sim" default="false"/>
          <arg name="mode"><choice value="fast"/><choice value="slow"/></arg>
          <node pkg="p" exec="driver" unless="$(var sim)"/>
          <node pkg="p" exec="$(var mode)" name="n"/>
        </launch>""",
    )
    model = it.model(file)
    assert model.domains["sim"] == ("false", "true", OTHER)
    assert model.domains["mode"] == ("fast", "slow", UNSET, OTHER)
    assert [a.name for a in model.args] == ["sim", "mode"]
    space = it.space
    driver, chosen = model.nodes
    sim = space.slot(model.inputs["sim"], "true")
    assert driver.condition & sim == space.false  # left out when sim:=true
    assert driver.condition & ~sim != space.false
    executables = {leaf for _condition, leaf in chosen.field("exec")}
    assert {"fast", "slow"} <= executables
    # a mode outside the choices, or none, fails the launch
    assert space.slot(model.inputs["mode"], UNSET) & model.loads == space.false
    assert space.slot(model.inputs["mode"], "fast") & model.loads != space.false


def test_an_included_files_arguments_are_inputs_where_the_include_does_not_set_them(
    tmp_path: Path,
) -> None:
    (tmp_path / "inner.xml").write_text(
        '<launch><arg name="x" default="1"/><arg name="z" default="3"/></launch>'
    )
    it, file = analysis(
        tmp_path,
        """<launch><arg name="y" default="2"/>
        <include file="$(dirname)/../inner.xml"><arg name="z" value="4"/></include></launch>""",
    )
    model = it.model(file)
    assert list(model.inputs) == ["y", "x"]  # ros2 launch sets x:=... before loading
    assert [a.name for a in model.args] == ["y", "x"]
    assert [os.path.realpath(f) for f in model.settable.values()] == [str(tmp_path / "inner.xml")]


def test_a_given_argument_no_file_declares_is_set_all_the_same(tmp_path: Path) -> None:
    """``ros2 launch a.launch.xml g:=x`` sets ``g`` before loading, declared or not: given a
    value, the model knows it as an input from the start (``rosvar resolve``'s analysis);
    without one, reading it fails, as in ros2 launch."""
    plain, file = analysis(tmp_path, '<launch><node pkg="p" exec="e" name="$(var g)"/></launch>')
    assert "g" not in plain.model(file).inputs
    assert [e.code for e in plain.resolve([file]).errors] == ["var-undefined"]
    given = Analysis(plain.workspace, extra_values={"g": ["x"]})
    assert "g" in given.model(file).inputs
    assert [n.name for n in given.resolve([file], {"g": "x"}).nodes] == ["/x"]
    assert not given.resolve([file]).ok  # left out: not set
