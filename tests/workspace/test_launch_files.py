"""Which files are launch files, and in which format, for ROS 1 and ROS 2."""

from __future__ import annotations

from pathlib import Path

import pytest

from rosvar.ros.version import RosVersion
from rosvar.workspace.launch_files import LaunchFormat, format_of, launch_format

ROS1, ROS2 = RosVersion.ROS1, RosVersion.ROS2
XML, YAML, PYTHON = LaunchFormat.XML, LaunchFormat.YAML, LaunchFormat.PYTHON
LAUNCH_XML = "<launch>\n  <arg name='a' default='1'/>\n</launch>\n"
LAUNCH_YAML = "launch:\n- arg:\n    name: a\n"
LAUNCH_PY = (
    "from launch import LaunchDescription\n\n"
    "def generate_launch_description():\n    return LaunchDescription([])\n"
)
HELPER_PY = "def helper():\n    return 1\n"
TEST_PY = "def generate_test_description():\n    pass\n"
PARAMS_YAML = "node:\n  ros__parameters:\n    rate: 10\n"

CASES = [
    # path, text, ROS 1 format, ROS 2 format
    ("launch/a.launch", LAUNCH_XML, XML, None),
    ("launch/b.launch.xml", LAUNCH_XML, XML, XML),
    ("config/c.xml", LAUNCH_XML, XML, None),  # ROS 2: only launch/*.xml is looked into
    ("launch/d.xml", LAUNCH_XML, XML, XML),
    ("launch/urdf.xml", "<robot name='r'/>", None, None),
    ("launch/e.launch.yaml", LAUNCH_YAML, None, YAML),
    ("anywhere/f.launch.yml", LAUNCH_YAML, None, YAML),
    ("launch/g.yaml", LAUNCH_YAML, None, YAML),
    ("launch/params.yaml", PARAMS_YAML, None, None),
    ("config/h.yaml", LAUNCH_YAML, None, None),
    ("launch/i.launch.py", LAUNCH_PY, None, PYTHON),
    ("scripts/j_launch.py", LAUNCH_PY, None, PYTHON),
    ("launch/k.py", LAUNCH_PY, None, PYTHON),
    ("launch/launch_utils.py", HELPER_PY, None, None),
    ("test/test_l_launch.py", TEST_PY, None, None),
    ("src/m.py", LAUNCH_PY, None, None),  # neither named nor placed as a launch file
    ("launch/.n.launch.py", LAUNCH_PY, None, None),
    ("package.xml", LAUNCH_XML, None, None),
]


@pytest.mark.parametrize(("relative", "text", "ros1", "ros2"), CASES, ids=[c[0] for c in CASES])
def test_launch_format(
    tmp_path: Path,
    relative: str,
    text: str,
    ros1: LaunchFormat | None,
    ros2: LaunchFormat | None,
) -> None:
    path = tmp_path / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    assert launch_format(str(path.parent), path.name, ROS1) == ros1
    assert launch_format(str(path.parent), path.name, ROS2) == ros2


def test_unreadable_candidate_is_not_a_launch_file(tmp_path: Path) -> None:
    (tmp_path / "launch").mkdir()
    (tmp_path / "launch" / "gone.launch.py").symlink_to(tmp_path / "missing.py")
    assert launch_format(str(tmp_path / "launch"), "gone.launch.py", ROS2) is None


@pytest.mark.parametrize(
    ("path", "ros2"),
    [("a.launch.py", PYTHON), ("a.yaml", YAML), ("a.yml", YAML), ("a.launch.xml", XML), ("a", XML)],
)
def test_format_of(path: str, ros2: LaunchFormat) -> None:
    assert format_of(path, ROS2) == ros2
    assert format_of(path, ROS1) == XML
