"""tf's classes, as every source language spells them: the topics their construction uses.

A broadcaster's output is for every listener, rviz and tools; a listener's ``/tf_static``
input may stay empty (a robot without static transforms works): both are boundary uses,
never a finding when no node is on the other end. A listener's ``/tf`` input is not: with
nothing broadcasting, every lookup of a moving frame fails.
"""

from __future__ import annotations

from rosvar.workspace.interfaces.model import Role

CLASSES: dict[str, tuple[Role, tuple[str, ...]]] = {
    "TransformBroadcaster": (Role.PUBLISHES, ("/tf",)),
    "StaticTransformBroadcaster": (Role.PUBLISHES, ("/tf_static",)),
    "TransformListener": (Role.SUBSCRIBES, ("/tf", "/tf_static")),
}
MESSAGE = "tf2_msgs/TFMessage"
ROS2_MESSAGE = "tf2_msgs/msg/TFMessage"


def is_boundary(role: Role, topic: str) -> bool:
    """Whether ``topic`` used by a tf class in ``role`` is a boundary use (above)."""
    return role is Role.PUBLISHES or topic == "/tf_static"
