"""The ROS 2 catalogue's sources and review (``tools/build_catalogue.py --ros ros2``)."""

from __future__ import annotations

from dataclasses import replace

from catalogue_review import Review, Source, by_parameter, read, use

NAV2 = [
    "nav2_amcl",
    "nav2_behaviors",
    "nav2_bt_navigator",
    "nav2_collision_monitor",
    "nav2_controller",
    "nav2_lifecycle_manager",
    "nav2_map_server",
    "nav2_planner",
    "nav2_smoother",
    "nav2_velocity_smoother",
    "nav2_waypoint_follower",
]

SOURCES: list[Source] = [
    # repository, branch (humble's where there is one: the release the repositories of
    # tests/data/ros2 target, else the ROS 2 branch the mirror holds), the packages: every
    # third-party package a launch file of tests/data/ros2 starts a node of, most launched
    # first, and the navigation stack's servers those systems bring up
    Source("ros/robot_state_publisher", "humble", [""]),
    # jazzy: the release ros2_control_demos and Universal_Robots_ROS2_Driver launch (its
    # manager subscribes robot_description, humble's ~/robot_description)
    Source("ros-controls/ros2_control", "jazzy", ["controller_manager"]),
    Source("ros-controls/ros2_controllers", "humble", ["ros2_controllers_test_nodes"]),
    Source("ros2/rviz", "humble", []),
    Source(
        "ros/joint_state_publisher", "ros2", ["joint_state_publisher", "joint_state_publisher_gui"]
    ),
    Source("ros2/geometry2", "humble", ["tf2_ros"]),
    Source("ros2/rclcpp", "humble", ["rclcpp_components"]),
    Source("ros-tooling/topic_tools", "humble", ["topic_tools"]),
    Source("ros-drivers/joystick_drivers", "ros2", ["joy", "joy_linux"]),
    Source("ros2/teleop_twist_joy", "foxy", [""]),
    Source("ros-teleop/twist_mux", "rolling", [""]),
    Source("cra-ros-pkg/robot_localization", "humble-devel", [""]),
    Source("ros-visualization/interactive_marker_twist_server", "humble-devel", [""]),
    Source("gazebosim/ros_gz", "humble", ["ros_gz_bridge", "ros_gz_sim"]),
    Source("ros-simulation/gazebo_ros_pkgs", "ros2", ["gazebo_ros"]),
    Source("IntelRealSense/realsense-ros", "ros2-master", ["realsense2_camera"]),
    Source("ros-perception/image_pipeline", "humble", ["image_proc", "depth_image_proc"]),
    Source("ros-perception/pointcloud_to_laserscan", "humble", [""]),
    Source("ros-perception/depthimage_to_laserscan", "ros2", [""]),
    Source("SteveMacenski/slam_toolbox", "humble", [""]),
    Source(
        "ros-navigation/navigation2",
        "humble",
        NAV2,
        ["nav2_util", "nav2_behavior_tree", "nav2_costmap_2d", "nav2_core"],
    ),
]

CM_SERVICES = "controller_manager/controller_manager/controller_manager_services.py"
CM_CLIENTS = {
    # controller_manager_services.py: the service each call names, below the manager
    "configure_controller": 176,
    "list_controllers": 188,
    "list_hardware_components": 214,
    "load_controller": 243,
    "set_hardware_component_state": 279,
    "switch_controller": 305,
    "unload_controller": 319,
}
SPAWNED_CLIENT = (
    "{f'{namespace}/{service_name}' if not service_name.startswith('/') else service_name}"
)


def _manager_clients(note: str, services: list[str]) -> Review:
    """A controller_manager script that calls the manager's services: named as without
    ``-c``/``--namespace`` (the manager ``controller_manager`` in the script's namespace,
    which is what a relative name resolves to)."""
    kinds = {name: "".join(word.title() for word in name.split("_")) for name in services}
    kinds["switch_controller"] = "SwitchController"
    return Review(
        note + "; the manager's services, as named without -c/--namespace (the manager "
        "controller_manager in the script's namespace)",
        add={
            "clients": [
                use(
                    f"controller_manager/{name}",
                    f"controller_manager_msgs/srv/{kinds[name]}",
                    CM_SERVICES,
                    CM_CLIENTS[name],
                )
                for name in services
            ]
        },
        drop={"clients": [SPAWNED_CLIENT]},
    )


TIMED_BEHAVIOR = "nav2_behaviors/include/nav2_behaviors/timed_behavior.hpp"
BEHAVIORS = Review(
    "each behaviour plugin (behavior_plugins, default spin, backup, drive_on_heading, wait: "
    "behavior_server.cpp) serves an action named after it and publishes cmd_vel "
    "(TimedBehavior); the costmap and footprint subscriptions (nav2_costmap_2d's "
    "subscribers, a compiled library) and plugins other than the defaults are not read",
    add={
        "action_servers": [
            use(name, f"nav2_msgs/action/{kind}", TIMED_BEHAVIOR, 124)
            for name, kind in (
                ("spin", "Spin"),
                ("backup", "BackUp"),
                ("drive_on_heading", "DriveOnHeading"),
                ("wait", "Wait"),
            )
        ],
        "publishes": [use("cmd_vel", "geometry_msgs/msg/Twist", TIMED_BEHAVIOR, 130)],
    },
)
NAVIGATORS = "nav2_bt_navigator/include/nav2_bt_navigator/navigators"
BT_XML = "nav2_bt_navigator/behavior_trees/navigate_to_pose_w_replanning_and_recovery.xml"
BT_NAVIGATOR = Review(
    "the navigators' action servers are named by getName() (navigate_to_pose, "
    "navigate_through_poses); goal_pose is rviz2's Goal tool; the behaviour tree (default "
    "XML) calls the planner, controller and behaviour servers' actions (the BT plugins' "
    "default names); its costmap-clearing services (served by the costmaps inside the "
    "planner and controller servers, not modelled) are left out; the node is bt_navigator "
    "(bt_navigator.cpp; the behaviour tree's helper node is another)",
    node_name="bt_navigator",
    add={
        "action_servers": [
            use(
                "navigate_to_pose",
                "nav2_msgs/action/NavigateToPose",
                NAVIGATORS + "/navigate_to_pose.hpp",
                75,
            ),
            use(
                "navigate_through_poses",
                "nav2_msgs/action/NavigateThroughPoses",
                NAVIGATORS + "/navigate_through_poses.hpp",
                64,
            ),
        ],
        "subscribes": [
            {
                **use(
                    "goal_pose",
                    "geometry_msgs/msg/PoseStamped",
                    "nav2_bt_navigator/src/navigators/navigate_to_pose.cpp",
                    50,
                ),
                "boundary": True,
            }
        ],
        "action_clients": [
            use(name, f"nav2_msgs/action/{kind}", BT_XML, line)
            for name, kind, line in (
                ("compute_path_to_pose", "ComputePathToPose", 13),
                ("follow_path", "FollowPath", 18),
                ("spin", "Spin", 29),
                ("wait", "Wait", 30),
                ("backup", "BackUp", 31),
            )
        ],
    },
    drop={"action_servers": ["{action_name}"]},
)
TOOL_BASE = "topic_tools/src/tool_base_node.cpp"
RELAY = Review(
    "relays input_topic (required) to output_topic (default input_topic + '_relay') with a "
    "generic subscription and publisher of the input's type (tool_base_node.cpp), which "
    "the extractor does not read: added by hand; the relay executable also takes them "
    "from its command line (relay IN [OUT], relay.cpp), which stays symbolic",
    add={
        "subscribes": [
            {
                **use("{input_topic}", None, TOOL_BASE, 56),
                **by_parameter("input_topic"),
                "static": False,
            }
        ],
        "publishes": [
            {
                **use("{output_topic}", None, TOOL_BASE, 40),
                **by_parameter("output_topic", {"expression": 'input_topic_ + "_relay"'}),
                "static": False,
            }
        ],
    },
)
CONTROLLER_SERVER = Review(
    "the speed limit (speed_limit_topic, default speed_limit) is an optional input: nav2's "
    "speed costmap filter or an application publishes it",
    boundary={"subscribes": ["{speed_limit_topic}"]},
)
SLAM_TOOLBOX = Review(
    "the map and scan topics are the parameters map_name (default /map) and scan_topic "
    "(default /scan), declared with a member's value as default (slam_toolbox_common.cpp)",
    named={
        "publishes": {211: by_parameter("map_name", "/map")},
        "subscribes": {
            41: by_parameter("map_name", "/map"),
            234: by_parameter("scan_topic", "/scan"),
        },
    },
)
INITIAL_POSE = "initialpose is rviz2's 2D Pose Estimate (people's input)"
SLAM_LOCALIZATION = Review(
    SLAM_TOOLBOX.note + "; " + INITIAL_POSE,
    named=SLAM_TOOLBOX.named,
    boundary={"subscribes": ["initialpose"]},
)
AMCL = Review(
    INITIAL_POSE + "; particle_cloud is for people (rviz2)",
    boundary={"subscribes": ["initialpose"], "publishes": ["particle_cloud"]},
)
LOCALIZATION_INPUTS = {1157: "odom", 1294: "pose", 1389: "twist", 1597: "imu"}
"""ros_filter.cpp: each sensor's topic is the value of odom0, odom1, ... (then pose0,
twist0, imu0), declared and read in a loop until one is not set."""
FILTER = Review(
    "set_pose (topic) is for people and tools resetting the filter; each sensor topic is "
    "the value of odomN/poseN/twistN/imuN (one per parameter set); cmd_vel only with "
    "use_control; the node's name is the first NodeOptions argument (ekf_node.cpp: "
    "ekf_filter_node, ukf_node.cpp: ukf_filter_node)",
    boundary={"subscribes": ["set_pose"]},
    named={
        "subscribes": {
            line: by_parameter(f"{kind}{{N}}") for line, kind in LOCALIZATION_INPUTS.items()
        }
    },
    when={"subscribes": {1673: "param('use_control')"}},
)
JOY = Review(
    "joy/set_feedback (force feedback) is an optional input",
    boundary={"subscribes": ["joy/set_feedback"]},
)
SPAWN_ENTITY = "gazebo_ros/scripts/spawn_entity.py"
RVIZ_CONFIG = "rviz_common/default.rviz"

REVIEW: dict[tuple[str, str], Review] = {
    ("controller_manager", "ros2_control_node"): Review(
        "~/activity tells tools (rqt_controller_manager) what the controllers do; the "
        "controllers (plugins the spawners load) and their topics are not included",
        boundary={"publishes": ["~/activity"]},
    ),
    ("controller_manager", "spawner"): _manager_clients(
        "loads, configures and starts the controllers named on the command line",
        ["list_controllers", "load_controller", "configure_controller", "switch_controller"],
    ),
    ("controller_manager", "unspawner"): _manager_clients(
        "stops and unloads the controllers named on the command line",
        ["switch_controller", "unload_controller"],
    ),
    ("controller_manager", "hardware_spawner"): _manager_clients(
        "activates or configures the hardware components named on the command line",
        ["list_hardware_components", "set_hardware_component_state"],
    ),
    ("twist_mux", "twist_mux"): Review(
        "each entry of the parameters topics.* (a Twist input) and locks.* (a Bool lock) "
        "is a subscription to its topic (topic_handle.hpp): one symbolic use per kind; the "
        "Twist one is added (the extractor kept one of the two {topic} uses)",
        add={
            "subscribes": [
                {
                    **use(
                        "{topic}",
                        "geometry_msgs/msg/Twist",
                        "include/twist_mux/topic_handle.hpp",
                        172,
                    ),
                    "static": False,
                }
            ]
        },
    ),
    ("gazebo_ros", "spawn_entity.py"): Review(
        "Gazebo's services and topics as named with the default -gazebo_namespace '' "
        "(global); gzserver runs as a process (ExecuteProcess with the gazebo_ros_factory "
        "plugin), not a node, so these are boundary uses",
        add={
            "subscribes": [
                {
                    **use("/model_states", "gazebo_msgs/msg/ModelStates", SPAWN_ENTITY, 129),
                    "boundary": True,
                }
            ],
            "clients": [
                {**use(f"/{name}", kind, SPAWN_ENTITY, line), "boundary": True}
                for name, kind, line in (
                    ("unpause_physics", "std_srvs/srv/Empty", 246),
                    ("spawn_entity", "gazebo_msgs/srv/SpawnEntity", 276),
                    ("delete_entity", "gazebo_msgs/srv/DeleteEntity", 301),
                )
            ],
        },
        drop={
            "subscribes": ["{'%s/model_states' % self.args.gazebo_namespace}"],
            "clients": [
                "{'%s/unpause_physics' % self.args.gazebo_namespace}",
                "{'%s/spawn_entity' % self.args.gazebo_namespace}",
                "{'%s/delete_entity' % self.args.gazebo_namespace}",
            ],
        },
    ),
    ("joint_state_publisher_gui", "joint_state_publisher_gui"): Review(
        "runs joint_state_publisher's JointStatePublisher class (another package) with a "
        "window of sliders: that node's topics and parameters",
        loads=("joint_state_publisher", "joint_state_publisher"),
    ),
    ("nav2_behaviors", "behavior_server"): BEHAVIORS,
    ("nav2_behaviors", "behavior_server::BehaviorServer"): BEHAVIORS,
    ("nav2_bt_navigator", "bt_navigator"): BT_NAVIGATOR,
    ("nav2_bt_navigator", "nav2_bt_navigator::BtNavigator"): BT_NAVIGATOR,
    ("topic_tools", "relay"): RELAY,
    ("topic_tools", "topic_tools::RelayNode"): RELAY,
    ("nav2_controller", "controller_server"): CONTROLLER_SERVER,
    ("nav2_controller", "nav2_controller::ControllerServer"): CONTROLLER_SERVER,
    ("nav2_amcl", "amcl"): AMCL,
    ("nav2_amcl", "nav2_amcl::AmclNode"): AMCL,
    ("slam_toolbox", "slam_toolbox::LocalizationSlamToolbox"): Review(
        INITIAL_POSE, boundary={"subscribes": ["initialpose"]}
    ),
    ("slam_toolbox", "slam_toolbox::MapAndLocalizationSlamToolbox"): Review(
        INITIAL_POSE, boundary={"subscribes": ["initialpose"]}
    ),
    ("robot_localization", "ekf_node"): replace(FILTER, node_name="ekf_filter_node"),
    ("robot_localization", "ukf_node"): replace(FILTER, node_name="ukf_filter_node"),
    ("joy", "joy_node"): JOY,
    ("joy", "joy::Joy"): JOY,
    ("joy", "game_controller_node"): JOY,
    ("joy", "joy::GameController"): JOY,
    ("joy_linux", "joy_linux_node"): JOY,
}
for _executable in (
    "async_slam_toolbox_node",
    "sync_slam_toolbox_node",
    "lifelong_slam_toolbox_node",
):
    REVIEW[("slam_toolbox", _executable)] = SLAM_TOOLBOX
for _executable in ("localization_slam_toolbox_node", "map_and_localization_slam_toolbox_node"):
    REVIEW[("slam_toolbox", _executable)] = SLAM_LOCALIZATION

EXTRA: dict[tuple[str, str, str], Review] = {
    ("ros2/rviz", "rviz2", "rviz2"): Review(
        "a visualiser: what it subscribes depends on the displays of its configuration "
        "(not modelled); its default configuration's tools publish a pose estimate, a goal "
        "and clicked points, made by people (boundary uses)",
        add={
            "publishes": [
                {**use(name, kind, RVIZ_CONFIG, line), "boundary": True}
                for name, kind, line in (
                    ("/initialpose", "geometry_msgs/msg/PoseWithCovarianceStamped", 64),
                    ("/goal_pose", "geometry_msgs/msg/PoseStamped", 66),
                    ("/clicked_point", "geometry_msgs/msg/PointStamped", 69),
                )
            ]
        },
    ),
}

# ros2_controllers' controller types (humble): plugins of the controller manager, not
# nodes. Each runs as a node named after the controller, in the manager's namespace, so its
# ~/ names lie below the controller's name. Commands are the robot's inputs for whatever
# application or person drives it, and the state topics are outputs for tools: boundary uses.
CONTROLLERS = "ros-controls/ros2_controllers"
CONTROLLER_NOTE = (
    "a controller type (a plugin the controller manager loads, named in its parameter "
    "NAME.type), read by hand: {}"
)


def _controller(note: str, **add: list[dict[str, object]]) -> Review:
    return Review(CONTROLLER_NOTE.format(note), add=add, kind="controller")


def _boundary(name: str, kind: str, file: str, line: int) -> dict[str, object]:
    return {**use(name, kind, file, line), "boundary": True}


def _when(entry: dict[str, object], condition: str) -> dict[str, object]:
    return {**entry, "when": condition}


FORWARD = "forward_command_controller/src/forward_controllers_base.cpp"
FORWARD_REVIEW = _controller(
    "subscribes ~/commands (forward_controllers_base.cpp)",
    subscribes=[_boundary("~/commands", "std_msgs/msg/Float64MultiArray", FORWARD, 61)],
)
JSB = "joint_state_broadcaster/src/joint_state_broadcaster.cpp"
JTC = "joint_trajectory_controller/src/joint_trajectory_controller.cpp"
JTC_STATE = "control_msgs/msg/JointTrajectoryControllerState"
DIFF_DRIVE = "diff_drive_controller/src/diff_drive_controller.cpp"
DIFF_DRIVE_PARAMETERS = "diff_drive_controller/src/diff_drive_controller_parameter.yaml"
GRIPPER = "gripper_controllers/include/gripper_controllers/gripper_action_controller_impl.hpp"
GRIPPER_REVIEW = _controller(
    "serves the action ~/gripper_cmd",
    action_servers=[use("~/gripper_cmd", "control_msgs/action/GripperCommand", GRIPPER, 300)],
)
STEERING = "steering_controllers_library/src/steering_controllers_library.cpp"
STEERING_PARAMETERS = "steering_controllers_library/src/steering_controllers_library.yaml"
STEERING_REVIEW = _controller(
    "steering_controllers_library's names: ~/reference (TwistStamped) where "
    "use_stamped_vel (default false), else ~/reference_unstamped",
    subscribes=[
        _when(
            _boundary("~/reference", "geometry_msgs/msg/TwistStamped", STEERING, 121),
            "param('use_stamped_vel')",
        ),
        _when(
            _boundary("~/reference_unstamped", "geometry_msgs/msg/Twist", STEERING, 127),
            "not param('use_stamped_vel')",
        ),
    ],
    publishes=[
        use("~/odometry", "nav_msgs/msg/Odometry", STEERING, 141),
        _boundary("~/tf_odometry", "tf2_msgs/msg/TFMessage", STEERING, 173),
        _boundary("~/controller_state", "control_msgs/msg/SteeringControllerStatus", STEERING, 197),
    ],
    params=[read("use_stamped_vel", False, STEERING_PARAMETERS, 123)],
)
PID = "pid_controller/src/pid_controller.cpp"
for _package, _type, _review in (
    ("forward_command_controller", "ForwardCommandController", FORWARD_REVIEW),
    ("forward_command_controller", "MultiInterfaceForwardCommandController", FORWARD_REVIEW),
    ("position_controllers", "JointGroupPositionController", FORWARD_REVIEW),
    ("velocity_controllers", "JointGroupVelocityController", FORWARD_REVIEW),
    ("effort_controllers", "JointGroupEffortController", FORWARD_REVIEW),
    ("gripper_controllers", "position_controllers/GripperActionController", GRIPPER_REVIEW),
    ("gripper_controllers", "effort_controllers/GripperActionController", GRIPPER_REVIEW),
    ("ackermann_steering_controller", "AckermannSteeringController", STEERING_REVIEW),
    ("bicycle_steering_controller", "BicycleSteeringController", STEERING_REVIEW),
    ("tricycle_steering_controller", "TricycleSteeringController", STEERING_REVIEW),
):
    _name = _type if "/" in _type else f"{_package}/{_type}"
    EXTRA[(CONTROLLERS, _package, _name)] = _review
EXTRA.update(
    {
        (
            CONTROLLERS,
            "joint_state_broadcaster",
            "joint_state_broadcaster/JointStateBroadcaster",
        ): _controller(
            "joint_states in the manager's namespace (~/joint_states where use_local_topics, "
            "default false, a read-only parameter: not modelled); dynamic_joint_states is for "
            "tools",
            publishes=[
                use("joint_states", "sensor_msgs/msg/JointState", JSB, 151),
                _boundary("dynamic_joint_states", "control_msgs/msg/DynamicJointState", JSB, 161),
            ],
        ),
        (
            CONTROLLERS,
            "joint_trajectory_controller",
            "joint_trajectory_controller/JointTrajectoryController",
        ): _controller(
            "the action and service are named NAME/follow_joint_trajectory and "
            "NAME/query_state after the node's name: ~/ names",
            subscribes=[
                _boundary("~/joint_trajectory", "trajectory_msgs/msg/JointTrajectory", JTC, 843)
            ],
            publishes=[
                _boundary("~/controller_state", JTC_STATE, JTC, 881),
                _boundary("~/state", JTC_STATE, JTC, 858),
            ],
            services=[use("~/query_state", "control_msgs/srv/QueryTrajectoryState", JTC, 947)],
            action_servers=[
                use(
                    "~/follow_joint_trajectory",
                    "control_msgs/action/FollowJointTrajectory",
                    JTC,
                    935,
                )
            ],
        ),
        (
            CONTROLLERS,
            "diff_drive_controller",
            "diff_drive_controller/DiffDriveController",
        ): _controller(
            "~/cmd_vel (TwistStamped) where use_stamped_vel (default true), else "
            "~/cmd_vel_unstamped (Twist); ~/cmd_vel_out where publish_limited_velocity; the "
            "odometry's transform on /tf",
            subscribes=[
                _when(
                    _boundary("~/cmd_vel", "geometry_msgs/msg/TwistStamped", DIFF_DRIVE, 348),
                    "param('use_stamped_vel')",
                ),
                _when(
                    _boundary("~/cmd_vel_unstamped", "geometry_msgs/msg/Twist", DIFF_DRIVE, 372),
                    "not param('use_stamped_vel')",
                ),
            ],
            publishes=[
                use("~/odom", "nav_msgs/msg/Odometry", DIFF_DRIVE, 392),
                _boundary("/tf", "tf2_msgs/msg/TFMessage", DIFF_DRIVE, 447),
                _when(
                    _boundary("~/cmd_vel_out", "geometry_msgs/msg/TwistStamped", DIFF_DRIVE, 332),
                    "param('publish_limited_velocity')",
                ),
            ],
            params=[
                read("use_stamped_vel", True, DIFF_DRIVE_PARAMETERS, 114),
                read("publish_limited_velocity", False, DIFF_DRIVE_PARAMETERS, 104),
            ],
        ),
        (
            CONTROLLERS,
            "imu_sensor_broadcaster",
            "imu_sensor_broadcaster/IMUSensorBroadcaster",
        ): _controller(
            "publishes ~/imu",
            publishes=[
                use(
                    "~/imu",
                    "sensor_msgs/msg/Imu",
                    "imu_sensor_broadcaster/src/imu_sensor_broadcaster.cpp",
                    53,
                )
            ],
        ),
        (
            CONTROLLERS,
            "force_torque_sensor_broadcaster",
            "force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster",
        ): _controller(
            "publishes ~/wrench",
            publishes=[
                use(
                    "~/wrench",
                    "geometry_msgs/msg/WrenchStamped",
                    "force_torque_sensor_broadcaster/src/force_torque_sensor_broadcaster.cpp",
                    92,
                )
            ],
        ),
        (CONTROLLERS, "pose_broadcaster", "pose_broadcaster/PoseBroadcaster"): _controller(
            "publishes ~/pose, and /tf where its tf.enable (default true)",
            publishes=[
                use(
                    "~/pose",
                    "geometry_msgs/msg/PoseStamped",
                    "pose_broadcaster/src/pose_broadcaster.cpp",
                    89,
                ),
                _boundary(
                    "/tf", "tf2_msgs/msg/TFMessage", "pose_broadcaster/src/pose_broadcaster.cpp", 97
                ),
            ],
        ),
        (
            CONTROLLERS,
            "range_sensor_broadcaster",
            "range_sensor_broadcaster/RangeSensorBroadcaster",
        ): _controller(
            "publishes ~/range",
            publishes=[
                use(
                    "~/range",
                    "sensor_msgs/msg/Range",
                    "range_sensor_broadcaster/src/range_sensor_broadcaster.cpp",
                    64,
                )
            ],
        ),
        (CONTROLLERS, "pid_controller", "pid_controller/PidController"): _controller(
            "~/measured_state where use_external_measured_states (default false)",
            subscribes=[
                _boundary("~/reference", "control_msgs/msg/MultiDOFCommand", PID, 171),
                _when(
                    _boundary("~/measured_state", "control_msgs/msg/MultiDOFCommand", PID, 188),
                    "param('use_external_measured_states')",
                ),
            ],
            publishes=[
                _boundary("~/controller_state", "control_msgs/msg/MultiDOFStateStamped", PID, 221)
            ],
            services=[use("~/set_feedforward_control", "std_srvs/srv/SetBool", PID, 215)],
            params=[
                read(
                    "use_external_measured_states",
                    False,
                    "pid_controller/src/pid_controller.yaml",
                    40,
                )
            ],
        ),
        (
            CONTROLLERS,
            "gpio_controllers",
            "gpio_controllers/GpioCommandController",
        ): _controller(
            "subscribes ~/commands, publishes ~/gpio_states",
            subscribes=[
                _boundary(
                    "~/commands",
                    "control_msgs/msg/DynamicInterfaceGroupValues",
                    "gpio_controllers/src/gpio_command_controller.cpp",
                    75,
                )
            ],
            publishes=[
                _boundary(
                    "~/gpio_states",
                    "control_msgs/msg/DynamicInterfaceGroupValues",
                    "gpio_controllers/src/gpio_command_controller.cpp",
                    80,
                )
            ],
        ),
    }
)
