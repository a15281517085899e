"""A hinted entry's ``when:``: a condition over the args the node's scope sees."""

from __future__ import annotations

from typing import TYPE_CHECKING

from configuration.helpers import choices
from rosvar.analyses.communication import model_edges
from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.when import expression, refusals, when_condition
from rosvar.configuration.engine import Configurator
from rosvar.diagnostics import Location
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.outputs.web.entries import render
from rosvar.workspace.hints import load_hints
from rosvar.workspace.interfaces.model import Entry, Interfaces, Role
from rosvar.workspace.interfaces.overrides import apply_hints

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

HINTS = """\
nodes:
  drv/driver:
    publishes:
      - {name: scan, type: sensor_msgs/LaserScan, when: "$(arg laser)"}
      - {name: odom, type: nav_msgs/Odometry}
      - {name: cloud, type: sensor_msgs/PointCloud2, when: "robot != 'jackal'"}
    services:
      - {name: calibrate, type: std_srvs/Empty, when: "$(eval laser and robot == 'husky')"}
"""
# the driver is included: its file's own `laser` arg comes from the entry file's `use_laser`
LAUNCH = """\
  <arg name="use_laser" default="true"/>
  <arg name="robot" default="husky"/>
  <group if="$(arg use_laser)"/>
  <group if="$(eval robot == 'jackal')"/>
  <include file="$(find pkg)/launch/driver.launch">
    <arg name="laser" value="$(arg use_laser)"/>
    <arg name="robot" value="$(arg robot)"/>
  </include>"""
DRIVER = """\
  <arg name="laser"/>
  <arg name="robot"/>
  <node pkg="drv" type="driver" name="driver"/>"""


def _no_params(name: str) -> Choice[object]:
    raise AssertionError(f"param {name} read")


def _interfaces(ws: LaunchWorkspace) -> Interfaces:
    hints = load_hints(ws.write("hints.yaml", HINTS))
    assert hints.diagnostics == [] and refusals(hints.nodes) == []
    interfaces = Interfaces()
    apply_hints(interfaces, hints.nodes)
    return interfaces


def test_edges_exist_where_their_when_holds(ws: LaunchWorkspace) -> None:
    ws.launch("driver.launch", DRIVER)
    entry = ws.launch("a.launch", LAUNCH)
    analysis = ws.analysis()
    model = analysis.model(entry)
    space = analysis.space
    edges = model_edges(space, model, _interfaces(ws))
    shown = {edge.name: space.describe(edge.condition) for edge in edges}
    assert shown == {
        "/scan": "use_laser",
        "/odom": "true",
        "/cloud": "robot=husky",  # (and other texts than jackal: shown for known values)
        "/calibrate": "robot=husky ∧ use_laser",
    }


def test_the_configure_graph_follows_the_when(ws: LaunchWorkspace) -> None:
    ws.launch("driver.launch", DRIVER)
    ws.launch("a.launch", LAUNCH)
    analysis = ws.analysis()
    model = extract(analysis, products=True)
    spelling = {f.file: f.file.rsplit("/", 1)[-1] for f in model.files}
    engine = Configurator(
        analysis, model, spelling=spelling, interfaces=_interfaces(ws), render=render
    )
    state = engine.state(choices("select a.launch"))
    shown = {t["name"]: (t["presence"], t["condition"]) for t in state.graph.topics}
    assert shown["/scan"] == ("undetermined", "use_laser")
    assert shown["/odom"] == ("present", None)
    off = engine.state(choices("select a.launch", "set a.launch:use_laser=false"))
    assert {t["name"]: t["presence"] for t in off.graph.topics}["/scan"] == "absent"
    [service] = off.graph.services
    assert (service["name"], service["presence"]) == ("/calibrate", "absent")


def test_when_texts_and_refusals() -> None:
    assert expression(" $(arg use_laser) ") == "arg('use_laser')"
    assert expression("$(eval robot == 'husky')") == "robot == 'husky'"
    assert expression("rate > 10") == "rate > 10"
    hints = load_hints(None)
    where = Location("hints.yaml", 4, 1)
    hints.nodes["drv/driver"] = [Entry(Role.PUBLISHES, "scan", where, when="__import__('os')")]
    [diagnostic] = refusals(hints.nodes)
    assert diagnostic.code == "hints-invalid" and diagnostic.location == where


def test_an_undefined_arg_or_a_failing_expression_does_not_hold(ws: LaunchWorkspace) -> None:
    entry = ws.launch("a.launch", '  <arg name="n" default="x"/>\n' + DRIVER.split("\n")[-1])
    analysis = ws.analysis()
    [node] = analysis.model(entry).nodes
    space = analysis.space

    def condition(text: str) -> BDD:
        return when_condition(space, node, text, _no_params).condition

    assert condition("missing") == space.false
    assert space.describe(condition("int(n) > 1")) == "only for other values"
    assert space.describe(condition("n == 'x'")) == "true"  # others: may
