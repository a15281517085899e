"""A file an argument names, read for the argument's default: the function is read again
with the default's file, under the condition that the argument is its default, and as
before (the file unknown) under the negation."""

from __future__ import annotations

from pathlib import Path

from rosvar.files import Confinement
from rosvar.frontends.entity import Entity
from rosvar.ros2.frontends.python.modules import ModulePath
from rosvar.ros2.frontends.python.parser import parse_python_launch_file

LAUNCH = """import yaml
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(context):
    with open(LaunchConfiguration('config').perform(context)) as f:
        names = yaml.safe_load(f)['names']
    return [Node(package='pkg', executable='x', name=name) for name in names]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('config', default_value=get_package_share_directory('pkg')
                              + '/config/c.yaml'),
        OpaqueFunction(function=setup),
    ])
"""


def test_the_default_file_is_read_under_its_condition_and_the_rest_stays_unknown(
    tmp_path: Path,
) -> None:
    package = tmp_path / "pkg"
    (package / "config").mkdir(parents=True)
    (package / "package.xml").write_text("<package/>")
    (package / "config" / "c.yaml").write_text("names: [a, b]\n")
    (package / "t.launch.py").write_text(LAUNCH)
    modules = ModulePath({"pkg": str(package)}, Confinement.of([str(tmp_path)]))
    result = parse_python_launch_file(package / "t.launch.py", modules)
    assert result.root is not None
    function = result.root.children[-1]
    assumed, other = function.children
    test = "$(rosvar-configuration-equals config $(find-pkg-share pkg)/config/c.yaml)"
    assert (assumed.tag, assumed.attributes["if"]) == ("group", test)
    assert (other.tag, other.attributes["unless"]) == ("group", test)
    assert [_name(node) for node in assumed.children] == ["a", "b"]
    assert other.children == []
    messages = [d.message for d in result.diagnostics]
    assert messages == ["iteration over a LaunchYaml is not followed"]


def _name(node: Entity) -> str:
    return node.attributes["name"]
