"""ROS 2 fixtures, one per corner of the semantics: rosvar's resolution against the real
ros2/launch (the oracle), for sampled launch arguments."""

from __future__ import annotations

from pathlib import Path

import pytest

from oracle.ros2_client import canonical_nodes, requires_ros2_oracle, run_oracle
from rosvar.analyses.ros2.resolve import resolve_ros2
from rosvar.workspace import discover

pytestmark = requires_ros2_oracle

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>pkg</name><version>0.0.0</version><description>d</description>
  <maintainer email="a@b.c">m</maintainer><license>BSD</license>
  <export><build_type>ament_cmake</build_type></export>
</package>
"""

Case = tuple[dict[str, str], list[dict[str, str]]]

CASES: dict[str, Case] = {
    "arg-default-and-given": (
        {
            "main.launch.xml": """<launch>
            <arg name="n" default="talker"/>
            <node pkg="pkg" exec="talker" name="$(var n)"/>
          </launch>"""
        },
        [{}, {"n": "other"}],
    ),
    "if-unless-truthiness": (
        {
            "main.launch.xml": """<launch>
            <arg name="on" default="true"/>
            <node pkg="pkg" exec="a" name="a" if="$(var on)"/>
            <node pkg="pkg" exec="b" name="b" unless="$(var on)"/>
          </launch>"""
        },
        [{}, {"on": "False"}, {"on": "1"}, {"on": "0"}],
    ),
    "include-args-leak-to-includer": (
        {
            "main.launch.xml": """<launch>
                <include file="$(dirname)/sub.launch.xml"><arg name="x" value="given"/></include>
                <node pkg="pkg" exec="a" name="$(var x)_$(var y)"/>
              </launch>""",
            "sub.launch.xml": """<launch>
                <arg name="x" default="dflt"/>
                <let name="y" value="leaked"/>
                <node pkg="pkg" exec="b" name="in_$(var x)"/>
              </launch>""",
        },
        [{}, {"x": "cli"}],
    ),
    "scoped-group-confines-let": (
        {
            "main.launch.xml": """<launch>
            <let name="v" value="outer"/>
            <group><let name="v" value="inner"/><node pkg="pkg" exec="a" name="$(var v)"/></group>
            <group scoped="false"><push-ros-namespace namespace="ns"/></group>
            <node pkg="pkg" exec="b" name="$(var v)"/>
          </launch>"""
        },
        [{}],
    ),
    "namespaces-pushed-and-absolute": (
        {
            "main.launch.xml": """<launch>
            <group>
              <push-ros-namespace namespace="robot"/>
              <push-ros-namespace namespace="arm"/>
              <node pkg="pkg" exec="a" name="a"/>
              <node pkg="pkg" exec="b" name="b" namespace="sub"/>
              <node pkg="pkg" exec="c" name="c" namespace="/abs"/>
            </group>
            <node pkg="pkg" exec="d" name="d"/>
          </launch>"""
        },
        [{}],
    ),
    "remaps-global-then-own": (
        {
            "main.launch.xml": """<launch>
            <group><set_remap from="z" to="w"/></group>
            <set_remap from="a" to="b"/>
            <group><set_remap from="c" to="d"/>
              <node pkg="pkg" exec="x" name="x"><remap from="e" to="f"/></node></group>
            <node pkg="pkg" exec="y" name="y"/>
          </launch>"""
        },
        [{}],
    ),
    "global-params-shared-list-through-groups": (
        {
            "main.launch.xml": """<launch>
            <group><set_parameter name="first" value="1"/></group>
            <node pkg="pkg" exec="x" name="x"/>
            <set_parameter name="a" value="1"/>
            <group><set_parameter name="b" value="2"/></group>
            <group forwarding="false"><node pkg="pkg" exec="z" name="z"/></group>
            <node pkg="pkg" exec="y" name="y"/>
          </launch>"""
        },
        [{}],
    ),
    "parameters-typed-files-nested-global": (
        {
            "main.launch.xml": """<launch>
                <arg name="rate" default="10"/>
                <set_parameter name="g" value="1.5"/>
                <node pkg="pkg" exec="x" name="x" namespace="r1">
                  <param from="$(find-pkg-share pkg)/params.yaml"/>
                  <param name="rate" value="$(var rate)"/>
                  <param name="flag" value="true"/>
                  <param name="text" value="hello"/>
                  <param name="group"><param name="inner" value="3"/></param>
                </node>
                <node pkg="pkg" exec="y" name="y"><param name="g" value="2"/></node>
              </launch>""",
            "params.yaml": """/**:
  ros__parameters: {common: 1, rate: 5}
/r1/x:
  ros__parameters: {only_x: [1, 2], nested: {a: b}}
/*/y:
  ros__parameters: {never: 0}
""",
        },
        [{}, {"rate": "20"}],
    ),
    "eval-and-substitution-quoting": (
        {
            "main.launch.xml": """<launch>
            <arg name="k" default="2"/>
            <node pkg="pkg" exec="x" name="n$(eval '$(var k) * 3')"
                  if="$(eval '\\'$(var k)\\' == \\'2\\'')"/>
            <node pkg="pkg" exec="y" name="y" args="--a 'b c' $(var k)"/>
          </launch>"""
        },
        [{}, {"k": "5"}],
    ),
    "errors-required-choices-truthiness": (
        {
            "main.launch.xml": """<launch>
            <arg name="need"/>
            <arg name="mode" default="a"><choice value="a"/><choice value="b"/></arg>
            <arg name="flag" default="true"/>
            <node pkg="pkg" exec="x" name="x_$(var need)_$(var mode)" if="$(var flag)"/>
          </launch>"""
        },
        [
            {},
            {"need": "1"},
            {"need": "1", "mode": "c"},
            {"need": "1", "flag": "yes"},
            {"need": "1", "mode": "b", "flag": "TRUE"},
        ],
    ),
    "unexpected-attribute-fails-even-where-never-entered": (
        {
            "main.launch.xml": """<launch>
            <arg name="on" default="false"/>
            <node pkg="pkg" exec="x" name="x"/>
            <group if="$(var on)"><node pkg="pkg" exec="y" name="y" bogus="1"/></group>
          </launch>"""
        },
        [{}, {"on": "true"}],
    ),
    "unknown-tag-fails": (
        {
            "main.launch.xml": """<launch>
            <node pkg="pkg" exec="x" name="x"/><frobnicate/>
          </launch>"""
        },
        [{}],
    ),
    "timers-run-in-the-final-context": (
        {
            "main.launch.xml": """<launch>
            <let name="x" value="before"/>
            <group>
              <push-ros-namespace namespace="g"/>
              <timer period="1.5"><node pkg="pkg" exec="a" name="a_$(var x)"/>
                <timer period="1"><node pkg="pkg" exec="c" name="c"/></timer></timer>
              <node pkg="pkg" exec="d" name="d"/>
            </group>
            <let name="x" value="after"/>
            <timer period="2"><node pkg="pkg" exec="b" name="b_$(var x)"/></timer>
          </launch>"""
        },
        [{}],
    ),
    "composable-nodes-in-and-loaded-into-containers": (
        {
            "main.launch.xml": """<launch>
            <set_remap from="g" to="h"/>
            <set_parameter name="gp" value="1"/>
            <push-ros-namespace namespace="ns"/>
            <node_container pkg="pkg" exec="component_container" name="box" namespace="">
              <composable_node pkg="pkg" plugin="pkg::A" name="a" namespace="sub">
                <param name="p" value="2"/><remap from="x" to="y"/>
              </composable_node>
            </node_container>
            <load_composable_node target="/ns/box">
              <composable_node pkg="pkg" plugin="pkg::B" name="b"/>
            </load_composable_node>
          </launch>"""
        },
        [{}],
    ),
    "parameter-value-typing": (
        {
            "main.launch.xml": """<launch>
            <node pkg="pkg" exec="x" name="x">
              <param name="a" value="[1, 2]"/><param name="b" value="1,2"/>
              <param name="c" value="yes"/><param name="d" value="1e3"/>
              <param name="e" value="0x10"/><param name="f" value="'7'"/>
              <param name="g" value="$(var g)"/><param name="h" value=""/>
              <param name="j" value="True"/>
            </node>
          </launch>"""
        },
        [{"g": "[a, b]"}, {"g": "[a, 1]"}, {"g": "[1, 2.5]"}, {"g": "~"}, {"g": "a: b"}],
    ),
    "parameter-file-named-by-an-unset-environment-variable": (
        {
            "main.launch.xml": """<launch>
            <node pkg="pkg" exec="a" name="a">
              <param from="$(dirname)/p_$(env JOY logitech).yaml"/>
            </node>
          </launch>""",
            "p_logitech.yaml": "/**:\n  ros__parameters:\n    x: 1\n",
        },
        [{}],
    ),
    "env-set-unset": (
        {
            "main.launch.xml": """<launch>
            <set_env name="R" value="set"/>
            <node pkg="pkg" exec="x" name="$(env R)_$(env NOPE fallback)"/>
            <unset_env name="R"/>
            <node pkg="pkg" exec="y" name="y_$(env R dflt)"/>
          </launch>"""
        },
        [{}],
    ),
}


def _workspace(tmp_path: Path, files: dict[str, str]) -> Path:
    package = tmp_path / "ws" / "pkg"
    package.mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE_XML)
    for name, text in files.items():
        (package / name).write_text(text)
    return package


@pytest.mark.parametrize("case", sorted(CASES))
def test_fixture_matches_the_oracle(case: str, tmp_path: Path) -> None:
    files, samples = CASES[case]
    package = _workspace(tmp_path, files)
    for arguments in samples:
        expected = run_oracle(package / "main.launch.xml", arguments, [package.parent])
        workspace = discover([str(package.parent)])
        result = resolve_ros2(workspace, str(package / "main.launch.xml"), arguments)
        assert result.ok == expected["ok"], (arguments, expected.get("error"), result.errors)
        if result.ok:
            assert canonical_nodes(result.to_json()) == canonical_nodes(expected), arguments
