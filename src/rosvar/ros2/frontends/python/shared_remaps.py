"""Remaps a Python launch file gives to several nodes as one rule, as a group's remap.

launch_ros has no remap for the nodes of a group (``PushNodeRemapping`` was only proposed),
so files give each node the same list instead: nav2's bringup passes every server
``remappings=remappings`` (``[('/tf', 'tf'), ('/tf_static', 'tf_static')]``), some
``remappings + [('cmd_vel', 'cmd_vel_nav')]``. Such a pair renames for every node it
reaches, as a ``<remap>`` of a ROS 1 ``<group>`` does, so a node that never uses its name is
no mistake (``remap-unused`` reports a node's own remaps only). A pair is shared where one
pair object reaches several nodes (a list in a variable, or a list made of it), or where the
file gives the same pair, by its texts, to each of its nodes, two or more. The reading marks
its ``<remap>`` with :data:`SHARED`, an attribute only this frontend writes.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field

from rosvar.frontends.entity import Entity
from rosvar.ros2.api.actions import ACTIONS, SHARED, Slot

REMAP = "remap"
REMAPPED = frozenset(
    name
    for action in ACTIONS
    if any(p.slot is Slot.PAIRS and p.xml == REMAP for p in action.params)
    for name in action.names
)
"""The elements a file may give remaps (nodes, containers, composable nodes)."""


@dataclass
class SharedRemaps:
    """The ``<remap>`` elements made of each pair object, and the nodes they are under."""

    given: dict[int, tuple[object, list[tuple[Entity, Entity]]]] = field(default_factory=dict)
    """``id`` of the pair object to the object (kept: its ``id`` is never another's) and
    each ``(node, remap)`` made of it."""

    def give(self, pair: object, node: Entity, remap: Entity) -> None:
        """``remap`` made of ``pair`` for ``node``."""
        made = self.given.setdefault(id(pair), (pair, []))[1]
        made.append((node, remap))

    def mark(self, root: Entity) -> None:
        """Mark the remaps of the file under ``root`` whose pair is shared."""
        by_texts: dict[tuple[str | None, str | None], list[tuple[Entity, Entity]]] = {}
        for _pair, made in self.given.values():
            if len({id(node) for node, _remap in made}) > 1:
                _shared(made)
            for node, remap in made:
                by_texts.setdefault((remap.get("from"), remap.get("to")), []).append((node, remap))
        nodes = {id(node) for node in _nodes(root)}
        if len(nodes) < 2:
            return
        for made in by_texts.values():
            if {id(node) for node, _remap in made} >= nodes:
                _shared(made)


def _shared(made: list[tuple[Entity, Entity]]) -> None:
    for _node, remap in made:
        remap.attributes[SHARED] = "true"


def _nodes(root: Entity) -> Iterator[Entity]:
    """The elements below ``root`` that may have remaps, each once (an element may be
    shared by several parents)."""
    seen: set[int] = set()
    pending = [root]
    while pending:
        entity = pending.pop()
        if id(entity) in seen:
            continue
        seen.add(id(entity))
        if entity.tag in REMAPPED:
            yield entity
        pending.extend(entity.children)
