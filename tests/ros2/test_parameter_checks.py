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
