"""A dialect on the shared walk: what one ROS's launch files mean, typed by its scope.

ROS 1 carries roslaunch's scope along the walk, ROS 2 ros2/launch's context: a dialect is
generic in that scope type (``S``), so that each tag handler, the substituter and the entry
walk agree on it, and the core, which sees a :class:`~rosvar.interpreter.dialect.Dialect`,
never needs to know it.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Generic, TypeVar

from rosvar.frontends.entity import Entity
from rosvar.frontends.xml import Snapshot
from rosvar.interpreter.dialect import Loader
from rosvar.interpreter.interpretation import Handler, Interpretation, Substituter
from rosvar.interpreter.model import LaunchModel, NodeSchema
from rosvar.interpreter.resolution import Checks, NodeFields, Resolver
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import Slot
from rosvar.ros.version import RosVersion
from rosvar.workspace import Workspace
from rosvar.workspace.paths import real_path

S = TypeVar("S")

EntryWalk = Callable[[Interpretation[S], str, Entity, Mapping[str, str]], set[str]]
"""How an entry file is walked: the scope its command line makes (the dialect's scope
factory: the file's args as inputs), the walk of the root's children in it, and the args read
before being declared (to know from the start in another interpretation)."""

Release = Callable[[ConditionSpace, Snapshot], None]
"""Drops what a memo of an analysis (its condition space, its files) keeps for one entry
file: the values over its inputs, the walks its inputs steered, which no other entry file
meets again, and which held most of the analysis's BDD nodes (docs/performance.md)."""


@dataclass
class Semantics(Generic[S]):
    """One ROS's launch semantics: its frontends, substitution language, tag handlers
    (registered by :meth:`tag`), entry walk, node schema and resolution. Implements
    :class:`~rosvar.interpreter.dialect.Dialect`."""

    version: RosVersion
    loader: Loader
    substituter: Callable[[Interpretation[S]], Substituter[S]]
    entry: EntryWalk[S]
    nodes: NodeSchema
    resolver: Resolver
    node_fields: NodeFields
    checks: Checks | None = None
    tags: dict[str, Handler[S]] = field(default_factory=dict)
    bind: Callable[[Workspace], Loader] | None = None
    """The loader for one workspace's files, where a frontend reads more than the file (a
    Python launch file's imports of the workspace's modules); ``loader`` otherwise."""
    released: list[Release] = field(default_factory=list)
    """What drops the memos' entries that served one entry file's interpretations, called
    when an analysis starts on another entry file (:meth:`interpret`)."""

    def loader_for(self, workspace: Workspace) -> Loader:
        return self.loader if self.bind is None else self.bind(workspace)

    def tag(self, name: str) -> Callable[[Handler[S]], Handler[S]]:
        """Register the handler of ``<name>`` (extension by registry, not if-chains)."""

        def register(handler: Handler[S]) -> Handler[S]:
            if name in self.tags:  # a second handler would silently replace the first
                raise ValueError(f"tag <{name}> is registered twice in {self.version.label}")
            self.tags[name] = handler
            return handler

        return register

    def interpretation(
        self,
        workspace: Workspace,
        space: ConditionSpace,
        domains: Callable[[str, str], tuple[Slot, ...]],
        env_domains: Callable[[str], tuple[Slot, ...]],
        file: str,
        files: Snapshot,
    ) -> Interpretation[S]:
        """A walk of ``file`` in this dialect."""
        return Interpretation(
            workspace, space, domains, env_domains, file, files, self.tags, self.substituter
        )

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
        if files.tables.get(__name__) != file:  # the entry file before is done
            files.tables[__name__] = file
            for release in self.released:
                release(space, files)
            if self.released:
                space.collect_garbage()
        it = self.interpretation(workspace, space, domains, env_domains, file, files)
        try:
            it.stack.append(real_path(file))
            root = it.load(file)
            late = set() if root is None else self.entry(it, file, root, undeclared)
            return it.finish(), late
        finally:
            it.close()
