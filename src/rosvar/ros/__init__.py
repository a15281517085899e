"""ROS 1 conventions (graph resource names) that every layer shares."""
