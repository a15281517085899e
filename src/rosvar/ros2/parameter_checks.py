"""ROS 2's own checks of a node's parameters, registered with the core's checks
(:func:`~rosvar.analyses.checks.node_check`).

A parameter file holds entries keyed by node names (``imu_filter_node: ros__parameters:``),
and rcl applies to a node only the entries whose key matches its full name (``/**`` and the
other wildcards included); the rest it ignores without a word. So a file whose keys name
another node (the executable's default name, a renamed node) leaves the node on its
defaults: :func:`unmatched_parameter_files` finds it, for every branch of the node's name.
"""

from __future__ import annotations

import os
from collections.abc import Iterator

from rosvar.analyses.checks import Check, Found, model_check, nearest, read_off_sources
from rosvar.analyses.communication import launched_units, node_branches
from rosvar.diagnostics import Location, Severity
from rosvar.files import Confinement
from rosvar.interpreter.model import LaunchModel, NodeParameter
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.ros.version import RosVersion
from rosvar.ros2.conventions.parameters import matches
from rosvar.ros2.resolve import given_entries
from rosvar.workspace.interfaces.model import Interfaces, Role


@model_check(RosVersion.ROS2)
def unmatched_parameter_files(
    space: ConditionSpace, model: LaunchModel, _interfaces: Interfaces, confinement: Confinement
) -> Iterator[Found]:
    """A parameter file given to a named node (its path known) none of whose entries rcl
    applies to a node the entry file launches in that configuration: its parameters reach
    no node (a file shared by several nodes may well have no entry for one of them)."""
    named = [
        (node, condition, launched.full_name)
        for node in model.nodes
        for condition, launched, values in node_branches(space, node)
        if launched.name and all(v is None or isinstance(v, str) for v in values)
    ]  # a node its code names, or named only per configuration, is left out
    # where each full name is launched, and where each key's entry is some launched node's:
    # a key is matched against each distinct name once, not against every branch of every
    # node for every parameter of every node
    launched_as: dict[str, BDD] = {}
    for _node, condition, fqn in named:
        launched_as[fqn] = launched_as.get(fqn, space.false) | condition
    reaches: dict[str, BDD] = {}

    def reached_by(key: str) -> BDD:
        found = reaches.get(key)
        if found is None:
            found = space.false
            for fqn, condition in launched_as.items():
                if matches(key, fqn):
                    found |= condition
            reaches[key] = found
        return found

    keys_of: dict[int, list[list[str]]] = {}  # a node's parameters' keys, read once per node
    for node, condition, fqn in named:
        if id(node) not in keys_of:
            keys_of[id(node)] = [
                [key for key, _params in _entries(parameter, confinement)]
                for parameter in node.parameters
            ]
        for parameter, keys in zip(node.parameters, keys_of[id(node)], strict=True):
            reached = space.false  # where an entry is some launched node's
            for key in keys:
                reached |= reached_by(key)
            if not keys or (condition & parameter.condition & ~reached) == space.false:
                continue
            shown = ", ".join(sorted({"/" + key.lstrip("/") for key in keys}))
            yield Found(
                Check.PARAM_FILE_UNMATCHED,
                Severity.WARNING,
                fqn,
                f"{fqn} gets none of the parameters of {os.path.basename(str(parameter.file))}: "
                f"its entries are for {shown}, which no launched node is (rcl applies an entry "
                "to the node its key names, /** to every node)",
                condition & parameter.condition & ~reached,
                # the file too: two files of one node reaching it not are two findings
                (node.location, *_start_of(parameter.file)),
            )


def _start_of(file: object) -> tuple[Location, ...]:
    """The start of a parameter file known by its path, as a place of a finding."""
    return (Location(file, 1, 1),) if isinstance(file, str) else ()


@model_check(RosVersion.ROS2)
def undeclared_parameters(
    space: ConditionSpace, model: LaunchModel, interfaces: Interfaces, confinement: Confinement
) -> Iterator[Found]:
    """Parameters a node is given (inline, or by a file's entries for its name) that it never
    declares, where rosvar knows its every declaration: read off the workspace's sources,
    each name static, and no ``allow_undeclared_parameters``. rclcpp and rclpy keep such a
    parameter out of the node without a word, so a misspelt name leaves it on its default.
    Parameters set for every node (``<set_parameter>``) are not the node's to declare."""
    for node in model.nodes:
        own = [p for p in node.parameters if not p.globally]
        if not own:
            continue
        files = [(p, _entries(p, confinement)) for p in own if p.file is not None]
        for condition, launched, interface, static in launched_units(space, node, interfaces):
            declared = interface.of(Role.PARAMS)
            known = read_off_sources(declared)
            if not static or not known or not declared:
                continue
            fqn = launched.full_name
            names = {e.name.removeprefix("~/").replace("/", ".") for e in declared}
            given = [
                (p.condition, p.name) for p in own if p.file is None and isinstance(p.name, str)
            ]
            given += [
                (p.condition, name)
                for p, entries in files
                for key, params in entries
                if matches(key, fqn)
                for name in params
            ]
            for given_condition, name in given:
                if name in BUILT_IN or name.startswith("qos_overrides.") or _declares(names, name):
                    continue
                near = nearest(name, names)
                yield Found(
                    Check.PARAM_UNREAD,
                    Severity.WARNING,
                    f"{fqn}/{name}",
                    f"{fqn} is given the parameter {name}, which it never declares"
                    + (f" (it declares {near})" if near else "")
                    + ": the node never sees it",
                    condition & given_condition,
                    (node.location,),
                )


BUILT_IN = frozenset({"use_sim_time", "start_type_description_service"})
"""Parameters every rclcpp and rclpy node declares itself."""


def _declares(names: set[str], name: str) -> bool:
    """Whether a node declaring ``names`` takes ``name`` (or a name below it, or above)."""
    return any(
        name == declared or name.startswith(declared + ".") or declared.startswith(name + ".")
        for declared in names
    )


def _entries(
    parameter: NodeParameter, confinement: Confinement
) -> list[tuple[str, dict[str, object]]]:
    return given_entries(parameter, confinement) or []
