"""The ROS client library APIs C++ extraction recognises: the calls and classes that make a
node publish, subscribe, serve, call or read a name, by the names the sources spell them.

Kept in one table so that recognising another API is adding a row, not a branch.
"""

from __future__ import annotations

import re

from rosvar.workspace.interfaces.model import Role

FRAMEWORK_CALLBACKS = (
    "on_configure",
    "on_activate",
    "on_deactivate",
    "on_cleanup",
    "on_shutdown",
    "on_error",
)
"""Methods the framework calls on a node object once it is built: a lifecycle node
(``rclcpp_lifecycle::LifecycleNode``, nav2's) makes its interfaces in its transitions."""
MAKERS = frozenset({"make_shared", "make_unique", "allocate_shared"})
"""Calls that construct their first template argument with their arguments."""
VALUE_GETTERS = frozenset({"c_str", "as_string", "get_value", "get", "value", "str"})
"""Methods that give the value they are called on as text (``.c_str()``,
``get_parameter("x").as_string()``)."""
OUT_ARGUMENT_READS = frozenset(
    {"searchParam", "getParam", "getParamCached", "get_parameter", "get_parameter_or"}
)
"""Reads that write a parameter's value into their second argument."""
PRIVATE_HANDLES = frozenset({"getPrivateNodeHandle", "getMTPrivateNodeHandle"})
PUBLIC_HANDLES = frozenset({"getNodeHandle", "getMTNodeHandle"})
PARAM_READS = frozenset({"param", "getParam", "getParamCached"})
FREE_PARAM_READS = frozenset({"ros::param::get", "ros::param::param", "ros::param::getCached"})
ACTION_CLASSES = {
    "SimpleActionServer": Role.ACTION_SERVERS,
    "ActionServer": Role.ACTION_SERVERS,
    "SimpleActionClient": Role.ACTION_CLIENTS,
    "ActionClient": Role.ACTION_CLIENTS,
}
IMAGE = "sensor_msgs/Image"
CAMERA_INFO = "sensor_msgs/CameraInfo"
RCLCPP_CALLS = {
    "create_publisher": Role.PUBLISHES,
    "create_subscription": Role.SUBSCRIBES,
    "create_service": Role.SERVICES,
    "create_client": Role.CLIENTS,
}
"""rclcpp's ``Node`` methods: called on the node (``this->``, ``node->``, a member pointer,
``shared_from_this()``) or unqualified in a class derived from it. A ROS 2 node has one
namespace, so the receiver need not be followed."""
RCLCPP_FREE_CALLS = {
    # free function → role and the index of the name argument (the node comes first)
    "rclcpp_action::create_server": Role.ACTION_SERVERS,
    "rclcpp_action::create_client": Role.ACTION_CLIENTS,
    "image_transport::create_publisher": Role.PUBLISHES,
    "image_transport::create_subscription": Role.SUBSCRIBES,
    "image_transport::create_camera_publisher": Role.PUBLISHES,
    "image_transport::create_camera_subscription": Role.SUBSCRIBES,
}
RCLCPP_DECLARE = "declare_parameter"
RCLCPP_READS = frozenset({"get_parameter", "get_parameter_or"})
RCLCPP_PARAMETERS_HANDED = frozenset({"get_node_parameters_interface"})
"""What gives the node's parameters to other code, which declares what it will: filters'
``FilterChain::configure("", logging, parameters)`` declares ``filter1.name`` and the rest,
pluginlib plugins their own; the node's declarations are not all in its sources."""
RCLCPP_NODE = re.compile(r"^rclcpp::Node(?:::make_shared)?$|make_shared<rclcpp::Node>$")
"""An rclcpp node built here (``rclcpp::Node::make_shared("name")``): its first argument
is the node's name."""
RCLCPP_LIFECYCLE_NODE = re.compile(
    r"^rclcpp_lifecycle::LifecycleNode(?:::make_shared)?$"
    r"|make_shared<rclcpp_lifecycle::LifecycleNode>$"
)
"""An rclcpp_lifecycle node built here: named as an rclcpp node is, with the lifecycle
interface (``lifecycle.py``)."""
ROS2_IMAGE = "sensor_msgs/msg/Image"
ROS2_CAMERA_INFO = "sensor_msgs/msg/CameraInfo"
CONTROLLER_MANAGER_SERVICES = tuple(
    (service, "controller_manager_msgs/" + service.title().replace("_", ""))
    for service in (
        "list_controllers",
        "list_controller_types",
        "load_controller",
        "unload_controller",
        "switch_controller",
        "reload_controller_libraries",
    )
)
"""What ros_control's ControllerManager serves (its constructor, controller_manager.cpp)."""

WAIT_FOR_MESSAGE = frozenset({"ros::topic::waitForMessage", "rclcpp::wait_for_message"})
"""Waiting for one message subscribes to its topic while it waits."""
API_NAMES = frozenset(
    {
        *RCLCPP_CALLS,
        RCLCPP_DECLARE,
        *RCLCPP_READS,
        "advertise",
        "subscribe",
        "advertiseService",
        "serviceClient",
    }
)
"""Names a project may give its own functions (a wrapper): such a call is the project's."""
