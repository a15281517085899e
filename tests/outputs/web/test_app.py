"""The single-page app end to end: headless Chromium clicks, the engine answers, the page shows it.

Every scenario checks the page against the server's own state for the page's session (marks,
graph, warnings, command), and against what the launch files mean (an include selects the
included file, a node named after an arg follows the arg's value).
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any
from urllib.parse import urlsplit

import pytest

from configuration.helpers import configurator
from conftest import PACKAGE_XML
from outputs.web.live import Live, running
from outputs.web.test_overview import expected_links, wired_configurator, wired_workspace
from rosvar.configuration.choices import UserChoice
from rosvar.configuration.engine import ConfigurationState
from rosvar.outputs.web import api as api_module
from rosvar.outputs.web.overview import SEPARATOR, Grouping, key_of, labels, packages

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

MARKS = {"selected": ("✓", "(✓)"), "deselected": ("✗", "(✗)"), "unselected": ("·", "·")}
OTHER = "<other>"
MAX_STEPS = 400
FINISH_TIMEOUT_S = 180  # a few dozen engine steps; the machine running the tests may be busy


class App:
    """The page of one tab, driven as a user would: clicks in the tree, text in the inputs."""

    def __init__(self, page: Any, live: Live) -> None:
        self.page = page
        self.live = live
        page.goto(live.url)
        page.wait_for_selector("body[data-step]")  # selectors: the page's CSP forbids eval

    # -- reading -------------------------------------------------------------------------------
    @property
    def state(self) -> dict[str, Any]:
        state: dict[str, Any] = self.page.evaluate("window.rosvar.state")
        return state

    @property
    def features(self) -> dict[str, Any]:
        """The features of the shown state (cheaper to fetch than the whole state)."""
        features: dict[str, Any] = self.page.evaluate("window.rosvar.state.features")
        return features

    @property
    def session(self) -> str:
        return str(self.page.evaluate("sessionStorage.getItem('rosvar.session')"))

    def server_state(self) -> dict[str, Any]:
        """The state the server holds for the page's session, as it sends it (overview mode)."""
        reply = self.live.call("GET", f"/api/state?session={self.session}")
        assert reply.status == 200
        answer: dict[str, Any] = reply.json()
        return answer

    @property
    def whole(self) -> dict[str, Any]:
        """The session's state with every graph entry (the page fetches what it draws)."""
        return self.live.whole(self.session)

    def drawers(self, entries: list[dict[str, Any]]) -> list[str | None]:
        """The unit drawing each node or param: itself, else (not fetched) the "+N more" box
        of its group or the closed box it is in, as the page resolves it."""
        drawing: dict[str, str] = self.page.evaluate("window.rosvar.graph.drawing()")
        units = set(self.page.evaluate("window.rosvar.graph.cy.nodes().map((n) => n.id())"))
        grouping = Grouping(self.page.evaluate("window.rosvar.state.grouping"))
        named = packages(self.whole["features"])
        found: list[str | None] = []
        for entry in entries:
            if entry["id"] in drawing:
                found.append(drawing[entry["id"]])
                continue
            key = key_of(labels(grouping, entry, named))
            boxes = [f"m:{key}"] + [
                "g:" + SEPARATOR.join(key.split(SEPARATOR)[:depth])
                for depth in range(key.count(SEPARATOR) + 1, 1, -1)
            ]
            found.append(next((box for box in boxes if box in units), None))
        return found

    def marks(self) -> dict[str, str]:
        """Feature id → the mark the tree shows."""
        return dict(self.page.evaluate(
            """() => Object.fromEntries([...document.querySelectorAll('.feature')].map(
                 (row) => [row.dataset.id, row.querySelector('.mark').textContent]))"""
        ))  # fmt: skip

    def assert_draws(self, server: dict[str, Any]) -> None:
        """Every element that may be present in the whole state ``server`` is drawn, alone
        or in a box of the overview; an element drawn alone shows its presence and whether
        it is in a conflict."""
        self.wait_for_layout()
        units: dict[str, list[Any]] = self.page.evaluate(
            """() => Object.fromEntries(window.rosvar.graph.cy.nodes().map((n) =>
                 [n.id(), [n.hasClass('undetermined'), n.hasClass('conflict')]]))"""
        )
        clashing = {name for c in server["conflicts"] for name in c["names"]}
        prefix = {"nodes": "n:", "tests": "n:", "topics": "t:"}
        nodes = {e["id"]: e for kind in ("nodes", "tests") for e in server["graph"][kind]}
        linked = self.page.evaluate("window.rosvar.graph.linked()")
        for kind, mark in prefix.items():
            entries = server["graph"].get(kind, [])
            for entry, unit in zip(entries, self.drawers(entries), strict=True):
                if kind == "topics" and linked and unit != mark + entry["id"]:
                    # not fetched: none of its nodes is drawn but in a closed box (links)
                    boxes = self.drawers([nodes[node] for node in entry["nodes"]])
                    assert all(str(box).startswith("g:") for box in boxes), entry["name"]
                    continue
                if entry["presence"] == "absent":
                    alone = unit is not None and unit.startswith(mark)
                    assert not alone, f"absent {entry['name']} is drawn"
                    continue
                assert unit in units, f"{entry['name']} is not drawn"
                if unit == mark + entry["id"]:  # drawn alone
                    undetermined, conflict = units[unit]
                    assert undetermined == (entry["presence"] == "undetermined")
                    if kind != "topics":
                        assert conflict == (f"node {entry['name']}" in clashing)

    def wait_for_layout(self) -> None:
        self.page.wait_for_selector('#graph[data-layout="done"]')

    def units(self, kind: str) -> list[dict[str, Any]]:
        """The drawn units of a kind ("node", "group", "variants", "params", ...)."""
        return list(self.page.evaluate(
            """(kind) => window.rosvar.graph.cy.nodes(`[kind = "${kind}"]`).map((n) =>
                 ({id: n.id(), label: n.data('label'), element: n.data('element'),
                   box: n.renderedBoundingBox({includeLabels: false})}))""", kind
        ))  # fmt: skip

    def graph_labels(self) -> list[str]:
        """The names of the elements drawn one by one (not in a box of the overview)."""
        self.wait_for_layout()
        return list(self.page.evaluate(
            """() => window.rosvar.graph.cy.nodes(':visible')
                 .filter((n) => ['node', 'test', 'topic'].includes(n.data('kind')))
                 .map((n) => n.data('element').name)"""
        ))  # fmt: skip

    def wait_for_visible(self, test: Callable[[str], str], timeout_s: float = 30) -> None:
        """Wait until the number of drawn elements passes ``test`` (the graph redraws
        after the click's event handler returns)."""
        count = "window.rosvar.graph.cy.nodes(':visible').length"
        self.page.wait_for_function(f"() => {test(count)}", timeout=timeout_s * 1000)

    def warned_files(self) -> set[str]:
        return set(self.page.evaluate(
            """() => [...document.querySelectorAll('.file')]
                 .filter((row) => !row.querySelector(':scope > summary .warn').hidden)
                 .map((row) => row.dataset.id)"""
        ))  # fmt: skip

    def click_graph_element(self, element_id: str, double: bool = False) -> None:
        """A real mouse click where the element is drawn on the canvas (once it is drawn:
        centring the view on an element that is gone puts NaN into the pan)."""
        self.wait_for_layout()
        self.page.wait_for_function(
            "(id) => window.rosvar.graph.cy.getElementById(id).length > 0", arg=element_id
        )
        self.page.evaluate(
            "(id) => { window.rosvar.graph.cy.center(window.rosvar.graph.cy.getElementById(id)); }",
            element_id,
        )
        where = self.page.evaluate(
            "(id) => window.rosvar.graph.cy.getElementById(id).renderedPosition()", element_id
        )
        box = self.page.locator("#graph").bounding_box()
        click = self.page.mouse.dblclick if double else self.page.mouse.click
        click(box["x"] + where["x"], box["y"] + where["y"])

    def row(self, feature: str) -> Any:
        return self.page.locator(f'.feature[data-id="{feature}"]').first

    def own_row(self, feature: str) -> Any:
        return self.row(feature).locator(":scope > summary, :scope > .row").first

    # -- acting --------------------------------------------------------------------------------
    def wait_for_update(self, act: Any, timeout_s: float = 30) -> None:
        before = self.page.locator("body").get_attribute("data-step")
        act()
        self.page.wait_for_selector(f'body:not([data-step="{before}"])', timeout=timeout_s * 1000)

    def reveal(self, feature: str) -> None:
        """Unfold the rows above ``feature`` by clicking their names."""
        features = self.features
        chain = []
        parent = features[feature]["parent"]
        while parent is not None:
            chain.append(parent)
            parent = features[parent]["parent"]
        for ancestor in reversed(chain):
            if not self.row(ancestor).evaluate("(row) => row.open"):
                self.own_row(ancestor).locator(".name").click()

    def choose(self, feature: str, action: str) -> None:
        self.reveal(feature)
        button = self.own_row(feature).locator(f'.choose button[data-action="{action}"]')
        self.wait_for_update(button.click)

    def type_other(self, arg: str, text: str) -> None:
        self.reveal(f"{arg}={OTHER}")
        field = self.page.locator(f'input[data-arg="{arg}"]')
        field.fill(text)
        self.wait_for_update(lambda: field.press("Enter"))

    def decide_the_rest(self) -> None:
        """Click until no feature is left: files off, args at a known value (first offered)."""
        for _ in range(MAX_STEPS):
            features = self.features
            left = [k for k, f in features.items() if f["state"] == "unselected"]
            if not left:
                return
            feature = left[0]
            kind = features[feature]["kind"]
            if kind == "file":
                self.choose(feature, "deselect")
                continue
            arg = feature if kind == "arg" else features[feature]["parent"]
            values = [k for k, f in features.items()
                      if f["parent"] == arg and f["state"] == "unselected"]  # fmt: skip
            known = [k for k in values if features[k]["value"] != OTHER]
            if known:
                self.choose(known[0], "select")
            else:
                self.type_other(arg, "typed-by-test")
            if self.page.evaluate("window.rosvar.state.refused.length"):
                self.choose(known[0] if known else f"{arg}={OTHER}", "deselect")
        raise AssertionError(f"not complete after {MAX_STEPS} steps")

    # -- checks --------------------------------------------------------------------------------
    def assert_shows_server_state(self) -> dict[str, Any]:
        """The page shows exactly the state the server holds for its session; returns it
        whole (every graph entry, the features by id)."""
        sent, server = self.server_state(), self.whole
        # the page builds its state from deltas, its features from the catalog; a refusal
        # is in the answer only
        shown = self.state
        assert {**shown, "version": 0, "refused": [], "features": ""} == {
            **sent,
            "version": 0,
            "features": "",
        }
        assert shown["features"] == server["features"]
        expected = {k: MARKS[f["state"]][f["derived"]] for k, f in server["features"].items()}
        assert self.marks() == expected
        self.assert_draws(server)
        assert self.warned_files() == {f for c in server["conflicts"] for f in c["files"]}
        command = self.page.locator("#command").inner_text()
        if server["complete"] and server["command"]:
            assert command == server["command"]
        elif server["complete"] and server["untyped"]:  # says what the command waits for
            assert command.startswith("Type a value of your own for ")
        assert self.page.locator("#features-left").inner_text() == f"{server['unselected']:,}"
        return server


def present_nodes(state: dict[str, Any]) -> int:
    return sum(1 for node in state["graph"]["nodes"] if node["presence"] == "present")


def file_named(state: dict[str, Any], name: str) -> str:
    files = [k for k, f in state["features"].items() if f["kind"] == "file"]
    return str(next(k for k in files if k.endswith(name)))


# -- the bundled example ------------------------------------------------------------------------
def test_page_shows_the_workspace(page: Any, examples: Live) -> None:
    app = App(page, examples)
    server = app.assert_shows_server_state()
    files = [k for k, f in server["features"].items() if f["kind"] == "file"]
    assert page.locator(".file").count() == len(files) == 4
    assert app.graph_labels(), "the graph shows every element that may be present"
    assert page.locator("#copy").is_disabled()
    assert page.locator("#undo").is_disabled()


def test_select_and_deselect_files(page: Any, examples: Live) -> None:
    app = App(page, examples)
    robot = file_named(app.state, "robot.launch")
    control = file_named(app.state, "control.xml")
    app.choose(robot, "select")
    state = app.assert_shows_server_state()
    assert app.marks()[robot] == "✓"
    assert state["features"][control]["state"] == "selected"  # robot.launch includes it
    assert app.marks()[control] == "(✓)"
    app.choose(robot, "select")  # clicking the pressed ✓ again withdraws the choice
    assert app.marks()[robot] == "·"
    with page.expect_response("**/api/choose") as answer:
        app.choose(robot, "deselect")
    assert answer.value.json()["base"] == app.state["version"] - 1  # only what changed
    assert app.marks()[robot] == "✗"
    app.assert_shows_server_state()


def test_values_known_and_typed_change_the_graph(page: Any, examples: Live) -> None:
    app = App(page, examples)
    robot = file_named(app.state, "robot.launch")
    model = f"{robot}:model"
    app.choose(robot, "select")
    assert "/kobuki" in app.graph_labels()  # the driver node is named after model
    app.choose(f"{model}=husky", "select")
    app.assert_shows_server_state()
    assert "/husky" in app.graph_labels() and "/kobuki" not in app.graph_labels()
    assert app.marks()[f"{model}=husky"] == "✓"
    app.type_other(model, "turtle")
    app.assert_shows_server_state()
    assert app.marks()[f"{model}={OTHER}"] == "✓"
    assert page.locator(f'input[data-arg="{model}"]').input_value() == "turtle"
    assert "/husky" not in app.graph_labels()
    app.wait_for_update(lambda: page.click("#undo"))
    assert app.marks()[f"{model}=husky"] == "✓"
    assert "/husky" in app.graph_labels()
    app.wait_for_update(lambda: page.click("#redo"))
    assert app.marks()[f"{model}={OTHER}"] == "✓"
    app.wait_for_update(lambda: page.click("#reset"))
    assert set(app.marks().values()) == {"·"}
    app.assert_shows_server_state()


def test_a_tab_whose_state_the_server_forgot_gets_it_whole(page: Any, examples: Live) -> None:
    app = App(page, examples)
    robot = file_named(app.state, "robot.launch")
    app.server_state()
    app.server_state()  # two other readers: the server no longer holds the page's version
    with page.expect_response("**/api/choose") as answer:
        app.choose(robot, "select")
    assert "base" not in answer.value.json()
    app.assert_shows_server_state()
    assert app.marks()[robot] == "✓"


def test_warnings_follow_the_conflicts(page: Any, examples: Live) -> None:
    app = App(page, examples)
    control = file_named(app.state, "control.xml")
    teleop = file_named(app.state, "teleop_only.launch")
    assert {control, teleop} <= app.warned_files()
    app.own_row(control).locator(".warn").click()
    popup = page.locator("#conflict-popup")
    assert popup.is_visible()
    assert teleop in popup.inner_text() and "/controller" in popup.inner_text()
    page.keyboard.press("Escape")
    assert popup.is_hidden()
    app.choose(teleop, "deselect")
    app.assert_shows_server_state()
    assert control not in app.warned_files()


def test_clicking_a_graph_element_shows_its_details(page: Any, examples: Live) -> None:
    app = App(page, examples)
    (package,) = app.units("group")  # nothing selected: the package is one box
    assert app.units("node") == []
    app.click_graph_element(package["id"], double=True)  # opens it: a box per file
    box = next(u for u in app.units("group") if "robot.launch" in u["label"])
    app.click_graph_element(box["id"], double=True)
    app.wait_for_layout()
    (unit, *_) = app.units("node")
    node = unit["element"]
    app.click_graph_element(unit["id"])
    details = page.locator("#details")
    assert details.is_visible()
    text = details.inner_text()
    assert node["name"] in text and f":{node['line']}" in text and node["presence"] in text
    page.click("#details-close")
    assert details.is_hidden()
    robot = file_named(app.state, "robot.launch")
    app.choose(robot, "select")  # a step does not bring the closed details back
    assert details.is_hidden()
    app.wait_for_layout()
    again = next(u for u in app.units("node") if u["element"]["id"] == node["id"])
    app.click_graph_element(again["id"])
    assert details.is_visible()


def test_graph_navigation(page: Any, examples: Live) -> None:
    app = App(page, examples)
    app.choose(file_named(app.state, "robot.launch"), "select")
    total = len(app.graph_labels())
    page.check("#show-params")
    app.wait_for_layout()
    bundles = app.units("params")
    params = [p for p in app.whole["graph"]["params"] if p["presence"] != "absent"]
    assert bundles and all(app.drawers(params))
    page.fill("#graph-search", "controller")
    matches = page.evaluate("window.rosvar.graph.cy.nodes('.match').map((n) => n.id())")
    named = set(app.drawers([n for n in app.whole["graph"]["nodes"] if "controller" in n["name"]
                             and n["presence"] != "absent"]))  # fmt: skip
    assert matches and set(matches) == named
    page.evaluate("() => { window.rosvar.graph.cy.nodes('.match')[0].select(); }")
    page.click("#focus")
    drawn = page.evaluate("window.rosvar.graph.cy.nodes().length")
    app.wait_for_visible(lambda count: f"{count} < {drawn}")
    page.click("#show-all")
    app.wait_for_visible(lambda count: f"{count} >= {total}")


Answer = tuple[str, dict[str, Any], int]


def record_answers(page: Any) -> list[Answer]:
    """The API answers the page receives from now on: path, request body, size in bytes."""
    answers: list[Answer] = []

    def answered(response: Any) -> None:
        path = urlsplit(response.url).path
        if path.startswith("/api/"):
            body = response.request.post_data_json or {}
            answers.append((path, body, int(response.headers["content-length"])))

    page.on("response", answered)
    return answers


def opened_groups(answers: list[Answer]) -> set[str]:
    """The groups whose nodes the page fetched."""
    return {body["group"] for path, body, _ in answers if path == "/api/group"
            and body["kind"] == "nodes"}  # fmt: skip


def many_elements(ws: LaunchWorkspace, files: int = 24, nodes: int = 30, params: int = 8) -> None:
    """``files`` launch files of ``nodes`` nodes with ``params`` params each."""
    for file in range(files):
        body = "\n".join(
            f'  <node pkg="pkg" type="t" name="n{node}" ns="/f{file}">'
            + "".join(f'<param name="p{param}" value="{param}"/>' for param in range(params))
            + "</node>"
            for node in range(nodes)
        )
        ws.launch(f"f{file:02}.launch", body)


def test_the_pages_answers_stay_small_and_members_come_when_a_group_opens(
    page: Any, ws: LaunchWorkspace
) -> None:
    many_elements(ws)
    with running(configurator(ws)) as live:
        whole = len(live.call("POST", "/api/session", {}).body)
        answers = record_answers(page)
        app = App(page, live)
        app.wait_for_layout()
        assert opened_groups(answers) == set() and app.units("node") == []
        (package,) = app.units("group")
        app.click_graph_element(package["id"], double=True)  # a box per file, no member
        app.wait_for_layout()
        assert opened_groups(answers) == set() and len(app.units("group")) == 24
        box = next(u for u in app.units("group") if "f03.launch" in u["label"])
        del answers[:]
        app.click_graph_element(box["id"], double=True)
        app.wait_for_layout()
        assert opened_groups(answers) == {box["element"]["key"]}
        names = sorted(f"/f3/n{node}" for node in range(30))
        assert sorted(u["element"]["name"] for u in app.units("node")) == names[:24]  # a page
        assert [u["label"] for u in app.units("more")] == ["+6 more"]
        del answers[:]
        app.choose(file_named(app.state, "f05.launch"), "select")  # opens its group
        app.wait_for_layout()
        chosen = next(key for key in opened_groups(answers) if "f05" in key)
        assert opened_groups(answers) == {box["element"]["key"], chosen}  # fetched again
        page.check("#show-params")
        app.wait_for_layout()
        app.assert_shows_server_state()
    sizes = [size for _, _, size in answers]
    assert len(sizes) > 5 and max(sizes) < whole / 50


def fetched_groups(answers: list[Answer]) -> set[str]:
    """The groups whose members (of any kind) the page fetched."""
    return {body["group"] for path, body, _ in answers if path == "/api/group"}


def drawn_links(app: App) -> dict[tuple[str, str], dict[str, list[int]]]:
    """(source unit, target unit) → the counts per kind of the link edge drawn between them."""
    edges = app.page.evaluate(
        """() => window.rosvar.graph.cy.edges('[kind = "link"]').map((e) =>
             [e.source().id(), e.target().id(), e.data('element').counts])"""
    )
    return {(source, target): counts for source, target, counts in edges}


def test_many_topics_link_closed_boxes_and_only_open_groups_fetch_theirs(
    page: Any, ws: LaunchWorkspace
) -> None:
    """Above the page's bound on topics, services and actions drawn one by one, closed boxes
    are joined by the state's links and a step fetches only the open groups' members."""
    wired_workspace(ws, topics=260)
    with running(wired_configurator(ws)) as live:
        answers = record_answers(page)
        app = App(page, live)
        app.wait_for_layout()
        assert page.evaluate("window.rosvar.graph.linked()")
        assert fetched_groups(answers) == set()  # nothing open

        def expected() -> dict[tuple[str, str], dict[str, list[int]]]:
            """The whole state's names between the closed boxes drawn, pair by pair."""
            units = {u["id"] for u in app.units("group")}
            found: dict[tuple[str, str], dict[str, list[int]]] = {}
            grouping = Grouping(app.state["grouping"])
            for link, count in expected_links(app.whole, grouping).items():
                kind, source, target = link.split("\u0002")
                if f"g:{source}" in units and f"g:{target}" in units:
                    found.setdefault((f"g:{source}", f"g:{target}"), {})[kind] = count
            return found

        start = drawn_links(app)
        assert start == expected() and len(start) >= 2
        assert app.units("topic") == []
        channels = app.state["channels"]
        counts = page.locator("#graph-counts").inner_text()
        assert f"{channels['topics']} topics" in counts
        app.assert_shows_server_state()
        # a choice opens the selected file's group: its members alone are fetched, its
        # topics drawn one by one, the other boxes still linked
        del answers[:]
        app.choose(file_named(app.state, "drivers/launch/base.launch"), "select")
        app.wait_for_layout()
        groups = {g["id"]: g for g in app.state["graph"]["groups"]}
        (base,) = fetched_groups(answers)
        assert base.endswith("drivers/base.launch")
        kinds = {body.get("kind") for path, body, _ in answers if path == "/api/group"}
        assert kinds == {"nodes", "topics", "services", "actions"}
        [boxes] = [body["groups"] for path, body, _ in answers if path == "/api/links"]
        assert sorted(boxes) == sorted(u["element"]["key"] for u in app.units("group"))
        assert len(app.units("topic")) == groups[base]["topics"][1] > 250
        assert drawn_links(app) == expected() != {}
        app.assert_shows_server_state()
        # opening a box fetches that group's alone
        del answers[:]
        (view,) = [u for u in app.units("group") if "view.launch" in u["label"]]
        app.click_graph_element(view["id"], double=True)
        app.wait_for_layout()
        assert fetched_groups(answers) == {view["element"]["key"]}
        assert drawn_links(app) == expected()
        app.assert_shows_server_state()


LABELLED_LINKS = """() => window.rosvar.graph.cy.edges('[kind = "link"]')
  .filter((edge) => edge.style('text-opacity') !== '0').map((edge) => edge.id())"""


def test_crowded_links_are_labelled_for_the_selected_box_only(
    page: Any, ws: LaunchWorkspace
) -> None:
    """Two dozen boxes joined by links: every link's label over the others hid the boxes'
    names (Husky with its dependencies); they are drawn for the selected box's links alone."""
    chained_workspace(ws, packages=24, topics=11)  # 264 topics: linked; 23 links
    with running(wired_configurator(ws)) as live:
        app = App(page, live)
        app.wait_for_layout()
        assert len(drawn_links(app)) == 23
        assert page.evaluate(LABELLED_LINKS) == []
        (box,) = [u for u in app.units("group") if "p05" in u["label"]]
        app.click_graph_element(box["id"])
        page.wait_for_function("() => window.rosvar.graph.cy.$(':selected').length > 0")
        labelled = page.evaluate(LABELLED_LINKS)
        assert len(labelled) == 2 and all("p05" in link for link in labelled), labelled


def test_complete_product_gives_the_command(page: Any, examples: Live) -> None:
    app = App(page, examples)
    robot = file_named(app.state, "robot.launch")
    app.choose(robot, "select")
    app.choose(f"{robot}:model=husky", "select")
    app.decide_the_rest()
    server = app.assert_shows_server_state()
    assert server["complete"] and server["unselected"] == 0
    command = page.locator("#command").inner_text()
    assert command.startswith("roslaunch ") and "robot.launch" in command
    assert "model:=husky" in command  # not the default, so named
    assert page.locator("#completeness").inner_text() == "complete"
    page.click("#copy")
    page.locator("#copy", has_text="Copied ✓").wait_for(timeout=10_000)  # the clipboard is async


def test_what_stops_the_product_stays_in_view_until_it_is_gone(
    page: Any, ws: LaunchWorkspace
) -> None:
    """issue 30: on a bringup rosvar could not read, Finish showed "0 nodes" with Copy
    enabled, and the notice of what it could not read was gone at the next click; a
    product whose command roslaunch refuses was offered for copying."""
    ws.launch("unread.launch", '  <param name="p" value="$(find nopkg)/p.yaml"/>')
    ws.launch(
        "t.launch",
        '  <arg name="rate" default="5"/>\n  <arg name="fast" default="false"/>\n'
        '  <param name="rate" type="int" value="$(arg rate)" if="$(arg fast)"/>',
    )
    with running(configurator(ws)) as live:
        app = App(page, live)
        status = page.locator("#command-status")
        assert status.is_hidden()
        app.choose("unread.launch", "select")
        assert "rosvar could not read all of the selected files" in status.inner_text()
        assert "nopkg" in status.inner_text()
        app.wait_for_update(lambda: page.click("#finish"))  # another click: still said
        assert app.state["complete"] and app.state["launches"] is None
        assert status.is_visible() and "could not read" in status.inner_text()
        assert page.locator("#copy").is_enabled()  # the command is right; what it loads unknown
        app.wait_for_update(lambda: page.click("#undo"))
        assert status.is_visible() and "could not read" in status.inner_text()
        app.wait_for_update(lambda: page.click("#reset"))
        assert status.is_hidden()
        app.type_other("t.launch:rate", "abc")  # accepted: the param is in some products only
        app.choose("t.launch:fast=true", "select")
        app.wait_for_update(lambda: page.click("#finish"))
        assert app.state["launches"] is False
        assert "This product does not launch: roslaunch would stop at" in status.inner_text()
        assert "invalid literal for int()" in status.inner_text()
        assert page.locator("#copy").is_disabled()
        assert page.locator("#command.fails").inner_text().startswith("roslaunch pkg t.launch")


SLOW_S = 4.0
ROS2_EXPORT = "<export><build_type>ament_cmake</build_type></export>\n  "


def test_a_slow_choice_of_one_client_keeps_no_other_waiting(
    page: Any, browser: Any, ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    """issue 30.5: two clicks that took minutes froze every client. Here one client's choice
    takes ``SLOW_S`` in the engine: meanwhile another client's page loads at once (its files
    and the catalog need no engine), waits for its own steps no longer than the engine is
    busy (with a budget shorter than that, it is told to wait and tries again), and both
    pages end showing their own sessions' states."""
    ws.launch("slow.launch", '  <node pkg="pkg" type="t" name="slow"/>')
    ws.launch("quick.launch", '  <node pkg="pkg" type="t" name="quick"/>')
    engine = configurator(ws)
    original = engine.state

    slowed = False

    def state(choices: Sequence[UserChoice]) -> ConfigurationState:
        nonlocal slowed
        if any(c.feature == "slow.launch" for c in choices) and not slowed:
            slowed = True  # the first time only: a cold step of a large workspace
            time.sleep(SLOW_S)
        return original(choices)

    monkeypatch.setattr(engine, "state", state)
    monkeypatch.setattr(api_module, "ENGINE_WAIT", 1.0)
    with running(engine) as live:
        first = App(page, live)
        other = browser.new_context(viewport={"width": 1400, "height": 850}).new_page()
        first.reveal("slow.launch")
        button = first.own_row("slow.launch").locator('.choose button[data-action="select"]')
        arrived: dict[str, float] = {}
        other.on("response", lambda r: arrived.setdefault(urlsplit(r.url).path, time.monotonic()))
        started = time.monotonic()
        button.click()  # answered in SLOW_S: not waited for here
        second = App(other, live)  # the page, the catalog, then a session once the engine is free
        assert arrived["/api/catalog"] - started < SLOW_S  # no engine needed: not kept waiting
        assert arrived["/assets/js/app.js"] - started < SLOW_S
        assert "Waiting for the server" in other.locator("#message").inner_text()
        second.choose("quick.launch", "select")
        answered = time.monotonic() - started
        first.page.wait_for_function(
            "() => window.rosvar.state.features['slow.launch'].state === 'selected'"
        )
        assert answered < SLOW_S + 5  # its own steps waited for the engine, no longer
        assert first.state["features"]["quick.launch"]["state"] == "unselected"
        assert second.state["features"]["slow.launch"]["state"] == "unselected"
        assert second.state["features"]["quick.launch"]["state"] == "selected"
        first.assert_shows_server_state()
        second.assert_shows_server_state()


def test_tabs_keep_their_own_sessions(page: Any, examples: Live) -> None:
    first = App(page, examples)
    robot = file_named(first.state, "robot.launch")
    first.choose(robot, "select")
    other_tab = App(page.context.new_page(), examples)
    assert other_tab.session != first.session
    assert other_tab.marks()[robot] == "·"
    # a duplicated tab starts with a copy of sessionStorage: it must not take over the session
    copy = page.context.new_page()
    copy.add_init_script(f"sessionStorage.setItem('rosvar.session', {json.dumps(first.session)})")
    duplicate = App(copy, examples)
    assert duplicate.session != first.session
    assert duplicate.marks()[robot] == "·"
    session = first.session
    page.reload()  # a reload keeps the tab's session
    page.wait_for_selector("body[data-step]")
    assert first.session == session and first.marks()[robot] == "✓"


# -- Lizi ------------------------------------------------------------------------------------------
def test_lizi_configured_to_a_complete_product(page: Any, lizi: Live) -> None:
    app = App(page, lizi)
    start = app.assert_shows_server_state()
    robot = file_named(start, "lizi/launch/lizi.launch")
    joints = file_named(start, "joints_test.launch")
    assert {robot, joints} <= app.warned_files()  # both declare /robot_state_publisher
    app.choose(robot, "select")
    chosen = app.assert_shows_server_state()
    assert present_nodes(chosen) > present_nodes(start)  # the selected file's own nodes
    app.choose(joints, "deselect")
    app.assert_shows_server_state()
    assert robot not in app.warned_files() and app.marks()[joints] == "✗"
    app.choose(f"{robot}:gazebo=true", "select")
    app.type_other(f"{robot}:x", "1.5")
    typed = app.assert_shows_server_state()
    assert app.marks()[f"{robot}:x={OTHER}"] == "✓"
    app.wait_for_update(lambda: page.click("#undo"))
    assert app.marks()[f"{robot}:x={OTHER}"] == "·"
    app.wait_for_update(lambda: page.click("#redo"))
    assert app.assert_shows_server_state()["features"] == typed["features"]
    app.wait_for_update(lambda: page.click("#finish"), FINISH_TIMEOUT_S)
    server = app.assert_shows_server_state()
    assert server["complete"]
    command = page.locator("#command").inner_text()
    assert command.startswith("roslaunch ") and "lizi.launch" in command
    assert "gazebo:=true" in command and "x:=1.5" in command  # given, not defaults


# -- Husky -----------------------------------------------------------------------------------------
def test_husky_clicks_update_the_page_in_place(page: Any, husky: Live) -> None:
    app = App(page, husky)
    start = app.state
    value = next(k for k, f in start["features"].items() if f["kind"] == "value"
                 and f["state"] == "unselected" and not f["value"].startswith("<"))  # fmt: skip
    whole = len(app.live.call("GET", f"/api/state?session={app.session}").body)
    with page.expect_response("**/api/choose") as answer:
        app.choose(value, "select")
    assert len(answer.value.body()) < whole / 10  # a delta, not the state
    assert app.assert_shows_server_state()["features"][value]["state"] == "selected"
    app.wait_for_update(lambda: page.click("#undo"))
    assert app.marks()[value] == "·"


MAX_DRAWN = 150  # units a readable drawing holds; Husky has 985 nodes and 7,500 params
LEGIBLE_ZOOM = 0.6  # 12 px labels at 7 px or more
READABLE_ZOOM = 0.35  # a whole drawing of a hundred units: labels at 4 px, shapes and links clear


def husky_file(app: App, name: str) -> str:
    return file_named(app.state, f"husky_gazebo/launch/{name}")


def drawn(app: App) -> int:
    app.wait_for_layout()
    return int(app.page.evaluate("window.rosvar.graph.cy.nodes().length"))


def overlapping(app: App) -> list[tuple[str, str]]:
    """Pairs of drawn units whose shapes overlap (a layout that left things on each other)."""
    boxes = [
        u for kind in ("node", "group", "variants", "topic", "params") for u in app.units(kind)
    ]
    pairs = []
    for i, a in enumerate(boxes):
        for b in boxes[i + 1 :]:
            p, q = a["box"], b["box"]
            if p["x1"] < q["x2"] and q["x1"] < p["x2"] and p["y1"] < q["y2"] and q["y1"] < p["y2"]:
                pairs.append((a["id"], b["id"]))
    return pairs


def beyond_the_canvas(app: App) -> dict[str, float]:
    """How far (px) the drawn elements' bounding box, labels included, reaches past each side
    of the canvas once the view stopped moving: empty when the whole drawing is in view."""
    app.wait_for_layout()
    app.page.wait_for_function("() => !window.rosvar.graph.cy.animated()")
    box: dict[str, float] = app.page.evaluate(
        """() => { const cy = window.rosvar.graph.cy;
                   const b = cy.elements(':visible').renderedBoundingBox();
                   return {left: -b.x1, top: -b.y1,
                           right: b.x2 - cy.width(), bottom: b.y2 - cy.height()}; }"""
    )  # fmt: skip
    return {side: reach for side, reach in box.items() if reach > 0.5}


def zoom(app: App) -> float:
    return float(app.page.evaluate("window.rosvar.graph.cy.zoom()"))


def unselected_with_nodes(server: dict[str, Any]) -> str:
    """A file still open that loads nodes not absent: deselecting it takes units away (one
    that a selected file's conflicts deselected already would change nothing)."""
    return next(
        str(feature)
        for feature, state in server["features"].items()
        if state["kind"] == "file"
        and state["state"] == "unselected"
        and any(
            n["id"].startswith(f"{feature}|") and n["presence"] != "absent"
            for n in server["graph"]["nodes"]
        )
    )


def test_husky_the_whole_drawing_is_in_view_until_the_user_moves_it(page: Any, husky: Live) -> None:
    """The first view, Fit and the view after each choice show the whole drawn graph; once
    the user zoomed, a choice leaves the view alone until the next Fit."""
    page.set_viewport_size({"width": 1600, "height": 1000})
    app = App(page, husky)
    assert beyond_the_canvas(app) == {} and zoom(app) >= LEGIBLE_ZOOM
    page.click("#fit")
    assert beyond_the_canvas(app) == {}
    app.choose(husky_file(app, "husky_playpen.launch"), "select")
    assert app.units("node")  # its nodes drawn one by one, with their topics
    assert beyond_the_canvas(app) == {} and zoom(app) >= READABLE_ZOOM
    page.click("#fit")
    assert beyond_the_canvas(app) == {}
    canvas = page.locator("#graph").bounding_box()
    page.mouse.move(canvas["x"] + canvas["width"] / 2, canvas["y"] + canvas["height"] / 2)
    for _ in range(5):
        page.mouse.wheel(0, -400)  # the user zooms in
    page.wait_for_function("() => !window.rosvar.graph.cy.animated()")
    zoomed = zoom(app)
    assert beyond_the_canvas(app) != {}
    runs = page.evaluate("window.rosvar.graph.layoutRuns")
    app.choose(unselected_with_nodes(app.assert_shows_server_state()), "deselect")
    assert page.evaluate("window.rosvar.graph.layoutRuns") > runs  # units went: placed again
    assert zoom(app) == zoomed  # the view stays where the user put it
    page.click("#fit")
    assert beyond_the_canvas(app) == {}
    app.choose(husky_file(app, "husky_playpen.launch"), "select")  # withdrawn: fewer units
    assert beyond_the_canvas(app) == {}


def test_husky_overview_aggregates_and_opens_the_selected_files(page: Any, husky: Live) -> None:
    app = App(page, husky)
    app.assert_shows_server_state()
    assert drawn(app) <= MAX_DRAWN < len(app.whole["graph"]["nodes"])
    assert page.evaluate("window.rosvar.graph.cy.zoom()") >= LEGIBLE_ZOOM
    assert overlapping(app) == []
    assert app.units("node") == []  # nothing selected: every node is in a box
    playpen = husky_file(app, "husky_playpen.launch")
    runs = page.evaluate("window.rosvar.graph.layoutRuns")
    app.choose(playpen, "select")
    server = app.assert_shows_server_state()
    own = [n for n in server["graph"]["nodes"] if n["id"].startswith(f"{playpen}|")
           and n["presence"] != "absent"]  # fmt: skip
    alone = {u["element"]["id"] for u in app.units("node")}
    assert own and {n["id"] for n in own} <= alone  # the selected file's nodes, one by one
    assert page.evaluate("window.rosvar.graph.layoutRuns") > runs  # placed again
    assert overlapping(app) == []
    assert beyond_the_canvas(app) == {} and zoom(app) >= READABLE_ZOOM
    # elements going away: the layout runs again (no holes) and the page still shows all
    # (husky_empty_world.launch, which loads husky_playpen's nodes too, is out already)
    assert server["features"][husky_file(app, "husky_empty_world.launch")]["state"] == "deselected"
    runs = page.evaluate("window.rosvar.graph.layoutRuns")
    app.choose(unselected_with_nodes(server), "deselect")
    app.assert_shows_server_state()
    assert page.evaluate("window.rosvar.graph.layoutRuns") > runs
    assert overlapping(app) == []


def test_husky_groups_open_close_and_page(page: Any, husky: Live) -> None:
    app = App(page, husky)
    gazebo = next(u for u in app.units("group") if "husky_gazebo" in u["label"])
    app.click_graph_element(gazebo["id"], double=True)
    app.assert_shows_server_state()
    assert drawn(app) <= MAX_DRAWN
    spawn = next(u for u in app.units("group") if "spawn_husky.launch" in u["label"])
    app.click_graph_element(spawn["id"], double=True)
    app.assert_shows_server_state()
    assert drawn(app) <= MAX_DRAWN
    variants = next(u for u in app.units("variants") if "spawn_husky_model" in u["label"])
    app.click_graph_element(variants["id"])
    assert "they differ in" in page.locator("#details").inner_text()
    page.locator("#details button", has_text="Show each variant").click()
    app.wait_for_layout()
    twins = [u for u in app.units("node") if u["element"]["name"] == variants["element"]["name"]]
    more = app.units("more")
    assert len(twins) > 1 and drawn(app) <= MAX_DRAWN + len(twins)
    labels = [u["label"] for u in twins]
    assert len(set(labels)) == len(labels), "variants of one name are told apart"
    if more:  # a page of the group at a time
        before = drawn(app)
        app.click_graph_element(more[0]["id"], double=True)
        assert drawn(app) > before
    page.click("#overview")
    app.wait_for_layout()
    assert app.units("node") == [] and drawn(app) <= MAX_DRAWN


def test_husky_params_and_namespaces_stay_bounded(page: Any, husky: Live) -> None:
    app = App(page, husky)
    app.choose(husky_file(app, "husky_playpen.launch"), "select")
    page.check("#show-params")
    app.wait_for_layout()
    params = [p for p in app.whole["graph"]["params"] if p["presence"] != "absent"]
    bundles = app.units("params")
    assert len(params) > MAX_DRAWN and all(app.drawers(params))
    assert drawn(app) <= MAX_DRAWN
    assert any("params" in u["label"] for u in app.units("group"))  # counted on closed boxes
    largest = max(bundles, key=lambda b: len(b["element"]["params"]))
    app.click_graph_element(largest["id"])
    rows = page.locator("#details tr")
    assert rows.count() == min(50, len(largest["element"]["params"]))
    if len(largest["element"]["params"]) > 50:
        page.locator("#details button", has_text="more").click()
        assert rows.count() > 50
    app.wait_for_update(lambda: page.select_option("#group-by", "namespace"))
    app.assert_shows_server_state()
    assert drawn(app) <= MAX_DRAWN
    size = page.evaluate(
        "(() => { const b = window.rosvar.graph.cy.elements().boundingBox();"
        " return Math.max(b.w, b.h); })()"
    )
    assert size < 10_000  # model px: the drawing stays a few screens wide at most
    assert overlapping(app) == []


def test_husky_counts_defaults_and_refusals_read_well(page: Any, husky: Live) -> None:
    app = App(page, husky)
    server = app.server_state()
    shown = page.locator("#configurations")
    exact = str(server["configurations"])
    assert len(exact) > 20 and shown.inner_text().startswith("≈ ")
    assert "× 10" in shown.inner_text() and len(shown.inner_text()) < 16
    assert shown.get_attribute("title").replace(",", "").find(exact) >= 0
    # defaults: badged; an unevaluated default reads whole, without the <default: ...> wrapper
    rows = app.live.call("GET", "/api/catalog").json()["features"]
    port = next(row[0] for row in rows if row[0].endswith("base.launch:port"))
    default = next(row[0] for row in rows if row[6] and rows[row[5]][0] == port)
    app.reveal(default)
    value = app.own_row(default)
    assert value.locator(".default-badge").is_visible()
    text = value.locator(".name").inner_text()
    assert text == "$(optenv HUSKY_PORT /dev/prolific)"
    assert value.locator(".name").evaluate("(e) => e.scrollWidth <= e.clientWidth + 1")
    assert "default: $(optenv HUSKY_PORT /dev/prolific)" in app.own_row(port).inner_text()
    # a refusal: a readable, bounded notice that pushes nothing down, closed with its ×
    um6 = file_named(app.state, "um6_config/um6.launch")
    um7 = file_named(app.state, "um7_config/um7.launch")
    app.choose(um6, "select")
    top = page.locator("main").bounding_box()["y"]
    app.choose(um7, "select")
    notice = page.locator("#notice")
    assert notice.is_visible()
    text = notice.inner_text()
    assert text.startswith("Not applied: select husky_bringup/um7_config/um7.launch")
    assert "husky_bringup/um6_config/um6.launch" in text and "../" not in text
    assert page.locator("main").bounding_box()["y"] == top
    assert notice.bounding_box()["height"] <= 0.4 * 900
    page.click("#notice-close")
    assert notice.is_hidden()


MAX_ANSWER = 2_000_000  # bytes: issue 17


def test_husky_the_page_is_sent_no_answer_over_2_mb(page: Any, husky: Live) -> None:
    """Husky with its dependencies (``rosvar serve husky --deps _external``): its whole
    state is over the bound, no answer the page receives is."""
    assert len(husky.call("POST", "/api/session", {}).body) > MAX_ANSWER
    answers = record_answers(page)
    app = App(page, husky)
    app.choose(husky_file(app, "husky_playpen.launch"), "select")
    gazebo = next(u for u in app.units("group") if "husky_bringup" in u["label"])
    app.click_graph_element(gazebo["id"], double=True)
    page.check("#show-params")
    app.wait_for_layout()
    app.wait_for_update(lambda: page.select_option("#group-by", "namespace"))
    app.wait_for_layout()
    app.assert_shows_server_state()
    paths = {path for path, _, _ in answers}
    assert {"/api/catalog", "/api/session", "/api/choose", "/api/grouping", "/api/group"} <= paths
    assert max(size for _, _, size in answers) < MAX_ANSWER


def test_husky_double_click_is_one_choice(page: Any, husky: Live) -> None:
    app = App(page, husky)
    base = file_named(app.state, "husky_base/launch/base.launch")
    button = app.own_row(base).locator('.choose button[data-action="select"]')
    app.wait_for_update(button.dblclick)
    page.wait_for_function("() => !document.body.classList.contains('busy')")
    server = app.assert_shows_server_state()
    assert server["choices"] == [{"action": "select", "feature": base, "value": None}]


def chained_workspace(ws: LaunchWorkspace, packages: int, topics: int) -> None:
    """``packages`` packages in a chain: each one's node publishes ``topics`` topics the next
    package's node subscribes to (links p0 → p1 → …, each box joined to its neighbours)."""
    for index in range(packages):
        name = f"p{index:02d}"
        lines = ["import rospy", "from std_msgs.msg import String"]
        lines += [f'rospy.Publisher("c{index}_{n}", String)' for n in range(topics)]
        lines += [f'rospy.Subscriber("c{index - 1}_{n}", String)' for n in range(topics) if index]
        ws.write("scripts/node.py", "\n".join(lines) + "\n", name)
        ws.launch("run.launch", f'<node pkg="{name}" type="node.py" name="n{index}"/>', name)


def test_linked_boxes_are_all_in_view(page: Any, ws: LaunchWorkspace) -> None:
    """Links do not place the boxes they join: a chain of a dozen packages, laid out along its
    links, would run over several screens; every box is in view."""
    chained_workspace(ws, packages=12, topics=25)
    with running(wired_configurator(ws)) as live:
        app = App(page, live)
        app.wait_for_layout()
        assert page.evaluate("window.rosvar.graph.linked()")
        assert len(drawn_links(app)) == 11
        outside = page.evaluate(
            """() => {
                 const cy = window.rosvar.graph.cy;
                 const out = (b) => b.x1 < 0 || b.y1 < 0 || b.x2 > cy.width() || b.y2 > cy.height();
                 return cy.nodes('[kind = "group"]').filter((n) => out(n.renderedBoundingBox()))
                   .map((n) => n.id());
               }"""
        )
        assert len(app.units("group")) == 12 and outside == []


def test_a_notice_above_the_canvas_keeps_the_drawing_in_view(
    page: Any, ws: LaunchWorkspace
) -> None:
    """The notice of what rosvar could not read takes room above the canvas: the view is
    fitted to the smaller canvas, and to the larger one when the notice goes (the ROS 2
    Husky's accessories.launch.py ran 19 px past the bottom, the legend over it)."""
    wired_workspace(ws, topics=30)  # a column of topics: the fit is bound by the height
    ws.launch("unread.launch", '  <param name="p" value="$(find nopkg)/p.yaml"/>')
    with running(wired_configurator(ws)) as live:
        page.set_viewport_size({"width": 1600, "height": 1000})
        app = App(page, live)
        assert beyond_the_canvas(app) == {}
        height = page.evaluate("window.rosvar.graph.cy.height()")
        app.choose(file_named(app.state, "unread.launch"), "select")
        assert page.locator("#command-status").is_visible()
        page.wait_for_function(f"() => window.rosvar.graph.cy.height() < {height}")
        assert beyond_the_canvas(app) == {}
        app.wait_for_update(lambda: page.click("#reset"))
        assert page.locator("#command-status").is_hidden()
        page.wait_for_function(f"() => window.rosvar.graph.cy.height() === {height}")
        assert beyond_the_canvas(app) == {}


def test_a_ros2_product_that_does_not_launch_names_ros2_launch(
    page: Any, ws: LaunchWorkspace
) -> None:
    """The issue 28 audit: a ROS 2 product said roslaunch would stop."""
    ros2 = PACKAGE_XML.format(name="pkg").replace("<license>", ROS2_EXPORT + "<license>")
    ws.write("package.xml", ros2)
    ws.write(
        "launch/t.launch.xml",
        '<launch><arg name="fast" default="false"/>\n'
        '  <node pkg="pkg" exec="e" name="n" namespace="/$(eval \'1/0\')" if="$(var fast)"/>\n'
        "</launch>\n",
    )
    with running(configurator(ws)) as live:
        app = App(page, live)
        app.choose("t.launch.xml:fast=true", "select")  # the one file's one arg: complete
        assert app.state["complete"] and app.state["launches"] is False
        status = page.locator("#command-status").inner_text()
        assert "This product does not launch: ros2 launch would stop at" in status
        assert "ZeroDivisionError" in status
        assert page.locator("#command.fails").inner_text().startswith("ros2 launch pkg ")
