"""Names that are parameters' values (issue 29 item 2): the graph names a use by the value
each configuration gives the parameter, else by the code's default, and agrees with the
graph of ``resolve`` in every configuration."""

from __future__ import annotations

import itertools
from pathlib import Path
from typing import TYPE_CHECKING

from rosvar.analyses.communication import (
    Channel,
    model_edges,
    resolved_graph,
    restrict,
    uses_graph,
)
from rosvar.diagnostics import Location
from rosvar.interpreter.resolution import Restriction
from rosvar.interpreter.workspace_models import Analysis
from rosvar.ros1.resolve import resolve
from rosvar.workspace import discover
from rosvar.workspace.interfaces.extraction import extract_interfaces
from rosvar.workspace.interfaces.model import (
    Entry,
    Interfaces,
    NamedBy,
    NodeInterface,
    NodeKind,
    Role,
)

if TYPE_CHECKING:
    from conftest import LaunchWorkspace
    from rosvar.analyses.communication import Edge

FOLLOWER = """\
import rospy
from nav_msgs.msg import Path
from sensor_msgs.msg import Imu
topic = rospy.get_param("~path_topic", "plan")
rospy.Subscriber(topic, Path, None)
rospy.Subscriber(rospy.get_param("imu_topic"), Imu, None)
"""
LAUNCH = """
  <arg name="global_plan" default="false"/>
  <arg name="imu" default="imu/data"/>
  <node pkg="pkg" type="follower.py" name="follower" ns="robot">
    <param name="path_topic" value="/global_plan" if="$(arg global_plan)"/>
    <remap from="/global_plan" to="/planner/plan"/>
  </node>
  <param name="robot/imu_topic" value="$(arg imu)"/>
"""


def _edges(ws: LaunchWorkspace) -> tuple[Analysis, str, Interfaces, list[Edge]]:
    ws.write("scripts/follower.py", FOLLOWER)
    file = ws.launch("demo.launch", LAUNCH)
    analysis = ws.analysis(extra_values={"imu": ["imu/raw"]})
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    return analysis, file, interfaces, model_edges(analysis.space, analysis.model(file), interfaces)


def test_a_use_named_by_a_parameter_takes_each_value(ws: LaunchWorkspace) -> None:
    analysis, _, _, edges = _edges(ws)
    space = analysis.space
    subscribed = {(e.name, space.describe(e.condition)) for e in edges if e.role is Role.SUBSCRIBES}
    names = {name for name, _ in subscribed}
    # the default where the launch file sets nothing; the set value, remapped, where it does
    assert "/robot/plan" in names and "/planner/plan" in names
    assert {"/robot/imu/data", "/robot/imu/raw"} <= names
    [(_, when)] = [s for s in subscribed if s[0] == "/planner/plan"]
    assert "global_plan" in when
    # an imu value typed at configuration time is not known: the name stays symbolic there
    assert [e.name for e in edges if not e.static] == ["/robot/{imu_topic}"]


def test_restricted_graph_equals_resolved_graph(ws: LaunchWorkspace) -> None:
    analysis, file, interfaces, edges = _edges(ws)
    model = analysis.model(file)
    for plan, imu in itertools.product(["true", "false"], ["imu/data", "imu/raw"]):
        args = {"global_plan": plan, "imu": imu}
        resolution = resolve(analysis, [file], args)
        restriction = Restriction(analysis, model, args, {})
        kept = restrict(edges, restriction.holds)
        uses = [(e.node, e.role, e.name, e.type) for e in kept]
        expected = resolved_graph(resolution.nodes, interfaces, resolution.params)
        assert uses_graph(uses) == expected
        topics = {t.name for t in expected[Channel.TOPICS]}
        assert ("/planner/plan" in topics) == (plan == "true")
        assert f"/robot/{imu}" in topics


def test_an_indexed_parameter_names_one_use_per_parameter_set(ws: LaunchWorkspace) -> None:
    """robot_localization's ``imu0``, ``imu1``...: a catalogue entry names its topic by
    ``~imu{N}``; each parameter the launch file sets is one subscription, none unset."""
    file = ws.launch(
        "ekf.launch",
        """
  <arg name="second" default="false"/>
  <node pkg="pkg" type="ekf" name="ekf">
    <param name="imu0" value="imu/data"/>
    <param name="imu1" value="/other/imu" if="$(arg second)"/>
  </node>
""",
    )
    analysis = ws.analysis()
    entry = Entry(
        Role.SUBSCRIBES,
        "{~imu{N}}",
        Location("ekf.cpp", 1),
        type="sensor_msgs/Imu",
        static=False,
        named_by=NamedBy("~imu{N}"),
    )
    interfaces = Interfaces([NodeInterface("pkg", "ekf", NodeKind.NODE, [entry])])
    edges = model_edges(analysis.space, analysis.model(file), interfaces)
    space = analysis.space
    found = {(e.name, space.describe(e.condition)) for e in edges}
    assert {name for name, _ in found} == {"/imu/data", "/other/imu"}
    [(_, when)] = [f for f in found if f[0] == "/other/imu"]
    assert "second" in when


RELAY_SETUP = """\
from setuptools import setup
setup(name='relay_py', entry_points={'console_scripts': ['relay = relay_py.relay:main']})
"""
RELAY = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String
class Relay(Node):
    def __init__(self):
        super().__init__('relay')
        topic = self.declare_parameter('input', 'chatter').value
        self.create_subscription(String, topic, None, 10)
def main():
    rclpy.spin(Relay())
"""
ROS2_LAUNCH = """\
<launch>
  <arg name="remote" default="false"/>
  <node pkg="relay_py" exec="relay" name="relay" namespace="r1">
    <param name="input" value="/remote/chatter" if="$(var remote)"/>
  </node>
</launch>
"""
MANIFEST = """\
<package format="3"><name>{name}</name><version>0.0.0</version><description>d</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<export><build_type>{build}</build_type></export></package>
"""


def test_a_ros2_nodes_own_parameters_name_its_uses(tmp_path: Path) -> None:
    """ROS 2: the value the launch description gives the node's parameter, else the
    default of its declaration; the restriction equals the graph of ``resolve``."""
    package = tmp_path / "relay_py"
    (package / "relay_py").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST.format(name="relay_py", build="ament_python"))
    (package / "setup.py").write_text(RELAY_SETUP)
    (package / "relay_py" / "__init__.py").write_text("")
    (package / "relay_py" / "relay.py").write_text(RELAY)
    (package / "launch").mkdir()
    file = str(package / "launch" / "relay.launch.xml")
    Path(file).write_text(ROS2_LAUNCH)
    analysis = Analysis(discover([tmp_path]))
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    model = analysis.model(file)
    edges = model_edges(analysis.space, model, interfaces)
    assert {e.name for e in edges} == {"/r1/chatter", "/remote/chatter"}
    for remote in ("true", "false"):
        args = {"remote": remote}
        resolution = analysis.resolve([file], args)
        kept = restrict(edges, Restriction(analysis, model, args, {}).holds)
        uses = [(e.node, e.role, e.name, e.type) for e in kept]
        expected = resolved_graph(resolution.nodes, interfaces, resolution.params)
        assert uses_graph(uses) == expected
        [topic] = expected[Channel.TOPICS]
        assert topic.name == ("/remote/chatter" if remote == "true" else "/r1/chatter")
