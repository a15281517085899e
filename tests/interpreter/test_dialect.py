"""The core finds each ROS's dialect in its registry, imported on first use only."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from rosvar.interpreter import dialect
from rosvar.interpreter.dialect import dialect_of, register
from rosvar.ros.version import RosVersion

SOURCES = str(Path(dialect.__file__).resolve().parents[2])


def test_each_version_finds_its_own_dialect() -> None:
    for version in RosVersion:
        assert dialect_of(version).version is version


def test_a_second_dialect_for_a_version_is_refused() -> None:
    found = dialect_of(RosVersion.ROS2)
    with pytest.raises(ValueError, match="ROS 2 has two dialects"):
        register(RosVersion.ROS2, lambda: found)
    assert dialect_of(RosVersion.ROS2) is found


def test_a_version_without_a_dialect_is_named() -> None:
    with pytest.raises(LookupError, match="no dialect is registered for ROS 1"):
        saved = (
            dialect._FACTORIES.pop(RosVersion.ROS1),
            dialect._DIALECTS.pop(RosVersion.ROS1, None),
        )
        try:
            dialect_of(RosVersion.ROS1)
        finally:
            dialect._FACTORIES[RosVersion.ROS1] = saved[0]
            if saved[1] is not None:
                dialect._DIALECTS[RosVersion.ROS1] = saved[1]


def _imported_after(version: RosVersion, tmp_path: Path) -> set[str]:
    """The rosvar modules a fresh process has imported once it analysed a one-file
    workspace of ``version``."""
    package = tmp_path / "pkg"
    (package / "launch").mkdir(parents=True)
    build = "catkin" if version is RosVersion.ROS1 else "ament_cmake"
    (package / "package.xml").write_text(
        f'<package format="3"><name>pkg</name><buildtool_depend>{build}</buildtool_depend>'
        "</package>"
    )
    launch = "a.launch" if version is RosVersion.ROS1 else "a.launch.xml"
    (package / "launch" / launch).write_text('<launch><node pkg="p" exec="e" type="e"/></launch>')
    script = (
        "import sys\n"
        "from rosvar.interpreter.workspace_models import Analysis\n"
        "from rosvar.workspace import discover\n"
        f"workspace = discover([{str(tmp_path)!r}])\n"
        f"assert workspace.ros_version == {version.value!r}, workspace.ros_version\n"
        "Analysis(workspace).all_models()\n"
        "print('\\n'.join(m for m in sys.modules if m.startswith('rosvar.')))\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script],
        capture_output=True,
        text=True,
        check=True,
        env={"PYTHONPATH": SOURCES, "PATH": ""},
    )
    return set(done.stdout.split())


def test_an_analysis_imports_only_its_own_dialect(tmp_path: Path) -> None:
    ros1 = _imported_after(RosVersion.ROS1, tmp_path / "one")
    assert "rosvar.ros1.tags.node" in ros1
    assert not {m for m in ros1 if m.startswith("rosvar.ros2")}
    ros2 = _imported_after(RosVersion.ROS2, tmp_path / "two")
    assert "rosvar.ros2.tags.node" in ros2
    assert not {m for m in ros2 if m.startswith("rosvar.ros1")}
