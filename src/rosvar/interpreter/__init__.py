"""The variational interpretation of launch files: one walk of an entry file that covers
every configuration at once, and the launch model it builds.

The walk is shared by the dialects, which give it their tags, scope and substitutions
(``dialect``, ``semantics``): what differs between ROS 1 and ROS 2 stays in ``ros1``/``ros2``.
Each element of the model carries its presence condition, so analyses restrict the model to
a configuration instead of interpreting the file again.
"""
