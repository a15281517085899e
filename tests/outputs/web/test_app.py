"""The single-page app end to end: headless Chromium clicks, the engine answers, the page shows it.

Every scenario checks the page against the server's own state for the page's session (marks,
graph, warnings, command), and against what the launch files mean (an include selects the
included file, a node named after an arg follows the arg's value).
"""

from __future__ import annotations

import json
from collections.abc import Callable
from typing import Any

from outputs.web.live import Live

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
        reply = self.live.call("GET", f"/api/state?session={self.session}")
        assert reply.status == 200
        answer: dict[str, Any] = reply.json()
        return answer

    def marks(self) -> dict[str, str]:
        """Feature id → the mark the tree shows."""
        return dict(self.page.evaluate(
            """() => Object.fromEntries([...document.querySelectorAll('.feature')].map(
                 (row) => [row.dataset.id, row.querySelector('.mark').textContent]))"""
        ))  # fmt: skip

    def graph_labels(self) -> list[str]:
        return list(self.page.evaluate(
            """() => window.rosvar.graph.cy.nodes(':visible')
                 .filter((n) => n.data('kind') !== 'namespace').map((n) => n.data('label'))"""
        ))  # fmt: skip

    def wait_for_visible(self, test: Callable[[str], str], timeout_s: float = 30) -> None:
        """Wait until the number of drawn elements passes ``test`` (the graph redraws
        after the click's event handler returns)."""
        count = (
            "window.rosvar.graph.cy.nodes(':visible')"
            ".filter((n) => n.data('kind') !== 'namespace').length"
        )
        self.page.wait_for_function(f"() => {test(count)}", timeout=timeout_s * 1000)

    def warned_files(self) -> set[str]:
        return set(self.page.evaluate(
            """() => [...document.querySelectorAll('.file')]
                 .filter((row) => !row.querySelector(':scope > summary .warn').hidden)
                 .map((row) => row.dataset.id)"""
        ))  # fmt: skip

    def click_graph_element(self, element_id: str) -> None:
        """A real mouse click where the element is drawn on the canvas."""
        where = self.page.evaluate(
            "(id) => window.rosvar.graph.cy.getElementById(id).renderedPosition()", element_id
        )
        box = self.page.locator("#graph").bounding_box()
        self.page.mouse.click(box["x"] + where["x"], box["y"] + where["y"])

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
        """The page shows exactly the state the server holds for its session."""
        server = self.server_state()
        # the page builds its state from deltas; a refusal is in the answer only
        assert {**self.state, "version": 0, "refused": []} == {**server, "version": 0}
        expected = {k: MARKS[f["state"]][f["derived"]] for k, f in server["features"].items()}
        assert self.marks() == expected
        drawn = [e for kind in ("nodes", "tests", "topics") for e in server["graph"].get(kind, [])]
        shown = self.page.evaluate(
            """() => window.rosvar.graph.cy.nodes(':visible')
                 .filter((n) => n.data('kind') !== 'namespace')
                 .map((n) => [n.data('element').id, n.hasClass('undetermined')])"""
        )
        assert sorted(map(tuple, shown)) == sorted(
            (e["id"], e["presence"] == "undetermined") for e in drawn if e["presence"] != "absent"
        )
        assert self.warned_files() == {f for c in server["conflicts"] for f in c["files"]}
        clashing = {name for c in server["conflicts"] for name in c["names"]}
        marked = self.page.evaluate(
            "() => window.rosvar.graph.cy.nodes('.conflict').map((n) => n.data('element').id)"
        )
        assert sorted(marked) == sorted(
            e["id"]
            for e in [*server["graph"]["nodes"], *server["graph"].get("tests", [])]
            if e["presence"] != "absent" and f"node {e['name']}" in clashing
        )
        command = self.page.locator("#command").inner_text()
        if server["complete"]:
            assert command == server["command"]
        assert self.page.locator("#features-left").inner_text() == f"{server['unselected']:,}"
        return server


def present_nodes(state: dict[str, Any]) -> int:
    return sum(1 for node in state["graph"]["nodes"] if node["presence"] == "present")


def file_named(state: dict[str, Any], name: str) -> str:
    return next(k for k, f in state["features"].items() if f["kind"] == "file" and k.endswith(name))


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
    node = next(n for n in app.state["graph"]["nodes"] if n["presence"] != "absent")
    app.click_graph_element(f"n:{node['id']}")
    details = page.locator("#details")
    assert details.is_visible()
    text = details.inner_text()
    assert node["name"] in text and f":{node['line']}" in text and node["presence"] in text


def test_graph_navigation(page: Any, examples: Live) -> None:
    app = App(page, examples)
    total = len(app.graph_labels())
    page.check("#show-params")
    with_params = len(app.graph_labels())
    assert with_params > total, "params are hidden until asked for"
    page.fill("#graph-search", "controller")
    matches = page.evaluate("window.rosvar.graph.cy.nodes('.match').map((n) => n.data('label'))")
    assert matches and all("controller" in label for label in matches)
    page.evaluate("() => { window.rosvar.graph.cy.nodes('.match')[0].select(); }")
    page.click("#focus")
    app.wait_for_visible(lambda count: f"{count} < {with_params}")
    focused = len(app.graph_labels())
    assert 0 < focused < with_params
    page.click("#show-all")
    app.wait_for_visible(lambda count: f"{count} === {with_params}")
    assert len(app.graph_labels()) == with_params


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
    with page.expect_response("**/api/choose") as answer:
        app.choose(value, "select")
    assert len(answer.value.body()) < len(json.dumps(start)) / 10  # a delta, not the state
    assert app.assert_shows_server_state()["features"][value]["state"] == "selected"
    app.wait_for_update(lambda: page.click("#undo"))
    assert app.marks()[value] == "·"
