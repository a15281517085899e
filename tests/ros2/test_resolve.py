"""``ros2 launch FILE name:=value`` read off the model (``rosvar.ros2.resolve``): what one
configuration tells beyond its nodes."""

from __future__ import annotations

from pathlib import Path

from differential.ros2.test_fixtures import PACKAGE_XML
from ros2.tags.launches import launch
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover

ENTRY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
import os
import helpers_nowhere


def generate_launch_description():
    here = os.path.dirname(__file__)
    helpers_nowhere.rewrite()
    return LaunchDescription([
        DeclareLaunchArgument('with_nav', default_value='true'),
        Node(package='pkg', executable='n', name='own'),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(here, 'nav.launch.py')),
            condition=IfCondition(LaunchConfiguration('with_nav'))),
    ])
"""

INCLUDED = """from launch import LaunchDescription
from launch_ros.actions import Node
import helpers_nowhere


def generate_launch_description():
    helpers_nowhere.nav()
    return LaunchDescription([Node(package='pkg', executable='n', name='nav')])
"""


def test_what_was_not_followed_in_the_loaded_files_is_a_warning(tmp_path: Path) -> None:
    """As ``analyze`` lists them, with their place: a node whose parameters a helper made
    would otherwise seem to have none. An include this configuration leaves out says
    nothing."""
    it = launch(tmp_path, ENTRY, suffix=".launch.py", files={"nav.launch.py": INCLUDED})
    included = str(it.main.parent / "nav.launch.py")

    def warned(args: dict[str, str]) -> list[tuple[str, int, str]]:
        result = it.analysis.resolve([str(it.main)], args)
        assert result.ok, result.errors
        return [(w.location.file, w.location.line, w.message) for w in result.warnings]

    own = (str(it.main), 13, "call to helpers_nowhere.rewrite() is not followed")
    nav = (included, 7, "call to helpers_nowhere.nav() is not followed")
    assert warned({}) == [own, nav]
    assert warned({"with_nav": "false"}) == [own]


GZ_ENTRY = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('gui', default_value='true'),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(
                PathJoinSubstitution(
                    [FindPackageShare('ros_gz_sim'), 'launch', 'gz_sim.launch.py'])),
            condition=IfCondition(LaunchConfiguration('gui'))),
        Node(package='pkg', executable='n', name='own'),
    ])
"""


def test_a_dependency_file_rosvar_cannot_read_is_an_include_not_followed(tmp_path: Path) -> None:
    """ros_gz's ``gz_sim.launch.py`` is built from a template, so a dependency's sources
    lack it: the include is not followed, a warning where this configuration makes it,
    and the rest of the file launches (it is no failure of the user's launch)."""
    user, deps = tmp_path / "ws" / "pkg", tmp_path / "deps" / "ros_gz_sim"
    for folder, name in ((user, "pkg"), (deps, "ros_gz_sim")):
        (folder / "launch").mkdir(parents=True)
        (folder / "package.xml").write_text(PACKAGE_XML.replace("<name>pkg<", f"<name>{name}<"))
    (deps / "launch" / "gz_sim.launch.py.in").write_text("# a CMake template\n")
    entry = user / "launch" / "sim.launch.py"
    entry.write_text(GZ_ENTRY)
    analysis = Analysis(discover([user.parent], deps=[deps.parent], ament_prefix_path=""))
    message = (
        f"included file {deps / 'launch' / 'gz_sim.launch.py'} of a dependency is not read "
        "(cannot read file: No such file or directory): what it launches is not known"
    )
    for gui, warned in (("true", [(str(entry), 13, message)]), ("false", [])):
        result = analysis.resolve([str(entry)], {"gui": gui})
        assert result.ok, result.errors
        assert [n.name for n in result.nodes] == ["/own"]
        assert [(w.location.file, w.location.line, w.message) for w in result.warnings] == warned


DOUBLING = "".join(
    f'<let name="v{i}" value="$(var v{i - 1})$(var v{i - 1})"/>' for i in range(1, 40)
)


def test_a_condition_no_configuration_computes_is_no_bool_error(tmp_path: Path) -> None:
    """A value rosvar gave up on (2^39 characters even here) or did not follow (a helper's
    call), tested as a condition, is reported as such at the tag, not as "not a 'bool'
    type"; a value that is computed and is no boolean still is."""
    text = f"""<launch><arg name="on" default="true"/><let name="v0" value="xy"/>{DOUBLING}
      <group if="$(var v39)"><node pkg="pkg" exec="n" name="a"/></group>
      <node pkg="pkg" exec="n" name="b" if="$(var on)"/>
    </launch>"""
    it = launch(tmp_path, text)

    def errors(args: dict[str, str]) -> list[tuple[str, int, str]]:
        result = it.analysis.resolve([str(it.main)], args)
        return [(e.code, e.location.line, e.message) for e in result.errors]

    [(code, line, message)] = errors({})
    assert (code, line) == ("value-unknown", 2) and "work limits" in message, message
    assert message.startswith("<group> attribute 'if': ")
    assert ("bool-invalid", 3, "<node> attribute 'if': value is not a 'bool' type") in errors(
        {"on": "maybe"}
    )


def test_an_unfollowed_condition_says_what_was_not_followed(tmp_path: Path) -> None:
    text = """from launch import LaunchDescription
from launch.conditions import IfCondition
from launch_ros.actions import Node
import helpers_nowhere


def generate_launch_description():
    return LaunchDescription([
        Node(package='pkg', executable='n', name='a', condition=IfCondition(helpers_nowhere.on())),
    ])
"""
    it = launch(tmp_path, text, suffix=".launch.py")
    [error] = it.analysis.resolve([str(it.main)], {}).errors
    assert error.code == "value-unknown" and error.location.line == 9, error.message
    assert "helpers_nowhere.on() is not followed" in error.message
