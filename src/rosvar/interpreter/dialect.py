"""Dialects: which ROS's launch semantics an interpretation follows.

One walk (:class:`~rosvar.interpreter.interpretation.Interpretation`) serves ROS 1 and
ROS 2; a dialect supplies what differs between them: the tag handlers and the
substitution language. Each dialect registers its handlers in its own registry.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from rosvar.frontends.entity import Entity
from rosvar.workspace.ros_version import RosVersion

__all__ = ["Dialect", "Handler", "RosVersion"]

if TYPE_CHECKING:
    from rosvar.interpreter.interpretation import Interpretation

Handler = Callable[["Interpretation", Entity, Any], None]
"""A tag handler: the walk, the element, and the dialect's scope (context) type."""


@dataclass
class Dialect:
    """The tag registry and substituter factory of one :class:`RosVersion`."""

    version: RosVersion
    substituter: Callable[[Interpretation], Any]
    tags: dict[str, Handler] = field(default_factory=dict)

    def tag(self, name: str) -> Callable[[Handler], Handler]:
        """Register the handler of ``<name>`` (extension by registry, not if-chains)."""

        def register(handler: Handler) -> Handler:
            if name in self.tags:  # a second handler would silently replace the first
                raise ValueError(f"tag <{name}> is registered twice in {self.version}")
            self.tags[name] = handler
            return handler

        return register
