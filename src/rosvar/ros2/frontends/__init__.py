"""ROS 2's launch file formats to entity trees: XML (the shared reader), YAML and Python."""
