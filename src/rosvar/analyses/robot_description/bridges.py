"""``ros_gz_bridge`` bridges: the ROS side of each bridged topic and service, as edges of the
bridge node.

``parameter_bridge`` reads its command line (ros_gz's ``parameter_bridge.cpp``): each
argument is ``name@ROS_type@GZ_type`` (both ways: the bridge publishes and subscribes),
``name@ROS_type[GZ_type`` (Gazebo to ROS: it publishes), ``name@ROS_type]GZ_type`` (ROS to
Gazebo: it subscribes), or ``name@ROS_srv_type[@GZ_req@GZ_rep]`` (a Gazebo service offered
as a ROS service); a malformed argument stops it. Both it and ``bridge_node`` read the YAML
file of their ``config_file`` parameter (``bridge_config.cpp``): a sequence of entries with
``topic_name`` or ``ros_topic_name``/``gz_topic_name``, ``ros_type_name`` and
``direction`` (``BIDIRECTIONAL``, ``GZ_TO_ROS``, ``ROS_TO_GZ``). The names are resolved and
remapped as the bridge node's own (node ``ros_gz_bridge`` unless the launch file names it).
"""

from __future__ import annotations

import enum
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Final

import yaml

from rosvar.analyses.communication import Edge, Gap, entry_names, node_branches
from rosvar.analyses.robot_description.commands import CommandError, split
from rosvar.bounded_yaml import YamlLimitError, check_limits
from rosvar.diagnostics import Location, Severity
from rosvar.files import Confinement, read_file
from rosvar.interpreter.model import LaunchModel, NodeDecl, Raw
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.workspace.interfaces.model import Entry, Origin, Role

SOURCE: Final = (
    "https://github.com/gazebosim/ros_gz/blob/a4d00a90a1a5f753a0d0fbfe8e1e142540aebadd/"
    "ros_gz_bridge/src/"
)
BRIDGES: Final = frozenset(
    {
        ("ros_gz_bridge", "parameter_bridge"),
        ("ros_gz_bridge", "bridge_node"),
        ("ros_ign_bridge", "parameter_bridge"),
    }
)
"""The bridge executables, by (package, executable)."""
NODE_NAME: Final = "ros_gz_bridge"
CONFIG_PARAMETER: Final = "config_file"
MAX_CONFIG_BYTES: Final = 1 << 20


class Direction(enum.Enum):
    BIDIRECTIONAL = "BIDIRECTIONAL"
    GZ_TO_ROS = "GZ_TO_ROS"
    ROS_TO_GZ = "ROS_TO_GZ"
    NONE = "NONE"  # a service


ROLES: Final[dict[Direction, tuple[Role, ...]]] = {
    Direction.BIDIRECTIONAL: (Role.PUBLISHES, Role.SUBSCRIBES),
    Direction.GZ_TO_ROS: (Role.PUBLISHES,),
    Direction.ROS_TO_GZ: (Role.SUBSCRIBES,),
    Direction.NONE: (Role.SERVICES,),
}


class BridgeError(ValueError):
    """An argument or entry the bridge refuses (it prints its usage and stops)."""


@dataclass(frozen=True)
class Bridged:
    """One name the bridge offers on the ROS side."""

    name: str
    type: str
    direction: Direction


def parse_argument(argument: str) -> Bridged:
    """One ``parameter_bridge`` argument, as its ``main`` reads it."""
    name, at, rest = argument.partition("@")
    if not at or not name:
        raise BridgeError(f"{argument}: no topic name before '@'")
    direction = Direction.BIDIRECTIONAL
    cut = rest.find("@")
    if cut <= 0:
        cut = rest.find("[")
        direction = Direction.GZ_TO_ROS
        if cut <= 0:
            cut = rest.find("]")
            direction = Direction.ROS_TO_GZ
            if cut == 0:
                raise BridgeError(f"{argument}: no ROS type")
            if cut < 0:
                direction = Direction.NONE
    ros_type = rest if cut < 0 else rest[:cut]
    after = "" if cut < 0 else rest[cut + 1 :]
    if "/srv/" in ros_type:
        if direction in (Direction.GZ_TO_ROS, Direction.ROS_TO_GZ):
            raise BridgeError(f"{argument}: a service is bridged one way only")
        if direction is Direction.BIDIRECTIONAL and after.find("@") <= 0:
            raise BridgeError(f"{argument}: a service needs its request and reply types")
        return Bridged(name, ros_type, Direction.NONE)
    if direction is Direction.NONE or "@" in after or not after:
        raise BridgeError(f"{argument}: a topic needs a ROS type and a Gazebo type")
    return Bridged(name, ros_type, direction)


def parse_config(text: str) -> list[Bridged]:
    """The entries of a bridge's YAML configuration; an entry the bridge skips (no types,
    an unknown direction) is left out, as it does."""
    check_limits(text)
    document = yaml.safe_load(text)
    if not isinstance(document, list):
        raise BridgeError("the configuration's top level must be a YAML sequence")
    found = []
    for entry in document:
        if not isinstance(entry, dict):
            continue
        values = {k: str(v) for k, v in entry.items() if isinstance(k, str) and v is not None}
        topic, ros_name = values.get("topic_name"), values.get("ros_topic_name")
        gz_name = values.get("gz_topic_name")
        if (topic and (ros_name or gz_name)) or not values.get("ros_type_name"):
            continue
        if not values.get("gz_type_name"):
            continue
        try:
            direction = Direction(values.get("direction", "BIDIRECTIONAL"))
        except ValueError:
            continue
        name = topic or ros_name or gz_name
        if name and direction is not Direction.NONE:
            found.append(Bridged(name, values["ros_type_name"], direction))
    return found


class Bridges:
    """The bridge nodes of launch models and the names they bridge."""

    def __init__(self, space: ConditionSpace, confinement: Confinement) -> None:
        self.space = space
        self.confinement = confinement

    def of(self, model: LaunchModel) -> tuple[list[Edge], list[Gap]]:
        edges: list[Edge] = []
        gaps: list[Gap] = []
        for node in model.nodes:
            if not node.is_test:
                self._node(model, node, edges, gaps)
        return edges, gaps

    def _node(self, model: LaunchModel, node: NodeDecl, edges: list[Edge], gaps: list[Gap]) -> None:
        keys = node.schema.launched
        remaps = [(remap.condition, remap.source, remap.target) for remap in node.remaps]
        for condition, launched, values in node_branches(self.space, node):
            if (launched.package, launched.type) not in BRIDGES:
                continue
            if not self.space.satisfiable(condition):
                continue
            fields = dict(zip(keys, values, strict=True))
            if not launched.name:
                launched = replace(launched, name=NODE_NAME)
            for where, bridged, location in self._bridged(node, fields, condition, gaps):
                for role in ROLES[bridged.direction]:
                    entry = Entry(role, bridged.name, location, Origin.SOURCE, bridged.type)
                    for used, name in entry_names(launched, remaps, entry, where):
                        static = "{" not in name
                        edges.append(
                            Edge(
                                model.file,
                                launched.full_name,
                                role,
                                name,
                                bridged.type,
                                used,
                                node.location,
                                location,
                                static,
                            )
                        )

    def _bridged(
        self, node: NodeDecl, fields: Mapping[str, Raw | None], condition: BDD, gaps: list[Gap]
    ) -> Iterator[tuple[BDD, Bridged, Location]]:
        """The names the command line and the configuration file bridge."""
        source = Location(SOURCE + "parameter_bridge.cpp")
        args = fields.get("args")
        try:
            words = split(args) if args is not None else []
        except CommandError as error:
            gaps.append(_gap(node, condition, f"bridge arguments not read: {error}"))
            words = []
        for word in _before_ros_args(words):
            if not isinstance(word, str):
                gaps.append(
                    _gap(node, condition, f"bridge argument {word} is only known per configuration")
                )
                continue
            try:
                yield condition, parse_argument(word), source
            except BridgeError as error:
                gaps.append(_gap(node, condition, f"the bridge stops: {error}", Severity.WARNING))
        for parameter in node.parameters:
            if parameter.name != CONFIG_PARAMETER or parameter.value is None:
                continue
            where = condition & parameter.condition
            if not self.space.satisfiable(where):
                continue
            path = parameter.value
            if not isinstance(path, str):
                gaps.append(
                    _gap(
                        node, where, f"bridge configuration {path} is only known per configuration"
                    )
                )
                continue
            try:
                text = read_file(path, self.confinement, MAX_CONFIG_BYTES).decode(
                    "utf-8", "replace"
                )
                entries = parse_config(text)
            except (OSError, ValueError, yaml.YAMLError, YamlLimitError) as error:
                gaps.append(
                    _gap(
                        node,
                        where,
                        f"bridge configuration {path} not read: {error}",
                        Severity.WARNING,
                    )
                )
                continue
            for bridged in entries:
                yield where, bridged, Location(path)


def _before_ros_args(words: Sequence[Raw]) -> list[Raw]:
    """The bridge's own arguments: those before ``--ros-args`` (rcl's, removed by rclcpp)."""
    found = []
    for word in words:
        if word == "--ros-args":
            break
        found.append(word)
    return found


def _gap(node: NodeDecl, condition: BDD, message: str, severity: Severity = Severity.NOTE) -> Gap:
    return Gap("bridge", message, condition, (node.location,), severity)
