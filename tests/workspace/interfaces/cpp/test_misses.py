"""The classes of misses issue 29 found in real repositories, each on a small inline source:
lifecycle nodes, the project's own wrappers, names given to constructors of class
templates, a project method called like the API, a linked library's other classes,
``resolveName``, message_filters in ROS 2, ``waitForMessage``, tf's broadcasters and
listeners, and names that are parameters' values."""

from __future__ import annotations

from pathlib import Path

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.workspace.interfaces.cpp.extract import extract_node
from rosvar.workspace.interfaces.cpp.unit import Unit
from rosvar.workspace.interfaces.lifecycle import LIFECYCLE_USES
from rosvar.workspace.interfaces.model import RECONFIGURED, Entry, Expression, NamedBy, Role


def _entries(
    tmp_path: Path, source: str, entry: str = "main", owner: str | None = None, ros2: bool = True
) -> list[Entry]:
    (tmp_path / "node.cpp").write_text(source)
    unit = Unit.load([str(tmp_path / "node.cpp")], [])
    where = Location("CMakeLists.txt")
    return extract_node(unit, entry, owner, DiagnosticSink(), where, ros2).entries


def _uses(entries: list[Entry]) -> list[tuple[str, str, str | None, int]]:
    return [
        (str(e.role), e.name, e.type, e.location.line) for e in entries if e.role is not Role.PARAMS
    ]


def test_a_lifecycle_node_makes_its_interfaces_in_its_transitions(tmp_path: Path) -> None:
    source = """\
class MapServer : public nav2_util::LifecycleNode {
 public:
  MapServer() : nav2_util::LifecycleNode("map_server") {}
  CallbackReturn on_configure(const State &) {
    pub_ = create_publisher<nav_msgs::msg::OccupancyGrid>("map", 1);
    return CallbackReturn::SUCCESS;
  }
  CallbackReturn on_activate(const State &) {
    srv_ = create_service<std_srvs::srv::Trigger>(get_name() + std::string("/ready"), cb);
  }
};
class Unused : public nav2_util::LifecycleNode {
  CallbackReturn on_configure(const State &) { create_publisher<X>("never", 1); }
};
int main() { auto node = std::make_shared<MapServer>(); node->on_configure(state); }
"""
    uses = _uses(_entries(tmp_path, source))
    assert uses[:2] == [
        ("publishes", "map", "nav_msgs/msg/OccupancyGrid", 5),
        ("services", "~/ready", "std_srvs/srv/Trigger", 9),
    ]
    # the base's initializer (line 3) makes it a lifecycle node, with rcl_lifecycle's interface
    assert uses[2:] == [(str(role), name, kind, 3) for role, name, kind in LIFECYCLE_USES]


def test_the_projects_own_wrappers_give_one_use_per_call(tmp_path: Path) -> None:
    """A wrapper around the API (with a template type parameter) called with several names,
    and a project method that is itself called ``create_publisher``."""
    source = """\
template <typename T>
void make_pub(rclcpp::Node::SharedPtr node, const std::string & topic) {
  node->create_publisher<T>(topic, 10);
}
class Driver : public rclcpp::Node {
 public:
  Driver() : Node("driver") {
    make_pub<sensor_msgs::msg::Imu>(node_, "imu");
    make_pub<sensor_msgs::msg::LaserScan>(node_, "scan");
    create_publisher("status");
  }
  void create_publisher(const std::string & name) {
    status_ = rclcpp::Node::create_publisher<std_msgs::msg::String>(name, 1);
  }
};
int main() { rclcpp::spin(std::make_shared<Driver>()); }
"""
    assert _uses(_entries(tmp_path, source)) == [
        ("publishes", "imu", "sensor_msgs/msg/Imu", 8),
        ("publishes", "scan", "sensor_msgs/msg/LaserScan", 9),
        ("publishes", "status", "std_msgs/msg/String", 13),  # one call: the API's line
    ]


def test_names_given_to_constructors_of_class_templates(tmp_path: Path) -> None:
    """A ``TwistSubscriber`` given ``cmd_vel``; a service client wrapper given its name and
    type: each construction is one use, typed by its template argument."""
    source = """\
class TwistSubscriber {
 public:
  TwistSubscriber(rclcpp::Node::SharedPtr node, const std::string & topic) : topic_(topic) {
    sub_ = node->create_subscription<geometry_msgs::msg::Twist>(topic_, 1, cb);
  }
  std::string topic_;
};
template <class ServiceT>
class ServiceClient {
 public:
  ServiceClient(const std::string & name, rclcpp::Node::SharedPtr node) {
    client_ = node->create_client<ServiceT>(name);
  }
};
int main() {
  auto node = std::make_shared<rclcpp::Node>("smoother");
  auto twist = std::make_unique<TwistSubscriber>(node, "cmd_vel");
  auto other = std::make_unique<TwistSubscriber>(node, "cmd_vel_teleop");
  ServiceClient<std_srvs::srv::Trigger> reset("reset", node);
  auto load = std::make_shared<ServiceClient<nav2_msgs::srv::LoadMap>>("load_map", node);
}
"""
    assert sorted(_uses(_entries(tmp_path, source))) == [
        ("clients", "load_map", "nav2_msgs/srv/LoadMap", 20),
        ("clients", "reset", "std_srvs/srv/Trigger", 19),
        ("subscribes", "cmd_vel", "geometry_msgs/msg/Twist", 17),
        ("subscribes", "cmd_vel_teleop", "geometry_msgs/msg/Twist", 18),
    ]


def test_a_linked_librarys_other_classes_are_not_credited(tmp_path: Path) -> None:
    """The executable builds a ``Saver``; ``Server`` shares its method names (``on_configure``,
    ``init``) but nothing constructs it."""
    source = """\
class Saver : public rclcpp_lifecycle::LifecycleNode {
  CallbackReturn on_configure(const State &) { create_service<nav2_msgs::srv::SaveMap>("save"); }
  void init() { create_publisher<std_msgs::msg::Empty>("saved", 1); }
};
class Server : public rclcpp_lifecycle::LifecycleNode {
  CallbackReturn on_configure(const State &) { create_publisher<nav_msgs::msg::Path>("map", 1); }
  void init() { create_publisher<std_msgs::msg::Empty>("served", 1); }
};
int main() {
  auto saver = std::make_shared<Saver>();
  saver->on_configure(state);
  saver->init();
}
"""
    assert [name for _, name, _, _ in _uses(_entries(tmp_path, source))] == ["save", "saved"]


def test_a_resolved_name_is_not_put_in_a_namespace_again(tmp_path: Path) -> None:
    source = """\
int main() {
  ros::NodeHandle nh;
  ros::NodeHandle depth(nh, "depth");
  image_transport::ImageTransport it(depth);
  std::string image = depth.resolveName("image");
  ros::Publisher pub = depth.advertise<sensor_msgs::Image>(image, 1);
}
"""
    assert _uses(_entries(tmp_path, source, ros2=False)) == [
        ("publishes", "depth/image", "sensor_msgs/Image", 6)
    ]


def test_waiting_filters_and_tf(tmp_path: Path) -> None:
    ros1 = """\
class Node {
 public:
  Node() : sub_(nh_, "points", 1), listener_(buffer_) {
    auto first = ros::topic::waitForMessage<sensor_msgs::CameraInfo>("camera_info", nh_);
  }
  ros::NodeHandle nh_;
  message_filters::Subscriber<sensor_msgs::PointCloud2> sub_;
  tf::TransformBroadcaster broadcaster_;
  tf2_ros::TransformListener listener_;
};
int main() { Node node; }
"""
    entries = _entries(tmp_path, ros1, ros2=False)
    assert sorted(_uses(entries)) == [
        ("publishes", "/tf", "tf2_msgs/TFMessage", 8),
        ("subscribes", "/tf", "tf2_msgs/TFMessage", 3),
        ("subscribes", "/tf_static", "tf2_msgs/TFMessage", 3),
        ("subscribes", "camera_info", "sensor_msgs/CameraInfo", 4),
        ("subscribes", "points", "sensor_msgs/PointCloud2", 3),
    ]
    assert [e.boundary for e in entries if e.role is Role.PUBLISHES] == [True]
    # a listener's /tf_static may stay empty (no static transform); its /tf may not
    listened = {e.name: e.boundary for e in entries if e.role is Role.SUBSCRIBES}
    assert (listened["/tf"], listened["/tf_static"]) == (False, True)
    ros2 = """\
class Node : public rclcpp::Node {
 public:
  Node() : rclcpp::Node("n") {
    sub_.subscribe(this, "image");
    info_ = std::make_shared<message_filters::Subscriber<sensor_msgs::msg::Imu>>(this, "info");
    static_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>(*this);
    sensor_msgs::msg::Imu imu;
    rclcpp::wait_for_message(imu, shared_from_this(), "imu", 1s);
  }
  message_filters::Subscriber<sensor_msgs::msg::Image> sub_;
};
int main() { rclcpp::spin(std::make_shared<Node>()); }
"""
    assert _uses(_entries(tmp_path, ros2)) == [
        ("subscribes", "image", "sensor_msgs/msg/Image", 4),
        ("subscribes", "info", "sensor_msgs/msg/Imu", 5),
        ("publishes", "/tf_static", "tf2_msgs/msg/TFMessage", 6),
        ("subscribes", "imu", "sensor_msgs/msg/Imu", 8),
    ]


def test_names_that_are_parameters_values(tmp_path: Path) -> None:
    """roscpp's ``param``/``getParam``/``param<T>`` (private ``~``), rclcpp's
    ``declare_parameter``/``get_parameter``/``get_parameter_or``: the use is named by the
    parameter, with the code's default."""
    ros1 = """\
int main() {
  ros::NodeHandle nh, pnh("~");
  std::string path_topic, odom = "odom", cmd;
  pnh.param("path_topic", path_topic, std::string("plan"));
  nh.getParam("odom_topic", odom);
  cmd = pnh.param<std::string>("cmd_topic", "cmd_vel");
  ros::Subscriber a = nh.subscribe<nav_msgs::Path>(path_topic, 1, cb);
  ros::Subscriber b = pnh.subscribe<nav_msgs::Odometry>(odom, 1, cb);
  ros::Publisher c = nh.advertise<geometry_msgs::Twist>(cmd, 1);
}
"""
    found = [(e.name, e.named_by, e.default) for e in _entries(tmp_path, ros1, ros2=False)]
    assert [f for f in found if f[1] is not None] == [
        ("{~path_topic}", NamedBy("~path_topic"), "plan"),
        ("~{odom_topic}", NamedBy("odom_topic", "~"), "odom"),
        ("{~cmd_topic}", NamedBy("~cmd_topic"), "cmd_vel"),
    ]
    ros2 = """\
class Smoother : public rclcpp::Node {
 public:
  Smoother() : Node("smoother") {
    declare_parameter("odom_topic", "odom");
    std::string odom = get_parameter("odom_topic").as_string();
    std::string scan;
    get_parameter_or("scan_topic", scan, std::string("scan"));
    auto out = this->declare_parameter<std::string>("out_topic", "cmd_vel_smoothed");
    create_subscription<nav_msgs::msg::Odometry>(odom, 1, cb);
    create_subscription<sensor_msgs::msg::LaserScan>(scan, 1, cb);
    create_publisher<geometry_msgs::msg::Twist>(out, 1);
  }
};
int main() { rclcpp::spin(std::make_shared<Smoother>()); }
"""
    found = [(e.name, e.named_by, e.default) for e in _entries(tmp_path, ros2)]
    assert [f for f in found if f[1] is not None] == [
        ("{odom_topic}", NamedBy("odom_topic"), None),  # the declaration's default: the graph's
        ("{scan_topic}", NamedBy("scan_topic"), "scan"),
        ("{out_topic}", NamedBy("out_topic"), "cmd_vel_smoothed"),
    ]


def test_a_parameter_value_declared_is_its_default(tmp_path: Path) -> None:
    """nav2's ``declare_parameter(name, rclcpp::ParameterValue(value))``: the default is the
    value (a string the graph can name a topic by), not the constructor's text."""
    source = """\
class Server : public rclcpp::Node {
 public:
  Server() : Node("controller_server") {
    declare_parameter("speed_limit_topic", rclcpp::ParameterValue("speed_limit"));
    declare_parameter("min_x_velocity_threshold", rclcpp::ParameterValue(0.0001));
    declare_parameter("publish_zero_velocity", rclcpp::ParameterValue(true));
    declare_parameter("ids", rclcpp::ParameterValue(default_ids_));
  }
};
int main() { rclcpp::spin(std::make_shared<Server>()); }
"""
    assert [(e.name, e.default) for e in _entries(tmp_path, source)] == [
        ("speed_limit_topic", "speed_limit"),
        ("min_x_velocity_threshold", 0.0001),
        ("publish_zero_velocity", True),
        ("ids", Expression("default_ids_")),
    ]


def test_default_arguments_of_a_constructor(tmp_path: Path) -> None:
    """laser_filters: ``ScanToScanFilterChain(const ros::NodeHandle& nh = {}, const
    ros::NodeHandle& pnh = {"~"})`` built as ``ScanToScanFilterChain t;``."""
    source = """\
class Chain {
 public:
  Chain(const ros::NodeHandle& nh = {}, const ros::NodeHandle& pnh = {"~"})
      : nh_(nh), pnh_(pnh), sub_(nh_, "scan", 50) {
    pub_ = pnh_.advertise<sensor_msgs::LaserScan>("filtered", 1);
  }
  ros::NodeHandle nh_, pnh_;
  message_filters::Subscriber<sensor_msgs::LaserScan> sub_;
};
int main() { Chain t; }
"""
    assert _uses(_entries(tmp_path, source, ros2=False)) == [
        ("subscribes", "scan", "sensor_msgs/LaserScan", 4),
        ("publishes", "~filtered", "sensor_msgs/LaserScan", 5),
    ]


def test_a_dynamic_reconfigure_server_reads_its_namespace(tmp_path: Path) -> None:
    """Its config's parameters, each with the ``.cfg``'s default: the whole namespace counts
    as read (``param-unread`` stays quiet there, ``param-unset`` too)."""
    source = """\
class Node {
 public:
  Node() : pnh_("~") {
    server_.reset(new dynamic_reconfigure::Server<pkg::Config>(ros::NodeHandle(pnh_, "pid")));
  }
  ros::NodeHandle pnh_;
  boost::shared_ptr<dynamic_reconfigure::Server<pkg::Config>> server_;
  dynamic_reconfigure::Server<pkg::LimitsConfig> limits_;
};
int main() { Node node; }
"""
    reads = [
        (e.name, e.default, e.location.line)
        for e in _entries(tmp_path, source, ros2=False)
        if e.role is Role.PARAMS
    ]
    assert sorted(reads) == [("~", RECONFIGURED, 8), ("~pid", RECONFIGURED, 4)]


LIFECYCLE_INTERFACE = [
    ("publishes", "~/transition_event", "lifecycle_msgs/msg/TransitionEvent"),
    ("services", "~/change_state", "lifecycle_msgs/srv/ChangeState"),
    ("services", "~/get_state", "lifecycle_msgs/srv/GetState"),
    ("services", "~/get_available_states", "lifecycle_msgs/srv/GetAvailableStates"),
    ("services", "~/get_available_transitions", "lifecycle_msgs/srv/GetAvailableTransitions"),
    ("services", "~/get_transition_graph", "lifecycle_msgs/srv/GetAvailableTransitions"),
]
"""rcl_lifecycle's com_interface.c names, rclcpp_lifecycle's types."""


def test_a_lifecycle_node_built_or_derived_has_the_lifecycle_interface(tmp_path: Path) -> None:
    """rclcpp_lifecycle's node, built by ``make_shared`` or as a base class, has rcl_lifecycle's
    transition publisher and services; a plain rclcpp node has none."""
    built = """\
int main() {
  auto node = rclcpp_lifecycle::LifecycleNode::make_shared("lc");
  node->create_publisher<std_msgs::msg::String>("chatter", 10);
}
"""
    derived = """\
class Talker : public rclcpp_lifecycle::LifecycleNode {
 public:
  Talker() : rclcpp_lifecycle::LifecycleNode("lc_talker") {}
};
int main() { auto node = std::make_shared<Talker>(); }
"""
    plain = built.replace("rclcpp_lifecycle::LifecycleNode", "rclcpp::Node")
    for source, line, own in (
        (built, 2, [("publishes", "chatter", "std_msgs/msg/String")]),
        (derived, 3, []),
    ):
        uses = _uses(_entries(tmp_path, source))
        assert [use[:3] for use in uses] == own + LIFECYCLE_INTERFACE
        assert {use[3] for use in uses[len(own) :]} == {line}
    assert [use[:3] for use in _uses(_entries(tmp_path, plain))] == [
        ("publishes", "chatter", "std_msgs/msg/String")
    ]
