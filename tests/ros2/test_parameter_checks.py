"""ROS 2's own checks: a parameter file whose entries are for no node the launch starts."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rosvar.outputs.cli import main

MANIFEST = """<package format="3"><name>bringup</name><version>0.0.0</version>
<description>d</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend>ament_cmake</buildtool_depend>
<export><build_type>ament_cmake</build_type></export></package>
"""
LAUNCH = """<launch>
  <arg name="renamed" default="false"/>
  <node pkg="imu_filter_madgwick" exec="imu_filter_madgwick_node" name="imu_filter">
    <param from="$(find-pkg-share bringup)/config/imu.yaml"/>
  </node>
  <node pkg="demo" exec="talker" name="talker" if="$(var renamed)">
    <param from="$(find-pkg-share bringup)/config/shared.yaml"/>
  </node>
  <node pkg="demo" exec="talker" name="speaker" unless="$(var renamed)">
    <param from="$(find-pkg-share bringup)/config/shared.yaml"/>
  </node>
  <node pkg="demo" exec="listener" name="listener">
    <param from="$(find-pkg-share bringup)/config/shared.yaml"/>
  </node>
</launch>
"""
FILES = {
    "config/imu.yaml": "imu_filter_node:\n  ros__parameters:\n    gain: 0.1\n",
    "config/shared.yaml": "/talker:\n  ros__parameters:\n    rate: 2\n",
}


def _findings(root: Path, capsys: pytest.CaptureFixture[str]) -> list[dict[str, object]]:
    main(["check", str(root), "--format", "json"])
    found = json.loads(capsys.readouterr().out)["findings"]
    return [f for f in found if f["check"] == "param-file-unmatched"]


def test_a_parameter_file_for_no_launched_node(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The Madgwick filter's file is keyed by the executable's default name, not the node's:
    a warning in every configuration. The shared file has an entry for /talker: where
    /talker runs, the listener's lack of one is no mistake; where it is /speaker, the
    file's entries reach no node."""
    package = tmp_path / "bringup"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST)
    (package / "launch" / "bringup.launch.xml").write_text(LAUNCH)
    for name, text in FILES.items():
        (package / name).parent.mkdir(exist_ok=True)
        (package / name).write_text(text)
    found = {(f["name"], f["condition"]) for f in _findings(tmp_path, capsys)}
    assert found == {
        ("/imu_filter", "true"),
        ("/speaker", "¬renamed"),
        ("/listener", "¬renamed"),
    }
    [imu] = [f for f in _findings(tmp_path, capsys) if f["name"] == "/imu_filter"]
    assert str(imu["message"]).startswith(
        "/imu_filter gets none of the parameters of imu.yaml: its entries are for "
        "/imu_filter_node, which no launched node is"
    )


TWO_FILES = """<launch>
  <node pkg="demo" exec="talker" name="talker">
    <param from="$(find-pkg-share bringup)/config/first.yaml"/>
    <param from="$(find-pkg-share bringup)/config/second.yaml"/>
  </node>
</launch>
"""


def test_each_unmatched_file_of_one_node_is_its_own_finding(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Two files given to one node, neither with an entry for it: two problems at the same
    node, told apart by their messages (the workspace's findings are not merged by place)."""
    package = tmp_path / "bringup"
    (package / "launch").mkdir(parents=True)
    (package / "config").mkdir()
    (package / "package.xml").write_text(MANIFEST)
    (package / "launch" / "bringup.launch.xml").write_text(TWO_FILES)
    (package / "config" / "first.yaml").write_text("/one:\n  ros__parameters:\n    a: 1\n")
    (package / "config" / "second.yaml").write_text("/two:\n  ros__parameters:\n    b: 2\n")
    found = sorted(str(f["message"]).split(":")[0] for f in _findings(tmp_path, capsys))
    assert found == [
        "/talker gets none of the parameters of first.yaml",
        "/talker gets none of the parameters of second.yaml",
    ]


WILDCARDS = """<launch>
  <arg name="moved" default="false"/>
  <node pkg="demo" exec="talker" name="talker" namespace="ns" unless="$(var moved)"/>
  <node pkg="demo" exec="talker" name="talker" namespace="other" if="$(var moved)"/>
  <node pkg="demo" exec="listener" name="one">
    <param from="$(find-pkg-share bringup)/config/one.yaml"/>
  </node>
  <node pkg="demo" exec="listener" name="any">
    <param from="$(find-pkg-share bringup)/config/any.yaml"/>
  </node>
  <node pkg="demo" exec="listener" name="all">
    <param from="$(find-pkg-share bringup)/config/all.yaml"/>
  </node>
</launch>
"""
WILDCARD_FILES = {
    "config/one.yaml": "/ns/*:\n  ros__parameters:\n    rate: 2\n",
    "config/any.yaml": "/other/**:\n  ros__parameters:\n    rate: 2\n",
    "config/all.yaml": "/**:\n  ros__parameters:\n    rate: 2\n",
}


def test_wildcard_keys_reach_the_nodes_they_match(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """rcl's wildcards: ``/ns/*`` is one name below ``/ns`` (the talker, where it runs
    there), ``/other/**`` any below ``/other``, ``/**`` every node: a file reaches no node
    where no launched node's name matches one of its keys."""
    package = tmp_path / "bringup"
    (package / "launch").mkdir(parents=True)
    (package / "config").mkdir()
    (package / "package.xml").write_text(MANIFEST)
    (package / "launch" / "bringup.launch.xml").write_text(WILDCARDS)
    for name, text in WILDCARD_FILES.items():
        (package / name).write_text(text)
    found = {(f["name"], f["condition"]) for f in _findings(tmp_path, capsys)}
    assert found == {("/one", "moved"), ("/any", "¬moved")}


CMAKE = """cmake_minimum_required(VERSION 3.8)
project(demo)
find_package(ament_cmake REQUIRED)
add_executable(reader src/reader.cpp)
add_executable(open src/open.cpp)
ament_package()
"""
READER = """#include <rclcpp/rclcpp.hpp>
class Reader : public rclcpp::Node {
 public:
  Reader() : Node("reader") { declare_parameter("number_particles", 200); }
};
int main(int argc, char** argv) { rclcpp::spin(std::make_shared<Reader>()); }
"""
OPEN = """#include <rclcpp/rclcpp.hpp>
int main(int argc, char** argv) {
  auto options = rclcpp::NodeOptions().allow_undeclared_parameters(true);
  auto node = std::make_shared<rclcpp::Node>("open", options);
  node->declare_parameter("x", 1);
}
"""
UNDECLARED = """<launch>
  <node pkg="demo" exec="reader" name="reader">
    <param name="particles" value="300"/>
    <param name="use_sim_time" value="true"/>
    <param name="number_particles" value="100"/>
  </node>
  <node pkg="demo" exec="open" name="open"><param name="y" value="1"/></node>
</launch>
"""


def test_a_parameter_the_node_never_declares(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """rclcpp keeps a parameter the node never declares out of it: a misspelt name is a
    warning, unless the node takes undeclared parameters (or rclcpp declares it)."""
    package = tmp_path / "demo"
    (package / "src").mkdir(parents=True)
    (package / "launch").mkdir()
    (package / "package.xml").write_text(MANIFEST.replace("bringup", "demo"))
    (package / "CMakeLists.txt").write_text(CMAKE)
    (package / "src" / "reader.cpp").write_text(READER)
    (package / "src" / "open.cpp").write_text(OPEN)
    (package / "launch" / "demo.launch.xml").write_text(UNDECLARED)
    main(["check", str(tmp_path), "--format", "json"])
    found = json.loads(capsys.readouterr().out)["findings"]
    assert [(f["name"], f["message"]) for f in found if f["check"] == "param-unread"] == [
        (
            "/reader/particles",
            "/reader is given the parameter particles, which it never declares (it declares "
            "number_particles): the node never sees it",
        )
    ]
