"""Every launch condition as the frontends write it: one registration each. A condition
becomes the ``if`` or ``unless`` attribute of the action it is given to: the text of its
predicate, or whether a launch configuration is a text (``LaunchConfigurationEquals``; its
``NotEquals`` the ``unless`` of the same)."""

from __future__ import annotations

from dataclasses import dataclass

from rosvar.ros2.api.registry import Registry


@dataclass(frozen=True)
class Condition:
    python: tuple[str, ...]
    """Qualified Python class names."""
    attribute: str
    """``if`` or ``unless``."""
    compares: bool = False
    """Its arguments are a launch configuration's name and the text it must be (or none:
    undefined); else its argument is the predicate's text."""
    names: tuple[str, ...] = ()  # no frontend name of its own: it is an attribute


CONDITIONS: Registry[Condition] = Registry("condition")
CONDITIONS.expose(Condition(("launch.IfCondition",), "if"))
CONDITIONS.expose(Condition(("launch.UnlessCondition",), "unless"))
CONDITIONS.expose(Condition(("launch.LaunchConfigurationEquals",), "if", compares=True))
CONDITIONS.expose(Condition(("launch.LaunchConfigurationNotEquals",), "unless", compares=True))
