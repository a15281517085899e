"""Dialects: what one ROS brings to the core, and the registry the core finds them in.

The core (the walk, the analyses, configuration, outputs) follows whichever ROS a workspace
is, and names neither: it looks the workspace's :class:`Dialect` up by :class:`RosVersion`
(:func:`dialect_of`). The dialect packages (``rosvar.ros1``, ``rosvar.ros2``) provide them,
and a module above both registers them (:mod:`rosvar.dialects`), each imported on first use,
as ros2/launch finds its frontends by entry point without naming them.

This module stays light (typing-only imports): the package imports it at start-up.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Protocol

from rosvar.ros.version import RosVersion

if TYPE_CHECKING:
    from rosvar.frontends.entity import ParseResult
    from rosvar.frontends.xml import Snapshot
    from rosvar.interpreter.model import LaunchModel, NodeSchema
    from rosvar.interpreter.resolution import Checks, NodeFields, Resolver
    from rosvar.logic.conditions import ConditionSpace
    from rosvar.logic.inputs import Slot
    from rosvar.workspace import Workspace

__all__ = ["Dialect", "Loader", "RosVersion", "dialect_of", "register"]

Loader = Callable[[str], "ParseResult"]
"""A dialect's frontends: a launch file of any of its formats to an entity tree."""


class Dialect(Protocol):
    """What the core asks of one ROS, whatever the scope its walk carries (the generic
    :class:`~rosvar.interpreter.semantics.Semantics` implements it)."""

    @property
    def version(self) -> RosVersion: ...

    @property
    def loader(self) -> Loader: ...

    def loader_for(self, workspace: Workspace) -> Loader: ...

    @property
    def nodes(self) -> NodeSchema:
        """What its node declarations' fields mean (its node tags stamp them with it)."""
        ...

    @property
    def resolver(self) -> Resolver:
        """What its launch tool starts in one configuration, read off the models."""
        ...

    @property
    def checks(self) -> Checks | None:
        """What its launch tool checks of a node's strings (None: nothing the graph checks
        of a typed text)."""
        ...

    @property
    def node_fields(self) -> NodeFields:
        """What its launch tool holds of a node in one configuration, beyond what every
        dialect has (the configuration graph's entries show it)."""
        ...

    def interpret(
        self,
        workspace: Workspace,
        space: ConditionSpace,
        domains: Callable[[str, str], tuple[Slot, ...]],
        env_domains: Callable[[str], tuple[Slot, ...]],
        file: str,
        files: Snapshot,
        undeclared: Mapping[str, str],
    ) -> tuple[LaunchModel, set[str]]:
        """The model of entry file ``file`` over every command line, and the args to know
        from the start in another interpretation (ROS 2: read before being declared);
        ``undeclared`` are such args, known from a previous interpretation."""
        ...


_FACTORIES: dict[RosVersion, Callable[[], Dialect]] = {}
_DIALECTS: dict[RosVersion, Dialect] = {}


def register(version: RosVersion, factory: Callable[[], Dialect]) -> None:
    """Make ``factory`` (called on first use) the dialect of ``version``."""
    if version in _FACTORIES:  # a second one would silently replace the first
        raise ValueError(f"{version.label} has two dialects")
    _FACTORIES[version] = factory


def dialect_of(version: RosVersion) -> Dialect:
    """The registered dialect of ``version``."""
    found = _DIALECTS.get(version)
    if found is None:
        factory = _FACTORIES.get(version)
        if factory is None:
            raise LookupError(f"no dialect is registered for {version.label}")
        found = _DIALECTS[version] = factory()
    return found
