"""Overview mode: group summaries instead of the graph, members fetched by page, the feature
tree as a catalog and one character per feature; checked against the whole documents."""

from __future__ import annotations

import json
from collections import Counter
from collections.abc import Iterator
from itertools import product
from typing import TYPE_CHECKING, Any

import pytest

from json_view import read
from outputs.web.live import REPO, Live, running
from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.engine import Configurator
from rosvar.configuration.view import Rendering, View, Views
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.documents.state import state_document
from rosvar.outputs.web.delta import patch
from rosvar.outputs.web.entries import render
from rosvar.outputs.web.overview import (
    LINK,
    PAGE,
    SEPARATOR,
    SIDES,
    Grouping,
    key_of,
    labels,
    namespace_path,
    package_of,
    packages,
    short_path,
    summaries,
)
from rosvar.workspace import discover
from rosvar.workspace.interfaces.extraction import extract_interfaces

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def test_names_as_the_page_reads_them() -> None:
    assert package_of("ws/pkg/launch/sub/a.launch") == "pkg"
    assert package_of("ws/pkg/a.launch") == "pkg"
    assert short_path("ws/pkg/launch/sub/a.launch") == "pkg/sub/a.launch"
    assert short_path("ws/pkg/a.launch") == "pkg/a.launch"
    assert namespace_path("/a/b/c") == ["/a/", "/a/b/"]
    assert namespace_path("/c") == ["/"]
    entry = {"id": "ws/pkg/launch/a.launch|a.launch:3:5#1", "name": "/ns/x"}
    assert labels(Grouping.PACKAGE, entry, {}) == ("pkg", "pkg/a.launch")
    named = {"ws/pkg/launch/a.launch": "named_pkg"}  # its package.xml's name, as the tree's
    assert labels(Grouping.PACKAGE, entry, named) == ("named_pkg", "pkg/a.launch")
    assert labels(Grouping.NAMESPACE, entry, named) == ("/ns/",)
    assert key_of(["pkg", "pkg/a.launch"]) == f"{SEPARATOR}pkg{SEPARATOR}pkg/a.launch"


ROS2_DATA = REPO / "tests" / "data" / "ros2"


def test_ros2_package_groups_are_named_as_the_tree_names_packages() -> None:
    """ros2_control_demos keeps each package in a folder named otherwise (``example_2``
    holds ``ros2_control_demo_example_2``) and its launch files in ``bringup/launch``: the
    boxes are the packages the tree shows, not one ``bringup`` of every example."""
    analysis = Analysis(discover([str(ROS2_DATA / "ros2_control_demos")]))
    document = read(
        state_document(
            Configurator(analysis, extract(analysis, products=True), render=render).state([])
        )
    )
    tops = {g["label"] for g in summaries(document, Grouping.PACKAGE) if g["parent"] == ""}
    tree = {f["package"] for f in document["features"].values() if f["kind"] == "file"}
    assert "ros2_control_demo_example_2" in tops and "bringup" not in tops
    assert tops <= tree


def _pair(live: Live, grouping: str) -> tuple[dict[str, Any], dict[str, Any]]:
    """A session in overview mode and a plain one, both after the same choice."""
    plain, overview = live.open(), live.post("/api/session", {"overview": grouping})
    file = next(k for k, f in plain["features"].items() if f["kind"] == "file")
    for tab in (plain, overview):
        live.post("/api/choose", {"session": tab["session"], "action": "select", "feature": file})
    whole = live.call("GET", f"/api/state?session={plain['session']}").json()
    compact = live.call("GET", f"/api/state?session={overview['session']}").json()
    return whole, compact


@pytest.mark.parametrize("grouping", list(Grouping))
def test_summaries_count_the_whole_graph(examples: Live, grouping: Grouping) -> None:
    whole, compact = _pair(examples, grouping)
    named = packages(whole["features"])
    assert compact["grouping"] == grouping
    groups = {group["id"]: group for group in compact["graph"]["groups"]}
    expected: Counter[tuple[str, str]] = Counter()
    for kind in ("nodes", "tests", "params"):
        for entry in whole["graph"][kind]:
            if entry["presence"] == "absent":
                continue
            path = labels(grouping, entry, named)
            for depth in range(1, len(path) + 1):
                key = key_of(path[:depth])
                counted = "params" if kind == "params" else "nodes"
                expected[(key, counted)] += 1
                expected[(key, counted + " present")] += entry["presence"] == "present"
    found: Counter[tuple[str, str]] = Counter()
    for key, group in groups.items():
        assert group["parent"] == "" or group["parent"] in groups
        for kind in ("nodes", "params"):
            found[(key, kind + " present")], found[(key, kind)] = group[kind]
    assert +found == +expected
    files = {k for k, f in whole["features"].items() if f["state"] == "selected"}
    for key, group in groups.items():
        launched = [
            e
            for kind in ("nodes", "tests")
            for e in whole["graph"][kind]
            if e["presence"] != "absent"
            and e["id"].split("|")[0] in files
            and key_of(labels(grouping, e, named)).startswith(key)
        ]
        assert group["selected"] == len(launched)
    assert any(group["selected"] for group in groups.values())
    present = [e for e in whole["graph"]["errors"] if e["presence"] == "present"]
    assert compact["graph"]["errors"] == present


def test_members_by_page_are_the_groups_entries(examples: Live) -> None:
    whole, compact = _pair(examples, "file")
    session = compact["session"]
    for group in compact["graph"]["groups"]:
        fetched: list[dict[str, Any]] = []
        page, pages = 0, 1
        while page < pages:
            answer = examples.post(
                "/api/group", {"session": session, "group": group["id"], "page": page}
            )
            names = {member["name"] for member in answer["members"]}
            assert len(names) <= PAGE["nodes"]
            fetched += answer["members"]
            pages, page = answer["pages"], page + 1
        own = [
            {**entry, "kind": kind[:-1]}
            for kind in ("nodes", "tests")
            for entry in whole["graph"][kind]
            if entry["presence"] != "absent"
            and key_of(labels(Grouping.FILE, entry, {})) == group["id"]
        ]
        key = json.dumps
        assert sorted(map(key, fetched)) == sorted(map(key, own))
        assert len(own) == group["nodes"][1]
        params = examples.post(
            "/api/group", {"session": session, "group": group["id"], "kind": "params"}
        )
        assert len(params["members"]) == min(PAGE["params"], group["params"][1])
        topics = examples.post(
            "/api/group", {"session": session, "group": group["id"], "kind": "topics"}
        )
        assert len(topics["members"]) == min(PAGE["topics"], group["topics"][1])
        drawn = {e["id"]: key_of(labels(Grouping.FILE, e, {})) for e in whole["graph"]["nodes"]}
        for topic in topics["members"]:
            assert topic["groups"] == [drawn[node] for node in topic["nodes"]]
            assert group["id"] in topic["groups"]


def test_overview_mode_describes_the_conditions_of_what_it_sends_only(
    wired: Live, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Describing the conditions is most of rendering a large workspace's graph (Husky with
    _external: 3.5 of 5.5 s of CPU for the first state), and the summaries show none: an
    overview session renders no state whole, and the entries it sends (members, the ids the
    checks name) are those of the whole state, conditions described."""
    rendered: list[View] = []
    whole_rendering = Views.rendering

    def rendering(self: Views, view: View) -> Rendering:
        rendered.append(view)
        return whole_rendering(self, view)

    monkeypatch.setattr(Views, "rendering", rendering)
    tab = wired.post("/api/session", {"overview": "file"})
    session = tab["session"]
    rows = wired.call("GET", "/api/catalog").json()["features"]
    listen = next(row[0] for row in rows if row[0].endswith("plan.launch"))
    state = wired.post("/api/choose", {"session": session, "action": "select", "feature": listen})
    fetched = []
    for group in state["graph"]["groups"]:
        for kind in ("nodes", "params", "topics", "services", "actions"):
            body = {"session": session, "group": group["id"], "kind": kind}
            fetched += wired.post("/api/group", body)["members"]
    every = [group["id"] for group in state["graph"]["groups"]]
    assert wired.post("/api/links", {"session": session, "groups": every})["links"]
    answer = wired.post("/api/query", {"session": session, "expression": "nodes"})
    assert answer["results"] and rendered == []
    whole = wired.whole(session)
    entries = {e["id"]: e for kind in whole["graph"].values() for e in kind}
    undetermined = [e for e in fetched if e["presence"] == "undetermined"]
    assert undetermined and all(e["condition"] for e in undetermined)
    for entry in fetched:
        extra = {"kind", "groups", "names"}
        assert {k: v for k, v in entry.items() if k not in extra} == entries[entry["id"]]


def test_feature_tree_from_the_catalog_and_the_state_string(
    examples: Live, examples_engine: Configurator
) -> None:
    whole, compact = _pair(examples, "package")
    rows = examples.call("GET", "/api/catalog").json()["features"]
    assert len(compact["features"]) == len(rows) == len(whole["features"])
    codes = {"u": ("unselected", False), "s": ("selected", False), "d": ("deselected", False)}
    codes |= {"S": ("selected", True), "D": ("deselected", True)}
    for number, (
        (key, kind, _file, arg, value, _parent, default, _package, doc),
        code,
    ) in enumerate(zip(rows, compact["features"], strict=True)):
        feature = whole["features"][key]
        row = number
        while rows[row][2] is None:  # a file's row names it and its package
            row = rows[row][5]
        assert (kind, rows[row][2], rows[row][7], arg, value, doc) == tuple(
            feature.get(field) for field in ("kind", "file", "package", "arg", "value", "doc")
        )
        assert codes[code] == (feature["state"], feature["derived"])
        values = examples_engine.catalog.values_of(feature["parent"]) if kind == "value" else []
        assert default == any(entry.id == key and value.default for entry, value in values)


def test_deltas_in_overview_mode_patch_to_the_whole_state(examples: Live) -> None:
    tab = examples.post("/api/session", {"overview": "namespace"})
    rows = examples.call("GET", "/api/catalog").json()["features"]
    held = tab
    for row in [r for r in rows if r[1] == "file"][:3]:
        answer = examples.post(
            "/api/choose",
            {
                "session": tab["session"],
                "version": held["version"],
                "action": "deselect",
                "feature": row[0],
            },
        )
        assert answer["base"] == held["version"]
        held = patch(held, answer)
    answer = examples.post(
        "/api/grouping", {"session": tab["session"], "version": held["version"], "grouping": "file"}
    )
    held = patch(held, answer)
    assert held == examples.call("GET", f"/api/state?session={tab['session']}").json() | {
        "version": held["version"]
    }


@pytest.mark.parametrize(
    ("path", "body"),
    [
        ("/api/session", {"overview": "colour"}),
        ("/api/group", {"group": "", "page": -1}),
        ("/api/group", {"group": "", "kind": "things"}),
        ("/api/group", {"group": "", "page": True}),
        ("/api/grouping", {"grouping": 3}),
        ("/api/links", {"groups": "\u0001pkg"}),
        ("/api/links", {"groups": [3]}),
        ("/api/links", {"groups": ["x" * 5000]}),
        ("/api/links", {}),
    ],
)
def test_bad_overview_requests_are_refused(examples: Live, path: str, body: dict[str, Any]) -> None:
    tab = examples.post("/api/session", {"overview": "package"})
    sent = body if path == "/api/session" else {"session": tab["session"], **body}
    reply = examples.call("POST", path, sent)
    assert reply.status == 400 and "error" in reply.json()


def test_members_need_overview_mode(examples: Live) -> None:
    tab = examples.open()
    reply = examples.call("POST", "/api/group", {"session": tab["session"], "group": ""})
    assert reply.status == 400
    reply = examples.call("POST", "/api/links", {"session": tab["session"], "groups": []})
    assert reply.status == 400


MAX_ANSWER = 2_000_000  # bytes: issue 17


def test_no_answer_over_the_bound_on_husky(husky: Live) -> None:
    """Husky (its dependencies on the package path): the whole state is over the bound,
    every answer in overview mode is under it. Sizes, not times: a slow build (about 30 s)
    but no timing."""
    whole = husky.call("POST", "/api/session", {})
    assert len(whole.body) > MAX_ANSWER
    answers = [husky.call("POST", "/api/session", {"overview": grouping}) for grouping in Grouping]
    tab = answers[0].json()
    answers.append(husky.call("GET", "/api/catalog"))
    biggest = max(tab["graph"]["groups"], key=lambda group: group["nodes"][1] + group["params"][1])
    for kind in ("nodes", "params", "topics"):
        body = {"session": tab["session"], "group": biggest["id"], "kind": kind}
        answers.append(husky.call("POST", "/api/group", body))
    file = next(row[0] for row in answers[3].json()["features"] if row[1] == "file")
    body = {"session": tab["session"], "action": "select", "feature": file}
    answers.append(husky.call("POST", "/api/choose", body))
    assert all(answer.status == 200 for answer in answers)
    assert max(len(answer.body) for answer in answers) < MAX_ANSWER


# -- links between groups --------------------------------------------------------------------------
def wired_workspace(ws: LaunchWorkspace, topics: int) -> None:
    """Three packages whose nodes are wired by ``topics`` topics, a service and an action
    (their scripts' interfaces: publisher and server in ``drivers``, subscribers and clients
    elsewhere, a listener only when ``listen``), and relays of unknown interface remapped
    onto a topic of the talker's and onto one of their own (names without sides)."""
    header = "import rospy\nimport actionlib\nfrom std_msgs.msg import String\n"
    calls = {
        "talker": ("rospy.Publisher", "rospy.Service", "actionlib.SimpleActionServer"),
        "listener": ("rospy.Subscriber", "rospy.ServiceProxy", "actionlib.SimpleActionClient"),
    }
    for script, (topic, service, action) in calls.items():
        lines = [f'{topic}("t{number}", String)' for number in range(topics)]
        lines += [f'{service}("reset", Empty, None)', f'{action}("move", MoveAction)']
        ws.write(f"scripts/{script}.py", header + "\n".join(lines) + "\n", "drivers")
    ws.package("planning")
    ws.package("viz")
    relay = '<node pkg="drivers" type="relay" name="{name}"><remap from="in" to="{to}"/></node>'
    ws.launch(
        "base.launch",
        '<node pkg="drivers" type="talker.py" name="talker" ns="/w"/>\n'
        + relay.format(name="tap", to="/w/t0"),
        "drivers",
    )
    ws.launch(
        "plan.launch",
        '<arg name="listen" default="true"/>\n'
        '<node pkg="drivers" type="listener.py" name="planner" ns="/w" if="$(arg listen)"/>',
        "planning",
    )
    ws.launch("relay.launch", relay.format(name="relay", to="/loose"), "planning")
    ws.launch(
        "view.launch",
        '<node pkg="drivers" type="listener.py" name="viewer" ns="/w"/>\n'
        + relay.format(name="looker", to="/loose"),
        "viz",
    )


@pytest.fixture
def wired(ws: LaunchWorkspace) -> Iterator[Live]:
    """The wired workspace with 3 topics, files named by their paths (packages group)."""
    wired_workspace(ws, 3)
    with running(wired_configurator(ws)) as live:
        yield live


def wired_configurator(ws: LaunchWorkspace) -> Configurator:
    analysis = ws.analysis()
    found = extract_interfaces(analysis.workspace.packages.values())
    return Configurator(analysis, extract(analysis, products=True), interfaces=found, render=render)


def expected_links(whole: dict[str, Any], grouping: Grouping) -> dict[str, list[int]]:
    """Link id → [present, possible] from the whole state, pair of groups by pair of groups:
    names of a kind with a node feeding them under the first and one using them under the
    second (a node without a side does both; names with no side at all: once a pair)."""
    graph = whole["graph"]
    named = packages(whole["features"])
    home = {
        e["id"]: key_of(labels(grouping, e, named))
        for kind in ("nodes", "tests")
        for e in graph[kind]
        if e["presence"] != "absent"
    }
    groups = {key[:at] for key in home.values() for at in range(len(key) + 1)
              if key[at:].startswith(SEPARATOR) or at == len(key)} - {""}  # fmt: skip

    def holds(outer: str, key: str) -> bool:
        return (key + SEPARATOR).startswith(outer + SEPARATOR)

    def under(node: str, group: str) -> bool:
        return node in home and holds(group, home[node])

    found: dict[str, list[int]] = {}
    for kind, sides in SIDES.items():
        for entry in graph.get(kind, []):
            if entry["presence"] == "absent":
                continue
            feeding, using = ({edge["node"] for edge in entry.get(side, [])} for side in sides)
            sideless = set(entry["nodes"]) - feeding - using
            for source, target in product(groups, groups):
                if holds(source, target) or holds(target, source):
                    continue
                if not (feeding or using) and source > target:
                    continue
                if any(under(n, source) for n in feeding | sideless) and any(
                    under(n, target) for n in using | sideless
                ):
                    count = found.setdefault(LINK.join((kind, source, target)), [0, 0])
                    count[0] += entry["presence"] == "present"
                    count[1] += 1
    return found


def linked(live: Live, session: str, groups: list[str]) -> dict[str, list[int]]:
    """Link id → [present, possible] between ``groups``, as the API answers."""
    answer = live.post("/api/links", {"session": session, "groups": groups})
    return {link["id"]: link["count"] for link in answer["links"]}


@pytest.mark.parametrize("grouping", list(Grouping))
def test_links_aggregate_the_whole_states_names_per_pair_of_groups(
    wired: Live, grouping: Grouping
) -> None:
    tab = wired.post("/api/session", {"overview": grouping})
    session = tab["session"]
    states = []
    for feature in (None, "drivers/launch/base.launch"):
        if feature is not None:
            file = next(k for k in wired.whole(session)["features"] if k.endswith(feature))
            wired.post("/api/choose", {"session": session, "action": "select", "feature": file})
        compact = wired.call("GET", f"/api/state?session={session}").json()
        whole = wired.whole(session)
        expected = expected_links(whole, grouping)
        every = [group["id"] for group in compact["graph"]["groups"]]
        assert linked(wired, session, every) == expected
        assert "links" not in compact["graph"]  # asked for apart, for the boxes drawn
        # the boxes of one level: the links between those alone
        top = [key for key in every if key.count(SEPARATOR) == 1]
        assert linked(wired, session, top) == {
            key: count for key, count in expected.items() if set(key.split(LINK)[1:]) <= set(top)
        }
        assert compact["channels"] == {
            kind: sum(e["presence"] != "absent" for e in whole["graph"][kind]) for kind in SIDES
        }
        states.append(expected)
    start, chosen = states
    if grouping != Grouping.NAMESPACE:  # there, the wired nodes are all in /w/
        kinds = {link.split(LINK)[0] for link in start}
        assert kinds == {"topics", "services", "actions"}
        assert any(present for present, _ in chosen.values()) and not any(
            present for present, _ in start.values()
        )
