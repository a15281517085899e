"""Handlers of roslaunch's tags, one module per tag; importing registers them."""

from rosvar.ros1.tags import (  # noqa: F401 - imported for registration
    arg,
    env,
    group,
    include,
    machine,
    master,
    node,
    param,
    remap,
    rosparam,
)
