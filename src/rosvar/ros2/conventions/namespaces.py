"""ROS 2 namespace composition (launch_ros's ``namespace_utils``), on plain strings."""

from __future__ import annotations


def prefix_namespace(base: str | None, ns: str | None) -> str | None:
    """``ns`` under ``base`` when relative; trailing slashes stripped (except from ``/``)."""
    if base is None and ns is None:
        return None
    if ns is None:
        combined = base
    elif not base or ns.startswith("/"):
        combined = ns
    else:
        combined = ("" if base == "/" else base) + "/" + ns
    assert combined is not None
    return combined if combined == "/" else combined.rstrip("/")


def make_absolute(ns: str | None) -> str | None:
    """``make_namespace_absolute``: a leading slash added where missing."""
    if ns is None:
        return None
    return ns if ns.startswith("/") else "/" + ns


def full_name(pushed: str | None, namespace: str | None, name: str) -> str:
    """A node's fully qualified name from the pushed namespace, its own and its name."""
    absolute = make_absolute(prefix_namespace(pushed, namespace))
    return (absolute or "").rstrip("/") + "/" + name


def unnamed(namespace: str | None, executable: str | None) -> str:
    """How a node with no name is shown: ``⟨EXEC⟩`` in its namespace (the executable names
    it at run time; no launch file says how)."""
    return (namespace or "").rstrip("/") + f"/⟨{executable or ''}⟩"


NODE_NAME_MAX = 255
"""rmw's longest node name."""
NAMESPACE_MAX = 255 - 8 - 2
"""rmw's longest namespace: a topic name's (255 less the DDS prefix's 8) less 2."""


def _plain(text: str, slash: bool) -> bool:
    """Only ASCII letters, digits, ``_`` (and ``/`` where ``slash``)."""
    allowed = "_/" if slash else "_"
    return all(c.isascii() and (c.isalnum() or c in allowed) for c in text)


def namespace_error(namespace: str) -> str | None:
    """Why rmw refuses ``namespace`` (launch_ros validates each it composes), or None."""
    if namespace == "/":
        return None
    tokens = namespace.split("/")
    if not namespace.startswith("/"):
        return "namespace must be absolute"
    if namespace.endswith("/"):
        return "namespace must not end with a '/'"
    if not _plain(namespace, slash=True):
        return "namespace must not contain characters other than alphanumerics, '_', or '/'"
    if "" in tokens[1:]:
        return "namespace must not contain repeated '/'"
    if any(token[:1].isdigit() for token in tokens):
        return "namespace must not have a token that starts with a number"
    if len(namespace) > NAMESPACE_MAX:
        return f"namespace should not exceed {NAMESPACE_MAX} characters"
    return None


def node_name_error(name: str) -> str | None:
    """Why rmw refuses ``name`` as a node's name (launch_ros validates the given one)."""
    if not name:
        return "node name must not be empty"
    if not _plain(name, slash=False):
        return "node name must not contain characters other than alphanumerics or '_'"
    if name[0].isdigit():
        return "node name must not start with a number"
    if len(name) > NODE_NAME_MAX:
        return f"node name should not exceed {NODE_NAME_MAX} characters"
    return None
