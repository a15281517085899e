"""Topics, services and actions for queries, from the communication graph.

Without interfaces, queries know the topics remaps name, with no publishers or subscribers.
With the nodes' interfaces (docs/interfaces.md) the communication graph knows who uses which
resolved name under which condition: these collections replace ``topics`` and add
``services`` and ``actions``, each name's users an :class:`ElementSet` of the node elements
with the conditions of their edges, so ``topics[len(self.publishers) > 1]`` holds exactly
where two publishers are present. Names known statically only (as in ``rosvar check``).
"""

from __future__ import annotations

from collections.abc import Callable

from rosvar.analyses.communication import (
    JSON_SIDES,
    SIDES,
    Channel,
    Described,
    Edge,
    model_edges,
)
from rosvar.analyses.query.collections import (
    Collection,
    Element,
    ElementSet,
    Kind,
    Queryable,
    node_elements,
    remapped_topics,
)
from rosvar.diagnostics import Location
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.workspace.interfaces.model import Interfaces

KINDS = {Channel.TOPICS: Kind.TOPIC, Channel.SERVICES: Kind.SERVICE, Channel.ACTIONS: Kind.ACTION}
DOCS = {
    Channel.TOPICS: "topics nodes publish or subscribe to, or remaps name",
    Channel.SERVICES: "services nodes serve or call",
    Channel.ACTIONS: "actions nodes serve or call",
}


def channel_collections(
    interfaces: Interfaces, described: Described | None = None
) -> dict[str, Collection]:
    """``topics``, ``services`` and ``actions`` of the communication graph of ``interfaces``
    (and of what ``described`` adds: a spawned robot description's plugins, bridges)."""
    found = {}
    for channel in Channel:
        sides = JSON_SIDES[channel]
        remaps = ("remapped_by",) if channel == Channel.TOPICS else ()
        attributes = ("name", "types", *sides, *remaps, "launch_file")
        provider = _provider(channel, interfaces, described)
        found[str(channel)] = Collection(str(channel), attributes, provider, DOCS[channel])
    return found


def _provider(
    channel: Channel, interfaces: Interfaces, described: Described | None
) -> Callable[[Analysis, LaunchModel], list[Element]]:
    def elements(analysis: Analysis, model: LaunchModel) -> list[Element]:
        space = analysis.space
        entry = analysis.label(model.file)
        nodes: dict[tuple[Location, str | None], Element] = {}
        declared: dict[Location, Element] = {}  # a plugin's edge names its spawner's place
        for decl, node in node_elements(analysis, model):
            nodes[decl.location, node.name] = node
            declared.setdefault(decl.location, node)
            if decl.value(decl.schema.name).values() == [None]:
                # a ROS 2 node the launch file does not name: its code does (the edge's)
                nodes[decl.location, None] = node
        named: dict[str, list[Edge]] = {}
        for edge in model_edges(space, model, interfaces, described):
            if edge.static and edge.channel == channel:
                named.setdefault(edge.name, []).append(edge)
        remapped = {}
        if channel == Channel.TOPICS:
            remapped = {topic.name: topic for topic in remapped_topics(analysis, model)}
        found = []
        for name in sorted(named.keys() | remapped.keys()):
            edges = named.get(name, [])
            sides: tuple[list[tuple[BDD, Queryable]], list[tuple[BDD, Queryable]]] = ([], [])
            presence = space.false
            for edge in edges:
                presence |= edge.condition
                user = (
                    nodes.get((edge.launch, edge.node))
                    or nodes.get((edge.launch, None))
                    or declared.get(edge.launch)
                )
                if user is not None:
                    sides[SIDES[channel].index(edge.role)].append((edge.condition, user))
            location: Location | None = edges[0].launch if edges else None
            values: dict[str, Choice[object]] = {
                "name": Choice.const(space, name),
                "types": Choice.const(space, tuple(sorted({e.type for e in edges if e.type}))),
                **{
                    key: Choice.const(space, ElementSet(tuple(side)))
                    for key, side in zip(JSON_SIDES[channel], sides, strict=True)
                },
                "launch_file": Choice.const(space, entry),
            }
            topic = remapped.get(name)
            if channel == Channel.TOPICS:
                empty = Choice.const(space, ElementSet(()))
                values["remapped_by"] = empty if topic is None else topic.attribute("remapped_by")
            if topic is not None:
                presence |= topic.presence
                location = location or topic.location
            found.append(Element(KINDS[channel], name, entry, presence, location, values))
        return found

    return elements
