"""The corpus systems' own nodes, checked by hand against their sources; the CLI's JSON."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rosvar.outputs.cli import main
from rosvar.outputs.commands.exit_codes import EXIT_OK
from rosvar.workspace import discover
from rosvar.workspace.interfaces.extraction import extract_interfaces
from rosvar.workspace.interfaces.model import Interfaces, NodeInterface, NodeKind, Role
from workspace.interfaces.ros2_packages import write_ros2_packages

CORPUS = Path(__file__).resolve().parents[4] / "shared" / "corpus"  # ../shared of the checkout
SCHEMA = Path(__file__).resolve().parents[3] / "docs" / "schema" / "interfaces.schema.json"
needs_corpus = pytest.mark.skipif(not CORPUS.is_dir(), reason="corpus not available")


def _interfaces(system: str) -> Interfaces:
    return extract_interfaces(discover([CORPUS / system], ros_package_path="").packages.values())


@needs_corpus
def test_kobuki_nodelet() -> None:
    node = _interfaces("kobuki").find("kobuki_node", "kobuki_node/KobukiNodelet")
    assert node is not None and node.kind is NodeKind.NODELET
    # kobuki_ros.cpp: init(getPrivateNodeHandle(), getNodeHandle()) → advertiseTopics(nh) etc.
    published = {e.name: e.type for e in node.of(Role.PUBLISHES)}
    assert published == {
        "~joint_states": "sensor_msgs/JointState",
        "~version_info": "kobuki_msgs/VersionInfo",
        "~controller_info": "kobuki_msgs/ControllerInfo",
        **{
            f"~events/{n}": f"kobuki_msgs/{t}Event"
            for n, t in [
                ("button", "Button"),
                ("bumper", "Bumper"),
                ("cliff", "Cliff"),
                ("wheel_drop", "WheelDrop"),
                ("power_system", "PowerSystem"),
                ("digital_input", "DigitalInput"),
                ("robot_state", "RobotState"),
            ]
        },
        "~sensors/core": "kobuki_msgs/SensorState",
        "~sensors/dock_ir": "kobuki_msgs/DockInfraRed",
        "~sensors/imu_data": "sensor_msgs/Imu",
        "~sensors/imu_data_raw": "sensor_msgs/Imu",
        "~debug/raw_data_command": "std_msgs/String",
        "~debug/raw_data_stream": "std_msgs/String",
        "~debug/raw_control_command": "std_msgs/Int16MultiArray",
        "~odom": "nav_msgs/Odometry",  # odometry.cpp, Odometry::init(nh, name)
        "/tf": "tf2_msgs/TFMessage",  # odometry.hpp, a tf::TransformBroadcaster member
    }
    assert [e.boundary for e in node.of(Role.PUBLISHES) if e.name == "/tf"] == [True]
    subscribed = {e.name: e.type for e in node.of(Role.SUBSCRIBES)}
    assert subscribed["~commands/velocity"] == "geometry_msgs/Twist"
    assert subscribed["~commands/reset_odometry"] == "std_msgs/Empty"
    assert len(subscribed) == 9
    params = {e.name: e.default for e in node.of(Role.PARAMS)}
    assert params["~acceleration_limiter"] is False
    assert params["~wheel_left_joint_name"] == "wheel_left_joint"
    assert params["~cmd_vel_timeout"] == 0.6
    assert "~device_port" in params and params["~device_port"] is None
    assert "robot_description" in params  # read on getNodeHandle(), the public one
    joint_states = node.of(Role.PUBLISHES)[0]
    assert joint_states.location.file.endswith("src/library/kobuki_ros.cpp")
    assert joint_states.location.line == 308
    assert all(e.static for e in node.entries)


@needs_corpus
def test_lizi_hardware_node() -> None:
    node = _interfaces("lizi").find("lizi_hw", "lizi_hw_node")
    assert node is not None
    # lizi_hw_node.cpp: NodeHandle nh; LiziHW(nh) → ric_(nh) → RicBoard(nh) → wheels_control_.init
    published = {e.name: e.type for e in node.of(Role.PUBLISHES)}
    assert published["/espeak_node/speak_line"] == "std_msgs/String"
    assert published["imu/data"] == "sensor_msgs/Imu"
    assert published["wheels_pid"] == "lizi_hw/WheelsPID"
    assert {e.name for e in node.of(Role.CLIENTS)} == {"terminate_ric"}
    assert "lpf/front_right" in {e.name for e in node.of(Role.PARAMS)}


@needs_corpus
def test_kobuki_python_script() -> None:
    node = _interfaces("kobuki").find("kobuki_auto_docking", "getDockIR.py")
    assert node is not None
    assert [(e.name, e.type) for e in node.of(Role.SUBSCRIBES)] == [
        ("/mobile_base/sensors/dock_ir", "kobuki_msgs/DockInfraRed"),
        ("/mobile_base/sensors/core", "kobuki_msgs/SensorState"),
    ]
    assert [(e.name, e.default) for e in node.of(Role.PARAMS)] == [
        ("~window", 10),
        ("~oneline", False),
    ]


@needs_corpus
def test_cli_json_matches_schema(capsys: pytest.CaptureFixture[str]) -> None:
    jsonschema = pytest.importorskip("jsonschema")
    assert main(["interfaces", str(CORPUS / "kobuki"), "--json"]) == EXIT_OK
    document = json.loads(capsys.readouterr().out)
    jsonschema.validate(document, json.loads(SCHEMA.read_text()))
    nodelets = [n for n in document["interfaces"] if n["kind"] == "nodelet"]
    assert {n["package"] for n in nodelets} >= {"kobuki_node", "kobuki_safety_controller"}
    symbolic = [e for n in document["interfaces"] for r in ("action_servers",) for e in n[r]]
    assert any(e.get("static") is False for e in symbolic)  # {name_}_action: the nodelet's name
    assert any(d["code"] == "interface-symbolic-name" for d in document["diagnostics"])


def _summary(node: NodeInterface) -> list[tuple[str, str, object, int]]:
    """Each entry as (role, name, type or default, line)."""
    return [
        (str(e.role), e.name, e.default if e.role is Role.PARAMS else e.type, e.location.line)
        for e in node.entries
    ]


def test_ros2_packages(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """rclcpp and rclpy nodes, a component and the executable registered from it, each with
    the name its code gives the node."""
    write_ros2_packages(tmp_path)
    interfaces = extract_interfaces(discover([tmp_path]).packages.values())
    found = {(n.package, n.executable, n.kind, n.node_name): _summary(n) for n in interfaces.nodes}
    camera = [
        ("publishes", "image_raw", "sensor_msgs/msg/Image", 5),
        ("publishes", "camera_info", "sensor_msgs/msg/CameraInfo", 5),
        ("services", "enable", "std_srvs/srv/SetBool", 6),
        ("subscribes", "mask", "sensor_msgs/msg/Image", 8),
    ]
    assert found == {
        ("demo_cpp", "camera", NodeKind.NODE, "camera"): camera,
        ("demo_cpp", "demo_cpp::Camera", NodeKind.COMPONENT, "camera"): camera,
        ("demo_cpp", "talker", NodeKind.NODE, "talker"): [
            ("publishes", "chatter", "std_msgs/msg/String", 8),
            ("subscribes", "~/control", "std_msgs/msg/String", 9),
            ("params", "rate", 2.5, 11),
            ("action_servers", "fibonacci", "action_tutorials_interfaces/action/Fibonacci", 14),
            ("clients", "/reset", "std_srvs/srv/Trigger", 19),
            ("params", "frame", None, 13),  # read, never declared
        ],
        ("demo_py", "listener", NodeKind.NODE, "listener"): [
            ("subscribes", "chatter", "std_msgs/msg/String", 14),
            ("publishes", "~/echo", "std_msgs/msg/String", 15),
            ("services", "reset", "std_srvs/srv/Trigger", 16),
            ("action_clients", "/fibonacci", "action_tutorials_interfaces/action/Fibonacci", 17),
            ("params", "gain", 0.5, 18),
        ],
    }
    assert interfaces.diagnostics == []
    jsonschema = pytest.importorskip("jsonschema")
    assert main(["interfaces", str(tmp_path), "--json"]) == EXIT_OK
    document = json.loads(capsys.readouterr().out)
    jsonschema.validate(document, json.loads(SCHEMA.read_text()))
    assert {n["executable"]: n.get("node_name") for n in document["interfaces"]} == {
        "camera": "camera",
        "demo_cpp::Camera": "camera",
        "talker": "talker",
        "listener": "listener",
    }


def test_a_ros1_node_has_no_name_of_its_own(tmp_path: Path) -> None:
    """roslaunch always names a node: the code's ``init_node`` name is not the node's."""
    write_ros2_packages(tmp_path)
    manifest = tmp_path / "demo_cpp" / "package.xml"
    manifest.write_text(manifest.read_text().replace("ament_cmake", "catkin"))
    (tmp_path / "demo_py").rename(tmp_path.parent / "elsewhere")
    interfaces = extract_interfaces(discover([tmp_path]).packages.values())
    assert {n.executable: n.node_name for n in interfaces.nodes} == {"camera": None, "talker": None}
