"""The controllers ros_control's spawners load (registered with the core's
:mod:`~rosvar.analyses.controllers`).

``controller_manager spawner NAME...`` (and ``controller_manager spawn NAME...``) has the
manager in its namespace load each controller named in its arguments, whose type is the
parameter ``NS/NAME/type`` (usually from a ``<rosparam>`` YAML). The controller's node handle
is ``NS/NAME``: its names lie below its name, as a node's private ones.
"""

from __future__ import annotations

from collections.abc import Iterator

from rosvar.analyses.communication import node_branches
from rosvar.analyses.controllers import Controller, spawned
from rosvar.analyses.param_values import ParamValues, Unknown
from rosvar.files import Confinement
from rosvar.interpreter.model import LaunchModel
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.ros import names
from rosvar.ros.version import RosVersion

SPAWNERS = {("controller_manager", "spawner"), ("controller_manager", "controller_manager")}
"""The executables that load controllers named in their arguments (``controller_manager
spawn NAME`` for the second)."""
NOT_CONTROLLERS = frozenset({"spawn", "load", "start", "stop", "unload", "kill", "list"})


@spawned(RosVersion.ROS1)
def spawned_controllers(
    space: ConditionSpace, model: LaunchModel, _confinement: Confinement
) -> Iterator[Controller]:
    """The controllers of the spawners of ``model``, where their type parameter names one."""
    values = ParamValues(space, [(space.true, model)])
    for node in model.nodes:
        if node.is_test:
            continue
        for condition, launched, _values in node_branches(space, node):
            if (launched.package, launched.type) not in SPAWNERS:
                continue
            for name in launched.args.split():
                if name.startswith("-") or name in NOT_CONTROLLERS:
                    continue
                kind = names.ns_join(names.ns_join(launched.namespace, name), "type")
                for value, typed in _types(values, kind).items():
                    where = condition & typed
                    if where != space.false:
                        yield Controller(
                            where,
                            name,
                            value,
                            launched.namespace,
                            (),
                            launched.full_name,
                            node,
                            ros2=False,
                        )


def _types(values: ParamValues, name: str) -> dict[str, BDD]:
    """The controller types the parameter ``name`` holds, each with its condition. Where a
    value is unknown (a ``<rosparam>`` known only per configuration may set anything below
    its namespace) and the launch files give one type, that type is taken: such files tune
    controllers (a wheel multiplier), they do not retype them."""
    found: dict[str, BDD] = {}
    unknown = values.space.false
    for condition, value in values.values(name, None):
        if isinstance(value, str):
            found[value] = found.get(value, values.space.false) | condition
        elif isinstance(value, Unknown):
            unknown |= condition
    if len(found) == 1:
        (only,) = found
        found[only] |= unknown
    return found
