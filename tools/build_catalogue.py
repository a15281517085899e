"""Regenerate the bundled catalogue of third-party ROS 1 node interfaces.

Runs rosvar's own extractor on public sources: each repository below is expected as a
mirror (``/work/.mirror/OWNER+NAME/repo``, a bare git directory as the ``fetch`` tool leaves
it, or any clone given with ``--mirrors``); the named branch is exported to a temporary folder
(nothing fetched is kept or committed; tests are left out), its packages are extracted, the
review by hand below is applied, and every node records its repository and commit, every
entry its file and line there. Review the result by hand before committing:

    python tools/build_catalogue.py > src/rosvar/workspace/interfaces/catalogue/ros1.json
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

import catalogue_ros2
from catalogue_review import ROLES, Edition, Item, Review, Source, by_parameter, read, use

from rosvar.files import Confinement
from rosvar.outputs.documents.interfaces import node_document
from rosvar.workspace import discover
from rosvar.workspace.interfaces import tf
from rosvar.workspace.interfaces.extraction import extract_interfaces
from rosvar.workspace.interfaces.model import Role

SOURCES: list[Source] = [
    # repository, ROS 1 branch (melodic's where there is one: the corpus's systems are
    # melodic), folders holding the packages ("" = the repository's root): every package a
    # launch file of the corpus (its four systems and _external) starts a node of, most
    # launched first, whose sources the corpus does not hold
    Source("ros/robot_state_publisher", "melodic-devel", [""]),
    Source(
        "ros/joint_state_publisher",
        "kinetic-devel",
        ["joint_state_publisher", "joint_state_publisher_gui"],
    ),
    Source("ros-simulation/gazebo_ros_pkgs", "melodic-devel", ["gazebo_ros"]),
    Source("ros-planning/navigation", "melodic-devel", ["amcl", "map_server", "move_base"]),
    Source("ros-perception/slam_gmapping", "melodic-devel", ["gmapping"]),
    Source("ros-drivers/joystick_drivers", "melodic-devel", ["joy"]),
    Source("ros/diagnostics", "noetic-devel", ["diagnostic_aggregator"]),
    Source("ros/geometry", "melodic-devel", ["tf"]),
    Source("ros/geometry2", "melodic-devel", ["tf2_ros"]),
    Source("ros/ros_comm", "melodic-devel", ["tools/topic_tools"]),
    Source("ros-controls/ros_control", "melodic-devel", ["controller_manager"]),
    Source("ros-perception/image_pipeline", "melodic", ["image_proc", "depth_image_proc"]),
    Source("ros-perception/image_common", "noetic-devel", ["image_transport"]),
    Source("ros-planning/robot_pose_ekf", "master", [""]),
    Source("ros-perception/depthimage_to_laserscan", "melodic-devel", [""]),
    Source("ros-perception/pointcloud_to_laserscan", "lunar-devel", [""]),
    Source("cra-ros-pkg/robot_localization", "melodic-devel", [""]),
    Source("ros-teleop/twist_mux", "melodic-devel", [""]),
    Source("ros-teleop/teleop_twist_joy", "melodic-devel", [""]),
    Source("ros-drivers/urg_node", "melodic-devel", [""]),
    Source("CCNYRoboticsLab/imu_tools", "melodic", ["imu_filter_madgwick"]),
    Source("ros-perception/imu_pipeline", "noetic-devel", ["imu_transformer"]),
    Source("tu-darmstadt-ros-pkg/hector_slam", "melodic-devel", ["hector_mapping"]),
    Source("ros-visualization/interactive_marker_twist_server", "kinetic-devel", [""]),
    Source("ros-drivers/openni2_camera", "ros1", ["openni2_camera"]),
    Source("ros-drivers/openni_camera", "ros1", ["openni_camera"]),
    Source("yujinrobot/yujin_ocs", "devel", ["yocs_cmd_vel_mux", "yocs_velocity_smoother"]),
    Source("ros-visualization/rviz", "melodic-devel", []),
    Source("ros-controls/ros_controllers", "melodic-devel", []),
]

SKIPPED = [
    f":(exclude,glob)**/{pattern}"
    for pattern in ("test/**", "*.bag", "*.gif", "*.png", "*.jpg", "*.pgm", "*.pcd", "*.stl")
]
"""Tests are no launched nodes; large files (recordings, images, maps, meshes) may be
absent from a mirror."""
TF_TOPICS = frozenset({"/tf", "/tf_static"})
"""tf's topics: nearly every node and rviz hold a listener, modelled only where reviewed; a
publication of these, and a subscription of ``/tf_static``, is a boundary use in every node
(:mod:`rosvar.workspace.interfaces.tf`)."""
TEST_EXECUTABLE = re.compile(r"(^|[_-])(r?test|unittest)|^test|_test$|(^|_)test_")
"""Test programs built outside ``test/`` (``tf2_ros_test_listener``, ``gmapping-rtest``)."""

TF = "tf2_msgs/TFMessage"
RSP = Review(
    "added /tf and /tf_static (tf2_ros broadcasters) and robot_description "
    "(urdf::Model::initParam)",
    add={
        "publishes": [
            use("/tf", TF, "src/robot_state_publisher.cpp", 102),
            use("/tf_static", TF, "src/robot_state_publisher.cpp", 124),
        ],
        "params": [read("robot_description", None, "src/joint_state_listener_node.cpp", 64)],
    },
)
JSP_MODULE = "joint_state_publisher/src/joint_state_publisher/__init__.py"
JSP = Review(
    "the script imports its package's module, which the extractor does not read; entries "
    "from that module by hand: each parameter is read as ~name, else name (its get_param)",
    add={
        "publishes": [use("joint_states", "sensor_msgs/JointState", JSP_MODULE, 175)],
        "subscribes": [
            {**use("{source}", "sensor_msgs/JointState", JSP_MODULE, 173), "static": False}
        ],
        "params": [
            read("robot_description", None, JSP_MODULE, 143),
            read("~dependent_joints", {"expression": "{}"}, JSP_MODULE, 149),
            read("~use_mimic_tags", True, JSP_MODULE, 150),
            read("~use_smallest_joint_limits", True, JSP_MODULE, 151),
            read("~zeros", {"expression": "None"}, JSP_MODULE, 153),
            read("~publish_default_positions", True, JSP_MODULE, 155),
            read("~publish_default_velocities", False, JSP_MODULE, 156),
            read("~publish_default_efforts", False, JSP_MODULE, 157),
            read("~source_list", {"expression": "[]"}, JSP_MODULE, 170),
            read("~rate", 10, JSP_MODULE, 211),
            read("~delta", 0.0, JSP_MODULE, 214),
        ],
    },
)
TF2_LISTENER = "a tf2_ros::TransformListener"
GAZEBO_INTERFACE = "gazebo_ros/src/gazebo_ros/gazebo_interface.py"
SPAWN_MODEL = "gazebo_ros/scripts/spawn_model"
RELAY = "tools/topic_tools/src/relay.cpp"
REVIEW: dict[tuple[str, str], Review] = {
    ("robot_state_publisher", "robot_state_publisher"): RSP,
    ("robot_state_publisher", "state_publisher"): RSP,
    ("joint_state_publisher", "joint_state_publisher"): JSP,
    ("amcl", "amcl"): Review(
        "dropped base_scan and /tf publishers and the second initialpose subscriber (only "
        "when replaying a bag given on the command line); added /tf (tf2_ros broadcaster), "
        f"/tf and /tf_static ({TF2_LISTENER}) and the static_map client "
        "(ros::service::call, used when ~use_map_topic is false)",
        add={
            "publishes": [use("/tf", TF, "amcl/src/amcl_node.cpp", 1475)],
            "subscribes": [
                use("/tf", TF, "amcl/src/amcl_node.cpp", 471),
                use("/tf_static", TF, "amcl/src/amcl_node.cpp", 471),
            ],
            "clients": [use("static_map", "nav_msgs/GetMap", "amcl/src/amcl_node.cpp", 850)],
        },
        drop={"publishes": ["base_scan", "/tf"], "subscribes": ["initialpose@666"]},
        boundary={"subscribes": ["initialpose"], "publishes": ["particlecloud"]},
    ),
    ("move_base", "move_base"): Review(
        f"added /tf and /tf_static ({TF2_LISTENER}); the costmaps' and planners' plugins "
        "(loaded at run time) are not read; move_base_simple/goal is rviz's 2D Nav Goal, "
        "~current_goal, goal and recovery_status are for people; without "
        "~recovery_behaviors it loads its default recovery behaviours",
        defaults={1022: {"expression": "loadDefaultRecoveryBehaviors()"}},
        boundary={
            "subscribes": ["move_base_simple/goal"],
            "publishes": ["~current_goal", "move_base/goal", "move_base/recovery_status"],
        },
        add={
            "subscribes": [
                use("/tf", TF, "move_base/src/move_base_node.cpp", 36),
                use("/tf_static", TF, "move_base/src/move_base_node.cpp", 36),
            ]
        },
    ),
    ("gmapping", "slam_gmapping"): Review(
        "added /tf (tf::TransformBroadcaster) and its tf::TransformListener's /tf, /tf_static",
        add={
            "publishes": [use("/tf", TF, "gmapping/src/slam_gmapping.cpp", 802)],
            "subscribes": [
                use("/tf", TF, "gmapping/src/slam_gmapping.h", 70),
                use("/tf_static", TF, "gmapping/src/slam_gmapping.h", 70),
            ],
        },
    ),
    ("tf", "static_transform_publisher"): Review(
        "added /tf (tf::TransformBroadcaster)",
        add={"publishes": [use("/tf", TF, "tf/src/static_transform_publisher.cpp", 57)]},
    ),
    ("tf2_ros", "static_transform_publisher"): Review(
        "dropped /tf, /tf_static and ~tf2_frames: the library's TransformListener and Buffer "
        "are reached by name only, the program uses neither",
        drop={"subscribes": ["/tf", "/tf_static"], "services": ["~tf2_frames"]},
    ),
    ("controller_manager", "spawner"): Review(
        "the controller manager's services, as named without --namespace",
        add={
            "clients": [
                use(
                    f"controller_manager/{verb}_controller",
                    f"controller_manager_msgs/{verb.capitalize()}Controller",
                    "controller_manager/scripts/spawner",
                    line,
                )
                for verb, line in (("load", 115), ("unload", 116), ("switch", 117))
            ]
        },
        drop={
            "clients": [
                "{load_controller_service}",
                "{unload_controller_service}",
                "{switch_controller_service}",
            ]
        },
    ),
    ("gazebo_ros", "spawn_model"): Review(
        "Gazebo's services and topics as named with the default -gazebo_namespace /gazebo; "
        "the model is read from the parameter that -param names",
        add={
            "subscribes": [
                use("/gazebo/model_states", "gazebo_msgs/ModelStates", SPAWN_MODEL, 102)
            ],
            "clients": [
                use("/gazebo/spawn_sdf_model", "gazebo_msgs/SpawnModel", GAZEBO_INTERFACE, 18),
                use("/gazebo/spawn_urdf_model", "gazebo_msgs/SpawnModel", GAZEBO_INTERFACE, 30),
                use(
                    "/gazebo/set_model_configuration",
                    "gazebo_msgs/SetModelConfiguration",
                    GAZEBO_INTERFACE,
                    44,
                ),
                use("/gazebo/unpause_physics", "std_srvs/Empty", SPAWN_MODEL, 210),
                use("/gazebo/delete_model", "gazebo_msgs/DeleteModel", SPAWN_MODEL, 230),
            ],
        },
        drop={
            "subscribes": ["{'%s/model_states' % self.args.gazebo_namespace}"],
            "clients": [
                "{'%s/unpause_physics' % self.args.gazebo_namespace}",
                "{'%s/delete_model' % self.args.gazebo_namespace}",
            ],
        },
    ),
    ("topic_tools", "relay"): Review(
        "the topics are the command line's (relay IN_TOPIC [OUT_TOPIC]), of any type; "
        "dropped a publisher reached by name in ShapeShifter::advertise; ~lazy is read by "
        "getParam into g_lazy, which keeps false when it is unset",
        defaults={169: False},
        add={
            "subscribes": [
                {**use("{argv[1]}", None, RELAY, 58), "static": False},
            ],
            "publishes": [
                {**use("{argv[2]}", None, RELAY, 99), "static": False},
            ],
        },
        drop={"publishes": ["{nh}/{opts}"]},
    ),
    ("diagnostic_aggregator", "aggregator_node"): Review(
        "dropped the analyzers' parameters: each analyzer (a plugin) reads them below "
        "~analyzers/NAME/, named by the analyzers the launch file configures; /diagnostics "
        "comes from drivers' diagnostic_updater (not extracted), its outputs are for "
        "monitors (rqt_robot_monitor)",
        boundary={
            "subscribes": ["/diagnostics"],
            "publishes": ["/diagnostics_agg", "/diagnostics_toplevel_state"],
        },
        drop={
            "params": [
                f"{{n}}/{name}"
                for name in (
                    "path",
                    "find_and_remove_prefix",
                    "remove_prefix",
                    "startswith",
                    "name",
                    "contains",
                    "expected",
                    "regex",
                    "timeout",
                    "num_items",
                    "discard_stale",
                )
            ]
        },
    ),
}
REVIEW[("joint_state_publisher_gui", "joint_state_publisher_gui")] = JSP
API_PLUGIN = "gazebo_ros/src/gazebo_ros_api_plugin.cpp"
GAZEBO = [
    ("gazebo_ros/SpawnModel", "spawn_sdf_model", 281),
    ("gazebo_ros/SpawnModel", "spawn_urdf_model", 290),
    ("gazebo_msgs/DeleteModel", "delete_model", 299),
    ("gazebo_msgs/SetModelConfiguration", "set_model_configuration", 454),
    ("std_srvs/Empty", "pause_physics", 498),
    ("std_srvs/Empty", "unpause_physics", 507),
]
JOINT_STATE_CONTROLLER = "joint_state_controller/JointStateController"
JSC_SOURCE = "joint_state_controller/src/joint_state_controller.cpp"
DIFF_DRIVE_CONTROLLER = "diff_drive_controller/DiffDriveController"
DIFF_DRIVE_SOURCE = "diff_drive_controller/src/diff_drive_controller.cpp"
EXTRA: dict[tuple[str, str, str], Review] = {
    ("ros-visualization/rviz", "rviz", "rviz"): Review(
        "a visualiser: what it subscribes depends on the displays of its configuration "
        "(not modelled); its default configuration's tools publish a pose estimate, a goal "
        "and clicked points, made by people (boundary uses)",
        add={
            "publishes": [
                {**use(name, kind, "default.rviz", line), "boundary": True}
                for name, kind, line in (
                    ("/initialpose", "geometry_msgs/PoseWithCovarianceStamped", 63),
                    ("/move_base_simple/goal", "geometry_msgs/PoseStamped", 65),
                    ("/clicked_point", "geometry_msgs/PointStamped", 68),
                )
            ]
        },
    ),
    # (repository, package, executable): nodes the extractor cannot find at all, by hand
    ("ros-controls/ros_controllers", "joint_state_controller", JOINT_STATE_CONTROLLER): Review(
        "a controller type (a plugin the controller manager loads, named in its parameter "
        "NAME/type), read by hand: joint_states in the manager's namespace",
        add={"publishes": [use("joint_states", "sensor_msgs/JointState", JSC_SOURCE, 57)]},
        kind="controller",
    ),
    ("ros-controls/ros_controllers", "diff_drive_controller", DIFF_DRIVE_CONTROLLER): Review(
        "a controller type (a plugin the controller manager loads, named in its parameter "
        "NAME/type), read by hand: its node handle is the controller's name (~ names), the "
        "odometry's transform goes to /tf",
        add={
            "subscribes": [use("~cmd_vel", "geometry_msgs/Twist", DIFF_DRIVE_SOURCE, 355)],
            "publishes": [
                use("~odom", "nav_msgs/Odometry", DIFF_DRIVE_SOURCE, 705),
                {**use("/tf", "tf2_msgs/TFMessage", DIFF_DRIVE_SOURCE, 727), "boundary": True},
            ],
        },
        kind="controller",
    ),
    ("ros-simulation/gazebo_ros_pkgs", "gazebo_ros", "gzserver"): Review(
        "a shell script that runs Gazebo with gazebo_ros_api_plugin (a Gazebo plugin, no "
        "node source); the plugin creates its services through AdvertiseServiceOptions, "
        "which the extractor does not read: those spawn_model uses and the model states, "
        "in the node's namespace (~: the launch file names it gazebo); the model plugins of "
        "a robot's URDF (gazebo_ros_control, sensors) are not included",
        add={
            "services": [
                use("~" + name, kind.replace("gazebo_ros/", "gazebo_msgs/"), API_PLUGIN, line)
                for kind, name, line in GAZEBO
            ],
            "publishes": [
                use("/clock", "rosgraph_msgs/Clock", API_PLUGIN, 208),
                use("~link_states", "gazebo_msgs/LinkStates", API_PLUGIN, 400),
                use("~model_states", "gazebo_msgs/ModelStates", API_PLUGIN, 409),
            ],
        },
        # /clock is read by every node under use_sim_time (inside roscpp/rospy)
        boundary={"publishes": ["/clock", "~link_states", "~model_states"]},
    ),
}
for _key, _review in {
    ("joy", "joy_node"): Review(
        "joy/set_feedback (force feedback) is an optional input",
        boundary={"subscribes": ["joy/set_feedback"]},
    ),
    ("hector_mapping", "hector_mapping"): Review(
        "initialpose is rviz's 2D Pose Estimate; the markers and debug info are for people",
        boundary={
            "subscribes": ["initialpose"],
            "publishes": [
                "hector_debug_info",
                "visualization_marker",
                "visualization_marker_array",
            ],
        },
    ),
    ("gmapping", "slam_gmapping"): Review(
        REVIEW[("gmapping", "slam_gmapping")].note + "; entropy is for people",
        add=REVIEW[("gmapping", "slam_gmapping")].add,
        boundary={"publishes": ["~entropy"]},
    ),
}.items():
    REVIEW[_key] = _review
LOCALIZATION_INPUTS = {1107: "odom", 1224: "pose", 1301: "twist", 1471: "imu"}
"""ros_filter.cpp: each sensor's topic is the value of ~odom0, ~odom1, ... (then ~pose0,
~twist0, ~imu0), read in a loop until one is not set."""
for _filter in ("ekf_localization_node", "ukf_localization_node"):
    REVIEW[("robot_localization", _filter)] = Review(
        "set_pose (topic) is for people and tools resetting the filter; each sensor topic "
        "is the value of ~odomN/~poseN/~twistN/~imuN (one per parameter set); cmd_vel only "
        "with ~use_control, stamped after ~stamped_control; ~control_config is read only "
        "with ~use_control: unset then, the filter logs an error and turns the control term "
        "off (useControl_ = false), and cmd_vel is not subscribed either",
        defaults={888: {"expression": "useControl_ = false"}},
        boundary={"subscribes": ["set_pose"]},
        named={
            "subscribes": {
                line: by_parameter(f"~{kind}{{N}}") for line, kind in LOCALIZATION_INPUTS.items()
            }
        },
        when={
            "subscribes": {
                1538: "param('~use_control') and param('~stamped_control')",
                1542: "param('~use_control') and not param('~stamped_control')",
            }
        },
    )
REVIEW[("teleop_twist_joy", "teleop_node")] = Review(
    "~scale_linear, ~scale_linear_turbo, ~scale_angular and ~scale_angular_turbo are read "
    "by getParam into maps whose result is dropped: unset, a map stays empty and its axes "
    "move at scale 0 (teleop_twist_joy.cpp)",
    defaults={line: {"expression": "{}"} for line in (79, 80, 91, 92)},
)
REVIEW[("interactive_marker_twist_server", "marker_server")] = Review(
    "unset, ~linear_scale (tested by getParam) sends the constructor to the reads of "
    "~linear_scale, ~max_positive_linear_velocity and ~max_negative_linear_velocity as "
    "doubles, defaults 1.0, 1.0, -1.0; set (a map), it is read again as that map and the "
    "two velocity maps are read by getParam whose result is dropped: unset, they stay empty",
    defaults={
        56: {"expression": "linear_drive_scale_map"},
        57: {"expression": "{}"},
        58: {"expression": "{}"},
    },
)
REVIEW[("robot_pose_ekf", "robot_pose_ekf")] = Review(
    "each input only when its ~odom_used, ~imu_used, ~vo_used, ~gps_used says so "
    "(odom_estimation_node.cpp)",
    when={
        "subscribes": {
            112: "param('~odom_used')",
            119: "param('~imu_used')",
            126: "param('~vo_used')",
            132: "param('~gps_used')",
        }
    },
)
for _node, _nodelet in (
    ("pointcloud_to_laserscan_node", "pointcloud_to_laserscan_nodelet"),
    ("laserscan_to_pointcloud_node", "laserscan_to_pointcloud_nodelet"),
):
    REVIEW[("pointcloud_to_laserscan", _node)] = Review(
        f"runs the nodelet pointcloud_to_laserscan/{_nodelet} in-process under the node's "
        f"own name (nodelet::Loader in src/{_node}.cpp): its topics and parameters",
        loads=("pointcloud_to_laserscan", f"pointcloud_to_laserscan/{_nodelet}"),
    )
REVIEW[("yocs_cmd_vel_mux", "yocs_cmd_vel_mux/CmdVelMuxNodelet")] = Review(
    "the output topic is the YAML's publisher (default ~output) and the inputs its "
    "subscribers: the file ~yaml_cfg_file names (or dynamic_reconfigure's yaml_cfg_data), "
    "read at run time, so both stay symbolic; ~active (latched) tells people which input "
    "drives",
    boundary={"publishes": ["~active"]},
)
REVIEW[("yocs_velocity_smoother", "yocs_velocity_smoother/VelocitySmootherNodelet")] = Review(
    "~odometry and ~robot_cmd_vel are always subscribed but their messages are used only "
    "with ~robot_feedback 1 (odometry) or 2 (commands), default 0: modelled as uses with "
    "that condition, so an unused feedback input is no missing partner; unset "
    "~speed_lim_v/w or ~accel_lim_v/w stop the nodelet (ROS_ERROR, init fails)",
    when={
        "subscribes": {
            318: "param('~robot_feedback') == 1",
            319: "param('~robot_feedback') == 2",
        }
    },
)
OPENNI_DRIVER = "openni_camera/src/nodelets/driver.cpp"
REVIEW[("openni_camera", "openni_camera/driver")] = Review(
    "depth images go to depth/ or, with ~depth_registration (dynamic_reconfigure, default "
    "false in cfg/OpenNI.cfg), to depth_registered/ (publishDepthImage), never both",
    add={"params": [read("~depth_registration", False, "openni_camera/cfg/OpenNI.cfg", 24)]},
    when={
        "publishes": {
            199: "not param('~depth_registration')",
            203: "param('~depth_registration')",
        }
    },
)
REVIEW[("hector_mapping", "hector_mapping")] = Review(
    REVIEW[("hector_mapping", "hector_mapping")].note
    + "; the scan, system message and pose update topics are parameters' values",
    boundary=REVIEW[("hector_mapping", "hector_mapping")].boundary,
    named={
        "subscribes": {
            187: by_parameter("~scan_topic", "scan"),
            188: by_parameter("~sys_msg_topic", "syscommand"),
        },
        "publishes": {190: by_parameter("~pose_update_topic", "poseupdate")},
    },
)


EDITIONS = {
    "ros1": Edition(SOURCES, REVIEW, EXTRA),
    "ros2": Edition(catalogue_ros2.SOURCES, catalogue_ros2.REVIEW, catalogue_ros2.EXTRA),
}


def _git(directory: str, *arguments: str) -> bytes:
    return subprocess.run(
        ["git", "--git-dir", directory, *arguments], check=True, capture_output=True
    ).stdout


def _reviewed(document: Item, review: Review, checkout: str) -> None:
    for role, names in review.drop.items():
        entries = document[role]
        assert isinstance(entries, list)
        for name in names:  # "name@line" when one name has several entries
            match = [e for e in entries if name in (e["name"], f"{e['name']}@{e['line']}")]
            assert match, (document["executable"], role, name)
            for entry in match:
                entries.remove(entry)
    for role, added in review.add.items():
        entries = document[role]
        assert isinstance(entries, list)
        entries.extend({**e, "file": os.path.join(checkout, str(e["file"]))} for e in added)
    for role, names in review.boundary.items():
        entries = document[role]
        assert isinstance(entries, list)
        for name in names:
            match = [e for e in entries if e["name"] == name]
            assert match, (document["executable"], role, name)
            for entry in match:
                entry["boundary"] = True
    _switched(document, review)
    document["review"] = review.note


def _added(document: Item, review: Review) -> None:
    """Apply the review's ``add`` to a built catalogue's node, once (an entry of that role,
    name and line already there is kept)."""
    for role, added in review.add.items():
        entries = document[role]
        assert isinstance(entries, list)
        for entry in added:
            if not any((e["name"], e["line"]) == (entry["name"], entry["line"]) for e in entries):
                entries.append(dict(entry))


def _loaded(nodes: list[Item], edition: Edition) -> None:
    """Give each node whose review ``loads`` a nodelet class (or another package's node
    class) that one's entries (those of a role and name the node has already left out: a
    node and its nodelet both read ``~concurrency_level``)."""
    by_unit = {(node["package"], node["executable"]): node for node in nodes}
    for node in nodes:
        review = edition.review.get((str(node["package"]), str(node["executable"])))
        if review is None or review.loads is None:
            continue
        nodelet = by_unit[review.loads]
        for role in ROLES:
            entries = node[role]
            loaded = nodelet[role]
            assert isinstance(entries, list) and isinstance(loaded, list)
            names = {entry["name"] for entry in entries}
            entries.extend(dict(entry) for entry in loaded if entry["name"] not in names)


def _switched(document: Item, review: Review) -> None:
    """Apply the review's ``named`` and ``when`` (matched by role and line: an entry the
    extractor names by its parameter already keeps its line) and its ``node_name``."""
    if review.node_name is not None:
        document["node_name"] = review.node_name
    for role, by_line in review.named.items():
        entries = document[role]
        assert isinstance(entries, list)
        for line, named in by_line.items():
            match = [e for e in entries if e["line"] == line]
            assert match, (document["executable"], role, line)
            named_by = named["named_by"]
            assert isinstance(named_by, dict)
            for entry in match:
                entry.update(named, name="{" + str(named_by["parameter"]) + "}", static=False)
    params = document["params"]
    assert isinstance(params, list)
    for line, fallback in review.defaults.items():
        match = [e for e in params if e["line"] == line]
        assert match, (document["executable"], "params", line)
        for entry in match:
            entry["default"] = fallback
    for role, conditions in review.when.items():
        entries = document[role]
        assert isinstance(entries, list)
        for line, condition in conditions.items():
            match = [e for e in entries if e["line"] == line]
            assert match, (document["executable"], role, line)
            for entry in match:
                entry["when"] = condition


def build(mirrors: str, edition: Edition) -> dict[str, object]:
    nodes: list[Item] = []
    for source in edition.sources:
        nodes.extend(_repository(mirrors, source, edition))
    _loaded(nodes, edition)
    return {"catalogue": nodes}


def splice(path: str, mirrors: str, repository: str, edition: Edition) -> dict[str, object]:
    """The catalogue at ``path`` with the nodes of ``repository`` built again from its
    mirror (the others kept as they are: their mirrors are not needed); a repository new to
    the catalogue adds its nodes at the end."""
    with open(path, encoding="utf-8") as handle:
        nodes: list[Item] = json.load(handle)["catalogue"]
    (source,) = [source for source in edition.sources if source.repository == repository]
    built = _repository(mirrors, source, edition)
    at = [i for i, node in enumerate(nodes) if node["repository"] == repository]
    kept = [node for node in nodes if node["repository"] != repository]
    position = at[0] if at else len(kept)
    nodes = kept[:position] + built + kept[position:]
    _loaded(nodes, edition)
    return {"catalogue": nodes}


def _repository(mirrors: str, source: Source, edition: Edition) -> list[Item]:
    """The nodes of one repository's branch, extracted and reviewed."""
    nodes: list[Item] = []
    repository = source.repository
    directory = os.path.join(mirrors, repository.replace("/", "+"), "repo")
    commit = _git(directory, "rev-parse", source.branch).decode().strip()
    for (origin, package, executable), review in edition.extra.items():
        if origin == repository:
            extra: Item = {"package": package, "executable": executable, "kind": review.kind}
            extra.update({role: [] for role in ROLES})
            _reviewed(extra, review, "")
            extra.update(repository=repository, commit=commit)
            nodes.append(extra)
    if not source.folders:  # only nodes no source defines (rviz)
        return nodes
    with tempfile.TemporaryDirectory() as checkout:
        folders = [*source.folders, *source.headers]
        paths = [folder for folder in folders if folder] or ["."]
        archive = _git(directory, "archive", "--format=tar", commit, *paths, *SKIPPED)
        subprocess.run(["tar", "-x", "-C", checkout], input=archive, check=True)
        roots = [os.path.join(checkout, folder) for folder in source.folders]
        headers = [os.path.join(checkout, folder) for folder in source.headers]
        workspace = discover(roots + headers, ros_package_path="", ament_prefix_path="")
        catalogued = [
            package
            for package in workspace.packages.values()
            if not any(os.path.commonpath([package.path, folder]) == folder for folder in headers)
        ]
        everything = workspace.packages.values()
        interfaces = extract_interfaces(catalogued, Confinement.of([checkout]), everything)
        for diagnostic in interfaces.diagnostics:
            print(f"{repository}: {diagnostic}", file=sys.stderr)
        for node in interfaces.nodes:
            unreviewed = (node.package, node.executable) not in edition.review
            if unreviewed and (TEST_EXECUTABLE.search(node.executable) or not node.entries):
                continue
            document = node_document(node)
            review = edition.review.get((node.package, node.executable))
            if review is not None:
                _reviewed(document, review, checkout)
            document["repository"] = repository
            document["commit"] = commit
            for role in ROLES:
                entries = document[role]
                assert isinstance(entries, list)
                for entry in entries:
                    entry["file"] = os.path.relpath(entry["file"], checkout)
                    entry.pop("origin", None)
                    name = entry["name"]
                    if name in TF_TOPICS and tf.is_boundary(Role(role), name):
                        entry["boundary"] = True
            nodes.append(document)
    return nodes


def reapply(path: str, edition: Edition) -> dict[str, object]:
    """The catalogue at ``path`` with the review's additions, ``named``, ``when``,
    ``defaults`` and ``loads`` applied again (they change no entry the extractor reads: no
    mirror is needed)."""
    with open(path, encoding="utf-8") as handle:
        document = json.load(handle)
    for node in document["catalogue"]:
        found = edition.review.get((node["package"], node["executable"]))
        if found is not None:
            _added(node, found)
            _switched(node, found)
            node["review"] = found.note
    _loaded(document["catalogue"], edition)
    return dict(document)


def main() -> int:
    options = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    options.add_argument("--mirrors", default="/work/.mirror", help="folder of the mirrors")
    options.add_argument(
        "--reapply",
        metavar="JSON",
        help="apply the review's parameter names and conditions to a built catalogue",
    )
    options.add_argument(
        "--only",
        nargs=2,
        metavar=("REPOSITORY", "JSON"),
        help="build one repository of SOURCES again into a built catalogue (other mirrors "
        "not needed)",
    )
    options.add_argument(
        "--ros",
        choices=sorted(EDITIONS),
        default="ros1",
        help="the catalogue to build (catalogue/ros1.json, catalogue/ros2.json)",
    )
    arguments = options.parse_args()
    edition = EDITIONS[arguments.ros]
    if arguments.only:
        built = splice(arguments.only[1], arguments.mirrors, arguments.only[0], edition)
    elif arguments.reapply:
        built = reapply(arguments.reapply, edition)
    else:
        built = build(arguments.mirrors, edition)
    print(json.dumps(built, indent=1, ensure_ascii=False))
    return 0


if __name__ == "__main__":
    sys.exit(main())
