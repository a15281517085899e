"""Fingerprints survive another checkout: a finding that names a file (an `unread` robot
description) keeps its fingerprint when the workspace moves and when lines move above it,
wherever its files lie (in a package, or only under a workspace root)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import TYPE_CHECKING

from rosvar.analyses.checks import Check, Finding
from rosvar.analyses.fingerprints import Fingerprints
from rosvar.diagnostics import Location, Severity
from rosvar.outputs.cli import main
from rosvar.workspace.packages import Package

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


def _finding(root: Path, condition: object) -> Finding:
    missing = str(root / "robot_description" / "urdf" / "robot.urdf.xacro")  # no package.xml
    launch = str(root / "bringup" / "launch" / "sim.launch.py")
    return Finding(
        Check.UNREAD,
        Severity.WARNING,
        missing,
        f"xacro fails on {missing}: cannot read it",
        launch,
        condition,  # type: ignore[arg-type]  # the fingerprint never reads the condition
        (Location(launch, 3, 1), Location(missing, 0, 0)),
    )


def _print(root: Path) -> str:
    root.mkdir(parents=True, exist_ok=True)
    packages = [Package("bringup", str(root / "bringup"), None)]
    return Fingerprints(packages, [str(root)]).of(_finding(root, None))


def test_a_file_outside_every_package_is_named_from_its_root(tmp_path: Path) -> None:
    here, there = tmp_path / "checkout", tmp_path / "elsewhere" / "clone"
    assert _print(here) == _print(there)
    assert _print(here) != Fingerprints([], []).of(_finding(here, None))  # a root places it
