"""Topics, services and actions of the communication graph in queries."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from rosvar.analyses.query.channels import channel_collections
from rosvar.analyses.query.collections import ElementSet
from rosvar.analyses.query.evaluator import QueryEngine
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover
from rosvar.workspace.interfaces.extraction import extract_interfaces
from workspace.interfaces.ros2_packages import write_ros2_bringup

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

TALKER = """\
import rospy
from std_msgs.msg import String
from std_srvs.srv import Empty
rospy.Publisher("chatter", String)
rospy.Service("reset", Empty, None)
"""
LISTENER = """\
import rospy
from std_msgs.msg import String
from std_srvs.srv import Empty
rospy.Subscriber("chatter", String)
rospy.ServiceProxy("reset", Empty)
"""
LAUNCH = """\
  <arg name="second" default="false"/>
  <node pkg="pkg" type="talker.py" name="one"/>
  <node pkg="pkg" type="talker.py" name="two" if="$(arg second)"/>
  <node pkg="pkg" type="listener.py" name="listener"><remap from="chatter" to="/in"/></node>
"""


def _engine(ws: LaunchWorkspace) -> QueryEngine:
    ws.write("scripts/talker.py", TALKER)
    ws.write("scripts/listener.py", LISTENER)
    ws.launch("a.launch", LAUNCH)
    analysis = ws.analysis()
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    return QueryEngine(analysis, collections=channel_collections(interfaces))


def _answers(engine: QueryEngine, text: str) -> dict[str, str]:
    return {r.element.name: engine.space.describe(r.condition) for r in engine.run(text)}


def test_publishers_are_the_nodes_using_a_topic_with_their_conditions(ws: LaunchWorkspace) -> None:
    engine = _engine(ws)
    assert _answers(engine, "topics[len(self.publishers) > 1]") == {"/chatter": "second"}
    assert _answers(engine, "topics[len(self.subscribers) == 0]") == {"/chatter": "true"}
    # the listener's remap names /in: a topic with a subscriber and a remap, no publisher
    assert _answers(engine, "topics[not self.publishers]") == {"/in": "true"}
    assert _answers(engine, "topics[len(self.remapped_by) == 1]") == {"/in": "true"}
    assert _answers(engine, "topics[self.types == ('std_msgs/String',)]") == {
        "/chatter": "true",
        "/in": "true",
    }


def test_services_and_actions_have_servers_and_clients(ws: LaunchWorkspace) -> None:
    engine = _engine(ws)
    assert _answers(engine, "services[len(self.servers) == 2]") == {"/reset": "second"}
    [result] = engine.run("for s in services where len(s.clients) == 1 return s")
    assert result.element.kind == "service"
    assert _answers(engine, "actions") == {}


def test_ros2_nodes_and_their_topics(tmp_path: Path) -> None:
    """A ROS 2 node's name composes the pushed namespace with its own; one the launch file
    does not name (its code does) is still each of its topics' publisher."""
    write_ros2_bringup(
        tmp_path,
        """<launch><arg name="ns" default="r1"/>
        <group><push_ros_namespace namespace="$(var ns)"/>
          <node pkg="demo_cpp" exec="talker" namespace="arm"/>
          <node pkg="demo_py" exec="listener" name="ear"/></group>
        <node pkg="demo_py" exec="listener" name="top"/></launch>""",
    )
    analysis = Analysis(discover([tmp_path]))
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    engine = QueryEngine(analysis, collections=channel_collections(interfaces))
    assert _answers(engine, "nodes[self.namespace == '/r1']") == {"/r1/ear": "ns=r1"}
    assert _answers(engine, "nodes[self.name == '/top']") == {"/top": "true"}
    [talker] = engine.run("topics[self.name == '/r1/arm/chatter']")
    [publishing] = talker.element.attribute("publishers").values()
    assert isinstance(publishing, ElementSet)
    [(_when, publisher)] = publishing.members
    # the node's namespace where ns is r1, and where ns is another text, not known yet
    assert publisher.attribute("namespace").values() == ["/r1/arm", None]
    assert _answers(engine, "topics[self.name == '/r1/chatter']") == {"/r1/chatter": "ns=r1"}
    # the unnamed talker is shown as resolve and the page show it: its executable, in brackets
    # (a name known only once ns's other text is typed is None to a query too)
    assert _answers(engine, "nodes[self.name == None]")["/r1/arm/⟨talker⟩"] == "ns=r1"
