"""Fingerprints survive another checkout: a finding that names a file (an `unread` robot
description) keeps its fingerprint when the workspace moves and when lines move above it."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import TYPE_CHECKING

from rosvar.outputs.cli import main

if TYPE_CHECKING:
    import pytest

    from conftest import LaunchWorkspace

XACRO = """<robot name="r" xmlns:xacro="http://ros.org/wiki/xacro">
  <xacro:property name="a" value="1"/>
</robot>
"""
SPAWN = """
  <param name="robot_description" textfile="$(find pkg)/urdf/r.xacro"/>
  <node pkg="gazebo_ros" type="spawn_model" name="spawn"
        args="-param robot_description -urdf -model r"/>
"""


def _prints(root: Path, capsys: pytest.CaptureFixture[str]) -> dict[str, str]:
    main(["check", str(root), "--format", "json"])
    findings = json.loads(capsys.readouterr().out)["findings"]
    return {f"{f['check']} {f['message']}": f["fingerprint"] for f in findings}


def test_a_finding_naming_a_file_keeps_its_fingerprint_elsewhere(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    ws.write("urdf/r.xacro", XACRO)
    ws.launch("sim.launch", SPAWN)
    here = _prints(ws.root, capsys)
    assert any(key.startswith("unread ") for key in here)
    moved = tmp_path / "another" / "checkout"
    shutil.copytree(ws.root, moved)
    launch = next(moved.rglob("sim.launch"))
    launch.write_text(launch.read_text().replace("<launch>", "<launch>\n\n<!-- moved -->\n"))
    assert _prints(moved, capsys) == here
