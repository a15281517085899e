"""Every launch condition as the frontends write it: one registration each. A condition
becomes the ``if`` or ``unless`` attribute of the action it is given to, the text of its
predicate, or a comparison of a launch configuration with a value."""

from __future__ import annotations

from dataclasses import dataclass

from rosvar.ros2.api.registry import Registry


@dataclass(frozen=True)
class Condition:
    python: tuple[str, ...]
    """Qualified Python class names."""
    attribute: str
    """``if`` or ``unless``."""
    compare: str | None = None
    """The substitution comparing the launch configuration named by the first argument
    with the second (``equals``); none: the first argument is the predicate's text."""
    names: tuple[str, ...] = ()  # no frontend name of its own: it is an attribute


CONDITIONS: Registry[Condition] = Registry("condition")
CONDITIONS.expose(Condition(("launch.IfCondition",), "if"))
CONDITIONS.expose(Condition(("launch.UnlessCondition",), "unless"))
CONDITIONS.expose(Condition(("launch.LaunchConfigurationEquals",), "if", "equals"))
CONDITIONS.expose(Condition(("launch.LaunchConfigurationNotEquals",), "if", "not-equals"))
