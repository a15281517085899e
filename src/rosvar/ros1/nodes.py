"""What a ``<node>`` (or ``<test>``) declaration's fields mean: ROS 1's node schema, the typed
accessors every reader uses (:class:`~rosvar.interpreter.model.NodeSchema`)."""

from __future__ import annotations

from collections.abc import Sequence

from rosvar.interpreter.lifted import apply
from rosvar.interpreter.model import NodeField, NodeSchema, Raw, constant_field
from rosvar.logic.choice import Fail
from rosvar.ros.version import RosVersion


def _full_name(values: Sequence[Raw | None]) -> Raw | None:
    """roslaunch's ``ns_join`` of the node's namespace and name."""
    namespace, name = values
    if namespace is None or name is None:
        return None
    joined = apply("ns_join", (namespace, name))
    return None if isinstance(joined, Fail) else joined


_FULL_NAME = NodeField(("namespace", "name"), _full_name)

ROS1_NODES = NodeSchema(
    RosVersion.ROS1,
    package=NodeField(("pkg",)),
    executable=NodeField(("type",)),
    name=NodeField(("name",)),
    namespace=NodeField(("namespace",)),  # the ``ns`` attribute under its scope's, global
    full_name=_FULL_NAME,
    label=_FULL_NAME,
    args=NodeField(("args",)),
    plugin=constant_field(None),
    lifecycle=constant_field(None),
    launched=("pkg", "type", "namespace", "name", "args"),
)
"""A ``<node>``'s typed fields."""
