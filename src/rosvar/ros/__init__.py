"""ROS conventions every layer shares: graph resource names (rosgraph's rules) and the ROS
versions."""
