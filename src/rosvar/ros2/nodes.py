"""What a ROS 2 node declaration's fields mean (``<node>``, ``<executable>``, composable
nodes): what it starts, and ROS 2's node schema, the typed accessors every reader uses
(:class:`~rosvar.interpreter.model.NodeSchema`). Names compose as launch_ros composes them;
where a part is a term, into a term that composes the same once it is known."""

from __future__ import annotations

from collections.abc import Sequence
from enum import StrEnum

from rosvar.interpreter.model import NodeField, NodeSchema, Raw
from rosvar.logic.terms import Apply, register
from rosvar.ros.version import RosVersion
from rosvar.ros2.conventions.namespaces import full_name, make_absolute, prefix_namespace, unnamed


class ProcessKind(StrEnum):
    """What a declaration starts (the oracle's ``kind``)."""

    NODE = "node"
    LIFECYCLE_NODE = "lifecycle_node"
    PROCESS = "process"
    CONTAINER = "container"
    COMPOSABLE_NODE = "composable_node"


NAMES_CHECKED = frozenset({ProcessKind.NODE, ProcessKind.LIFECYCLE_NODE, ProcessKind.CONTAINER})
"""What launch_ros's ``Node`` starts, which checks its name and namespace before it does (a
composable node's are its container's to check, a process has none)."""


def _texts(values: Sequence[Raw | None]) -> list[str | None] | None:
    """The values when all are known (strings or absent)."""
    texts = [value for value in values if value is None or isinstance(value, str)]
    return texts if len(texts) == len(values) else None


def _namespace(values: Sequence[Raw | None]) -> Raw | None:
    """launch_ros's: the pushed namespace, then the node's own (under it when relative),
    absolute; None where neither is given."""
    texts = _texts(values)
    if texts is not None:
        return make_absolute(prefix_namespace(*texts))
    pushed, own = values
    return Apply("ros2_namespace", (pushed or "", own or ""))


def _full_name(values: Sequence[Raw | None]) -> Raw | None:
    """The fully qualified name; None without a name (its code names it)."""
    texts = _texts(values)
    if texts is not None:
        pushed_text, own_text, name_text = texts
        return None if name_text is None else full_name(pushed_text, own_text, name_text)
    pushed, own, name = values
    return None if name is None else Apply("ros2_full_name", (pushed or "", own or "", name))


def _label(values: Sequence[Raw | None]) -> Raw | None:
    """The fully qualified name, or ``⟨EXEC⟩`` in its namespace where its code names it."""
    pushed, own, name, executable = values
    if name is not None:
        return _full_name([pushed, own, name])
    namespace = _namespace([pushed, own])
    texts = _texts([namespace, executable])
    if texts is not None:
        return unnamed(*texts)
    return Apply("ros2_unnamed", (namespace or "", executable or ""))


register(
    "ros2_namespace", lambda _host, pushed, own: make_absolute(prefix_namespace(pushed, own)) or "/"
)
register("ros2_full_name", lambda _host, pushed, own, name: full_name(pushed, own, name))
register("ros2_unnamed", lambda _host, namespace, executable: unnamed(namespace, executable))

ROS2_NODES = NodeSchema(
    RosVersion.ROS2,
    package=NodeField(("pkg",)),
    executable=NodeField(("exec",)),
    name=NodeField(("name",)),
    namespace=NodeField(("ros_namespace", "namespace"), _namespace),
    full_name=NodeField(("ros_namespace", "namespace", "name"), _full_name),
    label=NodeField(("ros_namespace", "namespace", "name", "exec"), _label),
    args=NodeField(("args",)),
    plugin=NodeField(("plugin",)),
    lifecycle=NodeField(
        ("kind",), lambda values: "true" if values[0] == ProcessKind.LIFECYCLE_NODE else None
    ),
    launched=("pkg", "exec", "namespace", "name", "args", "ros_namespace", "plugin", "kind"),
)
"""A node's (a process's, a composable node's) typed fields."""
