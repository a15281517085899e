"""rmw's rules for a node's name and a namespace, which launch_ros checks before it starts a
node (``Node``: its ``name``, and its namespace once the pushed one is prefixed) or pushes a
namespace (``PushROSNamespace``): the launch stops there. Each function gives what is wrong,
as rmw says it, or None."""

from __future__ import annotations

import re

MAX_NODE_NAME = 255
MAX_NAMESPACE = 245
"""rmw's limits (a namespace leaves room in a topic name for its last token)."""

_NAME_CHARACTERS = re.compile(r"[A-Za-z0-9_]*")
_NAMESPACE_CHARACTERS = re.compile(r"[A-Za-z0-9_/]*")


def node_name_problem(name: str) -> str | None:
    """What makes ``name`` no node name (``validate_node_name``)."""
    if not name:
        return "node name must not be empty"
    if not _NAME_CHARACTERS.fullmatch(name):
        return "node name must not contain characters other than alphanumerics or '_'"
    if name[0].isdigit():
        return "node name must not start with a number"
    if len(name) > MAX_NODE_NAME:
        return f"node name should not exceed '{MAX_NODE_NAME}'"
    return None


def namespace_problem(namespace: str) -> str | None:
    """What makes ``namespace`` no absolute namespace (``validate_namespace``)."""
    if namespace == "/":
        return None
    if not namespace:
        return "namespace must not be empty"
    if not namespace.startswith("/"):
        return "namespace must be absolute, it must lead with a '/'"
    if namespace.endswith("/"):
        return "namespace must not end with a '/'"
    if not _NAMESPACE_CHARACTERS.fullmatch(namespace):
        return "namespace must not contain characters other than alphanumerics, '_', or '/'"
    for token in namespace[1:].split("/"):  # the first problem from the left
        if not token:
            return "namespace must not contain repeated '/'"
        if token[0].isdigit():
            return "namespace must not have a token that starts with a number"
    if len(namespace) > MAX_NAMESPACE:
        return f"namespace should not exceed '{MAX_NAMESPACE}'"
    return None


def node_problem(name: str | None, namespace: str | None) -> str | None:
    """What launch_ros says of a node of ``name`` in ``namespace`` (each None where not
    given), or None where it starts."""
    problem = None if name is None else node_name_problem(name)
    if problem is not None:
        return f"Invalid node name: {problem}: '{name}'"
    problem = None if namespace is None else namespace_problem(namespace)
    if problem is not None:
        return f"Invalid namespace: {problem}: '{namespace}'"
    return None
