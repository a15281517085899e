"""The bundled catalogue: loadable package data, every entry traceable to its source, and
entries checked by hand against the sources of the nodes the corpus launches most."""

from __future__ import annotations

import json
import re
from collections import Counter
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any

import jsonschema
import pytest

from rosvar.analyses.communication import model_edges
from rosvar.outputs.cli import main
from rosvar.ros.version import RosVersion
from rosvar.workspace.interfaces import catalogue
from rosvar.workspace.interfaces.catalogue import SCHEMA, data_file, load_catalogue
from rosvar.workspace.interfaces.model import Interfaces, NodeInterface, NodeKind, Origin, Role
from rosvar.workspace.interfaces.overrides import add_catalogue, apply_hints

if TYPE_CHECKING:
    from conftest import LaunchWorkspace
    from rosvar.logic.bdd import BDD

SOURCE_URL = re.compile(r"^https://github\.com/[\w.-]+/[\w.-]+/blob/[0-9a-f]{40}/\S+$")


def _items(version: RosVersion) -> list[dict[str, Any]]:
    """The catalogue's data as shipped."""
    data = resources.files("rosvar.workspace.interfaces").joinpath(data_file(version))
    items: list[dict[str, Any]] = json.loads(data.read_text("utf-8"))["catalogue"]
    return items


def _node(package: str, executable: str) -> NodeInterface:
    node = load_catalogue().find(package, executable)
    assert node is not None, (package, executable)
    return node


def _uses(node: NodeInterface, role: Role) -> set[tuple[str, str | None]]:
    return {(entry.name, entry.type) for entry in node.of(role)}


@pytest.mark.parametrize("version", list(RosVersion))
def test_every_entry_says_where_it_comes_from(version: RosVersion) -> None:
    nodes = load_catalogue(version).nodes()
    assert len(nodes) > 50
    for node in nodes:
        for entry in node.entries:
            assert entry.origin is Origin.CATALOGUE
            assert SOURCE_URL.match(entry.location.file), entry
            assert entry.location.line > 0


@pytest.mark.parametrize("version", list(RosVersion))
def test_every_node_records_its_repository_and_commit(version: RosVersion) -> None:
    for item in _items(version):
        assert re.fullmatch(r"[\w.-]+/[\w.-]+", item["repository"]), item["executable"]
        assert re.fullmatch(r"[0-9a-f]{40}", item["commit"]), item["executable"]


def _schema() -> dict[str, Any]:
    """The catalogue's JSON Schema, shipped beside the data."""
    data = resources.files("rosvar.workspace.interfaces").joinpath(SCHEMA)
    schema: dict[str, Any] = json.loads(data.read_text("utf-8"))
    return schema


@pytest.mark.parametrize("version", list(RosVersion))
def test_every_entry_satisfies_the_schema(version: RosVersion) -> None:
    validator = jsonschema.Draft202012Validator(_schema())
    validator.check_schema(_schema())
    errors = [
        f"{'/'.join(map(str, error.absolute_path))}: {error.message}"
        for error in validator.iter_errors({"catalogue": _items(version)})
    ]
    assert errors == []


def test_the_schema_refuses_what_the_loader_could_not_trace() -> None:
    """An entry without its line, a node without its commit, a kind that is no NodeKind,
    a default that is neither a literal nor an expression: each is an error."""
    validator = jsonschema.Draft202012Validator(_schema())
    node = next(item for item in _items(RosVersion.ROS2) if item["publishes"])
    entry = node["publishes"][0]
    for broken in (
        {**node, "publishes": [{key: value for key, value in entry.items() if key != "line"}]},
        {key: value for key, value in node.items() if key != "commit"},
        {**node, "kind": "plugin"},
        {**node, "params": [{"name": "x", "default": {"value": 1}, "file": "a.cpp", "line": 1}]},
        {**node, "publishes": [{**entry, "file": "/tmp/checkout/a.cpp"}]},
    ):
        assert not validator.is_valid({"catalogue": [broken]}), broken
    assert validator.is_valid({"catalogue": [node]})


MOST_LAUNCHED = 8
"""How many of a data set's most launched third-party executables must have entries."""
CORPUS = Path(__file__).resolve().parents[4] / "shared" / "corpus"  # ../shared of the checkout
ROS2_DATA = Path(__file__).resolve().parents[2] / "data" / "ros2"


def _missing(roots: list[Path], capsys: pytest.CaptureFixture[str]) -> Counter[str]:
    """``rosvar interfaces ROOT --missing``'s third-party executables (``pkg/exec``, a
    nodelet's ``pkg/Class``, a component's ``pkg/ns::Class``), launches summed over
    ``roots`` (those that hold launch files)."""
    launches: Counter[str] = Counter()
    for root in roots:
        capsys.readouterr()
        code = main(["interfaces", str(root), "--missing", "--json"])
        out, err = capsys.readouterr()
        if code != 0:  # a dependency's data only (launch_param_builder): nothing launched
            assert "no launch files found" in err, err
            continue
        for row in json.loads(out)["missing"]:
            if row["third_party"]:
                launches[row["executable"]] += row["launches"]
    return launches


@pytest.mark.parametrize(
    "data",
    [
        pytest.param([CORPUS], id="corpus"),
        pytest.param(sorted(p for p in ROS2_DATA.iterdir() if p.is_dir()), id="ros2"),
    ],
)
def test_the_most_launched_third_party_executables_have_entries(
    data: list[Path], capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Ranked by ``interfaces --missing`` without the catalogue (every launched executable
    no source or hint describes), the most launched ones are not missing with it."""
    if not all(root.is_dir() for root in data):
        pytest.skip("the corpus is not beside the repository")
    still_missing = _missing(data, capsys)
    with monkeypatch.context() as patch:
        patch.setattr(catalogue, "load_catalogue", lambda version: catalogue.Catalogue([]))
        launched = _missing(data, capsys)
    most = [unit for unit, _count in launched.most_common(MOST_LAUNCHED)]
    assert len(most) == MOST_LAUNCHED
    assert [unit for unit in most if unit in still_missing] == []


def test_the_corpus_most_launched_third_party_nodes_are_there() -> None:
    for package, executable in (
        ("robot_state_publisher", "robot_state_publisher"),
        ("robot_state_publisher", "state_publisher"),
        ("joint_state_publisher", "joint_state_publisher"),
        ("gazebo_ros", "spawn_model"),
        ("amcl", "amcl"),
        ("gmapping", "slam_gmapping"),
        ("joy", "joy_node"),
        ("diagnostic_aggregator", "aggregator_node"),
        ("map_server", "map_server"),
        ("tf", "static_transform_publisher"),
        ("tf2_ros", "static_transform_publisher"),
        ("topic_tools", "relay"),
        ("move_base", "move_base"),
        ("controller_manager", "spawner"),
        ("robot_pose_ekf", "robot_pose_ekf"),
        ("robot_localization", "ekf_localization_node"),
        ("twist_mux", "twist_mux"),
        ("teleop_twist_joy", "teleop_node"),
        ("depth_image_proc", "depth_image_proc/point_cloud_xyzrgb"),
        ("image_proc", "image_proc/rectify"),
        ("depthimage_to_laserscan", "depthimage_to_laserscan/DepthImageToLaserScanNodelet"),
        ("pointcloud_to_laserscan", "pointcloud_to_laserscan_node"),
        ("yocs_cmd_vel_mux", "yocs_cmd_vel_mux/CmdVelMuxNodelet"),
        ("yocs_velocity_smoother", "yocs_velocity_smoother/VelocitySmootherNodelet"),
    ):
        assert _node(package, executable).entries, (package, executable)


def test_robot_state_publisher() -> None:
    node = _node("robot_state_publisher", "robot_state_publisher")
    assert _uses(node, Role.SUBSCRIBES) == {("joint_states", "sensor_msgs/JointState")}
    assert {e.name for e in node.of(Role.PUBLISHES)} == {"/tf", "/tf_static"}  # reviewed
    params = {e.name: e.default for e in node.of(Role.PARAMS) if e.static}
    assert params["~publish_frequency"] == 50.0
    assert params["robot_description"] is None
    assert [e.name for e in node.of(Role.PARAMS) if not e.static] == ["~{tf_prefix_key}"]


def test_amcl() -> None:
    node = _node("amcl", "amcl")
    assert _uses(node, Role.SUBSCRIBES) >= {
        ("scan", "sensor_msgs/LaserScan"),  # a message_filters::Subscriber
        ("initialpose", "geometry_msgs/PoseWithCovarianceStamped"),
        ("map", "nav_msgs/OccupancyGrid"),
    }
    assert _uses(node, Role.PUBLISHES) == {
        ("amcl_pose", "geometry_msgs/PoseWithCovarianceStamped"),
        ("particlecloud", "geometry_msgs/PoseArray"),
        ("/tf", "tf2_msgs/TFMessage"),  # reviewed; base_scan (bag replay only) dropped
    }
    assert ("static_map", "nav_msgs/GetMap") in _uses(node, Role.CLIENTS)
    params = {e.name: e.default for e in node.of(Role.PARAMS)}
    assert params["~min_particles"] == 100
    assert params["~odom_model_type"] == "diff"


def test_map_server_and_gmapping() -> None:
    map_server = _node("map_server", "map_server")
    assert _uses(map_server, Role.PUBLISHES) == {
        ("map", "nav_msgs/OccupancyGrid"),
        ("map_metadata", "nav_msgs/MapMetaData"),
    }
    assert _uses(map_server, Role.SERVICES) == {("static_map", "nav_msgs/GetMap")}
    gmapping = _node("gmapping", "slam_gmapping")
    assert ("scan", "sensor_msgs/LaserScan") in _uses(gmapping, Role.SUBSCRIBES)
    assert ("map", "nav_msgs/OccupancyGrid") in _uses(gmapping, Role.PUBLISHES)
    # private_nh_("~") of the constructor the node calls, not the nodelet's
    assert {e.name for e in gmapping.of(Role.PARAMS)} >= {"~base_frame", "~maxUrange"}


def test_move_base() -> None:
    node = _node("move_base", "move_base")  # the target move_base_node's OUTPUT_NAME
    assert _uses(node, Role.ACTION_SERVERS) == {("move_base", "move_base_msgs/MoveBase")}
    assert ("cmd_vel", "geometry_msgs/Twist") in _uses(node, Role.PUBLISHES)
    assert ("move_base_simple/goal", "geometry_msgs/PoseStamped") in _uses(node, Role.SUBSCRIBES)


def test_nodelets_of_one_library_each_have_their_own() -> None:
    rectify = _node("image_proc", "image_proc/rectify")
    assert rectify.kind is NodeKind.NODELET
    assert _uses(rectify, Role.SUBSCRIBES) == {
        ("image_mono", "sensor_msgs/Image"),
        ("camera_info", "sensor_msgs/CameraInfo"),
    }
    assert _uses(rectify, Role.PUBLISHES) == {("image_rect", "sensor_msgs/Image")}


def test_command_line_topics_stay_symbolic() -> None:
    relay = _node("topic_tools", "relay")
    assert [(e.role, e.static) for e in relay.entries if e.role is not Role.PARAMS] == [
        (Role.PUBLISHES, False),
        (Role.SUBSCRIBES, False),
    ]


def test_looked_up_lazily_and_never_changed_by_hints() -> None:
    interfaces = Interfaces()
    add_catalogue(interfaces, load_catalogue())
    assert interfaces.nodes == []
    assert interfaces.find(None, "image_proc/rectify") is _node("image_proc", "image_proc/rectify")
    hint = _node("joy", "joy_node").of(Role.PUBLISHES)[0]
    apply_hints(interfaces, {"joy/joy_node": [hint.__class__(Role.PUBLISHES, "x", hint.location)]})
    hinted = interfaces.find("joy", "joy_node")
    assert hinted is not None and {e.name for e in hinted.of(Role.PUBLISHES)} == {"joy", "x"}
    assert {e.name for e in _node("joy", "joy_node").of(Role.PUBLISHES)} == {"joy"}
    assert len(interfaces.listed()) == len(load_catalogue().nodes())


def test_a_node_that_loads_a_nodelet_has_its_entries() -> None:
    node = _node("pointcloud_to_laserscan", "pointcloud_to_laserscan_node")
    assert _uses(node, Role.SUBSCRIBES) == {("cloud_in", "sensor_msgs/PointCloud2")}
    assert _uses(node, Role.PUBLISHES) == {("scan", "sensor_msgs/LaserScan")}
    params = {e.name: e.default for e in node.of(Role.PARAMS)}
    assert params["~concurrency_level"] == 0  # the node's own read, not the nodelet's 1
    assert params["~range_max"] is not None


def test_openni_depth_output_follows_depth_registration(ws: LaunchWorkspace) -> None:
    ws.launch(
        "camera.launch",
        '<arg name="reg" default="false"/>\n'
        '<node pkg="nodelet" type="nodelet" name="driver" args="load openni_camera/driver m">\n'
        '  <param name="depth_registration" value="$(arg reg)"/>\n'
        "</node>\n"
        '<node pkg="nodelet" type="nodelet" name="other" args="load openni_camera/driver m"/>',
    )
    analysis = ws.analysis(extra_values={"reg": ["true"]})
    model = analysis.model(analysis.workspace.launch_files[0])
    interfaces = Interfaces([])
    add_catalogue(interfaces, load_catalogue())
    space = analysis.space
    held: dict[tuple[str, str], BDD] = {}
    for edge in model_edges(space, model, interfaces):
        key = (edge.node, edge.name)
        held[key] = held.get(key, space.false) | edge.condition
    off = space.slot(model.inputs["reg"], "false")
    on = space.slot(model.inputs["reg"], "true")
    depth = held[("/driver", "/depth/image_raw")]
    assert space.satisfiable(depth & off)
    assert not space.satisfiable(depth & on)
    for name in ("/depth_registered/image_raw", "/depth_registered/camera_info"):
        registered = held[("/driver", name)]
        assert space.satisfiable(registered & on)
        assert not space.satisfiable(registered & off)
        assert ("/other", name) not in held  # unset: the source's default, false
    assert held[("/other", "/depth/image_raw")] == space.true
    assert held[("/driver", "/projector/camera_info")] == space.true


def test_yocs_nodelets() -> None:
    mux = _node("yocs_cmd_vel_mux", "yocs_cmd_vel_mux/CmdVelMuxNodelet")
    assert [(e.name, e.static) for e in mux.of(Role.PUBLISHES) if not e.boundary] == [
        ("~{output_topic_name}", False)  # the YAML file's, read at run time
    ]
    smoother = _node("yocs_velocity_smoother", "yocs_velocity_smoother/VelocitySmootherNodelet")
    assert _uses(smoother, Role.SUBSCRIBES) == {
        ("~odometry", "nav_msgs/Odometry"),
        ("~robot_cmd_vel", "geometry_msgs/Twist"),
        ("~raw_cmd_vel", "geometry_msgs/Twist"),
    }
    assert _uses(smoother, Role.PUBLISHES) == {("~smooth_cmd_vel", "geometry_msgs/Twist")}
    when = {e.name: e.when for e in smoother.of(Role.SUBSCRIBES)}
    assert when == {
        "~odometry": "param('~robot_feedback') == 1",
        "~robot_cmd_vel": "param('~robot_feedback') == 2",
        "~raw_cmd_vel": None,
    }


def test_ros2_nodes_meet_their_partners(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """nav2's navigator calls the planner's, controller's and behaviours' actions and the
    spawner the manager's services, all by the names the catalogue gives them (the nodes'
    own names: ``bt_navigator``, ``controller_manager``); rviz2's tools are boundary uses.
    What is left: joint_state_broadcaster's ``joint_states`` (ROS 2 controllers are not
    modelled)."""
    package = tmp_path / "p"
    package.mkdir()
    (package / "package.xml").write_text(
        "<package format='3'><name>p</name>"
        "<export><build_type>ament_cmake</build_type></export></package>"
    )
    nodes = [
        ("controller_manager", "ros2_control_node"),
        ("controller_manager", "spawner"),
        ("nav2_bt_navigator", "bt_navigator"),
        ("nav2_planner", "planner_server"),
        ("nav2_controller", "controller_server"),
        ("nav2_behaviors", "behavior_server"),
        ("robot_state_publisher", "robot_state_publisher"),
        ("rviz2", "rviz2"),
    ]
    (package / "a.launch.xml").write_text(
        "<launch>"
        + "".join(f'<node pkg="{p}" exec="{e}" args="joint_state_broadcaster"/>' for p, e in nodes)
        + "</launch>"
    )
    assert main(["check", str(tmp_path), "--format", "json"]) == 0
    findings = json.loads(capsys.readouterr().out)["findings"]
    warned = {(f["check"], f["name"]) for f in findings if f["severity"] != "note"}
    assert warned == {("no-provider", "/joint_states")}
    unmet = {f["name"] for f in findings if f["check"] == "no-provider"}
    assert unmet == {"/joint_states", "/speed_limit"}  # nav2's optional speed limit: a note
