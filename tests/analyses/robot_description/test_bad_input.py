"""Hostile and broken robot descriptions: each gives a diagnostic at its place, stays within
rosvar's bounds of work, and leaves the rest of the analysis intact."""

from __future__ import annotations

from pathlib import Path

import pytest

from analyses.robot_description.harness import expand
from rosvar.analyses.checks import Check, check_models
from rosvar.analyses.robot_description import xacro
from rosvar.analyses.robot_description.edges import Simulation
from rosvar.analyses.robot_description.xacro import MAX_MACRO_DEPTH
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover
from rosvar.workspace.interfaces.model import Interfaces

PACKAGE_XML = """<?xml version="1.0"?>
<package format="2"><name>pkg</name><version>0.0.0</version><description>t</description>
<maintainer email="t@example.com">t</maintainer><license>BSD</license></package>
"""
HEAD = '<robot name="r" xmlns:xacro="http://ros.org/wiki/xacro">\n'


def _write(root: Path, files: dict[str, str]) -> Path:
    (root / "pkg").mkdir(parents=True, exist_ok=True)
    (root / "pkg" / "package.xml").write_text(PACKAGE_XML)
    for name, text in files.items():
        (root / "pkg" / name).parent.mkdir(parents=True, exist_ok=True)
        (root / "pkg" / name).write_text(text)
    return root


def _codes(tmp_path: Path, files: dict[str, str]) -> dict[str, list[str]]:
    root = _write(tmp_path / "ws", files)
    expanded = expand([root], str(root / "pkg" / next(iter(files))), {}, {})
    found: dict[str, list[str]] = {}
    for diagnostic in expanded.description.diagnostics:
        found.setdefault(diagnostic.code, []).append(str(diagnostic.location))
    return found


def test_malformed_xml_is_placed(tmp_path: Path) -> None:
    codes = _codes(tmp_path, {"r.xacro": HEAD + "  <link name='a'>\n</robot>\n"})
    assert codes["xml-malformed"] == [f"{tmp_path}/ws/pkg/r.xacro:3:3"]
    assert "xacro-invalid" in codes  # and xacro fails there: nothing is printed


def test_an_include_cycle_is_a_failure_not_a_loop(tmp_path: Path) -> None:
    codes = _codes(
        tmp_path,
        {
            "a.xacro": HEAD + '  <xacro:include filename="b.xacro"/>\n</robot>\n',
            "b.xacro": HEAD
            + '  <link name="b"/>\n  <xacro:include filename="a.xacro"/>\n</robot>\n',
        },
    )
    assert codes["xacro-include-cycle"] == [f"{tmp_path}/ws/pkg/b.xacro:3:3"]


def test_endless_macro_recursion_stops_at_the_bound(tmp_path: Path) -> None:
    body = '  <xacro:macro name="m"><link name="x"/><xacro:m/></xacro:macro>\n  <xacro:m/>\n'
    root = _write(tmp_path / "ws", {"r.xacro": HEAD + body + "</robot>\n"})
    expanded = expand([root], str(root / "pkg" / "r.xacro"), {}, {})
    description = expanded.description
    assert [d.code for d in description.diagnostics] == ["xacro-too-large"]
    assert description.unknown == expanded.analysis.space.true  # not followed: unknown
    assert description.root is not None
    assert len(description.root.children) == MAX_MACRO_DEPTH


def test_a_doubling_macro_stops_everywhere_once_the_budget_is_spent(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(xacro, "MAX_ELEMENTS", 500)  # 2^60 elements: the bound is reached
    body = """
  <xacro:macro name="twice" params="n">
    <link name="l${n}"/>
    <xacro:if value="${n > 0}"><xacro:twice n="${n-1}"/><xacro:twice n="${n-1}"/></xacro:if>
  </xacro:macro>
  <xacro:twice n="60"/>
"""
    root = _write(tmp_path / "ws", {"r.xacro": HEAD + body + "</robot>\n"})
    expanded = expand([root], str(root / "pkg" / "r.xacro"), {}, {})
    description = expanded.description
    assert [d.code for d in description.diagnostics] == ["xacro-too-large"]
    assert description.unknown == expanded.analysis.space.true
    assert description.root is not None
    assert len(description.root.children) == 500  # what was made before the bound is kept


def test_system_files_and_fifos_are_never_read(tmp_path: Path) -> None:
    codes = _codes(
        tmp_path, {"r.xacro": HEAD + '  <xacro:include filename="/dev/zero"/>\n</robot>'}
    )
    assert codes["xacro-file-unreadable"] == [f"{tmp_path}/ws/pkg/r.xacro:2:3"]


LAUNCH = """<launch>
  <arg name="lib" default="libgazebo_ros_laser.so"/>
  <arg name="topic" default="scan"/>
  <param name="robot_description"
         command="xacro '$(find pkg)/r.xacro' lib:=$(arg lib) topic:=$(arg topic)"/>
  <node name="spawn" pkg="gazebo_ros" type="spawn_model" args="-param robot_description -model r"/>
</launch>
"""
ROBOT = (
    HEAD
    + """  <xacro:arg name="lib" default=""/><xacro:arg name="topic" default=""/>
  <gazebo><plugin name="p" filename="$(arg lib)"><topicName>$(arg topic)</topicName></plugin>
  </gazebo>
</robot>
"""
)


def test_unknown_plugin_library_and_topic_are_notes_and_the_check_goes_on(tmp_path: Path) -> None:
    root = _write(tmp_path / "ws", {"r.xacro": ROBOT, "launch/sim.launch": LAUNCH})
    analysis = Analysis(discover([root], ros_package_path=""))
    models = [analysis.model(f) for f in analysis.workspace.launch_files]
    findings = check_models(
        analysis.space,
        models,
        Interfaces(),
        analysis.workspace.confinement(),
        Simulation(analysis, Interfaces()),
    )
    kinds = {(f.check, f.locations[0].line) for f in findings}
    assert (Check.UNREAD, 6) in kinds  # the library is only known per value of lib
    assert (Check.SYMBOLIC_NAME, 6) in kinds  # so is the topic
    assert (Check.NO_SUBSCRIBER, 6) in kinds  # and where both are known: /scan
    symbolic = [f for f in findings if f.check is Check.SYMBOLIC_NAME]
    assert all(f.locations[1].file.endswith("r.xacro") for f in symbolic)
