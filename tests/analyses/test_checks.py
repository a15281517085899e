"""The checks on a small workspace: each finding's condition against the configurations
that ``resolve`` enumerates (the checks never enumerate them)."""

from __future__ import annotations

import itertools
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

from conftest import PACKAGE_XML
from oracle.client import requires_oracle
from rosvar.analyses.checks import Check, check_model, check_models
from rosvar.analyses.communication import Channel, resolved_graph
from rosvar.diagnostics import Location, Severity
from rosvar.interpreter.resolution import Restriction
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.documents.findings import finding_document
from rosvar.ros import names
from rosvar.ros1.resolve import resolve
from rosvar.workspace import discover
from rosvar.workspace.interfaces.extraction import extract_interfaces
from rosvar.workspace.interfaces.model import Interfaces, Role
from workspace.interfaces.ros2_packages import write_ros2_bringup, write_ros2_packages

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

HEADER = "import rospy\nfrom std_msgs.msg import Int32, String\n"
SOURCES = {
    "talker.py": HEADER + 'rospy.Publisher("chatter", String)\n',
    "listener.py": HEADER + 'rospy.Subscriber("chatter", String, None)\n',
    "counter.py": HEADER + 'rospy.Publisher("/chatter", Int32)\n',
    "reader.py": HEADER
    + 'rospy.get_param("~rate")\nrospy.get_param("~gain", 1.0)\n'
    + 'rospy.Subscriber("~input", String, None)\n',
}
LAUNCH = """
  <arg name="two" default="false"/>
  <arg name="listen" default="true"/>
  <arg name="wrong" default="false"/>
  <node pkg="pkg" type="talker.py" name="talker"/>
  <node pkg="pkg" type="talker.py" name="talker2" if="$(arg two)">
    <remap from="chatter" to="reader/input" if="$(arg listen)"/>
  </node>
  <node pkg="pkg" type="listener.py" name="listener" if="$(arg listen)"/>
  <node pkg="pkg" type="counter.py" name="counter" if="$(arg wrong)"/>
  <node pkg="pkg" type="reader.py" name="reader">
    <param name="rate" value="1" if="$(arg two)"/>
    <param name="gian" value="2" if="$(arg wrong)"/>
    <remap from="inptu" to="chatter" if="$(arg wrong)"/>
  </node>
  <node pkg="pkg" type="listener.py" name="listener" if="$(arg two)"/>
"""
ARGS = ("two", "listen", "wrong")
READS = {"reader": ("rate", "gain")}
USES = {  # the names each script uses (SOURCES), resolved in a node of name NODE in /
    "talker.py": {"/chatter"},
    "listener.py": {"/chatter"},
    "counter.py": {"/chatter"},
    "reader.py": {"/NODE/rate", "/NODE/gain", "/NODE/input"},
}


def _setup(ws: LaunchWorkspace) -> tuple[Analysis, str, Interfaces]:
    for name, text in SOURCES.items():
        ws.write(f"scripts/{name}", text)
    file = ws.launch("system.launch", LAUNCH)
    analysis = ws.analysis()
    return analysis, file, extract_interfaces(analysis.workspace.packages.values())


def _expected(
    analysis: Analysis, file: str, interfaces: Interfaces, args: dict[str, str]
) -> set[tuple[Check, str]]:
    """The findings of one configuration, from its resolution."""
    resolution = resolve(analysis, [file], args)
    graph = resolved_graph(resolution.nodes, interfaces, resolution.params)
    found = set()
    for topic in graph[Channel.TOPICS]:
        name = topic.name
        if len(topic.providers) >= 2:
            found.add((Check.MULTIPLE_PROVIDERS, name))
        if len(topic.types) >= 2:
            found.add((Check.TYPE_MISMATCH, name))
        if not topic.users:
            found.add((Check.NO_SUBSCRIBER, name))
        if not topic.providers:
            found.add((Check.NO_PROVIDER, name))
    if "/reader/rate" not in resolution.params:
        found.add((Check.PARAM_UNSET, "/reader/rate"))
    launched = {node.own_name for node in resolution.nodes}
    for started in resolution.nodes:
        own_name, executable = started.own_name or "", started.executable or ""
        uses = {use.replace("NODE", own_name) for use in USES[executable]}
        for source, _target in started.remaps:
            if names.ns_join("/", source) not in uses:
                found.add((Check.REMAP_UNUSED, names.ns_join("/", source)))
    for name in resolution.params:  # only reader.py reads parameters (SOURCES)
        node, _, own = name.removeprefix("/").partition("/")
        if node in launched and own not in READS.get(node, ()):
            found.add((Check.PARAM_UNREAD, name))
    found |= {(Check.NODE_NAME_CLASH, c.name) for c in resolution.conflicts}
    return found


def test_conditions_agree_with_every_configuration(ws: LaunchWorkspace) -> None:
    analysis, file, interfaces = _setup(ws)
    model = analysis.model(file)
    findings = check_model(analysis.space, model, interfaces, analysis.workspace.confinement())
    kinds = {f.check for f in findings}
    # every check has a case here (when-unknown: in test_when_params, with hints; unread:
    # in robot_description/test_edges; ROS 2's in tests/ros2; load-error below: a launch
    # that fails has no graph to compare)
    assert kinds == set(Check) - {
        Check.SYMBOLIC_NAME,
        Check.WHEN_UNKNOWN,
        Check.UNREAD,
        Check.PARAM_FILE_UNMATCHED,
        Check.LOAD_ERROR,
    }
    for values in itertools.product(["true", "false"], repeat=len(ARGS)):
        args = dict(zip(ARGS, values, strict=True))
        holds = Restriction(analysis, model, args, {}).holds
        found = {(f.check, f.name) for f in findings if holds(f.condition)}
        assert found == _expected(analysis, file, interfaces, args), args


def test_findings_are_readable(ws: LaunchWorkspace) -> None:
    analysis, file, interfaces = _setup(ws)
    findings = check_models(
        analysis.space, [analysis.model(file)], interfaces, analysis.workspace.confinement()
    )
    [mismatch] = [f for f in findings if f.check is Check.TYPE_MISMATCH]
    document = finding_document(mismatch, analysis.space)
    assert document["condition"] == "wrong"
    assert document["example"] == {"system.launch:wrong": "true"}
    assert document["severity"] == "error"
    assert "std_msgs/Int32" in str(document["message"])
    lines = {location.line for location in mismatch.locations}
    assert lines == {3, 6, 11}  # the publishers: their source line and their <node>s
    [unset] = [f for f in findings if f.check is Check.PARAM_UNSET]
    assert analysis.space.describe(unset.condition) == "¬two"
    assert not any(f.name == "/reader/gain" for f in findings)  # it has a default
    [misspelt] = [f for f in findings if f.check is Check.PARAM_UNREAD]
    assert (
        misspelt.message == "/reader/gian is set for /reader, which never reads it (it reads ~gain)"
    )
    assert analysis.space.describe(misspelt.condition) == "wrong"
    [renaming] = [f for f in findings if f.check is Check.REMAP_UNUSED]
    assert renaming.message == (
        "/reader never uses /inptu: its remap to chatter renames nothing (it uses /reader/input)"
    )
    assert [at.line for at in renaming.locations] == [15, 12]  # the <remap>, then its <node>
    [unfed] = [f for f in findings if f.check is Check.NO_PROVIDER]
    assert unfed.name == "/reader/input"
    assert analysis.space.describe(unfed.condition) in ("¬listen ∨ ¬two", "¬two ∨ ¬listen")


def test_boundary_uses_are_not_missing_partners(ws: LaunchWorkspace) -> None:
    """An input meant for people or tools (amcl's initialpose) without a provider is a note,
    not a warning; an output meant for them (/tf) without a subscriber is no finding."""
    analysis, file, interfaces = _setup(ws)
    reader = interfaces.find("pkg", "reader.py")
    talker = interfaces.find("pkg", "talker.py")
    assert reader is not None and talker is not None
    reader.entries = [
        replace(e, boundary=True) if e.role is Role.SUBSCRIBES else e for e in reader.entries
    ]
    talker.entries = [replace(e, boundary=True) for e in talker.entries]
    findings = check_model(
        analysis.space, analysis.model(file), interfaces, analysis.workspace.confinement()
    )
    [unfed] = [f for f in findings if f.check is Check.NO_PROVIDER]
    assert (unfed.name, unfed.severity) == ("/reader/input", Severity.NOTE)
    unheard = {f.message.split()[0] for f in findings if f.check is Check.NO_SUBSCRIBER}
    assert unheard == {"/counter"}  # the talkers' publications are boundary ones


def test_one_node_with_two_types_is_no_mismatch(ws: LaunchWorkspace) -> None:
    """robot_localization subscribes cmd_vel as Twist or TwistStamped (its stamped_control):
    alternative code paths of one node, which agrees with a node using either type."""
    analysis, file, interfaces = _setup(ws)
    counter = interfaces.find("pkg", "counter.py")
    assert counter is not None
    counter.entries = [*counter.entries, replace(counter.entries[0], type="std_msgs/Int64")]
    findings = check_model(
        analysis.space, analysis.model(file), interfaces, analysis.workspace.confinement()
    )
    mismatches = {f.message for f in findings if f.check is Check.TYPE_MISMATCH}
    assert len(mismatches) == 2  # Int32 and Int64 each against the talkers' String
    assert not any("Int32" in m and "Int64" in m for m in mismatches)
    counter.entries = [*counter.entries, replace(counter.entries[0], type="std_msgs/String")]
    findings = check_model(
        analysis.space, analysis.model(file), interfaces, analysis.workspace.confinement()
    )
    assert not any(f.check is Check.TYPE_MISMATCH for f in findings)  # it shares String


def test_a_partner_in_another_launch_file_makes_a_note(ws: LaunchWorkspace) -> None:
    """kobuki's safety_controller.launch subscribes to the bumper events that minimal.launch
    (the base) publishes: launch files started together; the finding says which."""
    analysis, file, interfaces = _setup(ws)
    other = ws.launch(
        "base.launch",
        '<node pkg="pkg" type="talker.py" name="feeder">'
        '<remap from="chatter" to="/reader/input"/></node>',
    )
    analysis = ws.analysis()
    models = [analysis.model(file), analysis.model(other)]
    findings = check_models(analysis.space, models, interfaces, analysis.workspace.confinement())
    [unfed] = [f for f in findings if f.check is Check.NO_PROVIDER]
    assert (unfed.name, unfed.severity) == ("/reader/input", Severity.NOTE)
    assert unfed.message.endswith("which no launched node provides here (base.launch does)")
    alone = check_models(analysis.space, models[:1], interfaces, analysis.workspace.confinement())
    assert [f.severity for f in alone if f.check is Check.NO_PROVIDER] == [Severity.WARNING]


def test_ros2_nodes_of_one_name_are_a_warning_and_two_providers(tmp_path: Path) -> None:
    """``ros2 launch`` starts both nodes of one name (roslaunch refuses): a warning, under the
    pushed namespace's values where the names meet; what both serve has two providers."""
    write_ros2_bringup(
        tmp_path,
        """<launch><arg name="ns" default="r1"/>
        <group><push_ros_namespace namespace="$(var ns)"/>
          <node pkg="demo_py" exec="listener" name="ear"/></group>
        <node pkg="demo_py" exec="listener" name="ear" namespace="r1"/></launch>""",
    )
    analysis = Analysis(discover([tmp_path]))
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    [model] = [analysis.model(f) for f in analysis.workspace.launch_files]
    findings = check_models(analysis.space, [model], interfaces, analysis.workspace.confinement())
    [clash] = [f for f in findings if f.check is Check.NODE_NAME_CLASH]
    assert clash.name == "/r1/ear" and clash.severity is Severity.WARNING
    assert analysis.space.describe(clash.condition) == "ns=r1"
    served = [f for f in findings if f.check is Check.MULTIPLE_PROVIDERS]
    assert [(f.name, f.message) for f in served if f.name.endswith("reset")] == [
        ("/r1/reset", "2 nodes serve /r1/reset: /r1/ear ×2")
    ]
    assert all(analysis.space.describe(f.condition) == "ns=r1" for f in served)


def _findings(ws: LaunchWorkspace, body: str, check: Check) -> list[tuple[str, Severity, str]]:
    for name, text in SOURCES.items():
        ws.write(f"scripts/{name}", text)
    file = ws.launch("system.launch", body)
    analysis = ws.analysis()
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    confinement = analysis.workspace.confinement()
    found = check_models(analysis.space, [analysis.model(file)], interfaces, confinement)
    return [(f.name, f.severity, f.message) for f in found if f.check is check]


def test_a_parameter_set_in_other_configurations_is_a_note(ws: LaunchWorkspace) -> None:
    """MoveIt's demo.launch: ``load_robot_description:=false`` leaves the description to what
    runs beside; a read no launch file ever sets stays a warning."""
    body = """<arg name="load" default="true"/>
      <param name="reader/rate" value="2" if="$(arg load)"/>
      <node pkg="pkg" type="reader.py" name="reader"/>"""
    [(name, severity, message)] = _findings(ws, body, Check.PARAM_UNSET)
    assert (name, severity) == ("/reader/rate", Severity.NOTE)
    assert message.endswith("in these configurations (it does in others)")
    body = '<node pkg="pkg" type="reader.py" name="reader"/>'
    assert [s for _n, s, _m in _findings(ws, body, Check.PARAM_UNSET)] == [Severity.WARNING]


def test_a_node_without_interface_beside_a_missing_partner_makes_a_note(
    ws: LaunchWorkspace,
) -> None:
    """Husky's navsat.launch: the GPS driver in /gps, whose interface rosvar does not know,
    publishes the gps/fix navsat_transform reads; one in another namespace says nothing."""
    body = """<node pkg="pkg" type="reader.py" name="reader"/>
      <node pkg="driver" type="gps" name="gps" ns="reader"/>"""
    [(name, severity, message)] = _findings(ws, body, Check.NO_PROVIDER)
    assert (name, severity) == ("/reader/input", Severity.NOTE)
    assert message.endswith("(unless /reader/gps, whose interface rosvar does not know, does)")
    body = body.replace('ns="reader"', 'ns="elsewhere"')
    assert [s for _n, s, _m in _findings(ws, body, Check.NO_PROVIDER)] == [Severity.WARNING]


def test_a_node_publishing_a_name_rosvar_cannot_resolve_may_be_the_partner(
    ws: LaunchWorkspace,
) -> None:
    """realsense's frame_latency beside the camera driver, whose topics its code composes:
    a missing provider is a note naming the unresolved name; not where the known parts of
    that name cannot fit, nor where the node itself is the only one with such a name."""
    ws.write(
        "scripts/relay.py", HEADER + 'import sys\nrospy.Publisher(sys.argv[1] + "/input", String)\n'
    )
    body = """<node pkg="pkg" type="reader.py" name="reader"/>
      <node pkg="pkg" type="relay.py" name="relay"/>"""
    [(name, severity, message)] = _findings(ws, body, Check.NO_PROVIDER)
    assert (name, severity) == ("/reader/input", Severity.NOTE)
    assert message.endswith(
        "(unless /relay's '/{sys.argv[1]}/input', a name rosvar cannot resolve, is it)"
    )
    ws.write(
        "scripts/relay.py",
        HEADER + 'import sys\nrospy.Publisher(sys.argv[1] + "/output", String)\n',
    )
    assert [s for _n, s, _m in _findings(ws, body, Check.NO_PROVIDER)] == [Severity.WARNING]


def test_one_problem_seen_through_two_uses_is_one_finding(ws: LaunchWorkspace) -> None:
    """A node subscribing one topic at two lines of its source (two message types chosen by
    a parameter): one finding showing both places, not two with one fingerprint."""
    ws.write(
        "scripts/twice.py",
        HEADER
        + 'rospy.Subscriber("input", String, None)\nrospy.Subscriber("input", Int32, None)\n',
    )
    for name, text in SOURCES.items():
        ws.write(f"scripts/{name}", text)
    file = ws.launch("system.launch", '<node pkg="pkg" type="twice.py" name="twice"/>')
    analysis = ws.analysis()
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    found = check_models(
        analysis.space, [analysis.model(file)], interfaces, analysis.workspace.confinement()
    )
    [finding] = [f for f in found if f.check is Check.NO_PROVIDER]
    assert finding.name == "/input"
    assert sorted(at.line for at in finding.locations[1:]) == [3, 4]


def test_a_parameter_nobody_reads_needs_every_read_known(ws: LaunchWorkspace) -> None:
    """A node that reads a name only known at run time may read the one set: no finding;
    nor for a node whose interface rosvar does not have, nor in the namespace of a
    dynamic_reconfigure server (its config's parameters)."""
    ws.write("scripts/dynamic.py", HEADER + "import sys\nrospy.get_param(sys.argv[1])\n")
    ws.write(
        "scripts/tuned.py",
        HEADER
        + "from dynamic_reconfigure.server import Server\n"
        + 'Server(object, None)\nrospy.get_param("~rate", 1)\n',
    )
    body = """<node pkg="pkg" type="reader.py" name="reader"><param name="rat" value="1"/></node>
      <node pkg="pkg" type="dynamic.py" name="dynamic"><param name="x" value="1"/></node>
      <node pkg="other" type="box" name="box"><param name="x" value="1"/></node>
      <node pkg="pkg" type="tuned.py" name="tuned"><param name="kp" value="1"/></node>"""
    found = _findings(ws, body, Check.PARAM_UNREAD)
    assert found == [
        (
            "/reader/rat",
            Severity.WARNING,
            "/reader/rat is set for /reader, which never reads it (it reads ~rate)",
        )
    ]


def test_a_mistake_of_the_files_text_is_a_load_error_where_roslaunch_refuses(
    ws: LaunchWorkspace,
) -> None:
    """fetch_navigation's keepout: an include given one arg twice under a condition. The
    finding holds exactly where resolve (roslaunch's semantics) refuses the file; an error a
    typed value makes (a non-boolean ``if``) is the command line's, not a finding."""
    ws.launch("inc.launch", '<arg name="map_topic" default="map"/>')
    body = """<arg name="keepout" default="false"/>
      <arg name="flag" default="true"/>
      <include file="$(find pkg)/launch/inc.launch">
        <arg name="map_topic" value="map"/>
        <arg name="map_topic" value="keepout_map" if="$(arg keepout)"/>
      </include>
      <node pkg="pkg" type="talker.py" name="talker" if="$(arg flag)"/>"""
    found = _findings(ws, body, Check.LOAD_ERROR)
    assert found == [
        (
            "map_topic",
            Severity.ERROR,
            "the launch tool refuses the launch here: arg 'map_topic' has already been declared",
        )
    ]
    analysis = ws.analysis()
    file = str(ws.root / "pkg" / "launch" / "system.launch")
    model = analysis.model(file)
    confinement = analysis.workspace.confinement()
    [error] = [
        f
        for f in check_models(analysis.space, [model], Interfaces(), confinement)
        if f.check is Check.LOAD_ERROR
    ]
    for keepout in ("true", "false"):
        args = {"keepout": keepout}
        holds = Restriction(analysis, model, args, {}).holds(error.condition)
        assert holds == bool(resolve(analysis, [file], args).errors), keepout


@requires_oracle[0]
@requires_oracle[1]
def test_a_node_of_a_file_included_twice_clashes_where_roslaunch_refuses(
    ws: LaunchWorkspace,
) -> None:
    """realsense's rs_multi_camera_launch.py, husky's spawn: one node declaration loaded
    twice, through two includes of its file. One finding for the name, holding exactly where
    roslaunch refuses "multiple nodes named"."""
    ws.launch("camera.launch", '<node pkg="pkg" type="talker.py" name="camera"/>')
    body = """<arg name="second" default="false"/>
      <include file="$(find pkg)/launch/camera.launch"/>
      <include file="$(find pkg)/launch/camera.launch" if="$(arg second)"/>"""
    [(name, severity, message)] = _findings(ws, body, Check.NODE_NAME_CLASH)
    assert (name, severity) == ("/camera", Severity.ERROR)
    assert "camera.launch included twice" in message
    analysis = ws.analysis()
    file = str(ws.root / "pkg" / "launch" / "system.launch")
    model = analysis.model(file)
    [clash] = [
        f
        for f in check_models(
            analysis.space, [model], Interfaces(), analysis.workspace.confinement()
        )
        if f.check is Check.NODE_NAME_CLASH
    ]
    results = ws.oracle(file, [({"second": v}, {}) for v in ("true", "false")])
    for second, result in zip(("true", "false"), results, strict=True):
        refused = "multiple nodes named" in str(result.get("error"))
        assert Restriction(analysis, model, {"second": second}, {}).holds(clash.condition) == (
            refused
        ), (second, result)


def test_a_file_rosvar_cannot_read_is_an_unread_error_once(ws: LaunchWorkspace) -> None:
    """A malformed included file (or one over a limit on hostile input) hides what it would
    launch: the checks say so at its place, once for every file including it, instead of
    passing with no finding."""
    ws.launch("broken.launch", '<node pkg="pkg" type="talker.py" name="t">')
    ws.launch("other.launch", '<include file="$(find pkg)/launch/broken.launch"/>')
    found = _findings(ws, '<include file="$(find pkg)/launch/broken.launch"/>', Check.UNREAD)
    assert found == [
        (
            "xml-malformed",
            Severity.ERROR,
            "rosvar could not read this, the checks do not see it: malformed XML: mismatched tag",
        )
    ]
    analysis = ws.analysis()
    models = [analysis.model(file) for file in analysis.workspace.launch_files]
    confinement = analysis.workspace.confinement()
    unread = [
        f
        for f in check_models(analysis.space, models, Interfaces(), confinement)
        if f.check is Check.UNREAD
    ]
    assert [(f.locations[0].file, f.locations[0].line) for f in unread] == [
        (str(ws.root / "pkg" / "launch" / "broken.launch"), 3)
    ]


def test_a_dependency_file_rosvar_cannot_read_is_a_warning_at_the_users_include(
    tmp_path: Path,
) -> None:
    """ros_gz's ``gz_sim.launch.py`` is made by its build from a template: a dependency's
    sources lack it, yet the installed launch works. The include is not followed (what it
    launches is not known), a warning at the user's include that reaches it (through a
    dependency's file), under that include's condition; a dependency's file nobody
    includes is no finding, and the user's own unreadable file stays an error."""
    user, deps = tmp_path / "ws" / "app", tmp_path / "deps" / "dpkg"
    for folder, name in ((user, "app"), (deps, "dpkg")):
        (folder / "launch").mkdir(parents=True)
        (folder / "package.xml").write_text(PACKAGE_XML.format(name=name))
    (user / "launch" / "own.launch").write_text("<launch><node")
    main = user / "launch" / "main.launch"
    main.write_text(
        '<launch>\n  <arg name="sim" default="true"/>\n'
        '  <include file="$(find dpkg)/launch/wrapper.launch" if="$(arg sim)"/>\n'
        '  <include file="$(find app)/launch/own.launch" unless="$(arg sim)"/>\n</launch>\n'
    )
    (deps / "launch" / "wrapper.launch").write_text(
        '<launch>\n  <include file="$(find dpkg)/launch/generated.launch"/>\n</launch>\n'
    )
    (deps / "launch" / "broken.launch").write_text("<launch><node")
    workspace = discover([user.parent], deps=[deps.parent], ros_package_path="")
    analysis = Analysis(workspace)
    model = analysis.model(str(main))
    found = check_models(
        analysis.space,
        [model],
        Interfaces(),
        workspace.confinement(),
        dependency=workspace.of_dependency,
    )
    unread = [(f.severity, f.locations, f.message) for f in found if f.check is Check.UNREAD]
    generated = deps / "launch" / "generated.launch"
    assert unread[0] == (
        Severity.WARNING,
        (Location(str(main), 3, 3), Location(str(deps / "launch" / "wrapper.launch"), 2, 3)),
        f"included file {generated} of a dependency is not read (cannot read file: No such "
        "file or directory): what it launches is not known",
    )
    assert [(severity, places[0].file) for severity, places, _ in unread[1:]] == [
        (Severity.ERROR, str(user / "launch" / "own.launch"))
    ]
    [dependency] = [f for f in found if f.locations[0].line == 3]
    for sim, holds in (("true", True), ("false", False)):
        restriction = Restriction(analysis, model, {"sim": sim}, {})
        assert restriction.holds(dependency.condition) is holds
    assert resolve(analysis, [str(main)], {"sim": "false"}).errors  # the user's own file
    [error] = resolve(analysis, [str(main)], {"sim": "true"}).errors
    assert (error.code, error.location.line) == ("include-unknown", 2)
    assert not any(e.code == "launch-invalid" for e in model.errors if "generated" in e.message)


LIFECYCLE_LAUNCH = """
from launch import LaunchDescription
from launch_ros.actions import LifecycleNode, Node

def generate_launch_description():
    return LaunchDescription([
        LifecycleNode(package="demo_cpp", executable="unknown", name="lc", namespace=""),
        Node(package="demo_py", executable="client"),
    ])
"""
LIFECYCLE_CLIENT = """
import rclpy
from rclpy.node import Node
from lifecycle_msgs.srv import ChangeState

def main():
    node = Node("client")
    node.create_client(ChangeState, "lc/change_state")
"""


def test_a_node_launched_as_a_lifecycle_node_serves_the_lifecycle_services(
    tmp_path: Path,
) -> None:
    """launch_ros's ``LifecycleNode`` drives its node through rcl_lifecycle's services: the
    node serves them whatever rosvar knows of its code (here nothing); the same executable
    started as a plain ``Node`` leaves the client without a provider."""
    write_ros2_packages(tmp_path)
    (tmp_path / "demo_py" / "setup.py").write_text(
        "from setuptools import setup\nsetup(name='demo_py', entry_points={'console_scripts': "
        "['client = demo_py.client:main']})\n"
    )
    (tmp_path / "demo_py" / "demo_py" / "client.py").write_text(LIFECYCLE_CLIENT)
    launch = tmp_path / "demo_py" / "launch" / "lc.launch.py"
    launch.parent.mkdir()
    missing = {}
    for action in ("LifecycleNode", "Node"):
        launch.write_text(LIFECYCLE_LAUNCH.replace("LifecycleNode(", action + "("))
        analysis = Analysis(discover([tmp_path]))
        interfaces = extract_interfaces(analysis.workspace.packages.values())
        model = analysis.model(str(launch))
        findings = check_models(
            analysis.space, [model], interfaces, analysis.workspace.confinement()
        )
        missing[action] = [f.name for f in findings if f.check is Check.NO_PROVIDER]
    assert missing == {"LifecycleNode": [], "Node": ["/lc/change_state"]}


def test_a_parameter_set_one_namespace_above_the_node_reading_it_is_unread(
    ws: LaunchWorkspace,
) -> None:
    """jackal's joystick YAML set ``/bluetooth_teleop/enable_button`` where
    ``/bluetooth_teleop/teleop_twist_joy`` reads ``~enable_button``: no node reads the name
    set, the node stays on its default. Not where the node's own name is set too, another
    node reads the name, or a node of that namespace whose interface is unknown may."""
    ws.write("scripts/other.py", HEADER + 'rospy.get_param("rate")\n')
    body = """<arg name="own" default="false"/><arg name="other" default="false"/>
      <arg name="unknown" default="false"/>
      <group ns="robot">
        <param name="rate" value="1"/>
        <param name="reader/rate" value="2" if="$(arg own)"/>
        <node pkg="pkg" type="reader.py" name="reader"/>
        <node pkg="pkg" type="other.py" name="other" if="$(arg other)"/>
        <node pkg="pkg" type="nowhere" name="nowhere" if="$(arg unknown)"/>
      </group>"""
    file = str(ws.root / "pkg" / "launch" / "system.launch")
    [(name, severity, message)] = _findings(ws, body, Check.PARAM_UNREAD)
    assert (name, severity) == ("/robot/rate", Severity.WARNING)
    assert message == (
        "/robot/rate is set where no launched node reads it, beside /robot/reader, which "
        "reads ~rate (/robot/reader/rate) and finds it unset"
    )
    analysis = ws.analysis()
    model = analysis.model(file)
    confinement = analysis.workspace.confinement()
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    [finding] = [
        f
        for f in check_models(analysis.space, [model], interfaces, confinement)
        if f.check is Check.PARAM_UNREAD
    ]
    for own, other, unknown in itertools.product(("true", "false"), repeat=3):
        args = {"own": own, "other": other, "unknown": unknown}
        holds = Restriction(analysis, model, args, {}).holds(finding.condition)
        assert holds == (own == other == unknown == "false"), args
