"""The configurations sampled for the real-repository differential (:mod:`.samples`): read
from launch files written inline in each frontend, never from rosvar."""

from __future__ import annotations

from pathlib import Path

from .samples import (
    PLACEHOLDER,
    Origin,
    Reading,
    configurations,
    passed_values,
    read,
    read_python,
    sample,
    undeclared,
)

PYTHON = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration

MODEL = "ur5e"

def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("use_sim", default_value="False"),
        DeclareLaunchArgument("robot_ip", description="required, no value named"),
        DeclareLaunchArgument(name="mode", default_value="fast", choices=["fast", "slow"]),
        DeclareLaunchArgument("computed", default_value=LaunchConfiguration("mode")),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource([FindPackageShare("p"), "/launch/inner.launch.xml"]),
            launch_arguments={"model": MODEL, "rate": LaunchConfiguration("x")}.items(),
        ),
    ])
"""

XML = """<launch>
  <arg name="model"/>
  <arg name="rate" default="10"/>
  <arg name="debug" default="true"/>
  <arg name="level" default="$(var rate)">
    <choice value="1"/>
  </arg>
  <include file="$(find-pkg-share p)/launch/leaf.launch.yaml">
    <arg name="flag" value="true"/>
    <arg name="name" value="$(var model)"/>
  </include>
</launch>
"""

YAML = """launch:
- arg: {name: flag, default: "false"}
- arg: {name: name}
- group:
    children:
    - arg: {name: nested, default: "True"}
"""


def _write(tmp_path: Path) -> dict[Path, Reading]:
    files = {
        tmp_path / "outer.launch.py": PYTHON,
        tmp_path / "inner.launch.xml": XML,
        tmp_path / "leaf.launch.yaml": YAML,
    }
    for path, text in files.items():
        path.write_text(text, encoding="utf-8")
    return {path: read(path) for path in files}


def test_python_declarations_and_includes(tmp_path: Path) -> None:
    readings = _write(tmp_path)
    outer = readings[tmp_path / "outer.launch.py"]
    assert outer.arguments["use_sim"].default == "False"
    assert outer.arguments["robot_ip"].required
    assert outer.arguments["computed"].default is None
    assert not outer.arguments["computed"].required
    sampled = configurations(outer, [])
    assert [s.config for s in sampled] == [
        {"robot_ip": PLACEHOLDER},
        {"robot_ip": PLACEHOLDER, "mode": "slow"},
        {"robot_ip": PLACEHOLDER, "use_sim": "True"},
    ]
    assert [s.origins for s in sampled] == [{Origin.DEFAULTS}, {Origin.CHOICE}, {Origin.FLIPPED}]


def test_values_passed_by_includers_and_choices(tmp_path: Path) -> None:
    readings = _write(tmp_path)
    passed = passed_values(readings)
    assert passed["inner.launch.xml"] == [{"model": "ur5e"}]  # LaunchConfiguration left out
    assert passed["leaf.launch.yaml"] == [{"flag": "true"}]  # $(var model) left out
    inner = readings[tmp_path / "inner.launch.xml"]
    sampled = configurations(inner, passed["inner.launch.xml"])
    assert [s.config for s in sampled] == [
        {"model": "ur5e"},
        {"model": "ur5e", "debug": "false"},
        {"model": "ur5e", "level": "1"},
    ]
    # the includer's set is the defaults (model is required and takes the passed value)
    assert sampled[0].origins == {Origin.DEFAULTS, Origin.PASSED}
    leaf = readings[tmp_path / "leaf.launch.yaml"]
    sampled = configurations(leaf, passed["leaf.launch.yaml"])
    assert [s.config for s in sampled] == [
        {"name": PLACEHOLDER},
        {"name": PLACEHOLDER, "flag": "true"},
        {"name": PLACEHOLDER, "nested": "False"},
    ]
    # flag=true is both the flipped default and what the includer passes
    assert [s.origins for s in sampled] == [
        {Origin.DEFAULTS},
        {Origin.FLIPPED, Origin.PASSED},
        {Origin.FLIPPED},
    ]


def test_unreadable_files_declare_nothing() -> None:
    assert read_python("def broken(:\n").arguments == {}


BRINGUP = """<launch>
  <arg name="vehicle" default="car"/>
  <let name="computed" value="x"/>
  <include file="$(find-pkg-share p)/launch/component.launch.xml">
    <arg name="given" value="$(var computed)"/>
  </include>
  <node pkg="p" exec="e" if="$(var use_gui)"/>
</launch>
"""

COMPONENT = """<launch>
  <node pkg="p" exec="e" name="$(var vehicle_model)" namespace="$(var given)">
    <param from="$(var ekf_param_path)"/>
    <param name="v" value="$(var vehicle)"/>
  </node>
</launch>
"""


def test_configurations_read_but_never_declared_are_given(tmp_path: Path) -> None:
    """What a file and its includes read without anything declaring, setting or passing it
    (``vehicle_model``) is the user's to give; conditions get ``true`` then ``false``, paths
    the repository's parameter file of their name."""
    (tmp_path / "config").mkdir()
    (tmp_path / "config" / "ekf.param.yaml").write_text("{}\n", encoding="utf-8")
    files = {"bringup.launch.xml": BRINGUP, "component.launch.xml": COMPONENT}
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    readings = {tmp_path / name: read(tmp_path / name) for name in files}
    assert undeclared(readings) == {
        tmp_path / "bringup.launch.xml": {"use_gui", "vehicle_model", "ekf_param_path"},
        tmp_path / "component.launch.xml": {"given", "vehicle", "vehicle_model", "ekf_param_path"},
    }
    parameters = str(tmp_path / "config" / "ekf.param.yaml")
    base = {"ekf_param_path": parameters, "use_gui": "true", "vehicle_model": PLACEHOLDER}
    assert [s.config for s in sample(readings, tmp_path)[tmp_path / "bringup.launch.xml"]] == [
        base,
        {**base, "use_gui": "false"},
    ]
