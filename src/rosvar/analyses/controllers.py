"""ros_control controllers: the topics of the controllers a ``controller_manager`` spawner
loads, as edges of the spawner.

Controllers are plugins of the controller manager (``gazebo_ros_control`` in simulation, the
robot's hardware node otherwise), not nodes: the launch files name them only in the
spawner's arguments, and their type in the parameter ``NS/CONTROLLER/type``. A controller
of a known type uses the names below: ``joint_state_controller`` publishes the manager
namespace's ``joint_states``, ``diff_drive_controller`` subscribes ``CONTROLLER/cmd_vel`` and
publishes ``CONTROLLER/odom``. Without them every ``robot_state_publisher`` would miss its
``joint_states`` and every odometry filter its ``odom``.
"""

from __future__ import annotations

from dataclasses import dataclass

from rosvar.analyses.communication import Edge, node_branches
from rosvar.analyses.param_values import ParamValues, Unknown
from rosvar.diagnostics import Location
from rosvar.interpreter.model import LaunchModel
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.ros import names
from rosvar.workspace.interfaces.model import Role

SPAWNERS = {("controller_manager", "spawner"), ("controller_manager", "controller_manager")}
"""The executables that load controllers named in their arguments (``controller_manager
spawn NAME`` for the second)."""
NOT_CONTROLLERS = frozenset({"spawn", "load", "start", "stop", "unload", "kill", "list"})


@dataclass(frozen=True)
class ControllerUse:
    """A name a controller type uses: ``{controller}`` stands for the controller's name; a
    relative name lies in the controller manager's namespace."""

    role: Role
    name: str
    type: str
    boundary: bool = False


SOURCE = "https://github.com/ros-controls/ros_controllers/blob/noetic-devel"
CONTROLLERS: dict[str, tuple[ControllerUse, ...]] = {
    "joint_state_controller/JointStateController": (
        ControllerUse(Role.PUBLISHES, "joint_states", "sensor_msgs/JointState"),
    ),
    "diff_drive_controller/DiffDriveController": (
        ControllerUse(Role.SUBSCRIBES, "{controller}/cmd_vel", "geometry_msgs/Twist"),
        ControllerUse(Role.PUBLISHES, "{controller}/odom", "nav_msgs/Odometry"),
        ControllerUse(Role.PUBLISHES, "/tf", "tf2_msgs/TFMessage", boundary=True),
    ),
}
"""Controller types and the names they use (registry: ``CONTROLLERS[type] = ...``)."""
LOCATIONS = {
    "joint_state_controller/JointStateController": Location(
        f"{SOURCE}/joint_state_controller/src/joint_state_controller.cpp", 0, 0
    ),
    "diff_drive_controller/DiffDriveController": Location(
        f"{SOURCE}/diff_drive_controller/src/diff_drive_controller.cpp", 0, 0
    ),
}


def controller_edges(space: ConditionSpace, model: LaunchModel) -> list[Edge]:
    """The edges of the controllers the spawners of ``model`` load, where their type
    parameter names a known controller type."""
    values = ParamValues(space, [(space.true, model)])
    edges = []
    for node in model.nodes:
        if node.is_test:
            continue
        for condition, launched, _values in node_branches(space, node):
            if (launched.package, launched.type) not in SPAWNERS:
                continue
            namespace = launched.namespace
            for controller in launched.args.split():
                if controller.startswith("-") or controller in NOT_CONTROLLERS:
                    continue
                kind = names.ns_join(names.ns_join(namespace, controller), "type")
                for value, typed in _types(values, kind).items():
                    uses = CONTROLLERS.get(value)
                    where = condition & typed
                    if uses is None or where == space.false:
                        continue
                    for use in uses:
                        name = names.ns_join(namespace, use.name.format(controller=controller))
                        edges.append(
                            Edge(
                                model.file,
                                f"{launched.full_name}: controller {controller}",
                                use.role,
                                names.canonicalize_name(name),
                                use.type,
                                where,
                                node.location,
                                LOCATIONS[value],
                                True,
                                use.boundary,
                            )
                        )
    return edges


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
