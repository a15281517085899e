"""Node interfaces: what one executable or nodelet class publishes, subscribes, serves, calls
and reads, each use with the place that says so.

Names are kept as the node resolves them against its own namespace (``x``, ``~x``, ``/x``):
the graph built on top still has to apply the launch file's namespaces and remappings, which
is where a name as written must stay apart from a resolved one. A part of a name that is not
known statically is written ``{expression}`` (braces cannot occur in a ROS name) and the
entry is marked not ``static``, so that it is never mistaken for a literal name.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field
from typing import Protocol

from rosvar.diagnostics import Diagnostic, Location


class NodeKind(enum.StrEnum):
    """How a launch file starts the code: a process, or a class loaded into a manager (a
    nodelet manager, a component container, a controller manager)."""

    NODE = "node"
    NODELET = "nodelet"
    COMPONENT = "component"  # ROS 2: a class a container loads (``plugin``)
    CONTROLLER = "controller"  # a controller type a controller manager loads (NAME/type)


class Role(enum.StrEnum):
    """What a node does with a name; the values are the JSON list names."""

    PUBLISHES = "publishes"
    SUBSCRIBES = "subscribes"
    SERVICES = "services"
    CLIENTS = "clients"
    ACTION_SERVERS = "action_servers"
    ACTION_CLIENTS = "action_clients"
    PARAMS = "params"


class Origin(enum.StrEnum):
    """Where an entry comes from: the catalogue stands in for sources not in the workspace,
    hints override both."""

    SOURCE = "source"
    CATALOGUE = "catalogue"
    HINTS = "hints"


@dataclass(frozen=True)
class Expression:
    """A value written in the source that is not a literal (kept as written)."""

    text: str

    def __str__(self) -> str:
        return self.text


Default = bool | int | float | str | Expression
"""A parameter's default: a literal's value, or the expression that computes it."""
UNDECLARED_PARAMETERS = frozenset(
    {"allow_undeclared_parameters", "automatically_declare_parameters_from_overrides"}
)
"""rclcpp's ``NodeOptions`` (rclpy's ``Node`` keywords) that make a node take parameters it
never declares."""
ANY_PARAMETER = "{any parameter}"
"""The name of what a ROS 2 node that takes undeclared parameters reads (rclcpp's
``allow_undeclared_parameters``, ``automatically_declare_parameters_from_overrides``): not
known statically, so no parameter it is given counts as unread."""
RECONFIGURED = Expression("its dynamic_reconfigure config's defaults")
"""What a dynamic_reconfigure server reads: every parameter of its ``.cfg`` (which the
extractor does not read) in its namespace, each with the default written there; so its
namespace counts as read, and with defaults."""


@dataclass(frozen=True)
class NamedBy:
    """A name that is a parameter's value (``nh.param("path_topic", t, "plan");
    nh.subscribe(t, ...)``): the graph takes the value each configuration gives
    ``parameter`` (as the node resolves it: ``~path_topic``), else the entry's ``default``,
    and resolves it within ``namespace`` (the node handle's, as written). A
    ``parameter`` holding ``{N}`` stands for every parameter of that form the launch files
    set (robot_localization's ``imu0``, ``imu1``, ...), each naming one use; one never set
    gives none."""

    parameter: str
    namespace: str = ""

    @property
    def indexed(self) -> bool:
        return INDEX in self.parameter


INDEX = "{N}"
"""In a parameter's name, any number (``~imu{N}``)."""


@dataclass(frozen=True)
class Entry:
    """One use of a name: ``type`` for topics, services and actions, ``default`` for params."""

    role: Role
    name: str
    location: Location
    origin: Origin = Origin.SOURCE
    type: str | None = None
    default: Default | None = None
    static: bool = True
    when: str | None = None  # a hint's presence condition, as written (launch args, params)
    boundary: bool = False
    """Meant for something outside the launched nodes: people and their tools (rviz's goal
    and pose tools, a joystick's feedback), tf's listeners, diagnostics monitors."""
    beside: str | None = None
    """image_transport's camera info: named after the image topic ``beside`` (as the node
    writes it) once that is remapped, so the graph derives this name, not ``name``."""
    named_by: NamedBy | None = None
    """The parameter whose value is the name (then ``default`` is that parameter's default
    and ``name`` its symbolic form)."""


@dataclass(frozen=True)
class Extracted:
    """What one entry point's code does, and the name a ROS 2 node built there gives itself
    (None when none, or several, are known statically)."""

    entries: list[Entry]
    node_name: str | None = None


@dataclass
class NodeInterface:
    """The interface of one launchable unit: ``executable`` is the class for a nodelet
    (``pkg/Class``) or a ROS 2 component (``ns::Class``, as a launch file's ``plugin``)."""

    package: str
    executable: str
    kind: NodeKind
    entries: list[Entry] = field(default_factory=list)
    node_name: str | None = None
    """ROS 2: the name the code gives the node, which a launch file's ``name`` overrides."""

    def of(self, role: Role) -> list[Entry]:
        return [entry for entry in self.entries if entry.role is role]


class Fallback(Protocol):
    """Nodes that stand in for those no source defines (the catalogue), looked up by name and
    never changed: a hint on one of them changes a copy."""

    def find(self, package: str | None, executable: str) -> NodeInterface | None: ...

    def nodes(self) -> list[NodeInterface]: ...


@dataclass
class Interfaces:
    """Every interface found in a workspace, and what could not be decided; ``fallback``
    answers for the nodes ``nodes`` lacks, when they are looked up."""

    nodes: list[NodeInterface] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    fallback: Fallback | None = None

    def find(self, package: str | None, executable: str) -> NodeInterface | None:
        """The node ``executable`` of ``package`` (of any package when None: a nodelet
        class ``pkg/Class`` says its own)."""
        for node in self.nodes:
            if package in (None, node.package) and node.executable == executable:
                return node
        return None if self.fallback is None else self.fallback.find(package, executable)

    def listed(self) -> list[NodeInterface]:
        """``nodes`` and every node of the fallback they lack, in (package, executable) order."""
        known = {(node.package, node.executable) for node in self.nodes}
        extra = [] if self.fallback is None else self.fallback.nodes()
        found = self.nodes + [n for n in extra if (n.package, n.executable) not in known]
        return sorted(found, key=lambda node: (node.package, node.executable))
