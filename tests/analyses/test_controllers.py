"""ros_control controllers: a spawner's controllers use the names of their type, so the
robot_state_publisher's joint_states and the odometry of a diff-drive controller have
providers."""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosvar.analyses.controllers import controller_edges
from rosvar.ros.version import RosVersion
from rosvar.workspace.interfaces.catalogue import load_catalogue
from rosvar.workspace.interfaces.model import Interfaces, Role

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

CATALOGUE = Interfaces(fallback=load_catalogue(RosVersion.ROS1))

CONTROL = """
joint_publisher:
  type: joint_state_controller/JointStateController
base_controller:
  type: diff_drive_controller/DiffDriveController
arm_controller:
  type: some_package/UnknownController
"""


def test_a_spawner_s_controllers_have_the_names_of_their_types(ws: LaunchWorkspace) -> None:
    ws.write("config/control.yaml", CONTROL)
    file = ws.launch(
        "control.launch",
        """<arg name="ns" default="r1"/>
        <group ns="$(arg ns)">
          <rosparam command="load" file="$(find pkg)/config/control.yaml"/>
          <node name="spawner" pkg="controller_manager" type="spawner"
                args="--shutdown-timeout 1 joint_publisher base_controller arm_controller"/>
        </group>""",
    )
    analysis = ws.analysis()
    model = analysis.model(file)
    edges = controller_edges(analysis.space, model, CATALOGUE, analysis.workspace.confinement())
    by_name = {
        (e.role, e.name, analysis.space.describe(e.condition)) for e in edges if not e.boundary
    }
    assert by_name == {
        (Role.PUBLISHES, "/r1/joint_states", "ns=r1"),
        (Role.SUBSCRIBES, "/r1/base_controller/cmd_vel", "ns=r1"),
        (Role.PUBLISHES, "/r1/base_controller/odom", "ns=r1"),
    }
    assert {e.node for e in edges} >= {"/r1/spawner: controller joint_publisher"}


def test_a_controller_of_no_known_type_or_without_type_has_no_edges(ws: LaunchWorkspace) -> None:
    ws.write("config/control.yaml", CONTROL)
    file = ws.launch(
        "control.launch",
        """<rosparam command="load" file="$(find pkg)/config/control.yaml"/>
        <node name="spawner" pkg="controller_manager" type="spawner"
              args="arm_controller untyped_controller"/>""",
    )
    analysis = ws.analysis()
    model = analysis.model(file)
    assert (
        controller_edges(analysis.space, model, CATALOGUE, analysis.workspace.confinement()) == []
    )
