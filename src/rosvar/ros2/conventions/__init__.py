"""ROS 2 conventions the analyses share: rcl's node command line, launch_ros's namespaces,
parameter values and files."""
