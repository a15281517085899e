"""Which robot description each spawner of a launch model hands to Gazebo, expanded.

A spawner (:data:`SPAWNERS`: ROS 1's ``gazebo_ros spawn_model``, ROS 2's ``spawn_entity.py``
and ``ros_gz_sim create``) names its model by its ``args``: a parameter (``-param``, read in
the spawner's namespace: a ``<param command="xacro ...">``, or a ``textfile``), a topic
(``-topic``: ``robot_state_publisher`` publishes its ``robot_description`` parameter there,
typically ``$(command 'xacro ...')``) or a file (``-file``, read as it is). Every field may
vary between configurations, so a spawner has a description per branch of its fields and of
the parameter it reads; the args each xacro run receives are merged into one choice per arg,
so that each xacro file is expanded once per spawner, whatever the branches.
"""

from __future__ import annotations

import re
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Final

from rosvar.analyses.communication import Gap, LaunchedNode, find_interface, node_branches
from rosvar.analyses.robot_description.commands import (
    CommandError,
    XacroCommand,
    options,
    parts,
    split,
    xacro_command,
)
from rosvar.analyses.robot_description.document import Description, Text
from rosvar.analyses.robot_description.plugins import Spawning
from rosvar.analyses.robot_description.reading import XacroReader
from rosvar.diagnostics import Location, Severity
from rosvar.interpreter.model import (
    DeferredValue,
    LaunchModel,
    NodeDecl,
    ParamDecl,
    ParamSource,
    Raw,
)
from rosvar.interpreter.substitution_args import MISSING, Missing
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.terms import Apply, concat, is_term
from rosvar.ros.version import RosVersion
from rosvar.workspace.interfaces.model import Interfaces

COMMAND_WRAPPERS: Final = (("__command__(", ")"), ("$(command ", ")"))
"""How a command's text is kept in a model: ROS 1's ``<param command>`` value, ROS 2's
``$(command ...)`` substitution (never run)."""
DESCRIPTION_PARAMETER: Final = "robot_description"
_FIND: Final = re.compile(r"\$\(find\s+([^)\s]+)\s*\)")


@dataclass(frozen=True)
class SpawnerKind:
    """How one spawner reads its command line."""

    ros: RosVersion
    param: str | None  # the option naming a parameter (read in the spawner's namespace)
    topic: str | None  # the option naming a topic robot_state_publisher publishes on
    file: str  # the option naming a file read as it is
    robot_namespace: str | None  # the option that sets the plugins' namespace
    model: str  # the option naming the model (entity)

    def options(self) -> tuple[str, ...]:
        """The options that say what is spawned, and where its plugins go."""
        found = (self.param, self.topic, self.file, self.robot_namespace, self.model)
        return tuple(option for option in found if option is not None)


SPAWNERS: dict[tuple[str, str], SpawnerKind] = {
    ("gazebo_ros", "spawn_model"): SpawnerKind(
        RosVersion.ROS1, "-param", None, "-file", "-robot_namespace", "-model"
    ),
    ("gazebo_ros", "spawn_entity.py"): SpawnerKind(
        RosVersion.ROS2, None, "-topic", "-file", "-robot_namespace", "-entity"
    ),
    ("ros_gz_sim", "create"): SpawnerKind(
        RosVersion.ROS2, "-param", "-topic", "-file", None, "-name"
    ),
}


@dataclass(frozen=True)
class Spawn:
    """A spawner in the configurations of ``condition``, and the description it spawns."""

    node: NodeDecl
    launched: LaunchedNode
    condition: BDD
    description: Description
    spawning: Spawning
    ros: RosVersion


@dataclass(frozen=True)
class _Source:
    """One way a description reaches a spawner: a xacro run, or a document read as it is
    (its file, or its text)."""

    condition: BDD
    command: XacroCommand | None = None
    file: Raw | None = None
    text: str | None = None
    location: Location | None = None
    origin: str | None = None
    """The file the text was read from (a ``textfile``), None for a value written inline."""


class Spawns:
    """The spawns of launch models, with the descriptions expanded once per spawner."""

    def __init__(self, space: ConditionSpace, reader: XacroReader, interfaces: Interfaces) -> None:
        self.space = space
        self.reader = reader
        self.interfaces = interfaces
        self._gaps: list[Gap] = []
        self._expanded: dict[tuple[object, ...], Description] = {}

    def of(self, model: LaunchModel) -> tuple[list[Spawn], list[Gap]]:
        """The model's spawns, and what of them could not be read."""
        found: list[Spawn] = []
        self._gaps = []
        for node in model.nodes:
            if not node.is_test:
                found.extend(self._node(model, node))
        return found, self._gaps

    def _node(self, model: LaunchModel, node: NodeDecl) -> Iterator[Spawn]:
        """A spawner's spawns: per branch of its fields, and of its ``args`` grouped by the
        options that say what it spawns (``-x $(arg x)`` makes branches that do not)."""
        if not any(
            (launched.package, launched.type) in SPAWNERS
            for _condition, launched, _values in node_branches(self.space, node)
        ):
            return  # no spawner in any configuration: its fields are not crossed again
        keys = [key for key in node.schema.launched if key != "args"]
        for condition, values in combine([node.field(key) for key in keys], list):
            condition &= node.condition
            if not self.space.satisfiable(condition):
                continue
            launched = LaunchedNode.of(node.schema, dict(zip(keys, values, strict=True)))
            kind = SPAWNERS.get((launched.package, launched.type))
            if kind is None:
                continue
            if not launched.name:  # ROS 2, unnamed: its code names it
                unit = launched.unit()
                interface = None if unit is None else find_interface(self.interfaces, unit)
                launched = launched.named(interface)
            grouped: dict[tuple[Raw | None, ...], tuple[BDD, BDD, dict[str, Raw | None]]] = {}
            for branch, text in node.field("args"):
                where = condition & branch
                if not self.space.satisfiable(where):
                    continue
                try:
                    given = options(split(text if text is not None else ""))
                except CommandError as error:
                    self._note(where, node.location, f"spawner args not read: {error}")
                    continue
                read = {option: given.get(option) for option in kind.options()}
                key = tuple(read.values())
                known = grouped.get(key)
                if known is not None:
                    where, branch = known[0] | where, known[1] | branch
                grouped[key] = (where, branch, read)
            for where, branch, read in grouped.values():
                if self._empty_file(node, launched, kind, read, where, branch):
                    continue
                yield from self._spawned(model, node, launched, kind, read, where)

    def _empty_file(
        self,
        node: NodeDecl,
        launched: LaunchedNode,
        kind: SpawnerKind,
        given: Mapping[str, Raw | None],
        condition: BDD,
        branch: BDD,
    ) -> bool:
        """A spawner told to read its model from an empty file name (an unset environment
        variable, an empty argument) has no model to read: it spawns nothing. Said in those
        words, where its ``args`` are so (``branch``), never as a file named ``''``."""
        file = given.get(kind.file)
        named = (given.get(kind.param) if kind.param else None) or (
            given.get(kind.topic) if kind.topic else None
        )
        if named is not None or not isinstance(file, str) or file.strip():
            return False
        where = "" if branch == self.space.true else f" where {self.space.describe(branch)}"
        message = (
            f"{launched.full_name} ({launched.package} {launched.type}) is given an empty "
            f"{kind.file} argument{where}: it has no model to read and spawns nothing"
        )
        gap = Gap(launched.full_name, message, condition, (node.location,), Severity.WARNING)
        self._gaps.append(gap)
        return True

    def _spawned(
        self,
        model: LaunchModel,
        node: NodeDecl,
        launched: LaunchedNode,
        kind: SpawnerKind,
        given: Mapping[str, Raw | None],
        condition: BDD,
    ) -> Iterator[Spawn]:
        sources: list[_Source] = []
        param = given.get(kind.param) if kind.param else None
        topic = given.get(kind.topic) if kind.topic else None
        if isinstance(param, str):
            sources += self._param_sources(model, launched.resolve(param), condition)
        elif isinstance(topic, str):
            sources += self._topic_sources(model, launched.resolve(topic), condition)
        elif given.get(kind.file) is not None:
            sources.append(_Source(condition, file=given[kind.file], location=node.location))
        spawning = Spawning(
            launched.namespace,
            given.get(kind.robot_namespace) if kind.robot_namespace else None,
            given.get(kind.model),
        )
        for description in self._descriptions(sources, node.location):
            yield Spawn(node, launched, condition, description, spawning, kind.ros)

    # -- where a description comes from -----------------------------------------------------
    def _param_sources(self, model: LaunchModel, name: str, condition: BDD) -> list[_Source]:
        """The values the parameter ``name`` has where the spawner reads it: the last
        ``<param>`` setting it wins, as roslaunch loads them."""
        sources: list[_Source] = []
        remaining = condition
        for param in reversed(model.params):
            if not isinstance(param, ParamDecl):
                continue
            for branch, written in param.name:
                if written != name:
                    continue
                taken = remaining & param.condition & branch
                if not self.space.satisfiable(taken):
                    continue
                files: Choice[Raw | None] = param.textfile or Choice.const(self.space, None)
                for value_branch, value in param.value:
                    for file_branch, origin in files:
                        where = taken & value_branch & file_branch
                        if self.space.satisfiable(where):
                            read = origin if isinstance(origin, str) else None
                            sources.extend(self._value(value, where, param.location, read))
                remaining &= ~(param.condition & branch)
        return sources

    def _topic_sources(self, model: LaunchModel, topic: str, condition: BDD) -> list[_Source]:
        """ROS 2: the ``robot_description`` parameters of the nodes that publish it on
        ``topic`` (robot_state_publisher, in its namespace)."""
        sources: list[_Source] = []
        for node in model.nodes:
            keys = node.schema.launched
            for branch, values in combine([node.field(key) for key in keys], list):
                launched = LaunchedNode.of(node.schema, dict(zip(keys, values, strict=True)))
                if launched.resolve(DESCRIPTION_PARAMETER) != topic:
                    continue
                for parameter in node.parameters:
                    if parameter.name != DESCRIPTION_PARAMETER or parameter.value is None:
                        continue
                    where = condition & branch & node.condition & parameter.condition
                    if self.space.satisfiable(where):
                        sources.extend(self._value(parameter.value, where, node.location))
        return sources

    def _value(
        self, value: object, condition: BDD, location: Location, origin: str | None = None
    ) -> list[_Source]:
        """A parameter's value as a description's source (``origin``: the file its text was
        read from)."""
        if isinstance(value, DeferredValue):
            if value.kind is not ParamSource.COMMAND:
                return []
            value = concat(["__command__(", value.raw, ")"])
        if not isinstance(value, str) and not is_term(value):
            return []
        command = _unwrapped(self._found(value))  # type: ignore[arg-type]
        if command is None:
            if isinstance(value, str) and value.lstrip().startswith("<"):
                return [_Source(condition, text=value, location=location, origin=origin)]
            return []
        try:
            run = xacro_command(split(command))
        except CommandError as error:
            self._note(condition, location, f"robot description command not read: {error}")
            return []
        if run is None:
            message = f"robot description command {command} is not xacro: not read"
            self._note(condition, location, message)
            return []
        return [_Source(condition, command=run, location=location)]

    def _found(self, value: Text) -> Text:
        """A value whose ``$(find)`` pass waits for a term, or for a package the workspace
        does not have: the pass done on its literal parts (where package paths lie), a
        ``$(find)`` of an unknown package left as written (``$(find xacro)/xacro`` still
        names xacro)."""
        done: list[Text] = []
        for part in parts(value):
            if isinstance(part, Apply) and part.function == "find_pass":
                inner = part.operands[0]
                done.append(part if isinstance(inner, tuple) else self._found(inner))
            elif isinstance(part, str) and "$(find" in part:
                done.append(self._find_known(part))
            else:
                done.append(part)
        return concat(done)

    def _find_known(self, text: str) -> str:
        """Each ``$(find pkg)`` of a known package replaced by its path."""
        return _FIND.sub(lambda m: self.reader.find_package(m[1]) or m[0], text)

    # -- expanding ---------------------------------------------------------------------------
    def _descriptions(self, sources: list[_Source], spawner: Location) -> Iterator[Description]:
        runs: dict[str, list[_Source]] = {}
        for source in sources:
            if source.command is not None:
                file = source.command.file
                if isinstance(file, str) and file.startswith("/"):
                    runs.setdefault(file, []).append(source)
                else:
                    message = f"xacro file {file or '(an empty name)'} is not known: not read"
                    self._note(source.condition, source.location or spawner, message)
            elif source.file is not None:
                if isinstance(source.file, str):
                    yield self._expanded_once(
                        (source.file, source.condition), source.file, {}, source.condition, True
                    )
                else:
                    message = f"model file {source.file} is not known: not read"
                    self._note(source.condition, spawner, message)
            elif source.text is not None:
                yield self._text(source)
        for file, group in runs.items():
            condition = self.space.false
            for source in group:
                condition |= source.condition
            args = _merged_args(self.space, group)
            key = (file, condition, tuple((n, c.branches) for n, c in sorted(args.items())))
            yield self._expanded_once(key, file, args, condition, False)

    def _expanded_once(
        self,
        key: tuple[object, ...],
        file: str,
        args: Mapping[str, Choice[Raw | Missing]],
        condition: BDD,
        plain: bool,
    ) -> Description:
        found = self._expanded.get(key)
        if found is None:
            found = self._expanded[key] = self.reader.expand(file, args, condition, plain)
        return found

    def _text(self, source: _Source) -> Description:
        assert source.text is not None and source.location is not None
        key = (source.text, source.condition, source.origin)
        found = self._expanded.get(key)
        if found is None:
            # lines count in the parameter's text: the file it was read from, if any, else
            # not the launch file that sets it
            label = source.origin or f"the text of the parameter at {source.location}"
            found = self.reader.expand_text(source.text, label, source.condition)
            self._expanded[key] = found
        return found

    def _note(self, condition: BDD, location: Location, message: str) -> None:
        self._gaps.append(Gap(location.file, message, condition, (location,), Severity.NOTE))


def _unwrapped(value: Text) -> Text | None:
    """The command a model's value stands for, None for another value."""
    pieces = value.operands if isinstance(value, Apply) and value.function == "concat" else (value,)
    head, tail = pieces[0], pieces[-1]
    if not isinstance(head, str) or not isinstance(tail, str):
        return None
    for start, end in COMMAND_WRAPPERS:
        if head.startswith(start) and tail.endswith(end):
            if len(pieces) == 1:
                return head[len(start) : len(head) - len(end)]
            middle = [p for p in pieces[1:-1] if not isinstance(p, tuple)]
            return concat([head[len(start) :], *middle, tail[: len(tail) - len(end)]])
    return None


def _merged_args(space: ConditionSpace, group: list[_Source]) -> dict[str, Choice[Raw | Missing]]:
    """Each arg of the runs of one file as one choice over their conditions."""
    names = {name for source in group if source.command for name in source.command.args}
    merged: dict[str, Choice[Raw | Missing]] = {}
    for name in sorted(names):
        branches: list[tuple[BDD, Raw | Missing]] = []
        for source in group:
            assert source.command is not None
            branches.append((source.condition, source.command.args.get(name, MISSING)))
        merged[name] = Choice.of(branches, space.false)
    return merged
