"""The interface every ROS 2 lifecycle node has besides its own code's.

rcl_lifecycle's communication interface, which rclcpp_lifecycle's and rclpy's lifecycle nodes
both create (unless built with ``enable_communication_interface`` false): a publisher of the
transitions and five services, each in the node's private namespace. A node's code written as
a lifecycle node (a C++ class deriving from ``LifecycleNode``, a Python class deriving from
``rclpy.lifecycle.Node``) has them, and so has whatever launch_ros starts as a
``LifecycleNode``: its action drives the node through these services.
"""

from __future__ import annotations

from typing import Final

from rosvar.diagnostics import Location
from rosvar.workspace.interfaces.model import Entry, Origin, Role

LIFECYCLE_USES: Final = (
    (Role.PUBLISHES, "~/transition_event", "lifecycle_msgs/msg/TransitionEvent"),
    (Role.SERVICES, "~/change_state", "lifecycle_msgs/srv/ChangeState"),
    (Role.SERVICES, "~/get_state", "lifecycle_msgs/srv/GetState"),
    (Role.SERVICES, "~/get_available_states", "lifecycle_msgs/srv/GetAvailableStates"),
    (Role.SERVICES, "~/get_available_transitions", "lifecycle_msgs/srv/GetAvailableTransitions"),
    (Role.SERVICES, "~/get_transition_graph", "lifecycle_msgs/srv/GetAvailableTransitions"),
)
"""rcl_lifecycle's names (``com_interface.c``) and the types rclcpp_lifecycle gives them."""


def lifecycle_entries(location: Location, origin: Origin = Origin.SOURCE) -> list[Entry]:
    """The lifecycle interface, placed at what makes the node a lifecycle node: boundary
    uses (a lifecycle manager, ``ros2 lifecycle``, launch_ros's action use them, or nobody)."""
    return [
        Entry(role, name, location, origin, type=kind, boundary=True)
        for role, name, kind in LIFECYCLE_USES
    ]


def with_lifecycle(entries: list[Entry], location: Location) -> list[Entry]:
    """``entries`` and the lifecycle interface's, those not among them already."""
    known = {(entry.role, entry.name) for entry in entries}
    extra = [e for e in lifecycle_entries(location) if (e.role, e.name) not in known]
    return entries + extra
