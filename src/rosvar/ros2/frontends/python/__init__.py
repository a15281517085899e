"""ROS 2 Python launch files to entity trees, read statically (never executed)."""
