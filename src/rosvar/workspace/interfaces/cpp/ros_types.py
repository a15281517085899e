"""C++ type names as ROS names them: ``std_msgs::String::ConstPtr`` is ``std_msgs/String``,
``std_msgs::msg::String`` (ROS 2) is ``std_msgs/msg/String``."""

from __future__ import annotations

import re

_SMART_POINTERS = re.compile(
    r"^(?:boost::|std::)?(?:shared_ptr|scoped_ptr|unique_ptr)<(.*)>$|^ros::MessageEvent<(.*)>$"
)


def ros_type(text: str) -> str | None:
    """A C++ message, service or action type as ROS names it (``pkg::Msg`` → ``pkg/Msg``)."""
    text = re.sub(r"\b(const|typename|volatile)\b|[&*]", "", text)
    text = "".join(text.split())
    smart = _SMART_POINTERS.match(text)
    while smart:
        text = smart.group(1) or smart.group(2)
        smart = _SMART_POINTERS.match(text)
    text = re.sub(
        r"::(ConstPtr|Ptr|ConstSharedPtr|SharedPtr|UniquePtr|Request|Response)$", "", text
    )
    text = re.sub(r"(?<=\w)(ConstPtr|Ptr)$", "", text)
    text = text.lstrip(":")
    if not text or not re.fullmatch(r"[A-Za-z_][\w:]*", text):
        return None
    parts = text.split("::")
    if len(parts) >= 3 and parts[-2] in ("msg", "srv", "action"):
        return "/".join(parts[-3:])  # ROS 2: std_msgs::msg::String is std_msgs/msg/String
    return "/".join(parts[-2:])
