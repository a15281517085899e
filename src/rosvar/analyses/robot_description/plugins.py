"""Gazebo (classic) model and sensor plugins: which names each one publishes, subscribes to or
serves, read from its ``<plugin>`` element, for every configuration of the description.

One registry entry per plugin library and ROS (:data:`PLUGINS`), each written from the
plugin's source (its ``source``): the SDF elements that name a topic and their defaults, the
message types, the elements that switch a topic on. ROS 1's plugins make a ``NodeHandle`` in
their ``<robotNamespace>`` (which ``spawn_model`` adds where a plugin has none: its
``-robot_namespace``, by default the spawner's namespace); ROS 2's are nodes of their own
(``gazebo_ros::Node``: named after the plugin, in ``<ros><namespace>``, with
``<ros><remapping>`` rules; ``spawn_entity.py -robot_namespace`` replaces the namespace).
"""

from __future__ import annotations

import enum
import os
import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import Final

from rosvar.analyses.robot_description.document import Text, XElement
from rosvar.diagnostics import Location
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.terms import Apply, concat, is_term
from rosvar.ros import names
from rosvar.ros.version import RosVersion
from rosvar.workspace.interfaces.model import Role

ROS1_SOURCE: Final = (
    "https://github.com/ros-simulation/gazebo_ros_pkgs/blob/"
    "f9e1a4607842afa5888ef01de31cd64a1e3e297f/gazebo_plugins/src/"
)
ROS2_SOURCE: Final = (
    "https://github.com/ros-simulation/gazebo_ros_pkgs/blob/"
    "d52f7c471d1d2fd9425bf8621290bc4831be8dea/gazebo_plugins/src/"
)
HECTOR_SOURCE: Final = (
    "https://github.com/tu-darmstadt-ros-pkg/hector_gazebo/blob/"
    "de947fb1e253b114d259e8690456792d91b93347/hector_gazebo_plugins/src/"
)


class Namespacing(enum.Enum):
    """How a plugin's names are resolved."""

    ROBOT_NAMESPACE = "robotNamespace"  # ROS 1: a NodeHandle in <robotNamespace>
    ROS_NODE = "ros"  # ROS 2: a node named after the plugin, <ros><namespace>, <remapping>


@dataclass(frozen=True)
class Use:
    """One name a plugin uses: given by the text of ``element`` (ROS 1's ``topicName``), or
    ``default`` where that element is absent (None: no use without it); ``{element}`` in a
    default is another element's value (hector's ``{topicName}/bias``)."""

    role: Role
    type: str
    default: str | None
    element: str | None = None
    under: str | None = None
    """An element whose value the name lies below (a camera's ``cameraName``)."""
    under_default: str | None = ""
    """``under``'s value where the element is absent (None: the enclosing sensor's name)."""
    type_element: str | None = None
    """An element whose text names the type (``output_type``, ROS 1's spelling)."""
    switch: tuple[str, bool] | None = None
    """An element that turns the use on (``publish_odom``), and its default."""
    sensor: str | None = None
    """The type of the enclosing ``<sensor>`` the use needs (a camera's depth topics)."""
    boundary: bool = False  # /tf: read by listeners everywhere, which the graph does not model


@dataclass(frozen=True)
class PluginKind:
    """One plugin library, as its source reads its ``<plugin>`` element."""

    library: str
    ros: RosVersion
    namespacing: Namespacing
    uses: tuple[Use, ...]
    source: str
    model_namespace: bool = False
    """An empty ``<robotNamespace>`` is the model's name (``GetRobotNamespace``)."""


PLUGINS: dict[tuple[RosVersion, str], PluginKind] = {}


def register(kind: PluginKind, *aliases: str) -> None:
    for library in (kind.library, *aliases):
        key = (kind.ros, library)
        if key in PLUGINS:
            raise ValueError(f"plugin {library} is registered twice")
        PLUGINS[key] = kind


def library_name(filename: str) -> str:
    """A ``filename`` as Gazebo finds the library: ``x`` is ``libx.so``."""
    name = os.path.basename(filename)
    if not name.startswith("lib"):
        name = "lib" + name
    if not name.endswith(".so"):
        name += ".so"
    return name


P, S, C, SV = Role.PUBLISHES, Role.SUBSCRIBES, Role.CLIENTS, Role.SERVICES
_ROS1 = (RosVersion.ROS1, Namespacing.ROBOT_NAMESPACE)
_ROS2 = (RosVersion.ROS2, Namespacing.ROS_NODE)
_TF = Use(P, "tf2_msgs/TFMessage", "/tf", boundary=True)
_CAMERA = (
    Use(P, "sensor_msgs/Image", "image_raw", "imageTopicName", under="cameraName"),
    Use(P, "sensor_msgs/CameraInfo", "camera_info", "cameraInfoTopicName", under="cameraName"),
)
_DEPTH = (
    Use(P, "sensor_msgs/Image", "ir/image_raw", "imageTopicName", under="cameraName"),
    Use(P, "sensor_msgs/CameraInfo", "ir/camera_info", "cameraInfoTopicName", under="cameraName"),
    Use(P, "sensor_msgs/PointCloud2", "points", "pointCloudTopicName", under="cameraName"),
    Use(P, "sensor_msgs/Image", "depth/image_raw", "depthImageTopicName", under="cameraName"),
    Use(
        P,
        "sensor_msgs/CameraInfo",
        "depth/camera_info",
        "depthImageCameraInfoTopicName",
        under="cameraName",
    ),
)
_CONTROLLER_MANAGER = tuple(
    Use(SV, f"controller_manager_msgs/{kind}", f"controller_manager/{name}")
    for name, kind in (
        ("list_controllers", "ListControllers"),
        ("list_controller_types", "ListControllerTypes"),
        ("load_controller", "LoadController"),
        ("unload_controller", "UnloadController"),
        ("switch_controller", "SwitchController"),
        ("reload_controller_libraries", "ReloadControllerLibraries"),
    )
)

for _kind, _aliases in (
    (
        PluginKind(
            "libgazebo_ros_imu.so",
            *_ROS1,
            (
                Use(P, "sensor_msgs/Imu", "/default_imu", "topicName"),
                Use(SV, "std_srvs/Empty", "/default_imu", "serviceName"),
            ),
            ROS1_SOURCE + "gazebo_ros_imu.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_imu_sensor.so",
            *_ROS1,
            (Use(P, "sensor_msgs/Imu", "imu_data", "topicName"),),
            ROS1_SOURCE + "gazebo_ros_imu_sensor.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_laser.so",
            *_ROS1,
            (Use(P, "sensor_msgs/LaserScan", "/world", "topicName"),),
            ROS1_SOURCE + "gazebo_ros_laser.cpp",
            model_namespace=True,
        ),
        ("libgazebo_ros_gpu_laser.so",),
    ),
    (
        PluginKind(
            "libgazebo_ros_camera.so",
            *_ROS1,
            _CAMERA,
            ROS1_SOURCE + "gazebo_ros_camera_utils.cpp",
            model_namespace=True,
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_openni_kinect.so",
            *_ROS1,
            _DEPTH,
            ROS1_SOURCE + "gazebo_ros_openni_kinect.cpp",
            model_namespace=True,
        ),
        ("libgazebo_ros_depth_camera.so",),
    ),
    (
        PluginKind(
            "libgazebo_ros_diff_drive.so",
            *_ROS1,
            (
                Use(S, "geometry_msgs/Twist", "cmd_vel", "commandTopic"),
                Use(P, "nav_msgs/Odometry", "odom", "odometryTopic"),
                Use(
                    P,
                    "sensor_msgs/JointState",
                    "joint_states",
                    switch=("publishWheelJointState", False),
                ),
                Use(P, "tf2_msgs/TFMessage", "/tf", switch=("publishTf", True), boundary=True),
            ),
            ROS1_SOURCE + "gazebo_ros_diff_drive.cpp",
            model_namespace=True,
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_p3d.so",
            *_ROS1,
            (Use(P, "nav_msgs/Odometry", None, "topicName"),),
            ROS1_SOURCE + "gazebo_ros_p3d.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_joint_state_publisher.so",
            *_ROS1,
            (Use(P, "sensor_msgs/JointState", "joint_states"),),
            ROS1_SOURCE + "gazebo_ros_joint_state_publisher.cpp",
            model_namespace=True,
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_planar_move.so",
            *_ROS1,
            (
                Use(S, "geometry_msgs/Twist", "cmd_vel", "commandTopic"),
                Use(P, "nav_msgs/Odometry", "odom", "odometryTopic"),
                _TF,
            ),
            ROS1_SOURCE + "gazebo_ros_planar_move.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_control.so",
            *_ROS1,
            (*_CONTROLLER_MANAGER, Use(S, "std_msgs/Bool", None, "eStopTopic")),
            "https://github.com/ros-simulation/gazebo_ros_pkgs/blob/"
            "f9e1a4607842afa5888ef01de31cd64a1e3e297f/gazebo_ros_control/src/"
            "gazebo_ros_control_plugin.cpp",
            model_namespace=True,
        ),
        (),
    ),
    (
        PluginKind(
            "libhector_gazebo_ros_imu.so",
            *_ROS1,
            (
                Use(P, "sensor_msgs/Imu", "imu", "topicName"),
                Use(P, "sensor_msgs/Imu", "{topicName}/bias", "biasTopicName"),
                Use(SV, "std_srvs/Empty", "{topicName}/calibrate", "serviceName"),
                Use(SV, "hector_gazebo_plugins/SetBias", "{topicName}/set_accel_bias"),
                Use(SV, "hector_gazebo_plugins/SetBias", "{topicName}/set_rate_bias"),
            ),
            HECTOR_SOURCE + "gazebo_ros_imu.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libhector_gazebo_ros_gps.so",
            *_ROS1,
            (
                Use(P, "sensor_msgs/NavSatFix", "fix", "topicName"),
                Use(P, "geometry_msgs/Vector3Stamped", "fix_velocity", "velocityTopicName"),
                Use(
                    SV,
                    "hector_gazebo_plugins/SetReferenceGeoPose",
                    "{topicName}/set_reference_geopose",
                ),
            ),
            HECTOR_SOURCE + "gazebo_ros_gps.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_velodyne_laser.so",
            *_ROS1,
            (Use(P, "sensor_msgs/PointCloud2", "/points", "topicName"),),
            "https://github.com/lmark1/velodyne_simulator/blob/"
            "e08185a3dd08c6efff7c23cf35c6603afb4e5d45/velodyne_gazebo_plugins/src/"
            "GazeboRosVelodyneLaser.cpp",
        ),
        ("libgazebo_ros_velodyne_gpu_laser.so",),
    ),
    # ROS 2: gazebo_ros::Node, names as the code writes them
    (
        PluginKind(
            "libgazebo_ros_imu_sensor.so",
            *_ROS2,
            (Use(P, "sensor_msgs/msg/Imu", "~/out"),),
            ROS2_SOURCE + "gazebo_ros_imu_sensor.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_ray_sensor.so",
            *_ROS2,
            (Use(P, "sensor_msgs/msg/PointCloud2", "~/out", type_element="output_type"),),
            ROS2_SOURCE + "gazebo_ros_ray_sensor.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_camera.so",
            *_ROS2,
            tuple(
                Use(P, kind, name, under="camera_name", under_default=None, sensor=sensor)
                for name, kind, sensor in (
                    ("image_raw", "sensor_msgs/msg/Image", None),
                    ("camera_info", "sensor_msgs/msg/CameraInfo", None),
                    ("depth/image_raw", "sensor_msgs/msg/Image", "depth"),
                    ("depth/camera_info", "sensor_msgs/msg/CameraInfo", "depth"),
                    ("points", "sensor_msgs/msg/PointCloud2", "depth"),
                )
            ),
            ROS2_SOURCE + "gazebo_ros_camera.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_diff_drive.so",
            *_ROS2,
            (
                Use(S, "geometry_msgs/msg/Twist", "cmd_vel"),
                Use(P, "nav_msgs/msg/Odometry", "odom", switch=("publish_odom", False)),
            ),
            ROS2_SOURCE + "gazebo_ros_diff_drive.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_p3d.so",
            *_ROS2,
            (Use(P, "nav_msgs/msg/Odometry", "odom"),),
            ROS2_SOURCE + "gazebo_ros_p3d.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_joint_state_publisher.so",
            *_ROS2,
            (Use(P, "sensor_msgs/msg/JointState", "joint_states"),),
            ROS2_SOURCE + "gazebo_ros_joint_state_publisher.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros_planar_move.so",
            *_ROS2,
            (
                Use(S, "geometry_msgs/msg/Twist", "cmd_vel"),
                Use(P, "nav_msgs/msg/Odometry", "odom", switch=("publish_odom", True)),
            ),
            ROS2_SOURCE + "gazebo_ros_planar_move.cpp",
        ),
        (),
    ),
    (
        PluginKind(
            "libgazebo_ros2_control.so",
            *_ROS2,
            tuple(
                Use(
                    SV,
                    f"controller_manager_msgs/srv/{kind}",
                    name,
                    under="controller_manager_name",
                    under_default="controller_manager",
                )
                for name, kind in (
                    ("list_controllers", "ListControllers"),
                    ("list_controller_types", "ListControllerTypes"),
                    ("load_controller", "LoadController"),
                    ("configure_controller", "ConfigureController"),
                    ("unload_controller", "UnloadController"),
                    ("switch_controller", "SwitchController"),
                    ("reload_controller_libraries", "ReloadControllerLibraries"),
                    ("list_hardware_components", "ListHardwareComponents"),
                    ("list_hardware_interfaces", "ListHardwareInterfaces"),
                )
            ),
            "https://github.com/ros-controls/gazebo_ros2_control/blob/"
            "3e6d3f4c0194d06a5850395a96b9537d02857a2e/gazebo_ros2_control/src/"
            "gazebo_ros2_control_plugin.cpp",
        ),
        (),
    ),
):
    register(_kind, *_aliases)


# -- reading a description's plugins -----------------------------------------------------------


@dataclass(frozen=True)
class PluginUse:
    """A name one plugin of a description uses, under ``condition``; ``name`` is as the
    plugin resolves it (a term where only known per configuration)."""

    plugin: str  # the plugin's name attribute
    library: str
    role: Role
    name: Text
    type: str | None
    condition: BDD
    location: Location  # the <plugin> element
    boundary: bool = False


@dataclass(frozen=True)
class Unread:
    """A ``<plugin>`` whose library is not known, or only known per configuration."""

    filename: Text
    condition: BDD
    location: Location


@dataclass(frozen=True)
class Spawning:
    """How the spawner places the model's plugins: its namespace (the default robot
    namespace of ROS 1's ``spawn_model``), its ``-robot_namespace`` and the model's name."""

    namespace: str
    robot_namespace: Text | None
    model: Text | None


def plugin_uses(
    space: ConditionSpace, root: XElement, ros: RosVersion, spawning: Spawning
) -> tuple[list[PluginUse], list[Unread]]:
    """Every name the description's known plugins use, each with its condition (the
    plugin element's and its values')."""
    uses: list[PluginUse] = []
    unread: list[Unread] = []
    for plugin, sensor in _plugins(root, None):
        filename = plugin.attributes.get("filename")
        if filename is None:
            continue
        for condition, value in filename:
            where = condition & plugin.condition
            if value is None or where == space.false:
                continue
            kind = None if is_term(value) else PLUGINS.get((ros, library_name(str(value))))
            if kind is None:
                if is_term(value) or "ros" in str(value):
                    unread.append(Unread(value, where, plugin.location))
                continue
            uses.extend(_uses(space, kind, plugin, sensor, where, spawning))
    return uses, unread


def _plugins(
    element: XElement, sensor: XElement | None
) -> Iterator[tuple[XElement, XElement | None]]:
    if element.tag == "plugin":
        yield element, sensor
        return
    inner = element if element.tag == "sensor" else sensor
    for child in element.children:
        yield from _plugins(child, inner)


def child_text(space: ConditionSpace, element: XElement, tag: str) -> Choice[Text | None]:
    """The text of ``element``'s first ``tag`` child present (SDF reads the first), None
    where there is none."""
    branches: list[tuple[BDD, Text | None]] = []
    remaining = element.condition
    for child in element.children:
        if child.tag != tag:
            continue
        present = remaining & child.condition
        if present != space.false:
            branches.extend((present & c, v) for c, v in child.text(space))
        remaining &= ~child.condition
    branches.append((remaining, None))
    return Choice.of(branches, space.false)


def _uses(
    space: ConditionSpace,
    kind: PluginKind,
    plugin: XElement,
    sensor: XElement | None,
    condition: BDD,
    spawning: Spawning,
) -> Iterator[PluginUse]:
    name_attribute = plugin.attributes.get("name")
    plugin_name = name_attribute.single() if name_attribute is not None else None
    label = plugin_name if isinstance(plugin_name, str) else "plugin"
    ros = plugin
    if kind.namespacing is Namespacing.ROS_NODE:
        inner = [c for c in plugin.children if c.tag == "ros"]
        ros = inner[0] if inner else plugin
    namespace = _namespace(space, kind, plugin, ros, spawning)
    remaps = _remaps(space, ros) if kind.namespacing is Namespacing.ROS_NODE else []
    for use in kind.uses:
        if use.sensor is not None and (sensor is None or _sensor_type(sensor) != use.sensor):
            continue
        parts: list[Choice[object]] = [namespace, _name(space, use, plugin, sensor)]
        parts.append(_switch(space, use, plugin))
        if use.type_element is not None:
            parts.append(child_text(space, plugin, use.type_element))
        for branch, values in combine(parts, list):
            where = condition & branch
            ns, name, on = values[0], values[1], values[2]
            if where == space.false or not on or name is None or name == "":
                continue
            kind_type = use.type
            if use.type_element is not None and isinstance(values[3], str):
                kind_type = _ros2_type(values[3])
            for used, resolved in _resolved(kind, ns, name, plugin_name, remaps, where):  # type: ignore[arg-type]
                yield PluginUse(
                    label, kind.library, use.role, resolved, kind_type, used, plugin.location,
                    use.boundary,
                )  # fmt: skip


def _sensor_type(sensor: XElement) -> str | None:
    value = sensor.attributes.get("type")
    found = value.single() if value is not None else None
    return found if isinstance(found, str) else None


def _namespace(
    space: ConditionSpace, kind: PluginKind, plugin: XElement, ros: XElement, spawning: Spawning
) -> Choice[object]:
    """The namespace the plugin's names lie in (ROS 2: its node's)."""
    if kind.namespacing is Namespacing.ROS_NODE:
        own = child_text(space, ros, "namespace")
        if spawning.robot_namespace not in (None, ""):
            return Choice.const(space, spawning.robot_namespace)
        return own.map(lambda text: "/" if text is None else text)
    own = child_text(space, plugin, "robotNamespace")
    given = spawning.robot_namespace
    default = spawning.namespace if given is None else given

    def chosen(text: Text | None) -> object:
        if text is None:
            return default
        if text == "" and kind.model_namespace:
            return spawning.model if spawning.model is not None else ""
        return text

    return own.map(chosen)


def _name(
    space: ConditionSpace, use: Use, plugin: XElement, sensor: XElement | None
) -> Choice[object]:
    """The name as the plugin writes it: its element's text, else the default (with the
    other elements it names), below ``under`` when that is given."""
    own = child_text(space, plugin, use.element) if use.element else Choice.const(space, None)
    default = _default(space, use.default, plugin)
    name = own.bind(lambda text: default if text is None else Choice.const(space, text))
    if use.under is None:
        return name
    under = child_text(space, plugin, use.under)
    fallback = use.under_default
    if fallback is None:
        value = sensor.attributes.get("name") if sensor is not None else None
        sensor_name = value.single() if value is not None else None
        fallback = sensor_name if isinstance(sensor_name, str) else ""
    return combine(
        [under, name], lambda pair: _below(pair[0] if pair[0] is not None else fallback, pair[1])
    )


def _below(prefix: object, name: object) -> object:
    if name is None:
        return None
    if prefix in ("", None):
        return name
    return concat([prefix, "/", name])  # type: ignore[list-item]


_PLACE: Final = re.compile(r"\{(\w+)\}")


def _default(space: ConditionSpace, template: str | None, plugin: XElement) -> Choice[object]:
    if template is None or "{" not in template:
        return Choice.const(space, template)
    elements = _PLACE.findall(template)
    values = [child_text(space, plugin, n) for n in elements]

    def filled(leaves: list[Text | None]) -> object:
        pieces: list[Text] = []
        rest = template
        for element, leaf in zip(elements, leaves, strict=True):
            before, _, rest = rest.partition("{" + element + "}")
            pieces += [before, leaf if leaf is not None else ""]
        return concat([*pieces, rest])

    return combine(values, filled)


def _switch(space: ConditionSpace, use: Use, plugin: XElement) -> Choice[object]:
    if use.switch is None:
        return Choice.const(space, True)
    element, default = use.switch
    return child_text(space, plugin, element).map(
        lambda text: default if text is None else _sdf_bool(text)
    )


def _sdf_bool(text: Text) -> bool:
    """SDF's reading of a boolean element (``true``/``1``); unknown text reads false."""
    return isinstance(text, str) and text.strip().lower() in ("true", "1")


def _remaps(space: ConditionSpace, ros: XElement) -> list[tuple[BDD, Text, Text]]:
    found: list[tuple[BDD, Text, Text]] = []
    for child in ros.children:
        if child.tag != "remapping":
            continue
        for condition, text in child.text(space):
            if isinstance(text, str) and ":=" in text:
                source, _, target = text.partition(":=")
                found.append((child.condition & condition, source.strip(), target.strip()))
    return found


def _ros2_type(text: str) -> str:
    """``sensor_msgs/LaserScan`` (how ``output_type`` writes it) as ROS 2 names it."""
    package, _, name = text.strip().partition("/")
    return f"{package}/msg/{name}" if "/" not in name else text.strip()


def _resolved(
    kind: PluginKind,
    namespace: Text,
    name: Text,
    plugin_name: object,
    remaps: Sequence[tuple[BDD, Text, Text]],
    condition: BDD,
) -> list[tuple[BDD, Text]]:
    """The names the plugin's node handle (ROS 2: its node, remapped by the first rule
    that matches) resolves ``name`` to, each with its condition; a term where a part is
    only known per configuration."""
    if is_term(namespace) or is_term(name):  # joined once the values are known
        joined = Apply("ns_join", (concat(["/", namespace]), name))
        return [(condition, Apply("canonicalize", (joined,)))]
    assert isinstance(namespace, str) and isinstance(name, str)
    if kind.namespacing is Namespacing.ROBOT_NAMESPACE:
        return [(condition, names.canonicalize_name(names.ns_join(_absolute(namespace), name)))]
    node = names.ns_join(_absolute(namespace), plugin_name if isinstance(plugin_name, str) else "")
    resolved = _ros2(namespace, node, name)
    outcomes: list[tuple[BDD, Text]] = []
    remaining = condition
    for when, source, target in remaps:
        if not isinstance(source, str) or _ros2(namespace, node, source) != resolved:
            continue
        taken = remaining & when
        if isinstance(target, str) and taken != condition.bdd.false:
            outcomes.append((taken, _ros2(namespace, node, target)))
        remaining &= ~when
    outcomes.append((remaining, resolved))
    return [(c, n) for c, n in outcomes if c != condition.bdd.false]


def _absolute(namespace: str) -> str:
    return namespace if namespace.startswith("/") else "/" + namespace


def _ros2(namespace: str, node: str, name: str) -> str:
    if name.startswith("~"):
        return names.canonicalize_name(node + "/" + name[1:].lstrip("/"))
    return names.canonicalize_name(names.ns_join(_absolute(namespace), name))
