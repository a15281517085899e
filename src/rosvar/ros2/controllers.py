"""The controllers ros2_control's spawners have a controller manager load (registered with
the core's :mod:`~rosvar.analyses.controllers`).

``ros2 run controller_manager spawner NAME... [-c MANAGER] [--param-file FILE]...`` asks
the manager ``MANAGER`` (default ``controller_manager``, relative to the spawner's
namespace) to load, configure and activate each controller ``NAME``. The manager
(``ros2_control_node``) gives each a node of its name in the manager's namespace, with the
manager's remaps (but those of ``robot_description``) and then the spawner's
``--controller-ros-args``. A controller's type is the manager's parameter ``NAME.type``,
which the spawner sets from the ``type`` of the controller's entry in its parameter files
(``/NS/NAME``, ``/**/NAME``, ``/**``; a bare ``NAME`` only in the root namespace). The
controller's node reads its parameters from the manager's files, then the spawner's. Where
a file rosvar cannot read may set one, or the manager is not one the entry file launches
(Gazebo's, another launch's), the value is not known: for the type, the core then takes a
controller named after a type's package (``joint_state_broadcaster``) for that type.
"""

from __future__ import annotations

import argparse
import shlex
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, replace
from typing import NoReturn

from rosvar.analyses.communication import LaunchedNode, node_branches
from rosvar.analyses.controllers import Controller, Parameters, spawned
from rosvar.analyses.param_values import Unknown, param_default
from rosvar.files import Confinement
from rosvar.interpreter.model import LaunchModel, NodeDecl, Raw
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.terms import Apply
from rosvar.ros import names
from rosvar.ros.version import RosVersion
from rosvar.ros2.conventions import command_line
from rosvar.ros2.conventions.parameters import matches, typed
from rosvar.ros2.resolve import given_entries, parameter_file
from rosvar.workspace.interfaces.model import Default

PACKAGE = "controller_manager"
SPAWNER = "spawner"
MANAGER = "ros2_control_node"
MANAGER_NAME = "controller_manager"
"""The name ``ros2_control_node`` gives its node, and the manager a spawner asks by
default."""
UNKNOWN_PART = "\x00"
"""Stands for a part of a spawner's arguments known only per configuration."""
UNKNOWN = Unknown("a parameter file rosvar cannot read may set it")


@dataclass(frozen=True)
class _Manager:
    """One branch of a launched ``ros2_control_node``."""

    condition: BDD
    node: NodeDecl
    launched: LaunchedNode

    @property
    def full_name(self) -> str:
        return self.launched.full_name


@dataclass(frozen=True)
class _Spawn:
    """A spawner's command line, as its ``argparse`` reads it."""

    controllers: list[str]
    manager: str
    namespace: str | None
    param_files: list[str]
    ros_args: list[str]
    load_only: bool
    type: str | None  # Humble's --controller-type


@spawned(RosVersion.ROS2)
def spawned_controllers(
    space: ConditionSpace, model: LaunchModel, confinement: Confinement
) -> Iterator[Controller]:
    """The controllers the spawners of ``model`` have loaded (``--load-only`` ones are not
    configured: they have no topics), each where its spawner runs with those arguments and
    its manager is the one it has."""
    managers = [
        _Manager(condition, node, _named(launched))
        for node in model.nodes
        for condition, launched, _values in node_branches(space, node)
        if (launched.package, launched.type) == (PACKAGE, MANAGER)
    ]
    for node in model.nodes:
        if node.is_test:
            continue
        for condition, launched, values in node_branches(space, node):
            if (launched.package, launched.type) != (PACKAGE, SPAWNER):
                continue
            spawn = _spawn(dict(zip(node.schema.launched, values, strict=True)).get("args"))
            if spawn is None or spawn.load_only or UNKNOWN_PART in spawn.manager:
                continue
            loads = _Loads(space, confinement, spawn, node, spawn.namespace or launched.namespace)
            remaining = condition
            for found in managers:
                both = remaining & found.condition
                if found.full_name != loads.manager or both == space.false:
                    continue
                yield from loads.controllers(node, found, both)
                remaining &= ~found.condition
            if remaining != space.false:  # a manager the entry file does not launch
                yield from loads.controllers(node, None, remaining)


class _Loads:
    """What one spawner's command line has its manager load."""

    def __init__(
        self,
        space: ConditionSpace,
        confinement: Confinement,
        spawn: _Spawn,
        node: NodeDecl,
        namespace: str,
    ) -> None:
        self.space = space
        self.confinement = confinement
        self.spawn = spawn
        self.namespace = names.SEP + namespace.lstrip(names.SEP)  # as the spawner makes it
        self.manager = names.canonicalize_name(names.ns_join(self.namespace, spawn.manager))
        self.files = [(space.true, self._file(path)) for path in spawn.param_files]
        self.files += [  # the spawner's own parameter files count too (Jazzy)
            (parameter.condition, given_entries(parameter, confinement))
            for parameter in node.parameters
            if parameter.file is not None
        ]

    def controllers(
        self, node: NodeDecl, manager: _Manager | None, condition: BDD
    ) -> Iterator[Controller]:
        """Its controllers where ``manager`` (None: one the entry file does not launch) is
        the one it asks."""
        if manager is None:
            namespace = names.namespaces_of(self.manager)[-1]
            remaps: tuple[tuple[BDD, Raw, Raw], ...] = ()
        else:
            namespace = manager.launched.namespace
            remaps = tuple(
                (remap.condition, remap.source, remap.target)
                for remap in manager.node.remaps
                if "robot_description" not in f"{remap.source} {remap.target}"
            )
        true = self.space.true
        remaps += tuple((true, source, target) for source, target in _remaps(self.spawn.ros_args))
        for name in self.spawn.controllers:
            if UNKNOWN_PART in name:
                continue
            controller = names.ns_join(namespace, name)  # its node's full name
            for kind, where in self._types(name, manager, condition):
                yield Controller(
                    where,
                    name,
                    kind,
                    namespace,
                    remaps,
                    self.manager,
                    node,
                    ros2=True,
                    parameters=self._parameters(manager, controller),
                )

    def _types(
        self, name: str, manager: _Manager | None, condition: BDD
    ) -> Iterator[tuple[str | None, BDD]]:
        """The types of controller ``name``, each with its condition (None: not known):
        the manager's ``NAME.type``, which the spawner sets from the ``type`` of the
        controller's entry in its files (looked up in the spawner's namespace) and its
        ``--controller-type``; where nothing says one, the manager refuses it."""
        space = self.space
        key = f"{name}.type"
        at = None if manager is None else manager.full_name
        found = self._sources(manager, at, key, names.ns_join(self.namespace, name), "type")
        if self.spawn.type is not None:
            found.append((space.true, self.spawn.type))
        for value, where in _latest(space, found, condition):
            yield (value if isinstance(value, str) and UNKNOWN_PART not in value else None), where

    def _parameters(self, manager: _Manager | None, controller: str) -> Parameters:
        """The controller's parameter values, each with its condition: what the manager's
        parameters (its files' entries for the controller, its inline ones, which launch_ros
        gives every node of the process) and then the spawner's files set, else the
        default; a file not read may set anything."""

        def lookup(name: str, default: Default | None) -> Choice[object]:
            key = name.removeprefix("~/")
            found = self._sources(manager, controller, key, controller, key)
            branches = _latest(self.space, found, self.space.true)
            remaining = self.space.true
            for _value, where in branches:
                remaining &= ~where
            if remaining != self.space.false:
                branches.append((param_default(default), remaining))
            return Choice.of([(where, value) for value, where in branches], self.space.false)

        return lookup

    def _sources(
        self, manager: _Manager | None, at: str | None, key: str, own: str, own_key: str
    ) -> list[tuple[BDD, object]]:
        """What sets a parameter, in order (a later one wins), each where it does: the
        manager's parameters (``key`` of its files' entries for ``at``, or inline), then
        the spawner's files (``own_key`` of their entry for ``own``). A value is
        :data:`UNKNOWN` where a file is not read (or the manager's parameters not known),
        None where a source does not set it."""
        found: list[tuple[BDD, object]] = []
        if manager is None or at is None:
            found.append((self.space.true, UNKNOWN))
        else:
            for parameter in manager.node.parameters:
                if parameter.file is None:
                    if parameter.name == key:
                        found.append((parameter.condition, _inline(parameter.value)))
                    continue
                entries = given_entries(parameter, self.confinement)
                found.append((parameter.condition, _entry_value(entries, at, key)))
        for where, entries in self.files:
            found.append((where, _entry_value(entries, own, own_key)))
        return found

    def _file(self, path: str) -> list[tuple[str, dict[str, object]]] | None:
        if UNKNOWN_PART in path:
            return None
        try:
            return parameter_file(path, self.confinement)
        except ValueError:
            return None


def _latest(
    space: ConditionSpace, found: Sequence[tuple[BDD, object]], condition: BDD
) -> list[tuple[object, BDD]]:
    """The values of ``found`` (in order: a later one wins; None sets nothing) within
    ``condition``, each with where it is the one that holds."""
    values: list[tuple[object, BDD]] = []
    remaining = condition
    for where, value in reversed(found):
        if value is None:
            continue
        taken = remaining & where
        if taken != space.false:
            values.append((value, taken))
        remaining &= ~where
    return values


def _entry_value(entries: list[tuple[str, dict[str, object]]] | None, fqn: str, key: str) -> object:
    """What the entries of a parameter file (None: not read) for the node ``fqn`` (rcl's
    wildcards; a bare key only in the root namespace) set ``key`` to; the last wins."""
    if entries is None:
        return UNKNOWN
    value: object = None
    for pattern, params in entries:
        if key in params and matches(pattern, fqn):
            value = params[key]
    return value


def _inline(value: Raw | None) -> object:
    """An inline parameter's value as launch_ros gives it (YAML rules)."""
    if not isinstance(value, str) or UNKNOWN_PART in value:
        return UNKNOWN
    try:
        return typed(value)
    except ValueError:
        return UNKNOWN


def _named(launched: LaunchedNode) -> LaunchedNode:
    """A manager without a launch ``name`` has the one ``ros2_control_node`` gives it."""
    return launched if launched.name else replace(launched, name=MANAGER_NAME)


def _spawn(args: Raw | None) -> _Spawn | None:
    """A spawner's arguments as its ``argparse`` reads them (parts known only per
    configuration stand as :data:`UNKNOWN_PART`); None when it refuses them."""
    words = _words(args)
    try:
        options, _extra = _PARSER.parse_known_args(words)
    except argparse.ArgumentError:
        return None
    return _Spawn(
        options.controller_names,
        options.controller_manager,
        options.namespace,
        options.param_file,
        options.controller_ros_args,
        options.load_only,
        options.controller_type,
    )


def _words(args: Raw | None) -> list[str]:
    """A command line's words, split as ``shlex`` does."""
    text = _known_text(args) if args is not None else ""
    try:
        return shlex.split(text)
    except ValueError:  # an unbalanced quote: the launch refuses it elsewhere
        return text.split()


def _known_text(value: Raw) -> str:
    """``value``'s text with each part known only per configuration as one
    :data:`UNKNOWN_PART`."""
    if isinstance(value, str):
        return value
    if isinstance(value, Apply) and value.function == "concat":
        return "".join(
            part
            if isinstance(part, str)
            else UNKNOWN_PART
            if isinstance(part, tuple)
            else _known_text(part)
            for part in value.operands
        )
    return UNKNOWN_PART


def _remaps(ros_args: Sequence[str]) -> Iterator[tuple[str, str]]:
    """The remaps of ``--controller-ros-args`` values (each split at spaces, as the spawner
    does), read as rcl reads the controller node's ``--ros-args``."""
    words = [word for value in ros_args for word in value.split()]
    for source, target in command_line.parse(["--ros-args", *words]).remaps:
        if target and UNKNOWN_PART not in source + target:
            yield source, target


class _Parser(argparse.ArgumentParser):
    """An ``argparse`` parser that raises where the spawner's would print and exit (it
    does so for an ambiguous abbreviation even without ``exit_on_error``)."""

    def error(self, message: str) -> NoReturn:
        raise argparse.ArgumentError(None, message)


def _parser() -> argparse.ArgumentParser:
    """The spawner's options (Jazzy's ``parse_native_args``, with Humble's
    ``--controller-type`` and ``--stopped``)."""
    parser = _Parser(add_help=False, exit_on_error=False)
    parser.add_argument("controller_names", nargs="*")
    parser.add_argument("-c", "--controller-manager", default=MANAGER_NAME)
    parser.add_argument("-p", "--param-file", action="append", default=[])
    parser.add_argument("-n", "--namespace")
    parser.add_argument("-t", "--controller-type")
    parser.add_argument("--load-only", action="store_true")
    parser.add_argument("--inactive", "--stopped", action="store_true")
    parser.add_argument("-u", "--unload-on-kill", action="store_true")
    for option in ("--controller-manager-timeout", "--switch-timeout", "--service-call-timeout"):
        parser.add_argument(option)
    parser.add_argument("--activate-as-group", action="store_true")
    parser.add_argument("--switch-asap", action=argparse.BooleanOptionalAction)
    parser.add_argument("--controller-ros-args", action="append", default=[])
    parser.add_argument("--fallback_controllers", nargs="*")
    return parser


_PARSER = _parser()
