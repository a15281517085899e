"""frontends/ros2_yaml: ROS 2 YAML launch files."""
