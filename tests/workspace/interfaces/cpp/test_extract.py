"""C++ extraction: handles followed through constructors, members, parameters, constants."""

from __future__ import annotations

from pathlib import Path

from rosvar.diagnostics import Diagnostic, DiagnosticSink, Location
from rosvar.workspace.interfaces.cpp.extract import extract_node
from rosvar.workspace.interfaces.cpp.ros_types import ros_type
from rosvar.workspace.interfaces.cpp.unit import Unit
from rosvar.workspace.interfaces.model import ANY_PARAMETER, Entry, Expression, NamedBy, Role

NODE = """\
#include "talker.h"
const std::string TOPIC = "chatter";
#define SERVICE "reset"

void Talker::setup(ros::NodeHandle& n) {
  sub_ = n.subscribe(TOPIC + "/in", 1, &Talker::onTwist, this);
  n.param("rate", rate_, 10.0);
}

int main(int argc, char** argv) {
  ros::NodeHandle nh("~");
  ros::NodeHandle ns(nh, "ns");
  ros::Publisher pub = nh.advertise<std_msgs::String>("out", 1);
  Talker talker;
  talker.setup(ns);
  nh.param<std::string>("frame", frame, std::string("base_link"));
  ros::param::get("/global", value);
  image_transport::ImageTransport it(nh);
  it.advertiseCamera("camera/image_raw", 1);
  actionlib::SimpleActionClient<move_base_msgs::MoveBaseAction> ac("move_base", true);
  ros::NodeHandle().advertiseService(SERVICE, &Talker::onReset, &talker);
  nh.serviceClient<std_srvs::Empty>(name_);
}

void unused(ros::NodeHandle& nh) { nh.advertise<std_msgs::Empty>("never", 1); }
"""
HEADER = """\
class Talker {
 public:
  void setup(ros::NodeHandle& n);
  void onTwist(const geometry_msgs::Twist::ConstPtr& msg);
  bool onReset(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
};
"""

NODELET = """\
class Camera : public nodelet::Nodelet {
  ros::NodeHandle nh_;
  message_filters::Subscriber<sensor_msgs::Image> image_sub_;
  boost::shared_ptr<actionlib::SimpleActionServer<control_msgs::FollowJointTrajectoryAction>> as_;
  void onInit() {
    nh_ = getPrivateNodeHandle();
    image_sub_.subscribe(nh_, "image", 1);
    as_.reset(new actionlib::SimpleActionServer<control_msgs::FollowJointTrajectoryAction>(
        getNodeHandle(), "follow", false));
  }
};
class Other : public nodelet::Nodelet {
  void onInit() { getNodeHandle().advertise<std_msgs::Empty>("other", 1); }
};
"""


def _extract(
    tmp_path: Path, files: dict[str, str], entry: str, owner: str | None = None
) -> tuple[list[Entry], list[Diagnostic]]:
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    sources = [str(tmp_path / name) for name in files if name.endswith(".cpp")]
    sink = DiagnosticSink()
    where = Location("CMakeLists.txt")
    entries = extract_node(Unit.load(sources, []), entry, owner, sink, where).entries
    return entries, sink.items


def _summary(entries: list[Entry]) -> list[tuple[str, str, object, int]]:
    return [
        (str(e.role), e.name, e.default if e.role is Role.PARAMS else e.type, e.location.line)
        for e in entries
    ]


def test_executable_interface(tmp_path: Path) -> None:
    entries, diagnostics = _extract(tmp_path, {"talker.cpp": NODE, "talker.h": HEADER}, "main")
    assert _summary(entries) == [
        ("subscribes", "~ns/chatter/in", "geometry_msgs/Twist", 6),
        ("params", "~ns/rate", 10.0, 7),
        ("publishes", "~out", "std_msgs/String", 13),
        ("params", "~frame", "base_link", 16),
        ("params", "/global", Expression("value"), 17),
        ("publishes", "~camera/image_raw", "sensor_msgs/Image", 19),
        ("publishes", "~camera/camera_info", "sensor_msgs/CameraInfo", 19),
        ("action_clients", "move_base", "move_base_msgs/MoveBase", 20),
        ("services", "reset", "std_srvs/Trigger", 21),
        ("clients", "~{name_}", "std_srvs/Empty", 22),
    ]
    symbolic = [e for e in entries if not e.static]
    assert [e.name for e in symbolic] == ["~{name_}"]
    assert [(d.code, d.location.line) for d in diagnostics] == [("interface-symbolic-name", 22)]


def test_nodelet_class_only(tmp_path: Path) -> None:
    entries, _ = _extract(tmp_path, {"camera.cpp": NODELET}, "onInit", "Camera")
    assert _summary(entries) == [
        ("subscribes", "~image", "sensor_msgs/Image", 7),
        ("action_servers", "follow", "control_msgs/FollowJointTrajectory", 8),
    ]
    other, _ = _extract(tmp_path, {"camera.cpp": NODELET}, "onInit", "Other")
    assert _summary(other) == [("publishes", "other", "std_msgs/Empty", 13)]


def test_parameter_bound_differently_stays_symbolic(tmp_path: Path) -> None:
    source = """\
void setup(ros::NodeHandle& n) { n.advertise<std_msgs::Empty>("x", 1); }
int main() {
  ros::NodeHandle a("~"), b;
  setup(a);
  setup(b);
}
"""
    entries, diagnostics = _extract(tmp_path, {"n.cpp": source}, "main")
    assert [(e.name, e.static) for e in entries] == [("{n}/x", False)]
    assert [d.code for d in diagnostics] == ["interface-symbolic-name"]


def test_missing_entry_reads_everything(tmp_path: Path) -> None:
    source = 'void f(ros::NodeHandle& n) { n.getParam("p", x); }\n'
    entries, diagnostics = _extract(tmp_path, {"f.cpp": source}, "main")
    assert [e.name for e in entries] == ["{n}/p"]
    assert "interface-no-entry" in [d.code for d in diagnostics]
    assert entries[0].default == Expression("x")  # dropped: x keeps its value


def test_default_expression_kept_as_written(tmp_path: Path) -> None:
    source = 'int main() { ros::NodeHandle nh; nh.param("cap", c, Battery::capacity); }\n'
    entries, _ = _extract(tmp_path, {"m.cpp": source}, "main")
    assert entries[0].default == Expression("Battery::capacity")


def test_ros_type() -> None:
    assert ros_type("const sensor_msgs::ImageConstPtr&") == "sensor_msgs/Image"
    assert ros_type("boost::shared_ptr<const nav_msgs::Odometry>") == "nav_msgs/Odometry"
    assert ros_type("std_srvs::Empty::Request &") == "std_srvs/Empty"
    assert ros_type("int (*)(void)") is None


def test_callback_type_through_typedef(tmp_path: Path) -> None:
    source = """\
typedef boost::shared_ptr<sensor_msgs::JointState const> StatePtr;
using Command = std_msgs::Float64;
void onState(const StatePtr& state) {}
int main() {
  ros::NodeHandle nh;
  nh.subscribe("joint_states", 1, &onState);
  nh.advertise<Command>("command", 1);
}
"""
    entries, _ = _extract(tmp_path, {"t.cpp": source}, "main")
    assert [(e.name, e.type) for e in entries] == [
        ("joint_states", "sensor_msgs/JointState"),
        ("command", "std_msgs/Float64"),
    ]


GMAPPING = """\
#include "slam.h"
Slam::Slam() : private_nh_("~") { init(); }
Slam::Slam(ros::NodeHandle& nh, ros::NodeHandle& pnh) : node_(nh), private_nh_(pnh) { init(); }
void Slam::init() { private_nh_.getParam("throttle_scans", throttle_); }
int main(int argc, char** argv) { Slam gn; return 0; }
class SlamNodelet : public nodelet::Nodelet {
  void onInit() { slam_.reset(new Slam(getNodeHandle(), getPrivateNodeHandle())); }
};
"""
GMAPPING_HEADER = """\
class Slam {
 public:
  Slam();
  Slam(ros::NodeHandle& nh, ros::NodeHandle& pnh);
  void init();
  ros::NodeHandle node_;
  ros::NodeHandle private_nh_;
};
"""


def test_member_initialiser_of_the_constructor_called(tmp_path: Path) -> None:
    """slam_gmapping: the class is declared in a header read after the constructors, and
    only the constructor that the node (``Slam gn;``) or the nodelet (``new Slam(nh, pnh)``)
    calls initialises the handle."""
    files = {"slam.cpp": GMAPPING, "slam.h": GMAPPING_HEADER}
    for entry, owner in (("main", None), ("onInit", "SlamNodelet")):
        entries, diagnostics = _extract(tmp_path, files, entry, owner)
        assert [(e.name, e.static) for e in entries] == [("~throttle_scans", True)], entry
        assert diagnostics == []


def test_action_server_through_typedef(tmp_path: Path) -> None:
    """move_base: ``typedef actionlib::SimpleActionServer<...> MoveBaseActionServer``."""
    source = """\
typedef actionlib::SimpleActionServer<move_base_msgs::MoveBaseAction> MoveBaseActionServer;
int main(int argc, char** argv) {
  MoveBaseActionServer* as = new MoveBaseActionServer(ros::NodeHandle(), "move_base", false);
}
"""
    entries, _ = _extract(tmp_path, {"m.cpp": source}, "main")
    assert [(e.role, e.name, e.type) for e in entries] == [
        (Role.ACTION_SERVERS, "move_base", "move_base_msgs/MoveBase")
    ]


def test_handles_through_pointers_resets_and_aliased_constructors(tmp_path: Path) -> None:
    """Patterns of image_pipeline (``it_.reset(new ImageTransport(nh))``), teleop_twist_joy
    (``Teleop t(&nh, &pnh)``), robot_localization (``typedef Filter<Ekf> RosEkf``, a
    delegating constructor, a default argument) and move_base (a pointer member initialised
    to ``NULL``)."""
    source = """\
template<class T> class Filter {
 public:
  Filter(ros::NodeHandle nh, ros::NodeHandle* pnh);
  Filter(ros::NodeHandle nh, ros::NodeHandle* pnh, int depth, int more = 0);
  ros::NodeHandle nh_;
  boost::shared_ptr<image_transport::ImageTransport> it_;
  actionlib::SimpleActionServer<move_base_msgs::MoveBaseAction>* as_;
};
typedef Filter<Ekf> RosEkf;
template<class T> Filter<T>::Filter(ros::NodeHandle nh, ros::NodeHandle* pnh)
    : Filter<T>::Filter(nh, pnh, 1) {}
template<class T> Filter<T>::Filter(ros::NodeHandle nh, ros::NodeHandle* pnh, int depth, int more)
    : nh_(nh), as_(NULL) {
  it_.reset(new image_transport::ImageTransport(nh_));
  it_->advertise("image", 1);
  pnh->advertise<std_msgs::Empty>("private", 1);
  nh_.subscribe<nav_msgs::Odometry>("odom", 1, &Filter::odom, this);
}
int main(int argc, char** argv) {
  ros::NodeHandle nh("ns"), pnh("~");
  ns::RosEkf ekf(nh, &pnh);
}
"""
    entries, diagnostics = _extract(tmp_path, {"f.cpp": source}, "main")
    assert sorted((str(e.role), e.name) for e in entries) == [
        ("publishes", "ns/image"),
        ("publishes", "~private"),
        ("subscribes", "ns/odom"),
    ]
    assert diagnostics == []


def test_nodelets_of_one_library_sharing_method_names(tmp_path: Path) -> None:
    """image_proc: every nodelet class has its own ``connectCb``; an unqualified call or
    ``&Class::connectCb`` inside a method means that class's."""
    source = """\
class Rectify : public nodelet::Nodelet {
  void onInit() { cb_ = boost::bind(&Rectify::connectCb, this); connectCb(); }
  void connectCb() { getNodeHandle().subscribe<sensor_msgs::Image>("image_mono", 1); }
};
class Resize : public nodelet::Nodelet {
  void onInit() { connectCb(); }
  void connectCb() { getNodeHandle().subscribe<sensor_msgs::Image>("image", 1); }
};
"""
    for owner, topic in (("Rectify", "image_mono"), ("Resize", "image")):
        entries, _ = _extract(tmp_path, {"n.cpp": source}, "onInit", owner)
        assert [e.name for e in entries] == [topic]


def test_names_resolved_by_the_node(tmp_path: Path) -> None:
    """image_transport's republish (``nh.resolveName("in")``) and imu_filter_madgwick
    (``ros::names::resolve("imu") + "/data"``): the name as the node would use it."""
    source = """\
int main(int argc, char** argv) {
  ros::NodeHandle nh, pnh("~");
  std::string in_topic = nh.resolveName("in");
  nh.subscribe<sensor_msgs::Image>(in_topic, 1);
  pnh.advertise<sensor_msgs::Imu>(pnh.resolveName("out"), 1);
  nh.advertise<sensor_msgs::Imu>(ros::names::resolve("imu") + "/data", 1);
}
"""
    entries, diagnostics = _extract(tmp_path, {"r.cpp": source}, "main")
    assert sorted((str(e.role), e.name) for e in entries) == [
        ("publishes", "imu/data"),
        ("publishes", "~out"),
        ("subscribes", "in"),
    ]
    assert diagnostics == []


def test_variables_written_by_parameter_reads(tmp_path: Path) -> None:
    """robot_localization: ``std::string path = ""; nh.searchParam("tf_prefix", path);
    nh.getParam(path, prefix)`` reads a parameter whose name is only known at run time; a
    topic initialised and then read from a parameter is named by the parameter, its
    initialiser the default."""
    source = """\
int main(int argc, char** argv) {
  ros::NodeHandle nh("~");
  std::string path = "", topic = "scan", fixed = "odom";
  if (nh.searchParam("tf_prefix", path)) { nh.getParam(path, prefix); }
  nh.param("topic", topic, topic);
  nh.subscribe<sensor_msgs::LaserScan>(topic, 1);
  nh.subscribe<nav_msgs::Odometry>(fixed, 1);
}
"""
    entries, _ = _extract(tmp_path, {"p.cpp": source}, "main")
    assert [
        (e.name, e.static, e.named_by, e.default) for e in entries if e.role is not Role.PARAMS
    ] == [
        ("~{~topic}", False, NamedBy("~topic", "~"), "scan"),
        ("~odom", True, None, None),
    ]
    assert [e.name for e in entries if e.role is Role.PARAMS] == ["~{path}", "~topic"]


def test_a_tested_read_has_the_code_as_default(tmp_path: Path) -> None:
    """slam_gmapping: ``if(!private_nh_.getParam("throttle_scans", t)) t = 1;`` handles an
    unset parameter; so does a read whose result is dropped (topic_tools' relay:
    ``pnh.getParam("lazy", g_lazy);`` leaves ``g_lazy`` as it was); one whose unset branch
    fails does not."""
    source = """\
int main(int argc, char** argv) {
  ros::NodeHandle nh("~");
  if (!nh.getParam("throttle_scans", throttle)) throttle = 1;
  bool ok = nh.getParam("frame", frame) && nh.getParam("rate", rate);
  nh.getParam("port", port);
  if (!nh.getParam("device", device)) { ROS_ERROR_STREAM("no device"); }
  if (nh.getParam("baud", baud)) { use(baud); } else { return false; }
}
"""
    entries, _ = _extract(tmp_path, {"g.cpp": source}, "main")
    assert [(e.name, e.default) for e in entries] == [
        ("~throttle_scans", Expression('!nh.getParam("throttle_scans", throttle)')),
        ("~frame", Expression('nh.getParam("frame", frame) && nh.getParam("rate", rate)')),
        ("~rate", Expression('nh.getParam("frame", frame) && nh.getParam("rate", rate)')),
        ("~port", Expression("port")),
        ("~device", None),  # kobuki_node: required, the unset branch fails
        ("~baud", None),
    ]


def test_defaults_of_guarded_and_initialised_reads(tmp_path: Path) -> None:
    """topic_tools' relay (``bool unreliable = false; pnh.getParam("unreliable",
    unreliable);``) and robot_localization (``if (nh.hasParam("x")) nh.getParam("x", v);``)."""
    source = """\
bool g_lazy = false;
int main(int argc, char** argv) {
  ros::NodeHandle pnh("~");
  bool unreliable = false;
  pnh.getParam("unreliable", unreliable);
  pnh.getParam("lazy", g_lazy);
  XmlRpc::XmlRpcValue config;
  if (pnh.hasParam("process_noise_covariance")) {
    pnh.getParam("process_noise_covariance", config);
  }
}
"""
    entries, _ = _extract(tmp_path, {"d.cpp": source}, "main")
    assert [(e.name, e.default) for e in entries] == [
        ("~unreliable", False),
        ("~lazy", False),
        ("~process_noise_covariance", Expression('(pnh.hasParam("process_noise_covariance"))')),
    ]


def test_controller_manager_services(tmp_path: Path) -> None:
    """husky_base: ``controller_manager::ControllerManager cm(&husky, nh)`` serves what
    ``controller_manager/spawner`` calls; lizi_hw omits the handle."""
    source = """\
int main(int argc, char** argv) {
  ros::NodeHandle nh, private_nh("~");
  controller_manager::ControllerManager cm(&husky, nh);
  controller_manager::ControllerManager other(&lizi);
}
"""
    entries, _ = _extract(tmp_path, {"c.cpp": source}, "main")
    services = [(e.name, e.type) for e in entries if e.role is Role.SERVICES]
    assert len(services) == 12
    assert services[2] == (
        "controller_manager/load_controller",
        "controller_manager_msgs/LoadController",
    )
    assert (
        "controller_manager/reload_controller_libraries",
        "controller_manager_msgs/ReloadControllerLibraries",
    ) in services[6:]


def test_ros2_controller_manager_is_no_ros1_one(tmp_path: Path) -> None:
    """ros2_control_node builds ``ControllerManager(executor, name)``, a node that makes its
    own services: ros_control's rule (services below ``controller_manager`` of a node
    handle) does not apply."""
    source = """\
int main(int argc, char** argv) {
  std::string manager_node_name = "controller_manager";
  auto cm = std::make_shared<controller_manager::ControllerManager>(executor, manager_node_name);
  controller_manager::ControllerManager ros1(&robot, nh);
}
"""
    (tmp_path / "c.cpp").write_text(source)
    unit = Unit.load([str(tmp_path / "c.cpp")], [])
    where = Location("CMakeLists.txt")
    ros2 = extract_node(unit, "main", None, DiagnosticSink(), where, ros2=True).entries
    ros1 = extract_node(unit, "main", None, DiagnosticSink(), where).entries
    assert ros2 == []
    assert len(ros1) == 12  # the same source read as ROS 1: both constructions serve


def test_service_type_from_a_request_typedef(tmp_path: Path) -> None:
    """openni2_camera: ``getSerialCb(openni2_camera::GetSerialRequest& req, ...)``."""
    source = """\
bool getSerialCb(openni2_camera::GetSerialRequest& req, openni2_camera::GetSerialResponse& res);
int main(int argc, char** argv) {
  ros::NodeHandle nh;
  nh.advertiseService("get_serial", &getSerialCb);
}
"""
    entries, _ = _extract(tmp_path, {"s.cpp": source}, "main")
    assert [(e.name, e.type) for e in entries] == [("get_serial", "openni2_camera/GetSerial")]


def test_ros2_types() -> None:
    assert ros_type("std_msgs::msg::String::SharedPtr") == "std_msgs/msg/String"
    assert ros_type("const std::shared_ptr<std_srvs::srv::Trigger::Request>") == (
        "std_srvs/srv/Trigger"
    )
    assert ros_type("nav2_msgs::action::NavigateToPose") == "nav2_msgs/action/NavigateToPose"


def test_rclcpp_node_built_in_main(tmp_path: Path) -> None:
    """A plain ``rclcpp::Node`` built in ``main``: its name, its methods through the
    pointer, the older action API (the node's four interfaces), an image transport on it."""
    source = """\
int main(int argc, char** argv) {
  auto node = rclcpp::Node::make_shared("driver");
  auto pub = node->create_publisher<sensor_msgs::msg::Imu>("imu/data", rclcpp::SensorDataQoS());
  double hz = node->get_parameter_or("hz", hz, 50.0);
  auto client = rclcpp_action::create_client<nav2_msgs::action::NavigateToPose>(
      node->get_node_base_interface(), node->get_node_graph_interface(),
      node->get_node_logging_interface(), node->get_node_waitables_interface(), "navigate");
  image_transport::ImageTransport it(node);
  auto sub = it.subscribe("camera/image", 1, callback);
}
"""
    sink = DiagnosticSink()
    (tmp_path / "m.cpp").write_text(source)
    found = extract_node(Unit.load([str(tmp_path / "m.cpp")], []), "main", None, sink, Location(""))
    assert found.node_name == "driver"
    assert _summary(found.entries) == [
        ("publishes", "imu/data", "sensor_msgs/msg/Imu", 3),
        ("action_clients", "navigate", "nav2_msgs/action/NavigateToPose", 5),
        ("subscribes", "camera/image", "sensor_msgs/msg/Image", 9),
        ("params", "hz", 50.0, 4),  # reads of undeclared parameters come last
    ]


def test_two_rclcpp_nodes_leave_the_name_open(tmp_path: Path) -> None:
    source = """\
int main() {
  auto a = std::make_shared<rclcpp::Node>("a");
  rclcpp::Node b("b");
  b.create_publisher<std_msgs::msg::Empty>("~/x", 1);
}
"""
    sink = DiagnosticSink()
    (tmp_path / "m.cpp").write_text(source)
    found = extract_node(Unit.load([str(tmp_path / "m.cpp")], []), "main", None, sink, Location(""))
    assert found.node_name is None
    assert [(e.name, e.type) for e in found.entries] == [("~/x", "std_msgs/msg/Empty")]


def test_parameters_handed_to_other_code_are_not_all_known(tmp_path: Path) -> None:
    """laser_filters gives its node's parameters interface to a filter chain, which declares
    ``filter1.name`` and the rest: the node takes parameters its sources never declare."""
    source = """\
class Chain : public rclcpp::Node {
 public:
  Chain() : Node("chain") {
    declare_parameter("tf_message_filter_target_frame", "");
    chain_.configure("", get_node_logging_interface(), get_node_parameters_interface());
  }
};
int main(int argc, char** argv) { rclcpp::spin(std::make_shared<Chain>()); }
"""
    sink = DiagnosticSink()
    (tmp_path / "m.cpp").write_text(source)
    unit = Unit.load([str(tmp_path / "m.cpp")], [])
    found = extract_node(unit, "main", None, sink, Location(""), ros2=True)
    params = [(e.name, e.static, e.location.line) for e in found.entries if e.role is Role.PARAMS]
    assert params == [("tf_message_filter_target_frame", True, 4), (ANY_PARAMETER, False, 5)]
