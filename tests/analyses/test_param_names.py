"""Names that are parameters' values (issue 29 item 2): the graph names a use by the value
each configuration gives the parameter, else by the code's default, and agrees with the
graph of ``resolve`` in every configuration."""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

from rosvar.analyses.communication import graph_json, model_edges, resolved_graph, restrict
from rosvar.diagnostics import Location
from rosvar.ros1.resolve import Restriction, resolve
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
    from rosvar.interpreter.workspace_models import Analysis

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
        expected = resolved_graph(
            resolution.nodes, interfaces, resolution.scopes, resolution.params
        )
        assert graph_json(uses) == expected
        topics = {t["name"] for t in expected["topics"]}
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
