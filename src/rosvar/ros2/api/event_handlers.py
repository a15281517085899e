"""Every event handler of launch and launch_ros that ``RegisterEventHandler`` registers, one
registration each: the event it waits for, the argument naming the action whose events it
handles, and the arguments holding the actions it runs. The Python frontend writes a
registered handler as an element of its own tag (``<on_process_start target=...>`` holding
its actions; no XML or YAML frontend has them), which :mod:`rosvar.ros2.tags.events` walks."""

from __future__ import annotations

from dataclasses import dataclass

from rosvar.ros2.api.registry import Registry


@dataclass(frozen=True)
class EventHandler:
    names: tuple[str, ...]
    """The element's tag."""
    python: tuple[str, ...]
    """Qualified Python class names."""
    target: str | None
    """The argument naming the action whose events it handles (none: every such event)."""
    actions: tuple[str, ...]
    """The arguments holding the actions it runs."""
    at_launch: bool
    """Whether its event comes as the launch starts (a process starting); else later (a
    process exiting, its output, a lifecycle transition, the shutdown), when the actions it
    runs start nothing the launch itself starts."""

    @property
    def tag(self) -> str:
        return self.names[0]


EVENT_HANDLERS: Registry[EventHandler] = Registry("event handler")


def expose(tag: str, python: str, target: str | None, *actions: str, at_launch: bool) -> None:
    EVENT_HANDLERS.expose(EventHandler((tag,), (python,), target, actions, at_launch))


expose("on_process_start", "launch.OnProcessStart", "target_action", "on_start", at_launch=True)
expose("on_process_exit", "launch.OnProcessExit", "target_action", "on_exit", at_launch=False)
expose(
    "on_execution_complete",
    "launch.OnExecutionComplete",
    "target_action",
    "on_completion",
    at_launch=False,
)
expose(
    "on_process_io",
    "launch.OnProcessIO",
    "target_action",
    "on_stdin",
    "on_stdout",
    "on_stderr",
    at_launch=False,
)
expose("on_shutdown", "launch.OnShutdown", None, "on_shutdown", at_launch=False)
expose(
    "on_state_transition",
    "launch_ros.OnStateTransition",
    "target_lifecycle_node",
    "entities",
    at_launch=False,
)
