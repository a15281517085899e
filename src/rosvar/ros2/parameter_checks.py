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

from rosvar.analyses.checks import Check, Found, model_check
from rosvar.analyses.communication import node_branches
from rosvar.diagnostics import Severity
from rosvar.files import Confinement
from rosvar.interpreter.model import LaunchModel, NodeParameter
from rosvar.logic.conditions import ConditionSpace
from rosvar.ros.version import RosVersion
from rosvar.ros2.conventions.parameters import matches
from rosvar.ros2.resolve import parameter_entries, parameter_file


@model_check(RosVersion.ROS2)
def unmatched_parameter_files(
    space: ConditionSpace, model: LaunchModel, confinement: Confinement
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
    for node, condition, fqn in named:
        for parameter in node.parameters:
            keys = [key for key, _params in _entries(parameter, confinement)]
            reached = space.false  # where an entry is some launched node's
            for _other, launched, name in named:
                if any(matches(key, name) for key in keys):
                    reached |= launched
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
                (node.location,),
            )


def _entries(
    parameter: NodeParameter, confinement: Confinement
) -> list[tuple[str, dict[str, object]]]:
    """The entries of a parameter file whose text is known (read inside the workspace's
    confinement; ``allow_substs``: its substituted text), else none."""
    path = parameter.file
    if path is None or not isinstance(path, str):
        return []
    try:
        if parameter.content is None:
            return parameter_file(path, confinement)
        if isinstance(parameter.content, str):
            return parameter_entries(parameter.content, path)
    except ValueError:
        pass  # refused or unreadable: the model's diagnostics say so
    return []
