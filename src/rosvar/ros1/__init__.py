"""ROS 1's launch semantics (roslaunch): its tags, substitution args, scope, typed values,
rosparam YAML and the resolution of one configuration, on the shared variational walk."""
