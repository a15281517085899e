"""Handlers of ROS 2's launch actions, one module per concept; importing registers them."""

from rosvar.ros2.tags import (  # noqa: F401 - imported for registration
    arg,
    events,
    group,
    include,
    inert,
    node,
    settings,
    timer,
)
