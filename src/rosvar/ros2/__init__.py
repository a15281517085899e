"""ROS 2's launch semantics (ros2/launch and launch_ros): its frontends (XML, YAML, Python),
actions, substitutions, launch context, conventions and the resolution of one command line,
on the shared variational walk."""
