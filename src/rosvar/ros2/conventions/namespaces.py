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
