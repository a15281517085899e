"""ros_gz_bridge: the ROS side of each bridged name, from the arguments and the YAML file,
as parameter_bridge and bridge_config read them."""

from __future__ import annotations

from pathlib import Path

import pytest

from rosvar.analyses.robot_description.bridges import (
    Bridged,
    BridgeError,
    Direction,
    parse_argument,
    parse_config,
)
from rosvar.analyses.robot_description.edges import Simulation
from rosvar.diagnostics import Severity
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover
from rosvar.workspace.interfaces.model import Interfaces, Role


@pytest.mark.parametrize(
    ("argument", "expected"),
    [
        ("/clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock", ("/clock", Direction.GZ_TO_ROS)),
        ("cmd_vel@geometry_msgs/msg/Twist]gz.msgs.Twist", ("cmd_vel", Direction.ROS_TO_GZ)),
        ("scan@sensor_msgs/msg/LaserScan@gz.msgs.LaserScan", ("scan", Direction.BIDIRECTIONAL)),
        (
            "/world/w/control@ros_gz_interfaces/srv/ControlWorld@gz.msgs.WorldControl@gz.msgs.Boolean",
            ("/world/w/control", Direction.NONE),
        ),
    ],
)
def test_arguments_as_parameter_bridge_reads_them(
    argument: str, expected: tuple[str, Direction]
) -> None:
    bridged = parse_argument(argument)
    assert (bridged.name, bridged.direction) == expected


@pytest.mark.parametrize(
    "argument",
    [
        "no_type",  # no '@'
        "@std_msgs/msg/String@gz.msgs.StringMsg",  # no name
        "topic@std_msgs/msg/String",  # no Gazebo type
        "topic@std_msgs/msg/String@gz.msgs.StringMsg@extra",
        "srv@std_srvs/srv/Empty[gz.msgs.Empty",  # a service one way
        "srv@std_srvs/srv/Empty@gz.msgs.Empty",  # no reply type
    ],
)
def test_malformed_arguments_stop_the_bridge(argument: str) -> None:
    with pytest.raises(BridgeError):
        parse_argument(argument)


def test_config_entries_as_bridge_config_reads_them() -> None:
    text = """
- ros_topic_name: "/scan"
  gz_topic_name: "/world/w/scan"
  ros_type_name: "sensor_msgs/msg/LaserScan"
  gz_type_name: "gz.msgs.LaserScan"
  direction: GZ_TO_ROS
- topic_name: "cmd_vel"
  ros_type_name: "geometry_msgs/msg/Twist"
  gz_type_name: "gz.msgs.Twist"
  direction: ROS_TO_GZ
- gz_topic_name: "/clock"
  ros_type_name: "rosgraph_msgs/msg/Clock"
  gz_type_name: "gz.msgs.Clock"
- topic_name: "skipped"
  ros_topic_name: "both"
  ros_type_name: "std_msgs/msg/String"
  gz_type_name: "gz.msgs.StringMsg"
- topic_name: "bad_direction"
  ros_type_name: "std_msgs/msg/String"
  gz_type_name: "gz.msgs.StringMsg"
  direction: SIDEWAYS
"""
    assert parse_config(text) == [
        Bridged("/scan", "sensor_msgs/msg/LaserScan", Direction.GZ_TO_ROS),
        Bridged("cmd_vel", "geometry_msgs/msg/Twist", Direction.ROS_TO_GZ),
        Bridged("/clock", "rosgraph_msgs/msg/Clock", Direction.BIDIRECTIONAL),
    ]
    with pytest.raises(BridgeError):
        parse_config("ros_topic_name: x")


MANIFEST = """<package format="3"><name>sim</name><version>0.0.0</version><description>d
</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>
<export><build_type>ament_cmake</build_type></export></package>"""
LAUNCH = """<launch>
  <arg name="use_clock" default="true"/>
  <node pkg="ros_gz_bridge" exec="parameter_bridge" name="bridge" namespace="sim"
        args="/clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock
              odom@nav_msgs/msg/Odometry[gz.msgs.Odometry"
        if="$(var use_clock)">
    <remap from="odom" to="/odometry"/>
  </node>
  <node pkg="ros_gz_bridge" exec="parameter_bridge" args="broken">
    <param name="config_file" value="$(find-pkg-share sim)/config/bridge.yaml"/>
  </node>
</launch>
"""
CONFIG = """
- topic_name: "cmd_vel"
  ros_type_name: "geometry_msgs/msg/Twist"
  gz_type_name: "gz.msgs.Twist"
  direction: ROS_TO_GZ
"""


def test_bridges_are_edges_of_their_node(tmp_path: Path) -> None:
    package = tmp_path / "ws" / "sim"
    (package / "launch").mkdir(parents=True)
    (package / "config").mkdir()
    (package / "package.xml").write_text(MANIFEST)
    (package / "launch" / "sim.launch.xml").write_text(LAUNCH)
    (package / "config" / "bridge.yaml").write_text(CONFIG)
    analysis = Analysis(discover([tmp_path / "ws"], ros_package_path=""))
    simulation = Simulation(analysis, Interfaces())
    model = analysis.model(str(package / "launch" / "sim.launch.xml"))
    edges = {(e.node, e.role, e.name, e.type) for e in simulation.edges(model)}
    assert edges == {
        ("/sim/bridge", Role.PUBLISHES, "/clock", "rosgraph_msgs/msg/Clock"),
        ("/sim/bridge", Role.PUBLISHES, "/odometry", "nav_msgs/msg/Odometry"),  # remapped
        ("/ros_gz_bridge", Role.SUBSCRIBES, "/cmd_vel", "geometry_msgs/msg/Twist"),
    }
    [stops] = simulation.gaps(model)
    assert stops.severity is Severity.WARNING and "broken" in stops.message
