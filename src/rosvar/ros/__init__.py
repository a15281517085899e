"""ROS graph resource names (rosgraph's rules), which every layer shares."""
