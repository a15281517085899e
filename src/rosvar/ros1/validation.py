"""Checks and conversions of node fields, shared by interpretation and resolution.

The interpreter applies them to the branches it knows; resolution applies the
same functions once terms become concrete, so both fail alike.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping

from rosvar.interpreter.booleans import bool_attribute
from rosvar.logic.terms import is_term
from rosvar.ros1.typed_values import float_attribute


@functools.lru_cache(maxsize=65536)
def node_problem(
    name: object,
    package: object,
    node_type: object,
    output: object,
    cwd: object,
    respawn: object,
    required: object,
    respawn_delay: object = None,
) -> str | None:
    """What roslaunch's ``Node`` constructor and attribute parsing reject, or None.

    Cached: every includer checks the same field values again.
    """
    if any(
        is_term(v)
        for v in (name, package, node_type, output, cwd, respawn, required, respawn_delay)
    ):
        return None
    try:
        respawn_flag = bool_attribute(respawn, False, "respawn")  # type: ignore[arg-type]
        float_attribute(respawn_delay, 0.0, "respawn_delay")  # type: ignore[arg-type]
        required_flag = bool_attribute(required, False, "required")  # type: ignore[arg-type]
    except ValueError as error:
        return str(error)
    if respawn_flag and required_flag:
        return "respawn and required cannot both be set to true"
    if isinstance(name, str) and "/" in name:
        return "node name cannot contain a namespace"
    if isinstance(package, str) and not package.strip():
        return "package must be non-empty"
    if isinstance(node_type, str) and not node_type.strip():
        return "type must be non-empty"
    if output not in ("log", "screen", None):
        return "output must be one of 'log', 'screen'"
    if cwd == "ros_home":
        cwd = "ROS_HOME"
    if cwd not in ("ROS_HOME", "node", None):
        return "cwd must be one of 'ROS_HOME', 'node'"
    return None


def node_values(fields: Mapping[str, str | None]) -> dict[str, object]:
    """Typed node fields as roslaunch's ``Node`` holds them (raises ValueError)."""
    problem = node_problem(
        fields.get("name"),
        fields.get("pkg"),
        fields.get("type"),
        fields.get("output"),
        fields.get("cwd"),
        fields.get("respawn"),
        fields.get("required"),
        fields.get("respawn_delay"),
    )
    if problem:
        raise ValueError(problem)
    cwd = fields.get("cwd")
    return {
        "respawn": bool_attribute(fields.get("respawn"), False, "respawn"),
        "required": bool_attribute(fields.get("required"), False, "required"),
        "respawn_delay": float_attribute(fields.get("respawn_delay"), 0.0, "respawn_delay"),
        "args": fields.get("args") or "",
        "machine": fields.get("machine") or None,
        "launch_prefix": fields.get("launch-prefix") or None,
        "cwd": "ROS_HOME" if cwd == "ros_home" else cwd,
        "output": fields.get("output"),
    }
