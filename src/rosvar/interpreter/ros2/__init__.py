"""ROS 2 launch semantics (ros2/launch and launch_ros) on the shared variational walk."""
