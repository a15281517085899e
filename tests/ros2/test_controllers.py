"""ros2_control's controllers: the names of the controllers a spawner has a manager load,
their types read from the manager's and the spawner's parameter files, under the conditions
the launch files give them."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from rosvar.analyses.communication import Edge
from rosvar.analyses.controllers import controller_edges
from rosvar.diagnostics import Severity
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.cli import main
from rosvar.ros.version import RosVersion
from rosvar.workspace import discover
from rosvar.workspace.interfaces.catalogue import load_catalogue
from rosvar.workspace.interfaces.model import Interfaces, Role
from workspace.interfaces.ros2_packages import MANIFEST

DATA = Path(__file__).parents[1] / "data" / "ros2"
CATALOGUE = Interfaces(fallback=load_catalogue(RosVersion.ROS2))
CONTROL = """<launch>
  <arg name="sim" default="false"/>
  <arg name="drive" default="diff"/>
  <node pkg="controller_manager" exec="ros2_control_node" namespace="robot">
    <param from="$(find-pkg-share bringup)/config/manager.yaml"/>
    <remap from="joint_states" to="platform/joint_states"/>
  </node>
  <node pkg="controller_manager" exec="spawner" namespace="robot"
        args="joint_state_broadcaster --controller-manager-timeout 60"/>
  <node pkg="controller_manager" exec="spawner" namespace="robot" unless="$(var sim)"
        args="base_controller -p $(find-pkg-share bringup)/config/$(var drive).yaml
              --controller-ros-args '-r ~/cmd_vel_unstamped:=/cmd_vel'"/>
  <node pkg="controller_manager" exec="spawner" args="arm_controller --load-only"/>
</launch>
"""
FILES = {
    # the manager's parameters: NAME.type below its own entry
    "config/manager.yaml": "/**/controller_manager:\n  ros__parameters:\n"
    "    joint_state_broadcaster:\n      type: joint_state_broadcaster/JointStateBroadcaster\n"
    "    arm_controller:\n"
    "      type: joint_trajectory_controller/JointTrajectoryController\n",
    # the controller's own entry, whose type the spawner sets
    "config/diff.yaml": "/**/base_controller:\n  ros__parameters:\n"
    "    type: diff_drive_controller/DiffDriveController\n    use_stamped_vel: false\n",
    "config/steer.yaml": "/robot/base_controller:\n  ros__parameters:\n"
    "    type: bicycle_steering_controller/BicycleSteeringController\n",
    # a bare key in a namespaced spawner: the spawner refuses it
    "config/bare.yaml": "base_controller:\n  ros__parameters:\n"
    "    type: diff_drive_controller/DiffDriveController\n",
}


def _workspace(root: Path, launch: str, name: str = "control.launch.xml") -> str:
    package = root / "bringup"
    (package / "launch").mkdir(parents=True, exist_ok=True)
    (package / "package.xml").write_text(MANIFEST.format(name="bringup", build="ament_cmake"))
    for relative, text in FILES.items():
        (package / relative).parent.mkdir(exist_ok=True)
        (package / relative).write_text(text)
    (package / "launch" / name).write_text(launch)
    return str(package / "launch" / name)


def _edges(root: Path, file: str, **values: list[str]) -> tuple[Analysis, list[Edge]]:
    workspace = discover([str(root)])
    analysis = Analysis(workspace, values, {}, {})
    model = analysis.model(file)
    edges = controller_edges(analysis.space, model, CATALOGUE, workspace.confinement())
    return analysis, edges


def test_a_spawner_s_controllers_use_their_types_names_in_the_manager_s_namespace(
    tmp_path: Path,
) -> None:
    """The broadcaster's type comes from the manager's file, its joint_states takes the
    manager's remap; the base controller's type from the spawner's file, which an arg
    chooses, and so does its use_stamped_vel (the diff drive's file says false, the
    steering controller's default is false): their unstamped inputs, the diff drive's
    renamed by the spawner's --controller-ros-args; --load-only loads a controller without
    configuring it: it has no topics yet."""
    file = _workspace(tmp_path, CONTROL)
    analysis, edges = _edges(tmp_path, file, drive=["steer", "bare"])
    found = {
        (e.role, e.name, analysis.space.describe(e.condition), e.uncertain)
        for e in edges
        if not e.boundary or e.role is Role.SUBSCRIBES
    }
    assert found == {
        (Role.PUBLISHES, "/robot/platform/joint_states", "true", False),
        (Role.SUBSCRIBES, "/cmd_vel", "drive=diff ∧ ¬sim", False),
        (Role.PUBLISHES, "/robot/base_controller/odom", "drive=diff ∧ ¬sim", False),
        (
            Role.SUBSCRIBES,
            "/robot/base_controller/reference_unstamped",
            "drive=steer ∧ ¬sim",
            False,
        ),
        (Role.PUBLISHES, "/robot/base_controller/odometry", "drive=steer ∧ ¬sim", False),
    }
    assert {e.node for e in edges} == {
        "/robot/controller_manager: controller joint_state_broadcaster",
        "/robot/controller_manager: controller base_controller",
    }
    [odom] = [e for e in edges if e.name == "/robot/base_controller/odom"]
    assert odom.source.file.endswith("diff_drive_controller/src/diff_drive_controller.cpp")


MANAGER_ELSEWHERE = """<launch>
  <node pkg="controller_manager" exec="spawner"
        args="joint_state_broadcaster imu_sensor_broadcaster diff_drive_controller lidar
              -c /arm/controller_manager"/>
</launch>
"""


def test_a_manager_the_entry_file_does_not_launch_has_its_controllers_named_by_type(
    tmp_path: Path,
) -> None:
    """Gazebo's manager, or one another launch starts: its parameters are not known, so a
    controller named after a type's package is taken for that type, in the namespace of the
    manager the spawner names, and a use its parameters switch on is uncertain; another
    name has no known type."""
    file = _workspace(tmp_path, MANAGER_ELSEWHERE)
    _analysis, edges = _edges(tmp_path, file)
    assert {(e.role, e.name, e.uncertain) for e in edges if e.name != "/tf"} == {
        (Role.PUBLISHES, "/arm/joint_states", False),
        (Role.PUBLISHES, "/arm/dynamic_joint_states", False),
        (Role.PUBLISHES, "/arm/imu_sensor_broadcaster/imu", False),
        (Role.PUBLISHES, "/arm/diff_drive_controller/odom", False),
        # its parameters are not known: each input is kept, uncertain
        (Role.SUBSCRIBES, "/arm/diff_drive_controller/cmd_vel", True),
        (Role.SUBSCRIBES, "/arm/diff_drive_controller/cmd_vel_unstamped", True),
        (Role.PUBLISHES, "/arm/diff_drive_controller/cmd_vel_out", True),
    }


def _check(root: Path, capsys: pytest.CaptureFixture[str]) -> list[dict[str, object]]:
    main(["check", str(root), "--format", "json"])
    findings: list[dict[str, object]] = json.loads(capsys.readouterr().out)["findings"]
    return findings


ROBOT = """<launch>
  <arg name="states" default="true"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher" namespace="robot">
    <param name="robot_description" value="&lt;robot name='r'/&gt;"/>
    <remap from="joint_states" to="platform/joint_states"/>
  </node>
  <node pkg="controller_manager" exec="ros2_control_node" namespace="robot">
    <param from="$(find-pkg-share bringup)/config/manager.yaml"/>
    <remap from="joint_states" to="platform/joint_states"/>
  </node>
  <node pkg="controller_manager" exec="spawner" namespace="robot"
        args="joint_state_broadcaster" if="$(var states)"/>
</launch>
"""


def test_the_broadcaster_feeds_robot_state_publisher_where_it_is_spawned(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """robot_state_publisher's joint_states has its publisher, the broadcaster the manager
    loads, wherever the spawner runs; where it does not, nobody publishes them."""
    _workspace(tmp_path, ROBOT)
    missing = [
        (f["severity"], f["condition"])
        for f in _check(tmp_path, capsys)
        if (f["check"], f["name"]) == ("no-provider", "/robot/platform/joint_states")
    ]
    assert missing == [("warning", "¬states")]


def _copy_example_1(root: Path, arguments: str) -> None:
    """ros2_control_demos' example 1 bringup alone (its description package's own launch
    files start joint_state_publisher), the spawner's arguments replaced."""
    source = DATA / "ros2_control_demos" / "example_1"
    target = root / "example_1"
    shutil.copytree(source / "bringup", target / "bringup")
    shutil.copy(source / "package.xml", target / "package.xml")
    launch = target / "bringup" / "launch" / "rrbot.launch.py"
    text = launch.read_text()
    spawner = '"joint_state_broadcaster",\n                    "--param-file",'
    assert spawner in text
    launch.write_text(text.replace(spawner, arguments))


@pytest.mark.parametrize(
    ("arguments", "warned"),
    [
        ('"joint_state_broadcaster",\n                    "--param-file",', False),
        ('"joint_state_broadcaster", "--load-only", "--param-file",', True),
    ],
)
def test_example_1_s_joint_states_are_the_broadcaster_s(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], arguments: str, warned: bool
) -> None:
    """As the repository has it, the broadcaster publishes robot_state_publisher's
    joint_states; loaded only (never configured), it publishes nothing: the missing
    publisher is found."""
    _copy_example_1(tmp_path, arguments)
    warnings = {
        f["name"]
        for f in _check(tmp_path, capsys)
        if f["check"] == "no-provider" and f["severity"] == "warning"
    }
    assert warnings == ({"/joint_states"} if warned else set())


@pytest.mark.parametrize("repository", ["ros2_control_demos", "clearpath_common"])
def test_controllers_topics_have_their_publishers_in_the_repositories(
    repository: str, capsys: pytest.CaptureFixture[str]
) -> None:
    """The joint_states of ros2_control_demos (example 15's namespaced managers) and of
    Clearpath's platform (the manager's remap to platform/joint_states) come from the
    broadcasters their spawners load: no warning says they have no publisher."""
    findings = _check(DATA / repository, capsys)
    unfed = {
        str(f["name"])
        for f in findings
        if f["check"] == "no-provider" and f["severity"] == "warning"
    }
    assert not {name for name in unfed if name.endswith("joint_states")}
    spawned = [f for f in findings if ": controller joint_state_broadcaster" in str(f["message"])]
    assert spawned  # the broadcasters are in the graph (their outputs' notes name them)


OPTIONS = """<launch>
  <node pkg="controller_manager" exec="spawner"
        args="imu -t imu_sensor_broadcaster/IMUSensorBroadcaster -n arm --unload-on-kill"/>
  <node pkg="controller_manager" exec="spawner" args="joint_state_broadcaster -c"/>
  <node pkg="controller_manager" exec="spawner" args="joint_state_broadcaster --controller"/>
</launch>
"""


def test_the_spawner_s_options_as_its_argparse_reads_them(tmp_path: Path) -> None:
    """Humble's --controller-type gives the type, the deprecated --namespace the spawner's
    namespace (the manager's, then); a command line the spawner's argparse refuses (an
    option without its value, an ambiguous abbreviation) loads nothing."""
    file = _workspace(tmp_path, OPTIONS)
    _analysis, edges = _edges(tmp_path, file)
    assert {(e.node, e.name) for e in edges} == {
        ("/arm/controller_manager: controller imu", "/arm/imu/imu")
    }


TWICE = """<launch>
  <arg name="arm" default="true"/>
  <node pkg="controller_manager" exec="ros2_control_node">
    <param from="$(find-pkg-share bringup)/config/manager.yaml"/>
  </node>
  <node pkg="controller_manager" exec="spawner" args="joint_state_broadcaster arm_controller"/>
  <node pkg="controller_manager" exec="spawner" args="arm_controller --inactive"
        if="$(var arm)"/>
</launch>
"""


def test_a_controller_two_spawners_load_is_one_controller(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The manager loads a name once (the second spawner finds it loaded): the trajectory
    controller's action server is one, not two servers of one name."""
    file = _workspace(tmp_path, TWICE)
    _analysis, edges = _edges(tmp_path, file)
    servers = [e for e in edges if e.role is Role.ACTION_SERVERS]
    assert [(e.node, e.name) for e in servers] == [
        (
            "/controller_manager: controller arm_controller",
            "/arm_controller/follow_joint_trajectory",
        )
    ]
    assert not [f for f in _check(tmp_path, capsys) if f["check"] == "multiple-providers"]


INSTALLED = """<launch>
  <node pkg="controller_manager" exec="ros2_control_node"/>
  <node pkg="controller_manager" exec="spawner"
        args="base_controller -p $(find-pkg-share demo)/config/controllers.yaml"/>
</launch>
"""


def test_share_paths_are_read_from_what_the_install_copies_there(tmp_path: Path) -> None:
    """ros2_control_demos' layout: the launch and parameter files live in ``bringup/`` and
    CMake installs them into the share folder, where the launch files name them: the
    included file and the controller's type are read from those sources."""
    package = tmp_path / "demo"
    (package / "bringup" / "launch").mkdir(parents=True)
    (package / "bringup" / "config").mkdir()
    (package / "package.xml").write_text(MANIFEST.format(name="demo", build="ament_cmake"))
    (package / "CMakeLists.txt").write_text(
        "project(demo)\n"
        "install(DIRECTORY bringup/launch bringup/config DESTINATION share/${PROJECT_NAME})\n"
    )
    (package / "bringup" / "config" / "controllers.yaml").write_text(FILES["config/diff.yaml"])
    (package / "bringup" / "launch" / "control.launch.xml").write_text(INSTALLED)
    entry = package / "bringup" / "launch" / "entry.launch.xml"
    entry.write_text(
        '<launch><include file="$(find-pkg-share demo)/launch/control.launch.xml"/></launch>'
    )
    analysis, edges = _edges(tmp_path, str(entry))
    assert not [
        d for d in analysis.model(str(entry)).diagnostics if d.severity is not Severity.NOTE
    ]
    found = {(e.role, e.name, e.uncertain) for e in edges if e.name != "/tf"}
    assert found == {  # the file says use_stamped_vel: false; known, not uncertain
        (Role.SUBSCRIBES, "/base_controller/cmd_vel_unstamped", False),
        (Role.PUBLISHES, "/base_controller/odom", False),
    }
