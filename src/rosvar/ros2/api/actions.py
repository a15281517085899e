"""Every launch action (and the elements actions read) as each frontend writes it: one
registration each, as launch's ``@expose_action``.

An :class:`Action` carries its XML/YAML tag(s), its Python class name(s) with their aliases,
and for each constructor argument the attribute or children it becomes and how (a
:class:`Param`); the attributes the XML and YAML frontends accept beyond those
(``xml_only``) complete what a file may write. The Python frontend builds elements from it
(:mod:`rosvar.ros2.frontends.python.actions`), the attribute check reads it
(:mod:`rosvar.ros2.schema`), and the ROS 2 dialect takes a handler only for an action
registered here (:mod:`rosvar.ros2.dialect`).
"""

from __future__ import annotations

import enum
import functools
from dataclasses import dataclass

from rosvar.ros2.api.event_handlers import EVENT_HANDLERS
from rosvar.ros2.api.registry import Registry

SHARED = "shared"
"""The attribute of a ``<remap>`` whose pair a Python file gives to several nodes, as a group's
remap (:mod:`rosvar.ros2.frontends.python.shared_remaps` writes it; no XML or YAML tag has it)."""


class Slot(enum.StrEnum):
    """How one constructor argument is written into the element."""

    ATTRIBUTE = "attribute"  # a text, or a typed scalar
    COMMAND_LINE = "command-line"  # a list of arguments, one space-separated attribute
    PARAMETERS = "parameters"  # dicts and files: <param name value> / <param from>
    PAIRS = "pairs"  # (from, to) pairs: <remap from to>
    NAMED_VALUES = "named-values"  # a dict or (name, value) pairs: <env name value>...
    VALUES = "values"  # a list: <choice value>
    ACTIONS = "actions"  # actions (or descriptions) as children
    DESCRIPTIONS = "descriptions"  # composable node descriptions, each under its condition


@dataclass(frozen=True, slots=True)
class Param:
    """One constructor argument: its Python name, its XML attribute or child tag (none for
    actions of any tag), and how it is written."""

    python: str
    xml: str
    slot: Slot = Slot.ATTRIBUTE
    before: str | None = None
    """Its Python name in launch_ros before Galactic (``node_executable``), which later
    releases refuse: read as this one, with a warning."""


@dataclass(frozen=True)
class Action:
    """One action, or an element an action reads (``walked`` false: ``<param>``)."""

    names: tuple[str, ...]
    """XML/YAML tags; the first is the one the Python frontend writes."""
    python: tuple[str, ...] = ()
    """Qualified Python class names, aliases included; none: no Python equivalent."""
    params: tuple[Param, ...] = ()
    """The Python constructor's arguments, positional ones first."""
    xml_only: tuple[str, ...] = ()
    """Attributes and children only the XML and YAML frontends take."""
    holds_actions: bool = False
    """Its children are actions (each checked as one), not elements it reads."""
    python_only: bool = False
    """A tag only the Python frontend makes (``LifecycleNode`` has no XML or YAML tag)."""
    walked: bool = True
    """An action the walk runs (with a handler); else an element its parent reads."""

    @property
    def tag(self) -> str:
        return self.names[0]

    @functools.cached_property
    def attributes(self) -> frozenset[str]:
        """The attributes and children a file may give it (beside ``if``/``unless``)."""
        return frozenset(p.xml for p in self.params if p.xml) | frozenset(self.xml_only)


ACTIONS: Registry[Action] = Registry("action")
expose = ACTIONS.expose


def attributes(*names: str) -> tuple[Param, ...]:
    """Attributes named as in Python, or ``python:xml``."""
    return tuple(Param(name.partition(":")[0], name.rpartition(":")[2]) for name in names)


# -- launch ---------------------------------------------------------------------------------

expose(Action(("launch",), xml_only=("version",), holds_actions=True, walked=False))
expose(
    Action(
        ("arg",),
        ("launch.DeclareLaunchArgument",),
        (
            *attributes("name", "default_value:default", "description"),
            Param("choices", "choice", Slot.VALUES),
        ),
        xml_only=("value",),
    )
)
expose(Action(("choice",), xml_only=("value",), walked=False))
expose(Action(("let",), ("launch.SetLaunchConfiguration",), attributes("name", "value")))
expose(
    Action(
        ("group",),
        ("launch.GroupAction",),
        (
            Param("actions", "", Slot.ACTIONS),
            *attributes("scoped", "forwarding"),
            Param("launch_configurations", "keep", Slot.NAMED_VALUES),
        ),
        holds_actions=True,
    )
)
expose(Action(("keep",), xml_only=("name", "value"), walked=False))
expose(
    Action(
        ("include",),
        ("launch.IncludeLaunchDescription",),
        (
            Param("launch_description_source", "file"),  # a source or a path, as text
            Param("launch_arguments", "arg", Slot.NAMED_VALUES),
        ),
    )
)
_TIMER = (
    *attributes("period"),
    Param("actions", "", Slot.ACTIONS),
    *attributes("cancel_on_shutdown"),
)
expose(Action(("timer",), ("launch.TimerAction",), _TIMER, holds_actions=True))
expose(Action(("shutdown",), ("launch.Shutdown",), attributes("reason")))
expose(Action(("log",), ("launch.LogInfo",), attributes("msg:message")))
expose(Action(("set_env",), ("launch.SetEnvironmentVariable",), attributes("name", "value")))
expose(Action(("unset_env",), ("launch.UnsetEnvironmentVariable",), attributes("name")))
expose(
    Action(
        ("append_env",),
        ("launch.AppendEnvironmentVariable",),
        attributes("name", "value", "prepend", "separator"),
    )
)
expose(Action(("reset_env",), ("launch.ResetEnvironment",)))
expose(
    Action(
        ("reset",),
        ("launch.ResetLaunchConfigurations",),
        (Param("launch_configurations", "keep", Slot.NAMED_VALUES),),
    )
)

_PROCESS = (
    *attributes(
        "name",
        "cwd",
        "output",
        "respawn",
        "respawn_delay",
        "respawn_max_retries",
        "prefix:launch-prefix",
        "emulate_tty",
        "shell",
        "sigterm_timeout",
        "sigkill_timeout",
    ),
    Param("additional_env", "env", Slot.NAMED_VALUES),
)
"""What every process (``ExecuteProcess``, ``Node``) takes."""
_PROCESS_XML = ("on_exit",)
expose(
    Action(
        ("executable",),
        ("launch.ExecuteProcess",),
        (Param("cmd", "cmd", Slot.COMMAND_LINE), *_PROCESS),
        xml_only=_PROCESS_XML,
    )
)
expose(Action(("env",), xml_only=("name", "value"), walked=False))

# -- launch_ros -----------------------------------------------------------------------------

_ROS_NODE = (
    Param("parameters", "param", Slot.PARAMETERS),
    Param("remappings", "remap", Slot.PAIRS),
)
_NODE_NAMES = (
    Param("name", "name", before="node_name"),
    Param("namespace", "namespace", before="node_namespace"),
)
"""A node's name and namespace, as launch_ros names them since Foxy."""
_NODE = (
    *attributes("package:pkg"),
    Param("executable", "exec", before="node_executable"),
    *_NODE_NAMES,
    *attributes("exec_name"),
    *_PROCESS,
    *_ROS_NODE,
    Param("arguments", "args", Slot.COMMAND_LINE),
    Param("ros_arguments", "ros_args", Slot.COMMAND_LINE),
)
_NODE_XML = (*_PROCESS_XML, "node-name")
expose(Action(("node",), ("launch_ros.Node",), _NODE, _NODE_XML))
expose(
    Action(("lifecycle_node",), ("launch_ros.LifecycleNode",), _NODE, _NODE_XML, python_only=True)
)
_DESCRIPTIONS = Param("composable_node_descriptions", "composable_node", Slot.DESCRIPTIONS)
expose(
    Action(
        ("node_container",),
        ("launch_ros.ComposableNodeContainer",),
        (*_NODE, _DESCRIPTIONS),
        _NODE_XML,
    )
)
expose(
    Action(
        ("load_composable_node",),
        ("launch_ros.LoadComposableNodes",),
        (_DESCRIPTIONS, *attributes("target_container:target")),
    )
)
expose(
    Action(
        ("composable_node",),
        ("launch_ros.ComposableNode",),
        (
            *attributes("package:pkg", "plugin"),
            *_NODE_NAMES,
            *_ROS_NODE,
            Param("extra_arguments", "extra_arg", Slot.PARAMETERS),
        ),
        walked=False,
    )
)
expose(Action(("extra_arg",), xml_only=("name", "value"), walked=False))
expose(
    Action(
        ("param",),
        xml_only=("name", "value", "type", "from", "allow_substs", "param", "sep"),
        walked=False,
    )
)
expose(Action(("remap",), xml_only=("from", "to"), walked=False))
expose(
    Action(
        ("push-ros-namespace", "push_ros_namespace"),
        ("launch_ros.PushROSNamespace", "launch_ros.PushRosNamespace"),
        attributes("namespace"),
    )
)
expose(Action(("set_remap",), ("launch_ros.SetRemap",), attributes("src:from", "dst:to")))
expose(Action(("set_parameter",), ("launch_ros.SetParameter",), attributes("name", "value")))
expose(
    Action(
        ("set_parameters_from_file",),
        ("launch_ros.SetParametersFromFile",),
        attributes("filename"),
    )
)
expose(Action(("set_use_sim_time",), ("launch_ros.SetUseSimTime",), attributes("value")))
expose(Action(("set_ros_log_dir",), ("launch_ros.SetROSLogDir",), attributes("new_log_dir")))
expose(
    Action(
        ("ros_timer",),
        ("launch_ros.RosTimer", "launch_ros.ROSTimer"),
        _TIMER,
        holds_actions=True,
    )
)

# -- event handlers, as RegisterEventHandler registers them (ros2/api/event_handlers.py) -----
for _handler in EVENT_HANDLERS:
    expose(Action(_handler.names, xml_only=("target",), holds_actions=True, python_only=True))
