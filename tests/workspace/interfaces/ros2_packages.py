"""A small ROS 2 workspace for the tests of extraction and of the communication graph: an
rclcpp node, an rclcpp component (with the executable registered from it) and an rclpy node,
each source with the interface the tests expect of it."""

from __future__ import annotations

from pathlib import Path

MANIFEST = """\
<package format="3"><name>{name}</name><version>0.0.0</version><description>d</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<export><build_type>{build}</build_type></export></package>
"""
CMAKE = """\
cmake_minimum_required(VERSION 3.8)
project(demo_cpp)
find_package(ament_cmake REQUIRED)
add_executable(talker src/talker.cpp)
add_library(camera_component SHARED src/camera.cpp)
rclcpp_components_register_node(camera_component PLUGIN "demo_cpp::Camera" EXECUTABLE camera)
ament_package()
"""
TALKER = """\
#include <rclcpp/rclcpp.hpp>
using Fibonacci = action_tutorials_interfaces::action::Fibonacci;
const std::string TOPIC = "chatter";

class Talker : public rclcpp::Node {
 public:
  Talker() : Node("talker") {
    pub_ = create_publisher<std_msgs::msg::String>(TOPIC, 10);
    sub_ = this->create_subscription<std_msgs::msg::String>(
        "~/control", 10, std::bind(&Talker::on_control, this, std::placeholders::_1));
    rate_ = declare_parameter("rate", 2.5);
    get_parameter("rate", rate_);
    get_parameter("frame", frame_);
    server_ = rclcpp_action::create_server<Fibonacci>(this, "fibonacci", a, b, c);
  }

 private:
  void on_control(const std_msgs::msg::String::SharedPtr msg) {
    auto client = this->create_client<std_srvs::srv::Trigger>("/reset");
  }
  void unused() { create_publisher<std_msgs::msg::Empty>("never", 1); }
};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Talker>());
}
"""
CAMERA = """\
#include "demo_cpp/camera.hpp"
namespace demo_cpp {
Camera::Camera(const rclcpp::NodeOptions & options) : rclcpp::Node("camera", options) {
  image_transport::ImageTransport it(shared_from_this());
  pub_ = it.advertiseCamera("image_raw", 1);
  srv_ = node_->create_service<std_srvs::srv::SetBool>(
      "enable", std::bind(&Camera::on, this, _1, _2));
  mask_ = image_transport::create_subscription(this, "mask", cb, "raw");
}
}  // namespace demo_cpp
#include "rclcpp_components/register_node_macro.hpp"
RCLCPP_COMPONENTS_REGISTER_NODE(demo_cpp::Camera)
"""
CAMERA_HEADER = """\
namespace demo_cpp {
class Camera : public rclcpp::Node {
 public:
  explicit Camera(const rclcpp::NodeOptions & options);
};
}  // namespace demo_cpp
"""
SETUP = """\
from setuptools import setup
setup(name='demo_py', entry_points={'console_scripts': ['listener = demo_py.listener:main']})
"""
LISTENER = """\
import rclpy
from rclpy.node import Node
from rclpy.action import ActionClient
from std_msgs.msg import String
from std_srvs.srv import Trigger
from action_tutorials_interfaces.action import Fibonacci

NAME = 'listener'


class Listener(Node):
    def __init__(self):
        super().__init__(NAME)
        self.sub = self.create_subscription(String, 'chatter', self.on_chatter, 10)
        self.pub = self.create_publisher(String, '~/echo', 10)
        self.srv = self.create_service(Trigger, 'reset', self.on_reset)
        self.client = ActionClient(self, Fibonacci, '/fibonacci')
        self.declare_parameter('gain', 0.5)


def main():
    rclpy.init()
    rclpy.spin(Listener())
"""


def write_ros2_packages(root: Path) -> None:
    """``demo_cpp`` (ament_cmake) and ``demo_py`` (ament_python) below ``root``."""
    files = {
        "demo_cpp/package.xml": MANIFEST.format(name="demo_cpp", build="ament_cmake"),
        "demo_cpp/CMakeLists.txt": CMAKE,
        "demo_cpp/src/talker.cpp": TALKER,
        "demo_cpp/src/camera.cpp": CAMERA,
        "demo_cpp/include/demo_cpp/camera.hpp": CAMERA_HEADER,
        "demo_py/package.xml": MANIFEST.format(name="demo_py", build="ament_python"),
        "demo_py/setup.py": SETUP,
        "demo_py/demo_py/__init__.py": "",
        "demo_py/demo_py/listener.py": LISTENER,
    }
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


def write_ros2_bringup(root: Path, launch_xml: str) -> None:
    """:func:`write_ros2_packages`, and ``demo_bringup`` whose ``a.launch.xml`` launches them."""
    write_ros2_packages(root)
    bringup = root / "demo_bringup"
    bringup.mkdir()
    (bringup / "package.xml").write_text(MANIFEST.format(name="demo_bringup", build="ament_cmake"))
    (bringup / "a.launch.xml").write_text(launch_xml)
