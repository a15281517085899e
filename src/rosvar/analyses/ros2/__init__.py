"""Analyses of ROS 2 launch models."""
