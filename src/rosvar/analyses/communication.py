"""The communication graph: which launched node publishes, subscribes, serves or calls which
name, in every configuration at once.

A launched node is matched to its interface by (package, executable), a nodelet loaded with
``args="load pkg/Class manager"`` by its class, a ROS 2 composable node by its ``plugin``.
Each name of the interface is resolved as the node does at run time (roscpp
``names::resolve``, rospy alike): ``/x`` is global, ``~x`` lies under the node's own name,
``x`` under its namespace; then the node's remappings (whose two sides are resolved the same
way) replace it: the last one of a name in ROS 1, the first in ROS 2 (rcl), where the pushed
namespaces and the global remaps (``<set_remap>``, before the node's own) count too and
``~/x`` is the private name. Every field of ``<node>`` may vary between
configurations, and each remap has its own condition: each use of a name becomes *edges*,
one per resolved name, each with the condition under which the node has it.

The same resolution, fed with one configuration's nodes (:func:`resolved_graph`), gives
``rosvar resolve`` its topics: restricting the variational edges to a configuration
must give exactly those.
"""

from __future__ import annotations

import enum
import re
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, replace
from typing import Protocol, TypeVar

from rosvar.analyses.param_values import ROS2_PARAMETERS, ParamValues, Unknown, param_default
from rosvar.analyses.when import When, concrete_holds, when_condition
from rosvar.diagnostics import Location, Severity
from rosvar.interpreter.model import LaunchModel, NodeDecl, NodeSchema, Raw
from rosvar.interpreter.resolution import ResolvedNode
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.terms import Term
from rosvar.ros import names
from rosvar.ros.version import RosVersion
from rosvar.workspace.interfaces.lifecycle import with_lifecycle
from rosvar.workspace.interfaces.model import (
    INDEX,
    Default,
    Entry,
    Interfaces,
    NamedBy,
    NodeInterface,
    NodeKind,
    Role,
)
from rosvar.workspace.interfaces.values import Text

_R = TypeVar("_R")


class Channel(enum.StrEnum):
    """What kind of name an edge is on; the values are the JSON list names."""

    TOPICS = "topics"
    SERVICES = "services"
    ACTIONS = "actions"


CHANNEL: dict[Role, Channel] = {
    Role.PUBLISHES: Channel.TOPICS,
    Role.SUBSCRIBES: Channel.TOPICS,
    Role.SERVICES: Channel.SERVICES,
    Role.CLIENTS: Channel.SERVICES,
    Role.ACTION_SERVERS: Channel.ACTIONS,
    Role.ACTION_CLIENTS: Channel.ACTIONS,
}
SIDES: dict[Channel, tuple[Role, Role]] = {  # the role feeding a name, the role using it
    Channel.TOPICS: (Role.PUBLISHES, Role.SUBSCRIBES),
    Channel.SERVICES: (Role.SERVICES, Role.CLIENTS),
    Channel.ACTIONS: (Role.ACTION_SERVERS, Role.ACTION_CLIENTS),
}
JSON_SIDES: dict[Channel, tuple[str, str]] = {
    Channel.TOPICS: ("publishers", "subscribers"),
    Channel.SERVICES: ("servers", "clients"),
    Channel.ACTIONS: ("servers", "clients"),
}


@dataclass(frozen=True)
class LaunchedNode:
    """A ``<node>`` as one configuration (or one branch of its fields) has it."""

    package: str
    type: str
    namespace: str  # ROS 2: the pushed and the node's own, combined and absolute
    name: str  # ROS 2: empty when the launch file gives none (the code's, :meth:`named`)
    args: str
    remaps: Sequence[tuple[str, str]]  # in order: a later remap of one name wins (ROS 2: first)
    plugin: str = ""  # a ROS 2 composable node's class
    ros2: bool = False
    lifecycle: bool = False  # ROS 2: started as a LifecycleNode (NodeSchema.lifecycle)

    @staticmethod
    def of(schema: NodeSchema, fields: Mapping[str, Raw | None]) -> LaunchedNode:
        """The node of one variant's field values (``schema.launched``; absent ones None),
        a part not known statically shown as ``{term}``."""
        texts = {key: _text(fields.get(key)) for key in schema.launched}
        return LaunchedNode(
            _text(schema.package.text(texts)),
            _text(schema.executable.text(texts)),
            schema.namespace.text(texts) or names.SEP,
            _text(schema.name.text(texts)),
            _text(schema.args.text(texts)),
            (),
            _text(schema.plugin.text(texts)),
            ros2=schema.version is RosVersion.ROS2,
            lifecycle=schema.lifecycle.text(texts) is not None,
        )

    @staticmethod
    def resolved(node: ResolvedNode) -> LaunchedNode:
        """A node one configuration starts (``rosvar resolve``'s)."""
        return LaunchedNode(
            node.package or "",
            node.executable or "",
            node.namespace or names.SEP,
            node.own_name or "",
            node.args,
            node.remaps,
            node.plugin or "",
            node.ros2,
        )

    def named(self, interface: NodeInterface | None) -> LaunchedNode:
        """ROS 2: without a launch ``name``, the node has the one its code gives it
        (``⟨executable⟩``, as ``rosvar resolve`` shows an unnamed node, when the code does not
        say statically or is not known)."""
        if not self.ros2 or self.name:
            return self
        if interface is not None:
            return replace(self, name=interface.node_name or f"⟨{interface.executable}⟩")
        return replace(self, name=f"⟨{self.plugin or self.type}⟩")

    def interface(self, found: NodeInterface | None, at: Location) -> NodeInterface | None:
        """The interface the node runs: ``found`` (its code's), and the lifecycle interface
        when launch_ros starts it as a ``LifecycleNode`` (the action drives it through those
        services: the node has them whatever rosvar knows of its code, placed at ``at``)."""
        if not self.lifecycle:
            return found
        if found is None:
            found = NodeInterface(self.package, self.plugin or self.type, NodeKind.NODE)
        return replace(found, entries=with_lifecycle(found.entries, at))

    @property
    def full_name(self) -> str:
        if self.ros2:
            return self.namespace.rstrip(names.SEP) + names.SEP + self.name
        return names.ns_join(self.namespace, self.name)

    def unit(self) -> tuple[str, str] | None:
        """The (package, executable) whose interface this node runs; a loaded nodelet's
        class, with an empty package (a class is named ``pkg/Class`` already); a ROS 2
        composable node's class."""
        if self.ros2:
            return self.package, self.plugin or self.type
        words = self.args.split()
        if self.package == "nodelet" and self.type == "nodelet":
            if len(words) >= 2 and words[0] in ("load", "standalone"):
                return "", words[1]
            return None  # a manager: its interface is what it loads
        return self.package, self.type

    def resolve(self, name: str) -> str:
        """``name`` (as the source writes it) as the node resolves it, before remapping."""
        if names.is_private(name):  # ROS 2 writes it ~/x
            return names.canonicalize_name(self.full_name + names.SEP + name[1:])
        return names.canonicalize_name(names.ns_join(self.namespace or names.SEP, name))

    def remap_order(self, remaps: Sequence[_R]) -> Iterable[_R]:
        """``remaps`` in the order they are tried: the first that matches wins."""
        return remaps if self.ros2 else reversed(remaps)


@dataclass(frozen=True)
class Edge:
    """One use of a resolved name by one node, under ``condition``."""

    file: str  # the entry launch file
    node: str  # the node's resolved name
    role: Role
    name: str
    type: str | None
    condition: BDD
    launch: Location  # the <node>
    source: Location  # the use in the node's source
    static: bool  # False: a part of the name is not known statically
    boundary: bool = False  # meant for something outside the launched nodes (Entry.boundary)
    term: Term | None = None
    """A name known per configuration (a robot description's value): evaluated in one."""
    uncertain: bool = False
    """Kept only where its entry's ``when:`` reads a parameter whose value is not known: a
    missing partner of it is a note, not a defect rosvar can see."""

    @property
    def channel(self) -> Channel:
        return CHANNEL[self.role]


@dataclass(frozen=True)
class Gap:
    """A part of the graph analysis could not read where ``condition`` holds (a robot
    description xacro fails on, a Gazebo plugin of an unknown library): ``name`` says what."""

    name: str
    message: str
    condition: BDD
    locations: tuple[Location, ...]  # the first is where it is reported (the launching node)
    severity: Severity
    stops: bool = False  # the launch stops there (xacro failing on a robot description)


class Described(Protocol):
    """Uses that a launch model makes beyond its nodes' code: the Gazebo plugins of the robot
    descriptions its spawners load, the topics its bridges' arguments name (edges of the
    node that loads or runs them), and what of those could not be read."""

    def edges(self, model: LaunchModel) -> list[Edge]: ...

    def gaps(self, model: LaunchModel) -> list[Gap]: ...

    def fails(self, model: LaunchModel) -> BDD:
        """Where running what the model launches fails although the model loads (xacro on
        a robot description: roslaunch stops, as ``ros2 launch`` does)."""
        ...


def find_interface(interfaces: Interfaces, unit: tuple[str, str]) -> NodeInterface | None:
    package, executable = unit
    return interfaces.find(package or None, executable)


def model_edges(
    space: ConditionSpace,
    model: LaunchModel,
    interfaces: Interfaces,
    described: Described | None = None,
) -> list[Edge]:
    """Every edge the nodes of ``model`` can have (tests excluded: they run apart), and
    those ``described`` gives them (robot descriptions, bridges)."""
    edges: list[Edge] = []
    params = ParamValues(space, [(space.true, model)])
    for node in model.nodes:
        if not node.is_test:
            edges.extend(node_edges(space, model.file, node, interfaces, params))
    if described is not None:
        edges.extend(described.edges(model))
    return edges


def launched_units(
    space: ConditionSpace, node: NodeDecl, interfaces: Interfaces
) -> Iterator[tuple[BDD, LaunchedNode, NodeInterface, bool]]:
    """Per branch of a ``<node>``'s fields: its condition, the node, the interface it runs
    and whether every field is known statically (nodes without a known interface skipped)."""
    for condition, launched, values in node_branches(space, node):
        unit = launched.unit()
        interface = None if unit is None else find_interface(interfaces, unit)
        interface = launched.interface(interface, node.location)
        if interface is not None:
            static = all(value is None or isinstance(value, str) for value in values)
            yield condition, launched.named(interface), interface, static


Branch = tuple[BDD, LaunchedNode, list[Raw | None]]
"""One branch of a ``<node>``'s fields: its condition, the node and the fields' values."""
_REMEMBERED: ContextVar[dict[int, tuple[NodeDecl, list[Branch]]] | None] = ContextVar(
    "branches", default=None
)


@contextmanager
def branches_remembered() -> Iterator[None]:
    """Within it, each ``<node>``'s branches (:func:`node_branches`) are crossed once: the
    checks of one entry file ask for them about ten times (the graph, the simulation, each
    check), which was most of ``rosvar check``'s own work on a large system. Scoped (one
    entry file at a time) so that the branches of every model are not kept at once."""
    if _REMEMBERED.get() is not None:
        yield
        return
    token = _REMEMBERED.set({})
    try:
        yield
    finally:
        _REMEMBERED.reset(token)


def node_branches(space: ConditionSpace, node: NodeDecl) -> Iterator[Branch]:
    """Per branch of a ``<node>``'s fields that can hold: its condition, the node and the
    fields' values."""
    remembered = _REMEMBERED.get()
    if remembered is None:
        return _branches(space, node)
    found = remembered.get(id(node))
    if found is None:  # the node is kept with its branches: its id stays its own
        found = remembered[id(node)] = (node, list(_branches(space, node)))
    return iter(found[1])


def _branches(space: ConditionSpace, node: NodeDecl) -> Iterator[Branch]:
    keys = node.schema.launched
    for condition, values in combine([node.field(key) for key in keys], list):
        condition &= node.condition
        if condition != space.false:
            yield (
                condition,
                LaunchedNode.of(node.schema, dict(zip(keys, values, strict=True))),
                values,
            )


@dataclass(frozen=True, order=True)
class Uninterfaced:
    """A launched ``<node>`` whose interface nothing gives (no source, catalogue entry or
    hint), with the full names it can have."""

    unit: str  # package/executable (a nodelet's or component's class)
    location: Location
    names: tuple[str, ...]


def uninterfaced(
    space: ConditionSpace, models: Iterable[LaunchModel], interfaces: Interfaces
) -> list[Uninterfaced]:
    """The nodes of ``models`` without a known interface: they have no edges, so the checks
    and the graph say nothing about their topics (a node of a file several entry files
    include is listed once; tests excluded, nodelet managers, whose interface is what they
    load, and processes that name no executable of a package: ROS 2's ``ExecuteProcess``
    of a command such as ``gzserver``)."""
    found: dict[tuple[str, Location], set[str]] = {}
    for model in models:
        for node in model.nodes:
            if node.is_test:
                continue
            for _condition, launched, _values in node_branches(space, node):
                unit = launched.unit()
                if unit is not None and unit[1] and find_interface(interfaces, unit) is None:
                    shown = "/".join(part for part in unit if part)
                    found.setdefault((shown, node.location), set()).add(launched.full_name)
    return sorted(Uninterfaced(u, at, tuple(sorted(n))) for (u, at), n in found.items())


def node_edges(
    space: ConditionSpace, file: str, node: NodeDecl, interfaces: Interfaces, params: ParamValues
) -> list[Edge]:
    """The edges of one ``<node>``: one per branch of its fields and per remap outcome (a
    hinted entry's only where its ``when:`` holds, its parameters' values from ``params``)."""
    edges = []
    remaps = [(remap.condition, remap.source, remap.target) for remap in node.remaps]
    for condition, launched, interface, static in launched_units(space, node, interfaces):
        for entry in interface.entries:
            if entry.role not in CHANNEL:
                continue
            parts = [(condition, False)]
            if entry.when is not None:
                when = entry_when(params, node, launched, interface, entry.when)
                known = when.condition & ~when.unknown
                parts = [(condition & known, False), (condition & when.unknown, True)]
            for used, uncertain in parts:
                if used == space.false:
                    continue
                for taken, use in entry_uses(params, node, launched, interface, entry, used):
                    for at, name in entry_names(launched, remaps, use, taken):
                        edge = _edge(file, launched, node, use, name, at, static)
                        edges.append(replace(edge, uncertain=True) if uncertain else edge)
    return edges


def entry_uses(
    params: ParamValues,
    node: NodeDecl,
    launched: LaunchedNode,
    interface: NodeInterface,
    entry: Entry,
    used: BDD,
) -> list[tuple[BDD, Entry]]:
    """``entry`` under ``used``; one named by a parameter becomes one entry per value the
    parameter takes (what the launched files set, else its default), each under its
    condition: a value not known keeps the symbolic entry; an indexed parameter
    (``~imu{N}``) gives one per such parameter set, none where unset."""
    named = entry.named_by
    if named is None:
        return [(used, entry)]
    defaults = _defaults(launched, interface)
    lookup = _ros2_lookup(params.space, node) if node.ros2 else None
    uses: list[tuple[BDD, Entry]] = []
    for parameter in _named_parameters(params, node, launched, named):
        resolved = launched.resolve(parameter)
        default = entry.default if entry.default is not None else defaults.get(resolved)
        if named.indexed:
            default = None
        values = (
            lookup(parameter, default) if lookup is not None else params.values(resolved, default)
        )
        for condition, value in values:
            taken = used & condition
            if taken == params.space.false:
                continue
            if isinstance(value, str) and value:
                name = Text(value).within(Text(named.namespace)).value
                uses.append((taken, replace(entry, name=name, static=True, named_by=None)))
            elif not named.indexed:
                uses.append((taken, entry))
    return uses


def _named_parameters(
    params: ParamValues, node: NodeDecl, launched: LaunchedNode, named: NamedBy
) -> list[str]:
    """The parameters that name a use: the one, or every one of an indexed name that the
    launched files set (as the node writes it)."""
    if not named.indexed:
        return [named.parameter]
    head, _, tail = named.parameter.partition(INDEX)
    if node.ros2:
        written = [p.name for p in node.parameters if isinstance(p.name, str)]
        pattern = re.compile(re.escape(head.lstrip("~/")) + r"(\d+)" + re.escape(tail) + "$")
        return sorted({n for n in written if pattern.match(n)})
    marker = "__index__"
    resolved = launched.resolve(head + marker + tail)
    pattern = re.compile(re.escape(resolved).replace(marker, r"(\d+)") + "$")
    return [
        head + match.group(1) + tail
        for name in params.names()
        if (match := pattern.match(name)) is not None
    ]


def _ros2_lookup(
    space: ConditionSpace, node: NodeDecl
) -> Callable[[str, Default | None], Choice[object]]:
    """A ROS 2 node's own parameters as its launch description gives them: the values
    written for it (the last that holds wins), else the default; a parameter file may set
    any of them (not read here: a value not known)."""

    def lookup(name: str, default: Default | None) -> Choice[object]:
        branches: list[tuple[BDD, object]] = []
        remaining = space.true
        for parameter in reversed(node.parameters):
            if parameter.file is not None:
                value: object = Unknown(f"a parameter file ({parameter.file}) may set it")
            elif parameter.name == name.lstrip("~/"):
                raw = parameter.value
                value = raw if isinstance(raw, str) else Unknown(f"its value is {raw}")
            else:
                continue
            taken = remaining & parameter.condition
            if taken != space.false:
                branches.append((taken, value))
            remaining &= ~parameter.condition
        if remaining != space.false:
            branches.append((remaining, param_default(default)))
        return Choice.of(branches, space.false)

    return lookup


def entry_when(
    params: ParamValues, node: NodeDecl, launched: LaunchedNode, interface: NodeInterface, text: str
) -> When:
    """Where the ``when:`` ``text`` of an entry of ``interface`` holds for ``node`` launched as
    ``launched`` (one branch of its fields): over the args of its scope and the values of its
    parameters, resolved as the node resolves their names: what the launched files set, else
    the default its source reads."""
    defaults = _defaults(launched, interface)

    def lookup(name: str) -> Choice[object]:
        if node.parameters:  # ROS 2: the node's own parameters, not the server's
            return Choice.const(params.space, ROS2_PARAMETERS)
        resolved = launched.resolve(name)
        return params.values(resolved, defaults.get(resolved))

    return when_condition(params.space, node, text, lookup)


def _defaults(launched: LaunchedNode, interface: NodeInterface) -> dict[str, Default]:
    """The defaults the node's source gives its parameters, by resolved name."""
    defaults: dict[str, Default] = {}
    for entry in interface.of(Role.PARAMS):
        if entry.static and entry.default is not None:
            defaults.setdefault(launched.resolve(entry.name), entry.default)
    return defaults


def entry_names(
    node: LaunchedNode, remaps: Sequence[tuple[BDD, Raw, Raw]], entry: Entry, when: BDD
) -> list[tuple[BDD, str]]:
    """The names ``entry`` uses under ``when``, each with its condition (:func:`remapped`);
    image_transport's camera info lies beside its image topic as remapped."""
    if entry.beside is None:
        return remapped(node, remaps, entry.name, when)
    return [
        (c, camera_info_beside(image)) for c, image in remapped(node, remaps, entry.beside, when)
    ]


def camera_info_beside(image: str) -> str:
    """image_transport's camera info topic: beside its image topic (once remapped)."""
    return names.ns_join(image.rsplit(names.SEP, 1)[0] or names.SEP, "camera_info")


def _edge(
    file: str,
    node: LaunchedNode,
    decl: NodeDecl,
    entry: Entry,
    name: str,
    condition: BDD,
    static: bool,
) -> Edge:
    return Edge(
        file,
        node.full_name,
        entry.role,
        name,
        entry.type,
        condition,
        decl.location,
        entry.location,
        static and entry.static and "{" not in name,
        entry.boundary,
    )


def _text(value: object) -> str:
    return "" if value is None else value if isinstance(value, str) else "{" + str(value) + "}"


def remapped(
    node: LaunchedNode, remaps: Sequence[tuple[BDD, Raw, Raw]], name: str, when: BDD
) -> list[tuple[BDD, str]]:
    """The names ``name`` becomes under ``when``, each with its condition: the last remap
    (condition, from, to) that holds of those whose source resolves to it wins (ROS 2: the
    first), else the name stays."""
    resolved = node.resolve(name)
    outcomes: list[tuple[BDD, str]] = []
    false = when.bdd.false
    remaining = when
    for condition, source, target in node.remap_order(remaps):
        if node.resolve(_text(source)) != resolved:
            continue
        taken = remaining & condition
        if taken != false:
            outcomes.append((taken, node.resolve(_text(target))))
        remaining &= ~condition
    if remaining != false:
        outcomes.append((remaining, resolved))
    return outcomes


# -- one configuration ---------------------------------------------------------------------


def restrict(edges: Iterable[Edge], holds: Callable[[BDD], bool]) -> list[Edge]:
    """The edges of one configuration (``holds`` decides a condition in it)."""
    return [edge for edge in edges if holds(edge.condition)]


def resolved_graph(
    nodes: Sequence[ResolvedNode],
    interfaces: Interfaces,
    params: Mapping[str, object],
    more: Iterable[Edge] = (),
) -> ResolvedGraph:
    """The topics, services and actions of one configuration's nodes (``rosvar resolve``'s);
    a hinted entry's where its ``when:`` holds with the node's args and the parameter server
    (``params``). A ROS 2 node's parameters are its own: there a ``when:`` is not known, and
    the entry is kept as the variational graph keeps it. ``more``: edges of the configuration
    beyond the nodes' interfaces (a spawned description's plugins, bridges:
    :class:`Described`'s)."""
    uses: list[tuple[str, Role, str, str | None]] = [
        (edge.node, edge.role, edge.name, edge.type) for edge in more if edge.static
    ]
    for node in nodes:
        launched = LaunchedNode.resolved(node)
        unit = launched.unit()
        interface = None if unit is None else find_interface(interfaces, unit)
        if interface is None:
            continue
        launched = launched.named(interface)
        table: dict[str, str] = {}
        for a, b in launched.remap_order(launched.remaps):
            table.setdefault(launched.resolve(a), launched.resolve(b))
        for entry in interface.entries:
            if entry.role not in CHANNEL:
                continue
            if entry.when is not None and node.parameters is None:
                value = _param_value(params, launched, interface)
                if not concrete_holds(entry.when, node.scope, value):
                    continue
            for use in _resolved_uses(node, launched, interface, entry, params):
                resolved = launched.resolve(use.beside or use.name)
                name = table.get(resolved, resolved)
                name = name if use.beside is None else camera_info_beside(name)
                uses.append((launched.full_name, use.role, name, use.type))
    return uses_graph(uses)


def _resolved_uses(
    node: ResolvedNode,
    launched: LaunchedNode,
    interface: NodeInterface,
    entry: Entry,
    params: Mapping[str, object],
) -> list[Entry]:
    """:func:`entry_uses` in one configuration: ROS 1's parameter server (``params``), or
    a ROS 2 node's own parameters."""
    named = entry.named_by
    if named is None:
        return [entry]
    if node.parameters is not None:  # ROS 2: the node's own parameters, by their plain names
        values: Mapping[str, object] = node.parameters
        key: Callable[[str], str] = lambda parameter: parameter.lstrip("~/")  # noqa: E731
    else:
        values, key = params, launched.resolve
    head, _, tail = named.parameter.partition(INDEX)
    if named.indexed:
        marker = "__index__"
        pattern = re.compile(re.escape(key(head + marker + tail)).replace(marker, r"\d+") + "$")
        chosen = [values[n] for n in sorted(values) if pattern.match(n)]
    else:
        resolved = launched.resolve(named.parameter)
        default = entry.default
        if default is None:
            default = _defaults(launched, interface).get(resolved)
        written = key(named.parameter)
        chosen = [values[written] if written in values else param_default(default)]
    found = []
    for value in chosen:
        if isinstance(value, str) and value:
            name = Text(value).within(Text(named.namespace)).value
            found.append(replace(entry, name=name, static=True, named_by=None))
        elif not named.indexed:
            found.append(entry)
    return found


def _param_value(
    params: Mapping[str, object], launched: LaunchedNode, interface: NodeInterface
) -> Callable[[str], object]:
    """A parameter of ``launched`` by its name as written: the value the launched files
    set, else its default (as :func:`entry_when` gives every value)."""
    defaults = _defaults(launched, interface)

    def value(name: str) -> object:
        resolved = launched.resolve(name)
        if resolved in params:
            return params[resolved]
        return param_default(defaults.get(resolved))

    return value


@dataclass(frozen=True)
class NameUses:
    """One resolved name of a channel in one configuration: the types the nodes' sources
    give it (more than one is a mismatch), the nodes feeding it and those using it."""

    name: str
    types: tuple[str, ...]
    providers: tuple[str, ...]
    users: tuple[str, ...]


ResolvedGraph = dict[Channel, list[NameUses]]
"""One configuration's communication graph: each channel's names, sorted."""


def uses_graph(uses: Iterable[tuple[str, Role, str, str | None]]) -> ResolvedGraph:
    """Uses (node, role, name, type) grouped by channel and name."""
    graph: ResolvedGraph = {}
    for channel in Channel:
        provide, use = SIDES[channel]
        grouped: dict[str, tuple[set[str], set[str], set[str]]] = {}
        for node, role, name, type_ in uses:
            if role not in (provide, use):
                continue
            types, providers, users = grouped.setdefault(name, (set(), set(), set()))
            if type_ is not None:
                types.add(type_)
            (providers if role is provide else users).add(node)
        graph[channel] = [
            NameUses(name, tuple(sorted(t)), tuple(sorted(p)), tuple(sorted(u)))
            for name, (t, p, u) in sorted(grouped.items())
        ]
    return graph
