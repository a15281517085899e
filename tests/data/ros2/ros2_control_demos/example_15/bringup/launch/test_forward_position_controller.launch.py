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
from launch.substitutions import LaunchConfiguration, PathSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():

    return LaunchDescription(
        [
            DeclareLaunchArgument(
                "publisher_config",
                default_value="rrbot_forward_position_publisher.yaml",
                description=(
                    "Name of the publisher config file stored inside "
                    "ros2_control_demo_bringup/config/"
                ),
            ),
            Node(
                package="ros2_controllers_test_nodes",
                executable="publisher_forward_position_controller",
                name="publisher_forward_position_controller",
                parameters=[
                    PathSubstitution(FindPackageShare("ros2_control_demo_example_15"))
                    / "config"
                    / LaunchConfiguration("publisher_config")
                ],
                output="both",
            ),
        ]
    )
