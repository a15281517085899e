"""frontends/ros2_python: ROS 2 Python launch files, read statically."""
