"""Fingerprints: the same finding in another checkout has the same one, wherever its files
lie (in a package, or only under a workspace root)."""

from __future__ import annotations

from pathlib import Path

from rosvar.analyses.checks import Check, Finding
from rosvar.analyses.fingerprints import Fingerprints
from rosvar.diagnostics import Location, Severity
from rosvar.workspace.packages import Package


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
