"""The variational graph: variants, topics, and complete products equal to ``rosvar resolve``."""

from __future__ import annotations

import json
import random
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from configuration.helpers import (
    choices,
    configurator,
    random_product,
    run,
    same_as_resolve,
)
from json_view import read
from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.engine import Configurator
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.documents.state import state_document
from rosvar.outputs.web.entries import render
from rosvar.workspace import discover

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

REPO = Path(__file__).resolve().parents[2]
CORPUS = REPO.parent / "shared" / "corpus"


def test_a_node_named_after_an_arg_has_one_variant_per_value(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="robot" default="kobuki"/>\n  <arg name="v" default="husky"/>\n'
        '  <node pkg="p" type="t" name="$(arg robot)"><remap from="in" to="$(arg robot)/in"/>'
        "</node>",
    )
    state = run(configurator(ws), "select a.launch")
    variants = {(n["name"], n["condition"]) for n in state.graph.nodes}
    assert variants == {("/kobuki", "robot=kobuki"), ("/⟨robot⟩", "only for other values")}
    ids = [str(n["id"]) for n in state.graph.nodes]
    assert len(set(ids)) == 2 and all(i.startswith("a.launch|a.launch:") for i in ids)
    [topic] = [t for t in state.graph.topics if t["name"] == "/kobuki/in"]
    assert topic["nodes"] == [ids[0]] and topic["presence"] == "undetermined"
    later = run(configurator(ws), "select a.launch", "set a.launch:robot=r2")
    assert [n["id"] for n in later.graph.nodes] == ids  # stable across steps
    assert {n["name"]: n["presence"] for n in later.graph.nodes} == {
        "/kobuki": "absent",
        "/r2": "present",  # the typed text fills the term
    }


def test_interfaces_wire_nodes_to_their_topics_edge_by_edge(ws: LaunchWorkspace) -> None:
    ws.write(
        "scripts/talker.py",
        'import rospy\nfrom std_msgs.msg import String\nrospy.Publisher("chatter", String)\n',
    )
    ws.launch(
        "a.launch",
        '  <arg name="relay" default="false"/>\n'
        '  <node pkg="pkg" type="talker.py" name="talker">'
        '<remap from="chatter" to="/relayed" if="$(arg relay)"/></node>',
    )
    engine = configurator(ws, interfaces=True)
    state = engine.state(choices("select a.launch"))
    topics = {t["name"]: read(t) for t in state.graph.topics}
    [node] = state.graph.nodes
    [edge] = topics["/chatter"]["publishers"]
    assert edge == {"node": node["id"], "presence": "undetermined", "condition": "¬relay"}
    assert topics["/chatter"]["types"] == ["std_msgs/String"]
    assert topics["/chatter"]["subscribers"] == [] and topics["/chatter"]["nodes"] == [node["id"]]
    relayed = engine.state(choices("select a.launch", "set a.launch:relay=true")).graph.topics
    shown = {t["name"]: (t["presence"], t["publishers"]) for t in relayed}
    assert shown["/chatter"] == ("absent", [])
    assert shown["/relayed"] == ("present", [{"node": node["id"], "presence": "present",
                                              "condition": None}])  # fmt: skip


def test_services_and_actions_have_servers_and_clients_edge_by_edge(ws: LaunchWorkspace) -> None:
    ws.write(
        "scripts/server.py",
        "import rospy\nimport actionlib\nfrom std_srvs.srv import Empty\n"
        'rospy.Service("reset", Empty, None)\n'
        'actionlib.SimpleActionServer("move", MoveAction)\n',
    )
    ws.write(
        "scripts/client.py",
        'import rospy\nfrom std_srvs.srv import Empty\nrospy.ServiceProxy("/ns/reset", Empty)\n',
    )
    ws.launch(
        "a.launch",
        '  <arg name="call" default="true"/>\n'
        '  <node pkg="pkg" type="server.py" name="server" ns="ns"/>\n'
        '  <node pkg="pkg" type="client.py" name="client" if="$(arg call)"/>',
    )
    engine = configurator(ws, interfaces=True)
    state = engine.state(choices("select a.launch"))
    ids = {str(n["name"]): str(n["id"]) for n in state.graph.nodes}
    [service] = read(state.graph.services)
    assert service["name"] == "/ns/reset" and service["types"] == ["std_srvs/Empty"]
    assert service["servers"] == [{"node": ids["/ns/server"], "presence": "present",
                                   "condition": None}]  # fmt: skip
    assert service["clients"] == [{"node": ids["/client"], "presence": "undetermined",
                                   "condition": "call"}]  # fmt: skip
    assert sorted(service["nodes"]) == sorted(ids.values())
    [action] = read(state.graph.actions)
    assert (action["name"], action["servers"][0]["node"], action["clients"]) == (
        "/ns/move", ids["/ns/server"], [],
    )  # fmt: skip
    assert not [t for t in state.graph.topics if t["name"] in ("/ns/reset", "/ns/move")]
    alone = engine.state(choices("select a.launch", "set a.launch:call=false")).graph.services
    assert [(s["presence"], s["clients"], s["nodes"]) for s in alone] == [
        ("present", [], [ids["/ns/server"]])
    ]
    schema = json.loads((REPO / "docs" / "schema" / "configure.schema.json").read_text())
    pytest.importorskip("jsonschema").validate(state_document(state), schema)


def test_conditional_remaps_on_independent_args_are_parts_not_variants(
    ws: LaunchWorkspace,
) -> None:
    """Variants per combination would be 2^24 here (one rtabmap.launch node had 44)."""
    args = "".join(f'  <arg name="c{i}" default="false"/>\n' for i in range(24))
    remaps = "".join(
        f'<remap if="$(arg c{i})" from="in{i}" to="on{i}"/>'
        f'<env unless="$(arg c{i})" name="E{i}" value="off"/>'
        for i in range(24)
    )
    ws.launch("a.launch", f'{args}  <node pkg="p" type="t" name="n">{remaps}</node>')
    engine = configurator(ws)
    state = run(engine, "select a.launch")
    schema = json.loads((REPO / "docs" / "schema" / "configure.schema.json").read_text())
    pytest.importorskip("jsonschema").validate(state_document(state), schema)
    [node] = read(state.graph.nodes)
    assert node["remaps"] == [] and node["env"] == []
    assert {(u["kind"], u["condition"]) for u in node["undetermined"]} == {
        *(("remap", f"c{i}") for i in range(24)),
        *(("env", f"¬c{i}") for i in range(24)),
    }
    [later] = read(run(engine, "select a.launch", "select a.launch:c3=true").graph.nodes)
    assert later["remaps"] == [["in3", "on3"]]
    assert len(later["undetermined"]) == 46 and ["E3", "off"] not in later["env"]
    _same_as_resolve(engine, ws.analysis(), seed=2, products=4, loading=4)


def test_environment_as_given_else_unset(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <node pkg="p" type="t" name="n" if="$(optenv CAM false)"/>\n'
        '  <param name="home" value="$(optenv HOME nowhere)"/>',
    )
    unset = run(configurator(ws), "select a.launch")
    assert unset.graph.nodes == []  # in no product: not listed
    assert [(p["name"], p["value"]) for p in unset.graph.params] == [("/home", "nowhere")]
    given_env = run(configurator(ws, {"CAM": "true", "HOME": "/h"}), "select a.launch")
    assert [n["presence"] for n in given_env.graph.nodes] == ["present"]
    assert [(p["name"], p["value"]) for p in given_env.graph.params] == [("/home", "/h")]


def _same_as_resolve(
    engine: Configurator, analysis: Analysis, seed: int, products: int, loading: int
) -> None:
    """Complete products' graphs against resolve of their command lines; at least
    ``loading`` of them must load (those are compared element by element)."""
    rng = random.Random(seed)
    compared = sum(same_as_resolve(analysis, random_product(engine, rng)) for _ in range(products))
    assert compared >= loading


def test_complete_products_of_the_example_equal_resolve() -> None:
    analysis = Analysis(discover([REPO / "examples"], ros_package_path=""))
    engine = Configurator(analysis, extract(analysis, products=True), render=render)
    _same_as_resolve(engine, analysis, seed=1, products=12, loading=8)


def test_complete_products_of_lizi_equal_resolve() -> None:
    if not (CORPUS / "lizi").is_dir():
        pytest.skip(f"corpus not found at {CORPUS}")
    analysis = Analysis(discover([CORPUS / "lizi"], ros_package_path=str(CORPUS / "_external")))
    engine = Configurator(analysis, extract(analysis, products=True), render=render)
    # most of Lizi's products fail in roslaunch (packages missing from the corpus, a
    # realsense include with unused args): they must fail for the engine too
    _same_as_resolve(engine, analysis, seed=4, products=6, loading=1)
