"""Controllers: the names the controllers a controller manager loads use, as edges of the
spawner that has them loaded (ROS 1) or of the manager that runs them (ROS 2).

Controllers are plugins of a controller manager (ROS 1: ``gazebo_ros_control`` or the
robot's hardware node; ROS 2: ``ros2_control_node``), not nodes: the launch files name them
only in a spawner's arguments, and their type in a parameter of the manager. Each dialect
reads which controllers its spawners have loaded, and where (:data:`SPAWNED`, filled by the
dialects: the core names neither); the names a controller type uses are its catalogue entry
(kind ``controller``), resolved as those of a node named after the controller in the
manager's namespace, with the manager's remaps. Without them every ``robot_state_publisher``
would miss its ``joint_states`` and every odometry filter its ``odom``.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, replace

from rosvar.analyses.communication import CHANNEL, Edge, LaunchedNode, entry_names
from rosvar.analyses.when import when_condition
from rosvar.files import Confinement
from rosvar.interpreter.model import LaunchModel, NodeDecl, Raw
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.ros.version import RosVersion
from rosvar.workspace.interfaces.model import (
    Default,
    Entry,
    Interfaces,
    NodeInterface,
    NodeKind,
    Role,
)

Parameters = Callable[[str, Default | None], Choice[object]]
"""A controller's parameter values (by name, with the default its type's entry gives), each
with its condition; a value not known is :class:`~rosvar.analyses.param_values.Unknown`."""


@dataclass(frozen=True)
class Controller:
    """A controller a spawner has a manager load, where ``condition`` holds: its node's
    ``name`` and ``namespace`` (the manager's), its ``type`` (None: no parameter rosvar can
    read says it, so a name that is a type's package, ``joint_state_broadcaster``, is taken
    for that type), the remaps its node takes, in the order they are tried, and its
    parameters (None: not read, so a use a parameter switches on is kept, uncertain)."""

    condition: BDD
    name: str
    type: str | None
    namespace: str
    remaps: tuple[tuple[BDD, Raw, Raw], ...]
    owner: str
    """Whose edges they are: the process that runs the controller as the graph names it
    (ROS 2: the manager's full name, so that two spawners of one controller give one
    controller; ROS 1: the spawner's, its manager being implicit)."""
    declaration: NodeDecl  # the spawner's (its args are the scope of a use's when:)
    ros2: bool
    parameters: Parameters | None = None


Spawned = Callable[[ConditionSpace, LaunchModel, Confinement], Iterable[Controller]]
"""The controllers the spawners of an entry file have loaded, as its dialect reads them."""
SPAWNED: dict[RosVersion, list[Spawned]] = defaultdict(list)
"""By the ROS of the spawners (filled by the dialects)."""


def spawned(version: RosVersion) -> Callable[[Spawned], Spawned]:
    """Register how the spawners of ``version`` name their controllers."""

    def register(reader: Spawned) -> Spawned:
        SPAWNED[version].append(reader)
        return reader

    return register


def controller_edges(
    space: ConditionSpace, model: LaunchModel, interfaces: Interfaces, confinement: Confinement
) -> list[Edge]:
    """The edges of the controllers the spawners of ``model`` have loaded, where their type
    is a known controller type (``confinement``: where parameter files may be read). One
    controller that several spawners load is one controller (the manager loads a name
    once): its uses are kept once, where any of them holds, at the first spawner."""
    types = _Types(interfaces)
    edges: dict[tuple[object, ...], Edge] = {}
    for version in sorted({node.schema.version for node in model.nodes}):
        for reader in SPAWNED.get(version, ()):
            for controller in reader(space, model, confinement):
                interface = types.of(controller)
                if interface is None:
                    continue
                for edge in _edges(space, model.file, controller, interface):
                    key = (edge.node, edge.role, edge.name, edge.source, edge.uncertain)
                    known = edges.get(key)
                    if known is not None:
                        edge = replace(known, condition=known.condition | edge.condition)
                    edges[key] = edge
    return list(edges.values())


def _edges(
    space: ConditionSpace, file: str, controller: Controller, interface: NodeInterface
) -> list[Edge]:
    """A controller's uses of names, as a node of its name in the manager's namespace."""
    node = LaunchedNode(
        interface.package,
        interface.executable,
        controller.namespace,
        controller.name,
        "",
        (),
        ros2=controller.ros2,
    )
    label = f"{controller.owner}: controller {controller.name}"
    edges = []
    defaults = {e.name.removeprefix("~/"): e.default for e in interface.of(Role.PARAMS) if e.static}
    for entry in interface.entries:
        if entry.role not in CHANNEL:
            continue
        for present, uncertain in _present(space, controller, entry, defaults):
            for condition, name in entry_names(node, controller.remaps, entry, present):
                edges.append(
                    Edge(
                        file,
                        label,
                        entry.role,
                        name,
                        entry.type,
                        condition,
                        controller.declaration.location,
                        entry.location,
                        entry.static and "{" not in name,
                        entry.boundary,
                        uncertain=uncertain,
                    )
                )
    return edges


def _present(
    space: ConditionSpace,
    controller: Controller,
    entry: Entry,
    defaults: Mapping[str, Default | None],
) -> list[tuple[BDD, bool]]:
    """Where the controller has ``entry``, and whether only because a parameter its
    ``when:`` reads is not known (uncertain: a missing partner of it is a note)."""
    parameters = controller.parameters
    if entry.when is None:
        return [(controller.condition, False)]
    if parameters is None:
        return [(controller.condition, True)]

    def lookup(name: str) -> Choice[object]:
        return parameters(name, defaults.get(name.removeprefix("~/")))

    when = when_condition(space, controller.declaration, entry.when, lookup)
    parts = [
        (controller.condition & when.condition & ~when.unknown, False),
        (controller.condition & when.unknown, True),
    ]
    return [(condition, uncertain) for condition, uncertain in parts if condition != space.false]


class _Types:
    """The controller types of the interfaces, looked up by type, or by package for a
    controller whose type is not known (listed once, on the first such one)."""

    def __init__(self, interfaces: Interfaces) -> None:
        self.interfaces = interfaces
        self._by_package: dict[str, list[NodeInterface]] | None = None

    def of(self, controller: Controller) -> NodeInterface | None:
        if controller.type is not None:
            found = self.interfaces.find(None, controller.type)
            return found if found is not None and found.kind is NodeKind.CONTROLLER else None
        if self._by_package is None:
            self._by_package = defaultdict(list)
            for node in self.interfaces.listed():
                if node.kind is NodeKind.CONTROLLER:
                    self._by_package[node.package].append(node)
        named = self._by_package.get(controller.name, [])
        return named[0] if len(named) == 1 else None
