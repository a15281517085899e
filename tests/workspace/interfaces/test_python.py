"""Python extraction: rospy/actionlib calls through imports and string constants."""

from __future__ import annotations

from pathlib import Path

from rosvar.diagnostics import DiagnosticSink
from rosvar.workspace.interfaces.model import RECONFIGURED, Expression, NamedBy, Role
from rosvar.workspace.interfaces.python import extract, extract_node

SCRIPT = """\
import rospy as rp
from geometry_msgs.msg import Twist
import std_srvs.srv
from actionlib import SimpleActionClient
from move_base_msgs.msg import MoveBaseAction

PREFIX = "robot"

class Node:
    def __init__(self):
        self.topic = PREFIX + "/cmd_vel"
        self.pub = rp.Publisher(self.topic, Twist, queue_size=1)
        rp.Subscriber("~odom", data_class=Twist, callback=self.cb)
        rp.Service("reset", std_srvs.srv.Empty, self.reset)
        self.ac = SimpleActionClient("move_base", MoveBaseAction)
        self.rate = rp.get_param("~rate", 10.0)
        self.frame = rp.get_param("/frame")
        self.other = rp.get_param("~other", [1, 2])
        rp.ServiceProxy(rp.get_param("~service", "x"), std_srvs.srv.Trigger)
"""


def test_script_interface(tmp_path: Path) -> None:
    path = tmp_path / "node.py"
    path.write_text(SCRIPT)
    sink = DiagnosticSink()
    entries = extract(str(path), sink)
    assert [
        (str(e.role), e.name, e.default if e.role is Role.PARAMS else e.type, e.location.line)
        for e in entries
    ] == [
        ("publishes", "robot/cmd_vel", "geometry_msgs/Twist", 12),
        ("subscribes", "~odom", "geometry_msgs/Twist", 13),
        ("services", "reset", "std_srvs/Empty", 14),
        ("action_clients", "move_base", "move_base_msgs/MoveBase", 15),
        ("params", "~rate", 10.0, 16),
        ("params", "/frame", None, 17),
        ("params", "~other", Expression("[1, 2]"), 18),
        ("clients", "{~service}", "std_srvs/Trigger", 19),  # the parameter's value
        ("params", "~service", "x", 19),
    ]
    (client,) = [e for e in entries if e.role is Role.CLIENTS]
    assert (client.named_by, client.default) == (NamedBy("~service"), "x")
    assert sink.items == []


def test_python2_script(tmp_path: Path) -> None:
    path = tmp_path / "old.py"
    path.write_text(
        'import rospy\nfrom std_msgs.msg import String\nprint "starting"\n'
        "try:\n    pass\nexcept Exception, e:\n    print e\n"
        'pub = rospy.Publisher("chatter", String)\n'
    )
    sink = DiagnosticSink()
    entries = extract(str(path), sink)
    assert [(e.name, e.type, e.location.line) for e in entries] == [
        ("chatter", "std_msgs/String", 8)
    ]
    assert [d.code for d in sink.items] == ["interface-python2"]


def test_unparsable_script_is_a_diagnostic(tmp_path: Path) -> None:
    path = tmp_path / "broken.py"
    path.write_text("def (:\n")
    sink = DiagnosticSink()
    assert extract(str(path), sink) == [] or sink.items
    assert sink.items


def test_rclpy_node_by_keywords(tmp_path: Path) -> None:
    """rclpy calls with keyword arguments, on a node that is not ``self``."""
    path = tmp_path / "node.py"
    path.write_text(
        "import rclpy\n"
        "import rclpy.action\n"
        "import geometry_msgs.msg\n"
        "node = rclpy.create_node('teleop')\n"
        "node.create_publisher(msg_type=geometry_msgs.msg.Twist, topic='cmd_vel', qos_profile=1)\n"
        "node.create_client(srv_name='~/reset', srv_type=None)\n"
        "rclpy.action.ActionServer(node, action_type=None, action_name='dock')\n"
        "node.declare_parameter(name='speed', value=[1, 2])\n"
    )
    sink = DiagnosticSink()
    found = extract_node(str(path), sink)
    assert found.node_name == "teleop"
    assert [
        (str(e.role), e.name, e.default if e.role is Role.PARAMS else e.type) for e in found.entries
    ] == [
        ("publishes", "cmd_vel", "geometry_msgs/msg/Twist"),
        ("clients", "~/reset", None),
        ("action_servers", "dock", None),
        ("params", "speed", Expression("[1, 2]")),
    ]
    assert [d.code for d in sink.items] == ["interface-unknown-type"] * 2


def test_rclpy_names_read_from_parameters(tmp_path: Path) -> None:
    path = tmp_path / "node.py"
    path.write_text(
        "from rclpy.node import Node\nfrom std_msgs.msg import String\n"
        "class Relay(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('relay')\n"
        "        topic = self.declare_parameter('input', 'chatter').value\n"
        "        self.create_subscription(String, topic, self.cb, 10)\n"
        "        out = self.get_parameter('output').get_parameter_value().string_value\n"
        "        self.create_publisher(String, out, 10)\n"
    )
    entries = extract(str(path), DiagnosticSink())
    named = [(str(e.role), e.name, e.named_by, e.default) for e in entries if e.named_by]
    assert named == [
        ("subscribes", "{input}", NamedBy("input"), "chatter"),
        ("publishes", "{output}", NamedBy("output"), None),
    ]


def test_the_nodes_own_name(tmp_path: Path) -> None:
    """turtlebot3_server: ``SimpleActionServer(rospy.get_name(), ...)`` serves at the node's
    own name, which ``~`` names."""
    path = tmp_path / "server.py"
    path.write_text(
        "import rospy, actionlib\nfrom demo.msg import DoAction\n"
        "actionlib.SimpleActionServer(rospy.get_name(), DoAction, None)\n"
        "rospy.Publisher(rospy.get_name() + '/state', DoAction)\n"
    )
    assert [(str(e.role), e.name) for e in extract(str(path), DiagnosticSink())] == [
        ("action_servers", "~"),
        ("publishes", "~/state"),
    ]


def test_a_dynamic_reconfigure_server_reads_its_namespace(tmp_path: Path) -> None:
    path = tmp_path / "node.py"
    path.write_text(
        "import rospy\nfrom dynamic_reconfigure.server import Server\n"
        "from pkg.cfg import PidConfig\n"
        "Server(PidConfig, None)\nServer(PidConfig, None, namespace='~pid')\n"
    )
    reads = [(e.name, e.default, e.location.line) for e in extract(str(path), DiagnosticSink())]
    assert reads == [("~", RECONFIGURED, 4), ("~pid", RECONFIGURED, 5)]


def test_an_rclpy_lifecycle_node_has_the_lifecycle_interface(tmp_path: Path) -> None:
    """A class deriving from ``rclpy.lifecycle.Node`` (as lifecycle_py's talker): its
    lifecycle publisher, and rcl_lifecycle's transition publisher and services."""
    path = tmp_path / "talker.py"
    path.write_text(
        "from rclpy.lifecycle import Node\nimport std_msgs.msg\n"
        "class Talker(Node):\n"
        "    def __init__(self):\n        super().__init__('lc_talker')\n"
        "    def on_configure(self, state):\n"
        "        self.create_lifecycle_publisher(std_msgs.msg.String, 'lifecycle_chatter', 10)\n"
    )
    extracted = extract_node(str(path), DiagnosticSink())
    assert extracted.node_name == "lc_talker"
    assert [(str(e.role), e.name, e.type, e.location.line) for e in extracted.entries] == [
        ("publishes", "lifecycle_chatter", "std_msgs/msg/String", 7),
        ("publishes", "~/transition_event", "lifecycle_msgs/msg/TransitionEvent", 3),
        ("services", "~/change_state", "lifecycle_msgs/srv/ChangeState", 3),
        ("services", "~/get_state", "lifecycle_msgs/srv/GetState", 3),
        ("services", "~/get_available_states", "lifecycle_msgs/srv/GetAvailableStates", 3),
        (
            "services",
            "~/get_available_transitions",
            "lifecycle_msgs/srv/GetAvailableTransitions",
            3,
        ),
        ("services", "~/get_transition_graph", "lifecycle_msgs/srv/GetAvailableTransitions", 3),
    ]
    path.write_text(path.read_text().replace("rclpy.lifecycle", "rclpy.node"))
    assert [e.name for e in extract_node(str(path), DiagnosticSink()).entries] == [
        "lifecycle_chatter"
    ]
