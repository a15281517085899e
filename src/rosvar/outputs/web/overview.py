"""The graph as the page draws it, grouped on the server: summaries first, members on demand.

A large workspace's whole graph is tens of MB of JSON (Husky with its dependencies' launch
files as features: 25,000 entries, 18 MB), far more than a page should load to draw a few
dozen boxes. So a session in *overview* mode is sent, instead of the graph's entries, one
summary per group of the chosen grouping (package then launch file, launch file, or
namespace: the page's own groups) with its counts, and a group's members are fetched when
the user opens it, a page at a time. The feature tree goes compactly too: its fixed part
(ids, kinds, parents) once, from :func:`catalog`, and each state's selections as one
character per feature.

Everything here reads the state document (``outputs.documents.state``), so what is
summarised is exactly what the whole document would carry.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from functools import lru_cache
from typing import Any

from rosvar.configuration.engine import Configurator, Selection

Entry = Mapping[str, Any]
SEPARATOR = "\u0001"  # between the labels of a group's key (never in a path or a ROS name)
PAGE = {"nodes": 24, "params": 50, "topics": 50, "services": 50, "actions": 50}
"""Members sent per page: for nodes, names (all the variants of a name come together)."""
LABELS_KEPT = 65_536  # names and files whose groups are remembered (every state files them all)
ABSENT = "absent"
PRESENT = "present"


class Grouping(StrEnum):
    """How the graph's elements are grouped: the page's *group by*."""

    PACKAGE = "package"
    FILE = "file"
    NAMESPACE = "namespace"


class MemberKind(StrEnum):
    """The members of a group that can be fetched."""

    NODES = "nodes"
    PARAMS = "params"
    TOPICS = "topics"
    SERVICES = "services"
    ACTIONS = "actions"


CHANNELS = (MemberKind.TOPICS, MemberKind.SERVICES, MemberKind.ACTIONS)
"""The names nodes are wired to: counted and listed under the groups of their nodes."""
SIDES = {
    MemberKind.TOPICS: ("publishers", "subscribers"),
    MemberKind.SERVICES: ("servers", "clients"),
    MemberKind.ACTIONS: ("servers", "clients"),
}
"""The side feeding a name and the side using it (a link goes from the one to the other)."""
LINK = "\u0002"  # between the kind and the two group keys of a link's id (never in a key)


# -- names (files spelled as the page's names.js spells them) ------------------------------------
def entry_file(element_id: str) -> str:
    """The launch file whose model holds a graph entry: its id starts with it (``FILE|...``)."""
    cut = element_id.find("|")
    return element_id[:cut] if cut > 0 else ""


def package_of(path: str) -> str:
    """The ROS package of a launch file: the directory above ``launch/``, else the parent."""
    parts = path.split("/")
    launch = _last(parts, "launch")
    if launch > 0:
        return parts[launch - 1]
    return parts[-2] if len(parts) > 1 else "."


def short_path(path: str) -> str:
    """``pkg/sub/file.launch``, as people name a launch file."""
    parts = path.split("/")
    launch = _last(parts, "launch")
    if launch > 0:
        return "/".join([parts[launch - 1], *parts[launch + 1 :]])
    return "/".join(parts[-2:])


def namespace_path(name: str) -> list[str]:
    """``/a/b/c`` → ``["/a/", "/a/b/"]``; a name in the root namespace → ``["/"]``."""
    cut = name.rfind("/")
    if cut <= 0:
        return ["/"]
    namespace = name[: cut + 1]
    return [namespace[: at + 1] for at, char in enumerate(namespace) if char == "/" and at > 0]


def _last(parts: Sequence[str], item: str) -> int:
    return max((index for index, part in enumerate(parts) if part == item), default=-1)


Packages = Mapping[str, str | None]
"""A launch file's id → its ROS package's name, as the feature tree groups files (a ROS 2
package's folder need not be named after it)."""


def packages(features: Mapping[str, Any]) -> dict[str, str]:
    """:data:`Packages` of a state's features as JSON."""
    return {key: f["package"] for key, f in features.items() if f.get("package")}


def labels(grouping: Grouping, entry: Entry, named: Packages) -> tuple[str, ...]:
    """The labels of the groups an entry is filed under, outermost first."""
    if grouping == Grouping.NAMESPACE:
        return _namespaces(str(entry.get("name", "")))
    file = entry_file(str(entry["id"]))
    return _files(grouping, file, named.get(file))


@lru_cache(maxsize=LABELS_KEPT)
def _namespaces(name: str) -> tuple[str, ...]:
    return tuple(namespace_path(name))


@lru_cache(maxsize=LABELS_KEPT)
def _files(grouping: Grouping, file: str, package: str | None) -> tuple[str, ...]:
    if grouping == Grouping.FILE:
        return (short_path(file),)
    return (package or package_of(file), short_path(file))


def key_of(path: Iterable[str]) -> str:
    """A group's id: its labels, each after a separator (the root group's is ``""``)."""
    return "".join(SEPARATOR + label for label in path)


def clash_name(kind: str, name: object) -> str:
    """How a conflict names an element: test nodes clash as nodes."""
    return f"{'node' if kind == 'test' else kind} {name}"


# -- summaries ---------------------------------------------------------------------------------
@dataclass
class _Group:
    label: str
    parent: str
    counts: dict[str, list[int]] = field(
        default_factory=lambda: {kind: [0, 0] for kind in MemberKind}
    )
    conflict: bool = False
    selected: int = 0  # nodes of selected files under it: the page opens such a group
    files: set[str] = field(default_factory=set)  # entry files of the nodes under it
    names: set[str] = field(default_factory=set)  # its own nodes' names, for the search


def summaries(document: Mapping[str, Any], grouping: Grouping) -> list[dict[str, object]]:
    """One summary per group (every level, parents first): label, parent, the present and
    possible (not absent) nodes, params, topics, services and actions under it, whether one
    of its nodes is in a conflict, how many of its nodes the selected files launch, from how
    many entry files its nodes are, and its own nodes' names.
    ``document`` is whole (its features by id)."""
    graph = document["graph"]
    clashing = {name for conflict in document["conflicts"] for name in conflict["names"]}
    features = document["features"]
    named = packages(features)
    selected = {key for key, f in features.items() if f["state"] == Selection.SELECTED}
    groups: dict[str, _Group] = {}

    def chain(entry: Entry) -> list[_Group]:
        found, key = [], ""
        for label in labels(grouping, entry, named):
            parent, key = key, key + SEPARATOR + label
            if key not in groups:
                groups[key] = _Group(label, parent)
            found.append(groups[key])
        return found

    def count(kind: MemberKind, entry: Entry, under: Iterable[_Group]) -> None:
        for group in under:
            counts = group.counts[kind]
            counts[0] += entry["presence"] == PRESENT
            counts[1] += 1

    node_groups: dict[str, list[_Group]] = {}
    for kind, entry in _nodes(graph):
        under = node_groups[str(entry["id"])] = chain(entry)
        count(MemberKind.NODES, entry, under)
        under[-1].names.add(str(entry["name"]))
        clash = clash_name(kind, entry["name"]) in clashing
        file = entry_file(str(entry["id"]))
        chosen = file in selected
        for group in under:
            group.conflict |= clash
            group.selected += chosen
            group.files.add(file)
    for entry in _possible(graph.get("params", ())):
        count(MemberKind.PARAMS, entry, chain(entry))
    for kind in CHANNELS:
        for entry in _possible(graph.get(kind, ())):
            reached = {id(g): g for n in entry.get("nodes", ()) for g in node_groups.get(n, ())}
            count(kind, entry, reached.values())
    return [
        {
            "id": key,
            "label": group.label,
            "parent": group.parent,
            **{kind.value: group.counts[kind] for kind in MemberKind},
            "conflict": group.conflict,
            "selected": group.selected,
            "files": len(group.files),
            "names": sorted(group.names),
        }
        for key, group in sorted(groups.items())
    ]


def links(
    document: Mapping[str, Any], grouping: Grouping, among: Collection[str]
) -> list[dict[str, object]]:
    """The topics, services and actions between the groups ``among`` (the boxes the page
    draws closed), aggregated: one link per kind and pair of those groups (neither holding
    the other) that a name connects, from a group of a node feeding it (publisher, server)
    to a group of a node using it (subscriber, client), with how many such names are present
    and possible: ``{"id": KIND + LINK + FROM + LINK + TO, "count": [present, possible]}``.
    A node wired to a name without a side (a remap, no interface) is at both ends; a name
    none of whose nodes has a side links each pair of groups once, from the smaller key to
    the larger. Each name is counted once per link.

    Asked for the boxes drawn, not sent with every state: every pair of groups at every
    level is thousands of links (3,600 on Husky with ``_external`` as a root, 600 KB), most
    of which change their counts at a step, and a page draws a few dozen boxes."""
    wanted = set(among)
    graph = document["graph"]
    named = packages(document["features"])
    boxes: dict[str, tuple[str, ...]] = {}  # node id → the groups of ``among`` it is under
    for _kind, entry in _nodes(graph):
        chain = _chain(grouping, entry, named)
        if wanted.intersection(chain):
            boxes[str(entry["id"])] = tuple(key for key in chain if key in wanted)
    found: dict[tuple[MemberKind, str, str], list[int]] = {}
    for kind in CHANNELS:
        for entry in _possible(graph.get(kind, ())):
            sided = [{str(edge["node"]) for edge in entry.get(side, ())} for side in SIDES[kind]]
            sideless = {str(node) for node in entry.get("nodes", ())} - sided[0] - sided[1]
            directed = bool(sided[0] or sided[1])
            ends = [
                {key for node in nodes | sideless for key in boxes.get(node, ())} for nodes in sided
            ]
            for source in ends[0]:
                for target in ends[1]:
                    if _under(source, target) or _under(target, source):
                        continue
                    if not directed and source > target:
                        continue  # no sides: one link per pair
                    counts = found.setdefault((kind, source, target), [0, 0])
                    counts[0] += entry["presence"] == PRESENT
                    counts[1] += 1
    return [
        {"id": LINK.join((kind, source, target)), "count": counts}
        for (kind, source, target), counts in sorted(found.items())
    ]


def _chain(grouping: Grouping, entry: Entry, named: Packages) -> tuple[str, ...]:
    """The keys of the groups an entry is under, outermost first."""
    path = labels(grouping, entry, named)
    return tuple(key_of(path[: depth + 1]) for depth in range(len(path)))


def members(
    document: Mapping[str, Any],
    grouping: Grouping,
    group: str,
    kind: MemberKind,
    page: int,
    described: Callable[[list[str]], Mapping[str, Entry]] | None = None,
) -> dict[str, object]:
    """A page of a group's members, sorted by name: whole graph entries. Nodes and params
    are its own (not its subgroups'); a page of nodes holds ``PAGE["nodes"]`` names with all
    their variants. Topics, services and actions are those of the nodes under it at any
    level, as its summary counts them, each with the ``groups`` and the ``names`` of its
    ``nodes`` (the page draws them linked to whatever draws the nodes, a closed box too).
    ``described``: the entries of the ids given with their conditions described, for a
    ``document`` whose entries have them not (the outline of the state)."""
    graph = document["graph"]
    named = packages(document["features"])
    if kind == MemberKind.NODES:
        own = [(k, e) for k, e in _nodes(graph) if key_of(labels(grouping, e, named)) == group]
        by_name: dict[str, list[dict[str, object]]] = {}
        for node_kind, entry in own:
            by_name.setdefault(str(entry["name"]), []).append({**entry, "kind": node_kind})
        names = sorted(by_name)
        chosen = names[page * PAGE[kind] : (page + 1) * PAGE[kind]]
        listed = [entry for name in chosen for entry in by_name[name]]
        total = len(names)
    else:
        if kind == MemberKind.PARAMS:
            found = [
                {**e}
                for e in _possible(graph.get("params", ()))
                if key_of(labels(grouping, e, named)) == group
            ]
        else:  # with its nodes' groups and names: what draws them, and how they read
            nodes = {str(e["id"]): e for _k, e in _nodes(graph)}
            keys = {node: key_of(labels(grouping, e, named)) for node, e in nodes.items()}
            found = [
                {
                    **e,
                    "groups": [keys.get(node) for node in e.get("nodes", ())],
                    "names": [nodes[n]["name"] if n in nodes else None for n in e.get("nodes", ())],
                }
                for e in _possible(graph.get(kind, ()))
                if any(_under(keys.get(node, ""), group) for node in e.get("nodes", ()))
            ]
        found.sort(key=lambda e: (str(e.get("name")), str(e["id"])))
        listed = found[page * PAGE[kind] : (page + 1) * PAGE[kind]]
        total = len(found)
    if described is not None:
        whole = described([str(entry["id"]) for entry in listed])
        listed = [{**entry, **whole[str(entry["id"])]} for entry in listed]
    pages = max(1, -(-total // PAGE[kind]))
    return {"group": group, "kind": kind, "page": page, "pages": pages, "members": listed}


def _under(key: str, group: str) -> bool:
    return key == group or key.startswith(group + SEPARATOR)


def _possible(entries: Iterable[Entry]) -> Iterator[Entry]:
    return (entry for entry in entries if entry["presence"] != ABSENT)


def _nodes(graph: Mapping[str, Any]) -> Iterator[tuple[str, Entry]]:
    for kind, listed in (("node", graph.get("nodes", ())), ("test", graph.get("tests", ()))):
        for entry in _possible(listed):
            yield kind, entry


# -- the feature tree --------------------------------------------------------------------------
SELECTIONS = {
    (Selection.UNSELECTED, False): "u",
    (Selection.SELECTED, False): "s",
    (Selection.DESELECTED, False): "d",
    (Selection.SELECTED, True): "S",
    (Selection.DESELECTED, True): "D",
}
"""A feature's state in one character: chosen by the user lower case, derived upper case."""


def catalog(configurator: Configurator) -> list[list[object]]:
    """The feature tree's fixed part, in tree order: ``[id, kind, file, arg, value, parent,
    default, package, doc]`` per feature: ``file`` and ``package`` on a file's row only (the
    others are their file's), ``parent`` the row of its parent (-1: none), ``default`` whether
    it is its arg's default value, ``doc`` an arg's description (None: none)."""
    features = configurator.state([]).features
    row = {key: number for number, key in enumerate(features)}
    defaults = {
        entry.id
        for arg in configurator.catalog.args
        for entry, value in configurator.catalog.values_of(arg)
        if value.default
    }
    return [
        [
            key,
            f.kind,
            f.file if f.parent is None else None,
            f.arg,
            f.value,
            row[f.parent] if f.parent is not None else -1,
            key in defaults,
            f.package if f.parent is None else None,
            f.doc,
        ]
        for key, f in features.items()
    ]


def compact(document: Mapping[str, Any], grouping: Grouping) -> dict[str, Any]:
    """``document`` in overview mode: the features' states as one string (in the order of
    :func:`catalog`), the graph as group summaries and the errors roslaunch stops on, and how
    many topics, services and actions are possible (the links between groups are asked for
    apart: :func:`links`)."""
    graph = document["graph"]
    return {
        **document,
        "features": "".join(
            SELECTIONS[(f["state"], f["derived"])] for f in document["features"].values()
        ),
        "graph": {
            "groups": summaries(document, grouping),
            "errors": [e for e in graph.get("errors", ()) if e["presence"] == PRESENT],
        },
        "channels": {
            kind.value: sum(1 for _ in _possible(graph.get(kind, ()))) for kind in CHANNELS
        },
        "grouping": grouping,
    }
