"""Robot descriptions in the communication graph: a spawner's Gazebo plugins are its edges,
with the launch file's and the description's conditions."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from rosvar.analyses.checks import Check, check_models
from rosvar.analyses.communication import Edge, model_edges
from rosvar.analyses.query.collections import ElementSet
from rosvar.analyses.robot_description.document import Node, XElement
from rosvar.analyses.robot_description.edges import Simulation, configuration_edges
from rosvar.diagnostics import Location, Severity
from rosvar.interpreter.resolution import Restriction
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.ros.version import RosVersion
from rosvar.workspace import discover
from rosvar.workspace.interfaces.catalogue import load_catalogue
from rosvar.workspace.interfaces.extraction import extract_interfaces
from rosvar.workspace.interfaces.model import Interfaces, Role
from rosvar.workspace.interfaces.overrides import add_catalogue

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

ROBOT = """<?xml version="1.0"?>
<robot name="bot" xmlns:xacro="http://ros.org/wiki/xacro">
  <xacro:arg name="laser" default="false"/>
  <xacro:arg name="prefix" default=""/>
  <xacro:macro name="lidar" params="topic">
    <gazebo reference="laser"><sensor type="ray" name="laser">
      <plugin name="lidar" filename="libgazebo_ros_laser.so">
        <topicName>${topic}</topicName><frameName>laser</frameName>
      </plugin>
    </sensor></gazebo>
  </xacro:macro>
  <xacro:if value="$(arg laser)"><xacro:lidar topic="$(arg prefix)scan"/></xacro:if>
  <gazebo>
    <plugin name="imu" filename="libhector_gazebo_ros_imu.so">
      <topicName>imu/data</topicName>
    </plugin>
    <plugin name="drive" filename="libgazebo_ros_diff_drive.so">
      <robotNamespace>/base</robotNamespace>
    </plugin>
    <plugin name="mystery" filename="libgazebo_ros_mystery.so"/>
  </gazebo>
</robot>
"""
LISTENER = """\
import rospy
from sensor_msgs.msg import LaserScan
rospy.Subscriber("scan", LaserScan, None)
"""
LAUNCH = """
  <arg name="laser" default="false"/>
  <arg name="ns" default="/"/>
  <param name="robot_description"
         command="$(find xacro)/xacro '$(find pkg)/urdf/robot.urdf.xacro' laser:=$(arg laser)"/>
  <group ns="$(arg ns)">
    <node name="spawn" pkg="gazebo_ros" type="spawn_model"
          args="-urdf -param /robot_description -model bot -x 1"/>
  </group>
  <node name="listener" pkg="pkg" type="listener.py"/>
"""


def _setup(ws: LaunchWorkspace) -> tuple[list[Edge], Simulation]:
    ws.write("urdf/robot.urdf.xacro", ROBOT)
    ws.write("scripts/listener.py", LISTENER)
    file = ws.launch("sim.launch", LAUNCH)
    analysis = ws.analysis()
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    described = Simulation(analysis, interfaces)
    return model_edges(analysis.space, analysis.model(file), interfaces, described), described


def _holds(ws: LaunchWorkspace, condition: BDD, **args: str) -> bool:
    analysis = ws.analysis()
    model = analysis.model(analysis.workspace.launch_files[0])
    return Restriction(analysis, model, args, {}).holds(condition)


def test_plugins_are_edges_of_the_spawner(ws: LaunchWorkspace) -> None:
    edges, _described = _setup(ws)
    uses = {(e.node, e.role, e.name, e.type): e.condition for e in edges if "plugin" in e.node}
    scan = uses[("/spawn: gazebo plugin lidar", Role.PUBLISHES, "/scan", "sensor_msgs/LaserScan")]
    assert _holds(ws, scan, laser="true") and not _holds(ws, scan, laser="false")
    # no robotNamespace: the spawner's namespace (spawn_model's -robot_namespace default)
    imu = uses[("/spawn: gazebo plugin imu", Role.PUBLISHES, "/imu/data", "sensor_msgs/Imu")]
    assert _holds(ws, imu) and not _holds(ws, imu, ns="r1")
    moved = [e for e in edges if e.name.endswith("/imu/data") and e.name != "/imu/data"]
    assert moved and not any(e.static for e in moved)  # a namespace only known per value
    drive = {k[2] for k in uses if k[0].endswith("plugin drive")}
    assert drive == {"/base/cmd_vel", "/base/odom", "/tf"}
    bias = [k for k in uses if k[2] == "/imu/data/bias"]  # hector's default after topicName
    assert bias


def test_a_simulated_sensor_is_the_missing_partner(ws: LaunchWorkspace) -> None:
    """The listener's scan has a provider exactly where the description has its laser."""
    _setup(ws)
    analysis = ws.analysis()
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    described = Simulation(analysis, interfaces)
    models = [analysis.model(f) for f in analysis.workspace.launch_files]
    findings = check_models(
        analysis.space, models, interfaces, analysis.workspace.confinement(), described
    )
    missing = [f for f in findings if f.check is Check.NO_PROVIDER and f.name == "/scan"]
    assert len(missing) == 1
    assert _holds(ws, missing[0].condition, laser="false")
    assert not _holds(ws, missing[0].condition, laser="true")
    unread = [f for f in findings if f.check is Check.UNREAD]
    assert any("libgazebo_ros_mystery.so" in f.message for f in unread)
    assert all(f.severity is Severity.NOTE for f in unread)


def test_a_description_read_with_textfile_is_located_in_its_file(ws: LaunchWorkspace) -> None:
    """Findings of a ``textfile`` description name lines of the file read, not of the
    parameter's text at the launch file's place."""
    urdf = ws.write("urdf/robot.urdf", ROBOT.replace("$(arg prefix)scan", "scan"))
    command = "command=\"$(find xacro)/xacro '$(find pkg)/urdf/robot.urdf.xacro' "
    command += 'laser:=$(arg laser)"'
    launch = LAUNCH.replace(command, 'textfile="$(find pkg)/urdf/robot.urdf"')
    assert launch != LAUNCH
    ws.launch("sim.launch", launch)
    analysis = ws.analysis()
    models = [analysis.model(f) for f in analysis.workspace.launch_files]
    findings = check_models(
        analysis.space,
        models,
        Interfaces(),
        analysis.workspace.confinement(),
        Simulation(analysis, Interfaces()),
    )
    [unread] = [f for f in findings if f.check is Check.UNREAD and "mystery" in f.message]
    assert unread.locations[1:] == (Location(urdf, 20, 5),)  # its <plugin>


def test_xacro_failing_is_a_warning_where_the_launch_stops(ws: LaunchWorkspace) -> None:
    launch = LAUNCH.replace("laser:=$(arg laser)", "laser:=$(arg laser) prefix:=$(arg ns)")
    failing = "<xacro:if value=\"${'$(arg prefix)' == 'bad'}\"><xacro:undefined_macro/></xacro:if>"
    ws.write("urdf/robot.urdf.xacro", ROBOT.replace("<gazebo>", failing + "<gazebo>", 1))
    ws.write("scripts/listener.py", LISTENER)
    file = ws.launch("sim.launch", launch)
    analysis = ws.analysis(extra_values={"ns": ["bad"]})
    described = Simulation(analysis, Interfaces())
    model = analysis.model(file)
    fails = described.fails(model)
    for ns, expected in (("bad", True), ("/", False), ("good", False)):
        assert Restriction(analysis, model, {"ns": ns}, {}).holds(fails) is expected
    warnings = [g for g in described.gaps(model) if g.severity is Severity.WARNING]
    assert [analysis.space.describe(g.condition) for g in warnings] == ["ns=bad"]
    assert "unknown macro name" in warnings[0].message


ROS2_MANIFEST = """<package format="3"><name>bot</name><version>0.0.0</version><description>d
</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>
<export><build_type>ament_cmake</build_type></export></package>"""
ROS2_ROBOT = """<robot name="bot" xmlns:xacro="http://ros.org/wiki/xacro">
  <xacro:arg name="lidar" default="true"/>
  <xacro:if value="$(arg lidar)">
    <gazebo reference="l"><sensor type="ray" name="lidar">
      <plugin name="scanner" filename="libgazebo_ros_ray_sensor.so">
        <ros><namespace>/bot</namespace><remapping>~/out:=scan</remapping></ros>
        <output_type>sensor_msgs/LaserScan</output_type>
      </plugin>
    </sensor></gazebo>
  </xacro:if>
  <gazebo><plugin name="diff" filename="libgazebo_ros_diff_drive.so">
    <publish_odom>true</publish_odom>
  </plugin></gazebo>
</robot>"""
ROS2_XML = """<launch>
  <arg name="lidar" default="true"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher">
    <param name="robot_description"
      value="$(command 'xacro $(find-pkg-share bot)/urdf/bot.urdf.xacro lidar:=$(var lidar)')"/>
  </node>
  <node pkg="gazebo_ros" exec="spawn_entity.py" args="-topic robot_description -entity bot"/>
</launch>"""
ROS2_PYTHON = """
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import Command, FindExecutable, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare

def generate_launch_description():
    description = Command([
        PathJoinSubstitution([FindExecutable(name="xacro")]), " ",
        PathJoinSubstitution([FindPackageShare("bot"), "urdf", "bot.urdf.xacro"]),
        " lidar:=", LaunchConfiguration("lidar"),
    ])
    return LaunchDescription([
        DeclareLaunchArgument("lidar", default_value="false"),
        Node(package="robot_state_publisher", executable="robot_state_publisher",
             parameters=[{"robot_description": ParameterValue(description, value_type=str)}]),
        Node(package="gazebo_ros", executable="spawn_entity.py",
             arguments=["-topic", "robot_description", "-entity", "bot",
                        "-robot_namespace", "r2"]),
    ])
"""


def test_ros2_spawners_read_robot_state_publishers_description(tmp_path: Path) -> None:
    """``$(command 'xacro ...')`` (XML) and ``Command([...])`` (Python) as the parameter of
    robot_state_publisher, whose topic spawn_entity.py reads; ROS 2 plugins are nodes named
    after themselves, with <ros><namespace> (replaced by -robot_namespace) and remappings."""
    package = tmp_path / "ws" / "bot"
    (package / "launch").mkdir(parents=True)
    (package / "urdf").mkdir()
    (package / "package.xml").write_text(ROS2_MANIFEST)
    (package / "urdf" / "bot.urdf.xacro").write_text(ROS2_ROBOT)
    (package / "launch" / "sim.launch.xml").write_text(ROS2_XML)
    (package / "launch" / "sim.launch.py").write_text(ROS2_PYTHON)
    analysis = Analysis(discover([tmp_path / "ws"], ros_package_path=""))
    simulation = Simulation(analysis, Interfaces())
    found = {}
    for name in ("sim.launch.xml", "sim.launch.py"):
        model = analysis.model(str(package / "launch" / name))
        found[name] = {
            (e.role, e.name, e.type): Restriction(analysis, model, {}, {}).holds(e.condition)
            for e in simulation.edges(model)
        }
    scan = (Role.PUBLISHES, "/bot/scan", "sensor_msgs/msg/LaserScan")
    assert found["sim.launch.xml"] == {
        scan: True,  # lidar defaults to true there
        (Role.SUBSCRIBES, "/cmd_vel", "geometry_msgs/msg/Twist"): True,
        (Role.PUBLISHES, "/odom", "nav_msgs/msg/Odometry"): True,
    }
    assert found["sim.launch.py"] == {
        (Role.PUBLISHES, "/r2/scan", "sensor_msgs/msg/LaserScan"): False,  # lidar: false
        (Role.SUBSCRIBES, "/r2/cmd_vel", "geometry_msgs/msg/Twist"): True,
        (Role.PUBLISHES, "/r2/odom", "nav_msgs/msg/Odometry"): True,
    }


def test_queries_see_the_plugins_topics_published_by_the_spawner(ws: LaunchWorkspace) -> None:
    from rosvar.analyses.query.channels import channel_collections
    from rosvar.analyses.query.evaluator import QueryEngine

    _setup(ws)
    analysis = ws.analysis()
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    collections = channel_collections(interfaces, Simulation(analysis, interfaces))
    engine = QueryEngine(analysis, collections=collections)
    [scan] = engine.run("topics[self.name == '/scan']")
    [publishing] = scan.element.attribute("publishers").values()
    assert isinstance(publishing, ElementSet)
    members = publishing.members
    publishers = {publisher.attribute("name").values()[0] for _when, publisher in members}
    assert publishers == {"/spawn"}  # the node that loads the plugin


CORPUS = Path(__file__).resolve().parents[4] / "shared" / "corpus"  # ../shared of the checkout
HUSKY_SPAWN = CORPUS / "husky/husky/husky_gazebo/launch/spawn_husky.launch"
HUSKY_CONFIGURATIONS = [
    ({}, {}),
    ({}, {"HUSKY_LMS1XX_ENABLED": "1"}),
    ({}, {"HUSKY_LMS1XX_ENABLED": "true", "HUSKY_LMS1XX_SECONDARY_ENABLED": "1"}),
    ({}, {"HUSKY_UST10_ENABLED": "1", "HUSKY_UST10_TOPIC": "hokuyo/scan"}),
    ({}, {"HUSKY_REALSENSE_ENABLED": "1"}),
    ({}, {"HUSKY_LASER_3D_ENABLED": "1", "HUSKY_LASER_3D_TOPIC": "velodyne_points"}),
    ({"robot_namespace": "husky_alpha"}, {"HUSKY_LMS1XX_ENABLED": "1"}),
    ({"robot_namespace": "husky_beta", "multimaster": "true"}, {"HUSKY_REALSENSE_ENABLED": "1"}),
]


def _element(node: Node, space: ConditionSpace) -> XElement:
    """xacro's printed element as a description element present everywhere."""
    tag, attributes, text, children = node
    element = XElement(tag, space.true, Location("xacro"))
    element.attributes = {k: Choice.const(space, v) for k, v in attributes}
    element.texts = [(space.true, Choice.const(space, text))]
    element.children = [_element(child, space) for child in children]
    return element


@pytest.mark.skipif(not HUSKY_SPAWN.is_file(), reason="corpus not available")
def test_husky_plugins_restricted_are_the_real_xacros(tmp_path: Path) -> None:
    """Differential: per configuration, the spawner's plugin edges restricted from the
    variational model are the plugins of what the real xacro prints for the command the
    launch file gives it (its args, the environment)."""
    from analyses.robot_description.xacro_oracle import XacroFailed, run_xacro
    from rosvar.analyses.robot_description.commands import split, xacro_command
    from rosvar.analyses.robot_description.plugins import Spawning, plugin_uses
    from rosvar.ros.version import RosVersion
    from rosvar.ros1.resolve import resolve

    workspace = discover([CORPUS / "husky"], deps=[CORPUS / "_external"], ros_package_path="")
    analysis = Analysis(workspace)
    simulation = Simulation(analysis, Interfaces())
    model = analysis.model(str(HUSKY_SPAWN))
    simulation.edges(model)
    packages = {name: package.path for name, package in workspace.packages.items()}
    compared = 0
    for args, env in HUSKY_CONFIGURATIONS:
        restricted = configuration_edges(analysis, [str(HUSKY_SPAWN)], args, env, Interfaces())
        ours = {  # the controllers' edges come from the spawner's args, not from xacro
            (e.role, e.name, e.type) for e in restricted.edges if ": controller " not in e.node
        }
        resolution = resolve(analysis, [str(HUSKY_SPAWN)], args, env)
        [spawner] = [n for n in resolution.nodes if n.executable == "spawn_model"]
        command = str(resolution.params[f"{spawner.namespace}robot_description"])
        run = xacro_command(split(command.removeprefix("__command__(").removesuffix(")")))
        assert run is not None and isinstance(run.file, str)
        printed = run_xacro(run.file, {k: str(v) for k, v in run.args.items()}, env, packages)
        assert not isinstance(printed, XacroFailed), (args, env)
        spawning = Spawning(str(spawner.namespace), None, "husky")
        uses, _unread = plugin_uses(
            analysis.space, _element(printed, analysis.space), RosVersion.ROS1, spawning
        )
        theirs = {(u.role, u.name, u.type) for u in uses}
        assert ours == theirs, (args, env)
        compared += bool(theirs)
    assert compared == len(HUSKY_CONFIGURATIONS)


ROS2_EMPTY_FILE = """
import os
from launch import LaunchDescription
from launch.substitutions import TextSubstitution
from launch_ros.actions import Node

def generate_launch_description():
    sdf = os.getenv("ROBOT_SDF")
    return LaunchDescription([
        Node(package="gazebo_ros", executable="spawn_entity.py",
             arguments=["-entity", "bot", "-file", TextSubstitution(text=sdf)]),
    ])
"""


def test_a_spawner_given_an_empty_file_says_so_in_words(tmp_path: Path) -> None:
    """``-file`` from an unset environment variable: the spawner (named as its code names
    it) is given an empty argument where the variable is unset, never a file named ''."""
    package = tmp_path / "ws" / "bot"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(ROS2_MANIFEST)
    (package / "launch" / "sim.launch.py").write_text(ROS2_EMPTY_FILE)
    analysis = Analysis(discover([tmp_path / "ws"], ros_package_path=""))
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    add_catalogue(interfaces, load_catalogue(RosVersion.ROS2))  # spawn_entity.py's name
    simulation = Simulation(analysis, interfaces)
    model = analysis.model(str(package / "launch" / "sim.launch.py"))
    [gap] = [g for g in simulation.gaps(model) if g.severity is Severity.WARNING]
    assert gap.message == (
        "/spawn_entity (gazebo_ros spawn_entity.py) is given an empty -file argument where "
        "$ROBOT_SDF=<unset>: it has no model to read and spawns nothing"
    )
    assert Restriction(analysis, model, {}, {}).holds(gap.condition)  # unset
    assert not Restriction(analysis, model, {}, {"ROBOT_SDF": "/r.sdf"}).holds(gap.condition)
    unknown = Simulation(analysis, Interfaces())  # its code not known: the executable, as
    [gap] = [g for g in unknown.gaps(model) if g.severity is Severity.WARNING]  # resolve shows
    assert gap.message.startswith("/⟨spawn_entity.py⟩ (gazebo_ros spawn_entity.py) is given")
