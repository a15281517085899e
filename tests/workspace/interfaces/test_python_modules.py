"""Python nodes whose interfaces are made in other modules of their own package: followed
through the script's imports (parsed, never imported), only what runs."""

from __future__ import annotations

from pathlib import Path

from rosvar.workspace import discover
from rosvar.workspace.interfaces.extraction import extract_interfaces
from rosvar.workspace.interfaces.model import Role

MANIFEST = """\
<package format="3"><name>{name}</name><version>0.0.0</version><description>d</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<export><build_type>{build}</build_type></export></package>
"""
ROS1_SCRIPT = """\
#!/usr/bin/env python
import rospy
from demo.obstacle import Obstacle
if __name__ == "__main__":
    rospy.init_node("obstacle")
    Obstacle("/mobile_base/events/bumper")
"""
ROS1_MODULE = """\
import rospy
import tf
from geometry_msgs.msg import Twist
from sensor_msgs.msg import LaserScan
from .base import Base

class Obstacle(Base):
    def __init__(self, bumper_topic):
        self.bumper = bumper_topic
        rospy.Subscriber(self.bumper, Twist, None)  # the name the script constructs it with
        self.pub = rospy.Publisher("cmd_vel", Twist, queue_size=1)
        scan = rospy.wait_for_message("scan", LaserScan)
        self.br = tf.TransformBroadcaster()

class Unused:
    def __init__(self):
        rospy.Publisher("never", Twist, queue_size=1)

if __name__ == "__main__":
    rospy.Publisher("only_as_script", Twist, queue_size=1)
"""
ROS1_BASE = """\
import rospy
from std_msgs.msg import Bool
class Base:
    def start(self):
        rospy.Subscriber("enable", Bool, self.cb)
"""
ROS2_SETUP = """\
from setuptools import setup
package_name = 'demo_py'
setup(name=package_name, entry_points={'console_scripts': [
    'teleop = ' 'demo_py.script.teleop:main',
]})
"""
ROS2_ENTRY = """\
import rclpy
from demo_py.nodes import TeleopNode
def main():
    rclpy.init()
    rclpy.spin(TeleopNode())
"""
ROS2_NODES = """\
from rclpy.node import Node
from rclpy.wait_for_message import wait_for_message
from geometry_msgs.msg import Twist
from sensor_msgs.msg import Joy
from tf2_ros import StaticTransformBroadcaster
class TeleopNode(Node):
    def __init__(self):
        super().__init__('teleop')
        self.create_publisher(Twist, 'cmd_vel', 10)
        wait_for_message(Joy, self, 'joy')
        self.static = StaticTransformBroadcaster(self)
"""


def _write(root: Path, files: dict[str, str]) -> None:
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


def test_modules_of_the_package_make_the_interface(tmp_path: Path) -> None:
    _write(
        tmp_path,
        {
            "demo/package.xml": MANIFEST.format(name="demo", build="catkin"),
            "demo/CMakeLists.txt": "catkin_install_python(PROGRAMS nodes/obstacle DESTINATION x)\n",
            "demo/nodes/obstacle": ROS1_SCRIPT,
            "demo/src/demo/__init__.py": "",
            "demo/src/demo/obstacle.py": ROS1_MODULE,
            "demo/src/demo/base.py": ROS1_BASE,
            "demo_py/package.xml": MANIFEST.format(name="demo_py", build="ament_python"),
            "demo_py/setup.py": ROS2_SETUP,
            "demo_py/demo_py/__init__.py": "",
            "demo_py/demo_py/script/__init__.py": "",
            "demo_py/demo_py/script/teleop.py": ROS2_ENTRY,
            "demo_py/demo_py/nodes.py": ROS2_NODES,
        },
    )
    ros1 = extract_interfaces(discover([tmp_path / "demo"]).packages.values())
    obstacle = ros1.find("demo", "obstacle")
    assert obstacle is not None
    assert sorted((str(e.role), e.name, e.type, e.boundary) for e in obstacle.entries) == [
        ("publishes", "/tf", "tf2_msgs/TFMessage", True),
        ("publishes", "cmd_vel", "geometry_msgs/Twist", False),
        ("subscribes", "/mobile_base/events/bumper", "geometry_msgs/Twist", False),
        ("subscribes", "enable", "std_msgs/Bool", False),  # Base's, a class it names
        ("subscribes", "scan", "sensor_msgs/LaserScan", False),
    ]
    ros2 = extract_interfaces(discover([tmp_path / "demo_py"]).packages.values())
    teleop = ros2.find("demo_py", "teleop")
    assert teleop is not None and teleop.node_name == "teleop"
    assert [(str(e.role), e.name, e.type) for e in teleop.entries if e.role is not Role.PARAMS] == [
        ("publishes", "cmd_vel", "geometry_msgs/msg/Twist"),
        ("subscribes", "joy", "sensor_msgs/msg/Joy"),
        ("publishes", "/tf_static", "tf2_msgs/msg/TFMessage"),
    ]
    assert [d for d in ros1.diagnostics + ros2.diagnostics if d.code != "interface-python2"] == []


def test_a_dotted_import_and_a_class_used_for_one_method(tmp_path: Path) -> None:
    """nmea_navsat_driver: ``import lib.nodes.reader; lib.nodes.reader.main()``, whose module
    calls only ``Driver.get_frame_id()`` (a static method: the driver's topics are not its)."""
    _write(
        tmp_path,
        {
            "nmea/package.xml": MANIFEST.format(name="nmea", build="catkin"),
            "nmea/scripts/reader": "#!/usr/bin/env python\nimport lib.nodes.reader\n"
            "lib.nodes.reader.main()\n",
            "nmea/src/lib/__init__.py": "",
            "nmea/src/lib/nodes/__init__.py": "",
            "nmea/src/lib/nodes/reader.py": "import rospy\nfrom nmea_msgs.msg import Sentence\n"
            "from lib.driver import Driver\n"
            "def main():\n    rospy.Publisher('nmea_sentence', Sentence)\n"
            "    Driver.get_frame_id()\n",
            "nmea/src/lib/driver.py": "import rospy\nfrom sensor_msgs.msg import NavSatFix\n"
            "class Driver:\n    def __init__(self):\n"
            "        rospy.Publisher('fix', NavSatFix)\n"
            "    @staticmethod\n    def get_frame_id():\n"
            "        return rospy.get_param('~frame_id', 'gps')\n",
        },
    )
    interfaces = extract_interfaces(discover([tmp_path / "nmea"]).packages.values())
    reader = interfaces.find("nmea", "reader")
    assert reader is not None
    assert [(str(e.role), e.name) for e in reader.entries] == [
        ("publishes", "nmea_sentence"),
        ("params", "~frame_id"),
    ]
