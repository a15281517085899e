"""ROS 2 YAML launch files to entity trees."""
