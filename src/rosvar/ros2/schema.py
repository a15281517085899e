"""The attributes and child tags ros2/launch's XML frontend accepts, per tag.

The frontend parses a whole file when it is loaded and fails on an element it does not
know or an attribute nothing read, even inside a group that is never entered: so the check
runs over the whole tree at each load, under the path of the load.
"""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation
from rosvar.workspace.launch_files import LaunchFormat, format_of
from rosvar.workspace.ros_version import RosVersion

PROCESS = frozenset(
    {
        "cwd", "launch-prefix", "output", "respawn", "respawn_delay", "respawn_max_retries",
        "shell", "emulate_tty", "sigterm_timeout", "sigkill_timeout", "on_exit", "env",
    }
)  # fmt: skip
ATTRIBUTES: dict[str, frozenset[str]] = {
    "launch": frozenset({"version"}),
    "arg": frozenset({"name", "default", "description", "value", "choice"}),
    "choice": frozenset({"value"}),
    "let": frozenset({"name", "value"}),
    "include": frozenset({"file", "arg"}),
    "group": frozenset({"scoped", "forwarding", "keep"}),
    "keep": frozenset({"name", "value"}),
    "timer": frozenset({"period", "cancel_on_shutdown"}),
    "ros_timer": frozenset({"period", "cancel_on_shutdown"}),
    "shutdown": frozenset({"reason"}),
    "reset_env": frozenset(),
    "push-ros-namespace": frozenset({"namespace"}),
    "push_ros_namespace": frozenset({"namespace"}),
    "set_remap": frozenset({"from", "to"}),
    "set_parameter": frozenset({"name", "value"}),
    "set_env": frozenset({"name", "value"}),
    "unset_env": frozenset({"name"}),
    "append_env": frozenset({"name", "value", "prepend", "separator"}),
    "reset": frozenset({"keep"}),
    "set_parameters_from_file": frozenset({"filename"}),
    "log": frozenset({"message"}),
    "set_use_sim_time": frozenset({"value"}),
    "set_ros_log_dir": frozenset({"new_log_dir"}),
    "node": PROCESS
    | {"pkg", "exec", "name", "namespace", "args", "ros_args", "exec_name", "node-name"}
    | {"param", "remap"},
    "executable": PROCESS | {"cmd", "name"},
    "node_container": PROCESS
    | {"pkg", "exec", "name", "namespace", "args", "ros_args", "exec_name", "node-name"}
    | {"param", "remap", "composable_node"},
    "load_composable_node": frozenset({"target", "composable_node"}),
    "composable_node": frozenset({"pkg", "plugin", "name", "namespace", "param", "remap"})
    | {"extra_arg"},
    "extra_arg": frozenset({"name", "value"}),
    "param": frozenset({"name", "value", "type", "from", "allow_substs", "param", "sep"}),
    "remap": frozenset({"from", "to"}),
    "env": frozenset({"name", "value"}),
}
PYTHON_ONLY: dict[str, frozenset[str]] = {"lifecycle_node": ATTRIBUTES["node"]}
"""Actions with no XML or YAML tag (``LifecycleNode``): the Python frontend's entities."""
ALWAYS = frozenset({"if", "unless"})
CONTAINERS = frozenset({"group", "launch", "timer", "ros_timer"})


def check(it: Interpretation, root: Entity) -> None:
    """Record the frontend's failure for every unknown element or attribute below ``root``."""
    python = format_of(root.location.file, RosVersion.ROS2) is LaunchFormat.PYTHON
    _check(it, root, {**ATTRIBUTES, **PYTHON_ONLY} if python else ATTRIBUTES)


def _check(it: Interpretation, root: Entity, attributes: dict[str, frozenset[str]]) -> None:
    for entity in root.children:
        allowed = attributes.get(entity.tag)
        if allowed is None:
            it.fail(
                it.space.true,
                "tag-unknown",
                f"Unrecognized entity of the type: {entity.tag}",
                entity.location,
            )
            continue
        container = entity.tag in CONTAINERS  # its children are actions, checked below
        children = [] if container else [child.tag for child in entity.children]
        unexpected = sorted(
            name
            for name in [*entity.attributes, *children]
            if name not in allowed and name not in ALWAYS
        )
        if unexpected:
            it.fail(
                it.space.true,
                "attribute-unexpected",
                f"Unexpected attribute(s) found in `{entity.tag}`: {set(unexpected)}",
                entity.location,
            )
        elif container:
            _check(it, entity, attributes)
        else:
            _nested(it, entity)


def _nested(it: Interpretation, entity: Entity) -> None:
    """Children of a leaf action (``<param>`` in a node, ``<arg>`` in an include...)."""
    for child in entity.children:
        allowed = ATTRIBUTES.get(child.tag, frozenset())
        unexpected = sorted(n for n in child.attributes if n not in allowed and n not in ALWAYS)
        if unexpected:
            it.fail(
                it.space.true,
                "attribute-unexpected",
                f"Unexpected attribute(s) found in `{child.tag}`: {set(unexpected)}",
                child.location,
            )
        _nested(it, child)
