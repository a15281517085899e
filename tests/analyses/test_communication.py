"""The communication graph: edges with conditions, and agreement with ``resolve``."""

from __future__ import annotations

import itertools
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from rosvar.analyses.communication import (
    Channel,
    Edge,
    LaunchedNode,
    branches_remembered,
    model_edges,
    node_branches,
    resolved_graph,
    restrict,
    uses_graph,
)
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.resolution import Restriction
from rosvar.interpreter.workspace_models import Analysis
from rosvar.ros1.resolve import resolve
from rosvar.ros2.nodes import ROS2_NODES
from rosvar.workspace import discover
from rosvar.workspace.interfaces.catalogue import load_catalogue
from rosvar.workspace.interfaces.extraction import extract_interfaces
from rosvar.workspace.interfaces.model import Entry, Interfaces, Role
from rosvar.workspace.interfaces.overrides import add_catalogue
from workspace.interfaces.ros2_packages import MANIFEST, write_ros2_packages

if TYPE_CHECKING:
    from conftest import LaunchWorkspace
    from rosvar.interpreter.workspace_models import Analysis

TALKER = """\
import rospy
from std_msgs.msg import String
rospy.Publisher("chatter", String, queue_size=1)
rospy.Subscriber("~control", String, None)
rospy.Service("/reset", None, None)
"""
LISTENER = """\
import rospy
from std_msgs.msg import String
rospy.Subscriber("chatter", String, None)
"""
LAUNCH = """
  <arg name="robot" default="r0"/>
  <arg name="relay" default="false"/>
  <arg name="second" default="false"/>
  <group ns="$(arg robot)">
    <node pkg="pkg" type="talker.py" name="talker">
      <remap from="chatter" to="/relayed" if="$(arg relay)"/>
    </node>
  </group>
  <node pkg="pkg" type="listener.py" name="listener"/>
  <node pkg="pkg" type="talker.py" name="talker2" if="$(arg second)"/>
"""


def _setup(ws: LaunchWorkspace) -> tuple[Analysis, str, Interfaces, list[Edge]]:
    ws.write("scripts/talker.py", TALKER)
    ws.write("scripts/listener.py", LISTENER)
    file = ws.launch("demo.launch", LAUNCH)
    analysis = ws.analysis(extra_values={"robot": ["r1"]})  # a known value: its own slot
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    return analysis, file, interfaces, model_edges(analysis.space, analysis.model(file), interfaces)


def test_edges_carry_conditions(ws: LaunchWorkspace) -> None:
    analysis, _file, _interfaces, edges = _setup(ws)
    space = analysis.space
    published = {
        (e.node, e.name, space.describe(e.condition)) for e in edges if e.role is Role.PUBLISHES
    }
    names = {(node, name) for node, name, _ in published}
    assert ("/r0/talker", "/r0/chatter") in names and ("/r0/talker", "/relayed") in names
    assert ("/talker2", "/chatter") in names
    assert ("/r1/talker", "/r1/chatter") in names
    [(_, _, when)] = [p for p in published if p[1] == "/relayed" and p[0] == "/r0/talker"]
    assert "relay" in when
    private = {e.name for e in edges if e.role is Role.SUBSCRIBES and e.node == "/r0/talker"}
    assert private == {"/r0/talker/control"}
    assert all(e.type == "std_msgs/String" for e in edges if e.role is not Role.SERVICES)


def test_remembered_branches_are_the_branches(ws: LaunchWorkspace) -> None:
    """Within ``branches_remembered`` a node's branches are crossed once and given again as
    they are (the same objects, the same order); outside it, crossed on each call."""
    analysis, file, _interfaces, _edges = _setup(ws)
    space = analysis.space
    nodes = analysis.model(file).nodes
    fresh = [list(node_branches(space, node)) for node in nodes]
    with branches_remembered():
        first = [list(node_branches(space, node)) for node in nodes]
        with branches_remembered():  # nested: the same memo
            again = [list(node_branches(space, node)) for node in nodes]
    later = [list(node_branches(space, node)) for node in nodes]
    assert first == fresh == later
    flat = itertools.chain.from_iterable
    assert all(a is b for a, b in zip(flat(first), flat(again), strict=True))
    assert not any(a is b for a, b in zip(flat(first), flat(later), strict=True))
    assert sum(len(branches) for branches in fresh) > len(nodes)  # some node has several


def test_restricted_graph_equals_resolved_graph(ws: LaunchWorkspace) -> None:
    """Differential: per configuration, the variational edges that hold are the graph of
    the nodes ``resolve`` gives."""
    analysis, file, interfaces, edges = _setup(ws)
    model = analysis.model(file)
    for robot, relay, second in itertools.product(
        ["r0", "r1"], ["true", "false"], ["true", "false"]
    ):
        args = {"robot": robot, "relay": relay, "second": second}
        resolution = resolve(analysis, [file], args)
        assert resolution.ok
        restriction = Restriction(analysis, model, args, {})
        kept = restrict(edges, restriction.holds)
        assert all(e.static for e in kept)
        uses = [(e.node, e.role, e.name, e.type) for e in kept]
        expected = resolved_graph(resolution.nodes, interfaces, resolution.params)
        assert uses_graph(uses) == expected
        assert expected[Channel.TOPICS]  # the test can fail: the graph is not empty


CORPUS = Path(__file__).resolve().parents[3] / "shared" / "corpus"  # ../shared of the checkout
MAX_CONFIGURATIONS = 12


def _configurations(model: LaunchModel) -> list[dict[str, str]]:
    """The defaults, then one arg at a time at each value analysis knows for it."""
    found: list[dict[str, str]] = [{}]
    for name in sorted(model.inputs):
        found += [{name: slot} for slot in model.domains.get(name, ()) if isinstance(slot, str)]
    return found[:MAX_CONFIGURATIONS]


@pytest.mark.skipif(not CORPUS.is_dir(), reason="corpus not available")
@pytest.mark.parametrize("system", ["kobuki", "husky"])
def test_corpus_restriction_equals_resolution(system: str) -> None:
    workspace = discover([CORPUS / system], deps=[CORPUS / "_external"], ros_package_path="")
    analysis = Analysis(workspace)
    packages = workspace.packages.values()
    interfaces = extract_interfaces(packages)
    add_catalogue(interfaces, load_catalogue())
    compared = 0
    for file in workspace.launch_files:
        model = analysis.model(file)
        edges = model_edges(analysis.space, model, interfaces)
        for args in _configurations(model):
            resolution = resolve(analysis, [file], args)
            if resolution.errors:
                continue
            kept = restrict(edges, Restriction(analysis, model, args, {}).holds)
            uses = [(e.node, e.role, e.name, e.type) for e in kept]
            assert uses_graph(uses) == resolved_graph(
                resolution.nodes, interfaces, resolution.params
            ), (file, args)
            compared += bool(kept)
    assert compared >= 10  # configurations with a graph were compared


@pytest.mark.parametrize(
    ("namespace", "name", "written", "resolved"),
    [
        ("/", "n", "x", "/x"),
        ("/a/", "n", "x", "/a/x"),
        ("/a/", "n", "~x", "/a/n/x"),
        ("/a/", "n", "/x", "/x"),
        ("/a/", "n", "~x/y/", "/a/n/x/y"),
    ],
)
def test_names_resolve_as_the_node_does(
    namespace: str, name: str, written: str, resolved: str
) -> None:
    assert LaunchedNode("p", "t", namespace, name, "", ()).resolve(written) == resolved


def test_a_nodelet_runs_its_class() -> None:
    def unit(args: str) -> tuple[str, str] | None:
        return LaunchedNode("nodelet", "nodelet", "/", "n", args, ()).unit()

    assert unit("load kobuki_node/KobukiNodelet manager") == ("", "kobuki_node/KobukiNodelet")
    assert unit("standalone pkg/Class") == ("", "pkg/Class")
    assert unit("manager") is None
    assert LaunchedNode("pkg", "exe", "/", "n", "", ()).unit() == ("pkg", "exe")


def test_camera_info_lies_beside_the_remapped_image(ws: LaunchWorkspace) -> None:
    """image_transport derives a camera's info topic from its image topic once remapped:
    rgbd_launch remaps a rectify nodelet's ``image_mono`` to ``rgb/image_raw``, so it reads
    ``rgb/camera_info``, not ``camera_info``."""
    ws.write("scripts/talker.py", TALKER)
    file = ws.launch(
        "camera.launch",
        '<arg name="relay" default="false"/>'
        '<node pkg="pkg" type="talker.py" name="rectify">'
        '<remap from="image_mono" to="/camera/rgb/image_raw" if="$(arg relay)"/></node>',
    )
    analysis = ws.analysis()
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    talker = interfaces.find("pkg", "talker.py")
    assert talker is not None
    where = talker.entries[0].location
    talker.entries = [
        Entry(Role.SUBSCRIBES, "image_mono", where, type="sensor_msgs/Image"),
        Entry(
            Role.SUBSCRIBES,
            "camera_info",
            where,
            type="sensor_msgs/CameraInfo",
            beside="image_mono",
        ),
    ]
    model = analysis.model(file)
    edges = model_edges(analysis.space, model, interfaces)
    info = {(e.name, analysis.space.describe(e.condition)) for e in edges if "Info" in str(e.type)}
    assert {name for name, _ in info} == {"/camera/rgb/camera_info", "/camera_info"}
    for relay in ("true", "false"):
        resolution = resolve(analysis, [file], {"relay": relay})
        kept = restrict(edges, Restriction(analysis, model, {"relay": relay}, {}).holds)
        uses = [(e.node, e.role, e.name, e.type) for e in kept]
        assert uses_graph(uses) == resolved_graph(resolution.nodes, interfaces, resolution.params)


ROS2_LAUNCH = """\
<launch>
  <arg name="robot" default="r1"/>
  <arg name="relay" default="false"/>
  <set_remap from="/reset" to="/robot_reset"/>
  <group>
    <push_ros_namespace namespace="$(var robot)"/>
    <node pkg="demo_cpp" exec="talker" namespace="arm">
      <remap from="chatter" to="/relayed" if="$(var relay)"/>
    </node>
    <node pkg="demo_py" exec="listener" name="ear"/>
  </group>
  <node_container pkg="rclcpp_components" exec="component_container" name="box" namespace="cam">
    <composable_node pkg="demo_cpp" plugin="demo_cpp::Camera" name="front" namespace="cam">
      <remap from="image_raw" to="image"/>
    </composable_node>
  </node_container>
  <node pkg="demo_cpp" exec="talker" name="second">
    <remap from="/reset" to="/second_reset"/>
  </node>
</launch>
"""


def _ros2_setup(tmp_path: Path) -> tuple[Analysis, str, Interfaces, list[Edge]]:
    write_ros2_packages(tmp_path)
    launch = tmp_path / "demo_bringup"
    launch.mkdir()
    (launch / "package.xml").write_text(MANIFEST.format(name="demo_bringup", build="ament_cmake"))
    (launch / "demo.launch.xml").write_text(ROS2_LAUNCH)
    analysis = Analysis(discover([tmp_path]), extra_values={"robot": ["r2"]})
    file = str(launch / "demo.launch.xml")
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    return analysis, file, interfaces, model_edges(analysis.space, analysis.model(file), interfaces)


def test_ros2_graph_is_the_interfaces_resolved(tmp_path: Path) -> None:
    """ROS 2's names: the pushed namespace and the node's combined, the code's node name
    where the launch file gives none, ``~/x`` below the node, the first matching remap
    (the global ``set_remap`` before the node's own), a composable node's plugin."""
    analysis, file, interfaces, _edges = _ros2_setup(tmp_path)
    graph = resolved_graph(analysis.resolve([file]).nodes, interfaces, {})
    pairs = {
        str(channel): {e.name: (list(e.providers), list(e.users)) for e in graph[channel]}
        for channel in Channel
    }
    talker, ear, front, second = "/r1/arm/talker", "/r1/ear", "/cam/front", "/second"
    assert pairs == {
        "topics": {
            "/r1/arm/chatter": ([talker], []),
            "/r1/arm/talker/control": ([], [talker]),
            "/r1/chatter": ([], [ear]),
            "/r1/ear/echo": ([ear], []),
            "/cam/image": ([front], []),
            "/cam/camera_info": ([front], []),
            "/cam/mask": ([], [front]),
            "/chatter": ([second], []),
            "/second/control": ([], [second]),
        },
        "services": {
            "/robot_reset": ([], [talker, second]),
            "/r1/reset": ([ear], []),
            "/cam/enable": ([front], []),
        },
        "actions": {
            "/r1/arm/fibonacci": ([talker], []),
            "/fibonacci": ([second], [ear]),
        },
    }


def test_ros2_processes_add_nothing_to_the_graph(tmp_path: Path) -> None:
    """An ``<executable>`` (``ExecuteProcess``) has no name nor package: no interface, no
    failure (Universal Robots' ``ur_control.launch.py`` starts ``socat`` so)."""
    analysis, file, interfaces, _edges = _ros2_setup(tmp_path)
    with_process = Path(file).with_name("with_process.launch.xml")
    with_process.write_text(
        f'<launch><include file="{file}"/><executable cmd="socat pty,link=/tmp/tty tcp:ur:54321"/>'
        "</launch>"
    )
    nodes = analysis.resolve([str(with_process)]).nodes
    alone = analysis.resolve([file]).nodes
    assert len(nodes) == len(alone) + 1
    assert resolved_graph(nodes, interfaces, {}) == resolved_graph(alone, interfaces, {})


def test_ros2_restricted_graph_equals_resolved_graph(tmp_path: Path) -> None:
    """Differential, as for ROS 1: the variational edges of a configuration are the graph of
    the nodes ``ros2 launch`` would start (``rosvar resolve``'s)."""
    analysis, file, interfaces, edges = _ros2_setup(tmp_path)
    model = analysis.model(file)
    for robot, relay in itertools.product(["r1", "r2"], ["true", "false"]):
        args = {"robot": robot, "relay": relay}
        resolution = analysis.resolve([file], args)
        assert resolution.ok
        kept = restrict(edges, Restriction(analysis, model, args, {}).holds)
        assert all(e.static for e in kept)
        uses = [(e.node, e.role, e.name, e.type) for e in kept]
        expected = resolved_graph(resolution.nodes, interfaces, resolution.params)
        assert uses_graph(uses) == expected
        assert any(t.name == f"/{robot}/chatter" for t in expected[Channel.TOPICS])
        relayed = any(t.name == "/relayed" for t in expected[Channel.TOPICS])
        assert relayed == (relay == "true")


@pytest.mark.parametrize(
    ("namespace", "name", "written", "resolved"),
    [
        ("/", "n", "x", "/x"),
        ("/a", "n", "x", "/a/x"),
        ("/a", "n", "~/x", "/a/n/x"),
        ("/a", "n", "~", "/a/n"),
        ("/a", "n", "/x", "/x"),
    ],
)
def test_ros2_names_resolve_as_rcl_does(
    namespace: str, name: str, written: str, resolved: str
) -> None:
    node = LaunchedNode("p", "t", namespace, name, "", (), ros2=True)
    assert node.resolve(written) == resolved


def test_ros2_namespaces_compose() -> None:
    def node(pushed: str | None, namespace: str | None) -> LaunchedNode:
        fields = {"pkg": "p", "exec": "t", "name": "n", "ros_namespace": pushed}
        return LaunchedNode.of(ROS2_NODES, {**fields, "namespace": namespace})

    assert node(None, None).full_name == "/n"
    assert node("/r1", None).full_name == "/r1/n"
    assert node("/r1", "arm").full_name == "/r1/arm/n"
    assert node("/r1", "/arm").full_name == "/arm/n"
    assert node(None, "arm/").full_name == "/arm/n"
