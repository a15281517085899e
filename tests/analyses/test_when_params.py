"""A hinted entry's ``when:`` over the node's own parameters (``param('~use_imu')``)."""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

import pytest

from configuration.helpers import choices
from rosvar.analyses.checks import Check, check_model
from rosvar.analyses.communication import (
    Channel,
    Edge,
    entry_when,
    launched_units,
    model_edges,
    resolved_graph,
    restrict,
    uses_graph,
)
from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.param_values import ParamValues
from rosvar.analyses.when import params_read, refusal, refusals
from rosvar.configuration.engine import Configurator
from rosvar.diagnostics import Severity
from rosvar.interpreter.resolution import Restriction
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER, Slot
from rosvar.outputs.web.entries import render
from rosvar.ros1.resolve import resolve
from rosvar.workspace.hints import load_hints
from rosvar.workspace.interfaces.extraction import extract_interfaces
from rosvar.workspace.interfaces.model import Interfaces, Role
from rosvar.workspace.interfaces.overrides import apply_hints

if TYPE_CHECKING:
    from conftest import LaunchWorkspace
    from rosvar.interpreter.model import LaunchModel
    from rosvar.interpreter.workspace_models import Analysis

# The node reads ~use_imu (default true) and ~rate (default 10); its sources subscribe to
# imu and publish fused and debug unconditionally: the hints say when it really does.
DRIVER = """\
import rospy
from sensor_msgs.msg import Imu
from nav_msgs.msg import Odometry
use_imu = rospy.get_param("~use_imu", True)
rate = rospy.get_param("~rate", 10)
rospy.Subscriber("imu", Imu, None)
rospy.Publisher("odom", Odometry, queue_size=1)
rospy.Publisher("fused", Odometry, queue_size=1)
rospy.Publisher("debug", Odometry, queue_size=1)
"""
HINTS = """\
nodes:
  pkg/driver.py:
    subscribes:
      - {name: imu, type: sensor_msgs/Imu, when: "param('~use_imu')"}
    publishes:
      - {name: fused, type: nav_msgs/Odometry, when: "param('~rate') > 15 and fast"}
      - {name: debug, type: nav_msgs/Odometry, when: "param('/debug_mode') == 'verbose'"}
"""
# ~use_imu: set from an arg where set_imu, else the node's default (true); the included file
# sets it again (later: it wins) where off. ~rate: the namespace's <rosparam> of the same
# file. /debug_mode: nobody sets it and there is no default.
LAUNCH = """\
  <arg name="set_imu" default="true"/>
  <arg name="imu" default="true"/>
  <arg name="off" default="false"/>
  <arg name="fast" default="false"/>
  <arg name="rate" default="10"/>
  <group ns="robot">
    <node pkg="pkg" type="driver.py" name="driver">
      <param name="use_imu" value="$(arg imu)" if="$(arg set_imu)"/>
    </node>
    <param name="driver/rate" value="$(arg rate)"/>
  </group>
  <include file="$(find pkg)/launch/off.launch" if="$(arg off)"/>"""
OFF = '  <param name="/robot/driver/use_imu" value="false"/>'
VALUES = {
    "set_imu": ["true", "false"],
    "imu": ["true", "false"],
    "off": ["true", "false"],
    "fast": ["true", "false"],
    "rate": ["10", "20"],
}


def _setup(ws: LaunchWorkspace) -> tuple[Analysis, LaunchModel, str, Interfaces]:
    ws.write("scripts/driver.py", DRIVER)
    ws.launch("off.launch", OFF)
    file = ws.launch("a.launch", LAUNCH)
    hints = load_hints(ws.write("hints.yaml", HINTS))
    assert hints.diagnostics == [] and refusals(hints.nodes) == []
    analysis = ws.analysis(extra_values=VALUES)  # each a known slot
    interfaces = extract_interfaces(analysis.workspace.packages.values())
    apply_hints(interfaces, hints.nodes)
    return analysis, analysis.model(file), file, interfaces


def _slot(space: ConditionSpace, model: LaunchModel, name: str, value: str) -> BDD:
    return space.slot(model.inputs[name], value)


def _conditions(space: ConditionSpace, edges: list[Edge]) -> dict[str, BDD]:
    found: dict[str, BDD] = {}
    for edge in edges:
        found[edge.name] = found.get(edge.name, space.false) | edge.condition
    return found


def test_the_edge_holds_where_the_parameter_satisfies_the_when(ws: LaunchWorkspace) -> None:
    analysis, model, _file, interfaces = _setup(ws)
    space = analysis.space
    conditions = _conditions(space, model_edges(space, model, interfaces))

    def arg(name: str, value: Slot = "true") -> BDD:
        return space.slot(model.inputs[name], value)

    # every arg at a value analysis knows (typed texts: below)
    known = space.true
    for name, values in VALUES.items():
        known &= arg(name, values[0]) | arg(name, values[1])
    # set from the arg where set_imu, else the node's default (true); the included file's
    # false, set later, wins where off
    imu = ~arg("off") & (~arg("set_imu") | arg("imu"))
    assert _same(space, conditions["/robot/imu"] & known, imu & known)
    fused = arg("rate", "20") & arg("fast")
    assert _same(space, conditions["/robot/fused"] & known, fused & known)
    assert conditions["/robot/odom"] == space.true
    assert conditions["/robot/debug"] == space.true  # unset without a default: kept
    # imu typed: "its text is true", decided once typed (as an if=)
    typed = ~arg("off") & arg("set_imu") & arg("imu", OTHER)
    assert space.satisfiable(conditions["/robot/imu"] & typed)
    assert not _same(space, conditions["/robot/imu"] & typed, typed)


def _same(space: ConditionSpace, first: BDD, second: BDD) -> bool:
    """Equal in every configuration (the facts, e.g. one slot per arg, conjoined)."""
    return not space.satisfiable((first & ~second) | (~first & second))


def test_restriction_equals_resolution(ws: LaunchWorkspace) -> None:
    """Differential: per configuration, the variational edges that hold are the graph of
    the nodes ``resolve`` gives, which evaluates each ``when:`` with the concrete values."""
    analysis, model, file, interfaces = _setup(ws)
    edges = model_edges(analysis.space, model, interfaces)
    seen = set()
    for values in itertools.product(*VALUES.values()):
        args = dict(zip(VALUES, values, strict=True))
        resolution = resolve(analysis, [file], args)
        assert resolution.ok
        kept = restrict(edges, Restriction(analysis, model, args, {}).holds)
        graph = resolved_graph(resolution.nodes, interfaces, resolution.params)
        assert uses_graph([(e.node, e.role, e.name, e.type) for e in kept]) == graph
        seen.add(tuple(topic.name for topic in graph[Channel.TOPICS]))
    assert len(seen) == 4  # imu and fused each present and absent


@pytest.mark.parametrize(
    ("args", "imu"),
    [
        ({"imu": "true"}, True),
        ({"imu": "false"}, False),
        ({"set_imu": "false"}, True),  # unset: the node's default
        ({"set_imu": "false", "off": "true"}, False),  # another file sets it
        ({"imu": "True"}, True),  # a typed text: converted as <param> converts it
        ({"imu": "0"}, False),
    ],
)
def test_resolve_gives_the_topics_of_the_parameter(
    ws: LaunchWorkspace, args: dict[str, str], imu: bool
) -> None:
    analysis, model, file, interfaces = _setup(ws)
    resolution = resolve(analysis, [file], args)
    graph = resolved_graph(resolution.nodes, interfaces, resolution.params)
    names = {topic.name for topic in graph[Channel.TOPICS]}
    assert names == {"/robot/odom", "/robot/debug"} | ({"/robot/imu"} if imu else set())
    kept = restrict(
        model_edges(analysis.space, model, interfaces), Restriction(analysis, model, args, {}).holds
    )
    assert ("/robot/imu" in {e.name for e in kept}) is imu


def test_the_configure_graph_follows_the_parameter(ws: LaunchWorkspace) -> None:
    analysis, _model, _file, interfaces = _setup(ws)
    model = extract(analysis, products=True)
    spelling = {f.file: f.file.rsplit("/", 1)[-1] for f in model.files}
    engine = Configurator(analysis, model, spelling=spelling, interfaces=interfaces, render=render)
    unset = ("select a.launch", "set a.launch:set_imu=false")

    def imu(*words: str) -> str:
        state = engine.state(choices(*unset, *words))
        return {t["name"]: str(t["presence"]) for t in state.graph.topics}["/robot/imu"]

    assert imu("set a.launch:off=false") == "undetermined"  # off.launch itself may set it
    assert imu("set a.launch:off=false", "deselect off.launch") == "present"  # the default
    assert imu("set a.launch:off=true") == "absent"  # included, it sets false


def test_param_names_and_refusals() -> None:
    assert params_read("param('~use_imu') and param(\"/mode\") == 'x' or param('~use_imu')") == (
        "~use_imu",
        "/mode",
    )
    assert params_read("$(arg laser)") == ()
    assert refusal("param('~a') > 3 and laser") is None
    assert refusal("param(name)") is not None  # not a literal name
    assert refusal("param('a b')") is not None  # not a ROS name
    assert refusal("param('~a').__class__") is not None


def test_the_interface_default_is_the_value_nobody_sets(ws: LaunchWorkspace) -> None:
    *_, interfaces = _setup(ws)
    driver = interfaces.find("pkg", "driver.py")
    assert driver is not None
    [default] = [e.default for e in driver.of(Role.PARAMS) if e.name == "~use_imu"]
    assert default is True


def test_check_notes_where_a_value_is_unknown(ws: LaunchWorkspace) -> None:
    analysis, model, _file, interfaces = _setup(ws)
    space = analysis.space
    findings = check_model(space, model, interfaces, analysis.workspace.confinement())
    unknown = {f.name: f for f in findings if f.check is Check.WHEN_UNKNOWN}
    assert set(unknown) == {"debug", "fused"}  # imu: its typed text is decided once typed
    assert unknown["debug"].condition == space.true
    assert "/debug_mode: no launch file sets it and the node gives no default" in (
        unknown["debug"].message
    )
    rate = space.slot(model.inputs["rate"], OTHER)
    assert _same(space, unknown["fused"].condition, rate)  # the typed rate: not known
    assert unknown["fused"].severity is Severity.NOTE


def test_names_resolve_as_the_node_resolves_them(ws: LaunchWorkspace) -> None:
    """``~rate``, ``driver/rate`` (in the node's namespace /robot) and ``/robot/driver/rate``
    are one parameter; ``rate`` is another (/robot/rate), which nobody sets."""
    analysis, model, _file, interfaces = _setup(ws)
    [node] = model.nodes
    [(_condition, launched, interface, _static)] = launched_units(analysis.space, node, interfaces)
    values = ParamValues(analysis.space, [(analysis.space.true, model)])

    def when(text: str) -> BDD:
        return entry_when(values, node, launched, interface, text).condition

    fast = when("param('~rate') > 15")
    assert fast not in (analysis.space.true, analysis.space.false)
    assert when("param('driver/rate') > 15") == fast
    assert when("param('/robot/driver/rate') > 15") == fast
    assert entry_when(values, node, launched, interface, "param('rate') > 15").reasons == (
        "rate: no launch file sets it and the node gives no default",
    )
