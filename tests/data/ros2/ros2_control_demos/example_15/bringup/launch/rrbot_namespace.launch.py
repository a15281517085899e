# Copyright 2021 Stogl Robotics Consulting UG (haftungsbeschränkt)
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.


from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import Command, LaunchConfiguration, PathSubstitution

from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription(
        [
            DeclareLaunchArgument(
                "start_rviz",
                default_value="true",
                description="Start RViz2 automatically with this launch file.",
            ),
            Node(
                package="controller_manager",
                executable="ros2_control_node",
                namespace="/rrbot",
                parameters=[
                    PathSubstitution(FindPackageShare("ros2_control_demo_example_15"))
                    / "config"
                    / "rrbot_namespace_controllers.yaml",
                ],
                output={"stdout": "screen", "stderr": "screen"},
            ),
            Node(
                package="robot_state_publisher",
                executable="robot_state_publisher",
                namespace="/rrbot",
                output="both",
                parameters=[
                    {
                        "robot_description": Command(
                            [
                                "xacro",
                                " ",
                                PathSubstitution(FindPackageShare("ros2_control_demo_example_1"))
                                / "urdf"
                                / "rrbot.urdf.xacro",
                            ]
                        )
                    }
                ],
            ),
            Node(
                package="rviz2",
                executable="rviz2",
                name="rviz2",
                output="log",
                arguments=[
                    "-d",
                    PathSubstitution(FindPackageShare("ros2_control_demo_example_15"))
                    / "rviz"
                    / "rrbot_namespace.rviz",
                ],
                condition=IfCondition(LaunchConfiguration("start_rviz")),
            ),
            Node(
                package="controller_manager",
                executable="spawner",
                namespace="rrbot",
                name="controller_active_spawner",
                arguments=[
                    "joint_state_broadcaster",
                    "forward_position_controller",
                    "--param-file",
                    PathSubstitution(FindPackageShare("ros2_control_demo_example_15"))
                    / "config"
                    / "rrbot_namespace_controllers.yaml",
                    "--controller-ros-args",
                    # we use the remapping from a relative name to FQN /position_commands
                    "-r forward_position_controller/commands:=/position_commands",
                ],
            ),
            Node(
                package="controller_manager",
                executable="spawner",
                namespace="rrbot",
                name="controller_inactive_spawner",
                arguments=[
                    "position_trajectory_controller",
                    "--inactive",
                    "--param-file",
                    PathSubstitution(FindPackageShare("ros2_control_demo_example_15"))
                    / "config"
                    / "rrbot_namespace_controllers.yaml",
                ],
            ),
        ]
    )
