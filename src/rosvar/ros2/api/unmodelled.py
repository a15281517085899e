"""The public names of launch and launch_ros that rosvar does not model, each with the reason:
one registration each, so that a Python launch file using one is told why
(``python-not-followed``) and an XML or YAML ``$(name)`` fails with it
(``substitution-unsupported``), never as an unknown name. Every other public name is
modelled: an action, substitution, condition, description source or event handler of the
other registries, or a value the Python frontend builds (``tests/ros2/api/test_names.py``
walks launch's and launch_ros' ``__all__`` lists and fails on a name that is neither).
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from rosvar.ros2.api.registry import Registry


class Kind(enum.StrEnum):
    """What the name is in launch, which says why it cannot be in a launch model."""

    ACTION = "action"
    SUBSTITUTION = "substitution"
    EVENT = "event"
    EVENT_HANDLER = "event handler"
    DESCRIPTION = "description"
    HELPER = "helper"  # a function or type of the API, not an entity of a launch
    BASE = "base class"
    ERROR = "exception"
    SERVICE = "launch service"  # what runs a launch, not what a launch file describes
    MODULE = "module"


@dataclass(frozen=True)
class Unmodelled:
    python: tuple[str, ...]
    """Qualified Python names (``launch.OpaqueCoroutine``)."""
    kind: Kind
    reason: str
    """Why it is not modelled: what launch does with it that rosvar does not follow."""
    names: tuple[str, ...] = ()
    """Its ``$(name)`` in the XML and YAML frontends, if any."""

    def why(self, name: str = "") -> str:
        """The diagnostic's text: the name (``name``, else its first) and the reason."""
        name = name or (f"$({self.names[0]})" if self.names else self.python[0])
        return f"{name.rpartition('.')[2]} ({self.kind}: {self.reason})"


UNMODELLED: Registry[Unmodelled] = Registry("unmodelled name")


def unmodelled(kind: Kind, reason: str, *python: str, names: tuple[str, ...] = ()) -> None:
    UNMODELLED.expose(Unmodelled(python, kind, reason, names))


_RUN_TIME = "known only when the launch runs"

# -- actions --------------------------------------------------------------------------------
unmodelled(
    Kind.ACTION,
    "runs a coroutine on the launch's event loop, which is never run",
    "launch.OpaqueCoroutine",
)
unmodelled(
    Kind.ACTION,
    "a process of an Executable description; rosvar models ExecuteProcess and Node",
    "launch.ExecuteLocal",
)
unmodelled(
    Kind.ACTION,
    "pushes or pops the environment or the launch configurations: what a scoped GroupAction "
    "does; written alone they pair across the description, which is not followed",
    "launch.PushEnvironment",
    "launch.PopEnvironment",
    "launch.PushLaunchConfigurations",
    "launch.PopLaunchConfigurations",
)
unmodelled(
    Kind.ACTION,
    "removes a launch configuration by name, which only the Python API can",
    "launch.UnsetLaunchConfiguration",
)
unmodelled(
    Kind.ACTION,
    "removes an event handler registered before; the handlers' actions run on events",
    "launch.UnregisterEventHandler",
)
unmodelled(
    Kind.ACTION,
    "asks a lifecycle node for a transition at run time; the node itself is modelled",
    "launch_ros.LifecycleTransition",
)
unmodelled(
    Kind.ACTION,
    "rolling's loops over a launch argument's values (not in jazzy, the oracle)",
    "launch.ForEach",
    "launch.ForLoop",
)
unmodelled(
    Kind.ACTION,
    "rolling's include in a scope of its own (not in jazzy, the oracle)",
    "launch.ScopedIncludeLaunchDescription",
)

# -- substitutions --------------------------------------------------------------------------
unmodelled(
    Kind.SUBSTITUTION,
    "a value of the event being handled (its pid, its return code), " + _RUN_TIME,
    "launch.LocalSubstitution",
)
unmodelled(
    Kind.SUBSTITUTION,
    "the launch's log folder (~/.ros/log/<date>-<host>-<pid>), " + _RUN_TIME,
    "launch.LaunchLogDir",
    names=("launch_log_dir", "log_dir"),
)
unmodelled(
    Kind.SUBSTITUTION,
    "a global parameter's value as SetParameter left it, not followed",
    names=("param",),
)
unmodelled(
    Kind.BASE, "the base of FindPackagePrefix and FindPackageShare", "launch_ros.FindPackage"
)
unmodelled(
    Kind.SUBSTITUTION,
    "launch_testing's, for test descriptions, which are not launch files",
    names=("test",),
)

# -- events and their handlers --------------------------------------------------------------
unmodelled(
    Kind.EVENT_HANDLER,
    "the handler of included launch descriptions launch registers itself",
    "launch.OnIncludeLaunchDescription",
)
unmodelled(
    Kind.EVENT,
    "emitted by launch itself, or by EmitEvent, whose events other than Shutdown (the "
    "<shutdown> action's) are not followed",
    "launch.ExecutionComplete",
    "launch.TimerEvent",
    "launch.ProcessExited",
    "launch.ProcessIO",
    "launch.ProcessStarted",
    "launch.ProcessStderr",
    "launch.ProcessStdin",
    "launch.ProcessStdout",
    "launch.ProcessTargetedEvent",
    "launch.RunningProcessEvent",
    "launch.ShutdownProcess",
    "launch.SignalProcess",
    "launch_ros.ChangeState",
    "launch_ros.StateTransition",
)
unmodelled(
    Kind.HELPER,
    "matches the events of a process or node, for event handlers",
    "launch.matches_action",
    "launch.event_named",
    "launch.matches_executable",
    "launch.matches_name",
    "launch.matches_pid",
    "launch_ros.matches_node_name",
)

# -- descriptions, sources, helpers ---------------------------------------------------------
unmodelled(
    Kind.DESCRIPTION,
    "an executable's command line for ExecuteLocal, which is not modelled",
    "launch.Executable",
)
unmodelled(
    Kind.HELPER,
    "loads or imports a launch file at run time; an include of it is modelled",
    "launch.get_launch_description_from_any_launch_file",
    "launch.get_launch_description_from_python_launch_file",
    "launch.get_launch_description_from_frontend_launch_file",
    "launch.load_python_launch_file_as_module",
)
unmodelled(
    Kind.HELPER,
    "evaluates a condition's text; the conditions themselves are modelled",
    "launch.evaluate_condition_expression",
)
unmodelled(
    Kind.HELPER,
    "a type of the API's signatures, no value",
    "launch.SomeEntitiesType",
    "launch.SomeEntitiesType_types_tuple",
    "launch.SomeSubstitutionsType",
    "launch.SomeSubstitutionsType_types_tuple",
)
unmodelled(
    Kind.BASE,
    "a base class: a launch file's subclass of it is its own code",
    "launch.Action",
    "launch.Condition",
    "launch.Event",
    "launch.EventHandler",
    "launch.LaunchDescriptionEntity",
    "launch.LaunchDescriptionSource",
    "launch.Substitution",
)
unmodelled(
    Kind.ERROR,
    "raised by launch where rosvar reports a diagnostic",
    "launch.InvalidLaunchFileError",
    "launch.InvalidFrontendLaunchFileError",
    "launch.InvalidPythonLaunchFileError",
    "launch.InvalidConditionExpressionError",
    "launch.SubstitutionFailure",
)
unmodelled(
    Kind.SERVICE,
    "runs or inspects a launch; a launch file only describes one",
    "launch.LaunchService",
    "launch.LaunchIntrospector",
    "launch.LaunchContext",
)
unmodelled(
    Kind.HELPER,
    "a frontend's parser and entity classes; rosvar reads XML and YAML with its own",
    "launch.Entity",
    "launch.Parser",
    "launch_xml.Entity",
    "launch_xml.Parser",
    "launch_yaml.Entity",
    "launch_yaml.Parser",
)
unmodelled(
    Kind.MODULE,
    "launch's logging, frontend machinery and ROS adapters, which launch files do not describe",
    "launch.logging",
    "launch.frontend",
    "launch_ros.ros_adapters",
)
