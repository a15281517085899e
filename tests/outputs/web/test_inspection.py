"""Queries and checks in the web API: answered under a tab's choices, with graph entry ids."""

from __future__ import annotations

import argparse
import json
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pytest

from configuration.helpers import configurator
from outputs.web.live import Live, running
from outputs.web.test_app import App
from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.engine import Configurator
from rosvar.configuration.session import Session
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.cli import main
from rosvar.outputs.commands.loading import interfaces_of
from rosvar.outputs.web import inspection
from rosvar.outputs.web.entries import render
from rosvar.outputs.web.overview import key_of
from rosvar.workspace import discover

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def small_workspace(ws: LaunchWorkspace) -> None:
    """A talker always, a listener when ``listen`` (its topic then has a subscriber, its
    service a client)."""
    header = "import rospy\nfrom std_msgs.msg import String\nfrom std_srvs.srv import Empty\n"
    ws.write(
        "scripts/talker.py",
        f'{header}rospy.Publisher("chatter", String)\nrospy.Service("reset", Empty, None)\n',
    )
    ws.write(
        "scripts/listener.py",
        f'{header}rospy.Subscriber("chatter", String)\nrospy.ServiceProxy("/reset", Empty)\n',
    )
    ws.launch(
        "a.launch",
        '  <arg name="listen" default="true"/>\n'
        '  <node pkg="pkg" type="talker.py" name="talker"/>\n'
        '  <node pkg="pkg" type="listener.py" name="listener" if="$(arg listen)">'
        '<remap from="other" to="/heard"/></node>',
    )


@pytest.fixture
def small(ws: LaunchWorkspace) -> Iterator[Live]:
    small_workspace(ws)
    with running(configurator(ws, interfaces=True)) as live:
        yield live


def checks(live: Live, session: str) -> dict[str, Any]:
    """The checks' answer once the findings are listed (the first question starts that)."""
    for _ in range(600):
        answer: dict[str, Any] = live.post("/api/checks", {"session": session})
        if "pending" not in answer:
            return answer
        time.sleep(0.05)
    raise AssertionError("the findings were not listed in 30 s")


def ask(live: Live, session: str, expression: str) -> list[dict[str, Any]]:
    answer = live.post("/api/query", {"session": session, "expression": expression})
    assert answer["query"] == expression
    results: list[dict[str, Any]] = answer["results"]
    return results


def test_a_query_is_judged_under_the_tabs_choices(small: Live) -> None:
    session = small.open()["session"]
    [result] = ask(small, session, "nodes[self.name == '/listener']")
    assert (result["kind"], result["launch_file"]) == ("node", "pkg/launch/a.launch")
    assert (result["presence"], result["condition"]) == ("undetermined", "listen")
    assert result["line"] == 4 and result["file"].endswith("a.launch")
    state = small.call("GET", f"/api/state?session={session}").json()
    [listener] = [n["id"] for n in state["graph"]["nodes"] if n["name"] == "/listener"]
    assert result["ids"] == [listener]
    [topic] = ask(small, session, "topics[self.name.startswith('/he')]")
    assert topic["name"] == "/heard" and topic["ids"] == ["topic:/heard"]
    [heard] = ask(small, session, "topics[len(self.subscribers) > 0]")  # the interfaces'
    assert (heard["name"], heard["condition"], heard["ids"]) == (
        "/chatter", "listen", ["topic:/chatter"],
    )  # fmt: skip
    feature = "a.launch:listen=false"
    small.post("/api/choose", {"session": session, "action": "select", "feature": "a.launch"})
    small.post("/api/choose", {"session": session, "action": "select", "feature": feature})
    assert ask(small, session, "nodes[self.name == '/listener']") == []
    [talker] = ask(small, session, "for n in nodes where n.name != '/listener' return n")
    assert (talker["name"], talker["presence"], talker["condition"]) == ("/talker", "present", None)


def test_in_overview_mode_results_name_the_groups_of_their_entries(small: Live) -> None:
    """A tab in overview mode does not hold the entries: it opens the group of a result."""
    session = small.post("/api/session", {"overview": "file"})["session"]
    [node] = ask(small, session, "nodes[self.name == '/listener']")
    assert node["groups"] == [key_of(["a.launch"])]
    [topic] = ask(small, session, "topics[self.name == '/chatter']")
    assert topic["groups"] == [None]  # drawn one by one
    findings = checks(small, session)["findings"]
    for finding in findings:
        assert len(finding["groups"]) == len(finding["ids"])
        for id_, group in zip(finding["ids"], finding["groups"], strict=True):
            assert group == (None if id_.startswith(("topic:", "service:")) else node["groups"][0])
    assert "groups" not in ask(small, small.open()["session"], "nodes")[0]


def test_services_are_summarised_and_listed_like_topics(small: Live) -> None:
    tab = small.post("/api/session", {"overview": "file"})
    [group] = tab["graph"]["groups"]
    assert group["services"] == [0, 1] and group["topics"] == [0, 2] and group["files"] == 1
    answer = small.post(
        "/api/group", {"session": tab["session"], "group": group["id"], "kind": "services"}
    )
    [service] = answer["members"]
    assert service["name"] == "/reset" and service["groups"] == [group["id"]] * 2
    assert sorted(service["names"]) == ["/listener", "/talker"]


def test_a_query_the_parser_refuses_is_a_400_with_its_position(small: Live) -> None:
    session = small.open()["session"]
    reply = small.call("POST", "/api/query", {"session": session, "expression": "nodes[open(1)]"})
    assert reply.status == 400
    assert reply.json()["position"] == 6 and "functions" in reply.json()["error"]
    unknown = small.call("POST", "/api/query", {"session": "nope", "expression": "nodes"})
    assert unknown.status == 404
    extra = small.call("POST", "/api/query", {"session": session, "expression": "x", "y": 1})
    assert extra.status == 400


def test_a_query_building_a_huge_nested_list_is_a_400(small: Live) -> None:
    """issue 30.5: it built a million references to a list of a million, within the outer
    sequence's bound, and compared them for minutes, every client waiting."""
    session = small.open()["session"]
    expression = "nodes[[[0] * 999999] * 999999 == [[1] * 999999] * 999999]"
    reply = small.call("POST", "/api/query", {"session": session, "expression": expression})
    assert reply.status == 400 and "longer than" in reply.json()["error"]


def test_checks_follow_the_choices(small: Live) -> None:
    session = small.open()["session"]
    answer = checks(small, session)
    assert answer["choices"] == []
    [unheard] = [f for f in answer["findings"] if f["check"] == "no-subscriber"]
    assert (unheard["name"], unheard["severity"]) == ("/chatter", "note")
    assert (unheard["presence"], unheard["condition"]) == ("undetermined", "¬listen")
    assert unheard["example"] == {"a.launch:listen": "false"}
    assert unheard["locations"][0]["line"] == 3 and unheard["launch_file"] == "pkg/launch/a.launch"
    state = small.call("GET", f"/api/state?session={session}").json()
    [talker] = [n["id"] for n in state["graph"]["nodes"] if n["name"] == "/talker"]
    assert talker in unheard["ids"] and "topic:/chatter" in unheard["ids"]
    assert answer["counts"]["note"] == len(
        [f for f in answer["findings"] if f["severity"] == "note"]
    )
    small.post("/api/choose", {"session": session, "action": "select", "feature": "a.launch"})
    feature = "a.launch:listen=true"
    small.post("/api/choose", {"session": session, "action": "select", "feature": feature})
    after = checks(small, session)
    assert [c["feature"] for c in after["choices"]] == ["a.launch", feature]  # the state judged
    assert "/chatter" not in {f["name"] for f in after["findings"]}


def test_a_finding_reached_from_two_entry_files_is_shown_from_the_launched_one(
    ws: LaunchWorkspace,
) -> None:
    small_workspace(ws)
    ws.launch("b.launch", '  <node pkg="pkg" type="talker.py" name="talker"/>')
    for name in ("a2.launch", "z.launch"):
        ws.launch(name, '  <include file="$(find pkg)/launch/b.launch"/>')
    with running(configurator(ws, interfaces=True)) as live:
        session = live.open()["session"]
        live.post("/api/choose", {"session": session, "action": "select", "feature": "z.launch"})
        findings = checks(live, session)["findings"]
    [unheard] = [f for f in findings if f["name"] == "/chatter" and "b.launch" in str(f)]
    assert (unheard["launch_file"], unheard["presence"]) == ("pkg/launch/z.launch", "present")
    assert findings[0] is unheard  # a note, but the only one present


def test_findings_are_listed_off_the_click_path(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Listing the findings of every entry file takes seconds on a large workspace: it runs
    beside the clicks, which are answered meanwhile, and a question asked before it is done
    says how far it is."""
    small_workspace(ws)
    for name in ("b.launch", "c.launch"):
        ws.launch(name, '  <node pkg="pkg" type="talker.py" name="talker"/>')
    held = threading.Event()  # the listing waits after its first file until a click is answered
    monkeypatch.setattr(inspection._Findings, "_pause", lambda _self: held.wait(30))
    with running(configurator(ws, interfaces=True)) as live:
        session = live.open()["session"]
        first = live.post("/api/checks", {"session": session})
        assert first["pending"][1] == 3 and first["choices"] == []
        live.post("/api/choose", {"session": session, "action": "select", "feature": "a.launch"})
        pending = live.post("/api/checks", {"session": session})
        assert pending["pending"][0] < 3 and len(pending["choices"]) == 1
        held.set()
        answer = checks(live, session)
        assert answer["choices"] == pending["choices"] and answer["total"] >= 1


# -- the page ------------------------------------------------------------------------------------
def red_units(app: App) -> list[str]:
    return sorted(app.page.evaluate("window.rosvar.graph.cy.nodes('.queried').map((n) => n.id())"))


def drawn(app: App, entry: str) -> str | None:
    [node] = [n for n in app.whole["graph"]["nodes"] if n["id"] == entry]
    [unit] = app.drawers([node])
    return unit


def test_answers_list_the_first_results_and_count_them_all(
    small: Live, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A large workspace's findings would make an answer of megabytes: the first are listed,
    the same as the whole list begins with, and all are counted."""
    session = small.open()["session"]
    whole = checks(small, session)
    nodes = ask(small, session, "nodes")
    assert whole["total"] == len(whole["findings"]) >= 1 and len(nodes) >= 2
    monkeypatch.setattr(inspection, "LISTED", 1)
    answer = small.post("/api/query", {"session": session, "expression": "nodes"})
    assert answer["results"] == nodes[:1] and answer["total"] == len(nodes)
    monkeypatch.setattr(inspection, "LISTED", 0)
    cut = checks(small, session)
    assert cut["findings"] == [] and (cut["total"], cut["counts"]) == (
        whole["total"],
        whole["counts"],
    )


def test_the_query_box_marks_its_results_and_follows_the_choices(page: Any, small: Live) -> None:
    app = App(page, small)
    box = page.locator("#query")
    box.fill("nodes[self.name == '/listener']")
    box.press("Enter")
    page.wait_for_selector("#query-results li.result")
    assert page.locator("#query-status").text_content() == "1 result"
    assert "when listen" in page.locator("#query-results li").first.text_content()
    [listener] = [n["id"] for n in app.whole["graph"]["nodes"] if n["name"] == "/listener"]
    assert red_units(app) == [drawn(app, listener)]
    app.choose("a.launch", "select")
    app.wait_for_layout()
    assert red_units(app) == ["n:" + listener]  # the file's nodes are drawn one by one
    # the service is drawn too, requests going from its client to its server
    [talker] = [n["id"] for n in app.whole["graph"]["nodes"] if n["name"] == "/talker"]
    edges = page.evaluate(
        """window.rosvar.graph.cy.edges('[kind = "service"]')
             .map((e) => [e.source().id(), e.target().id()])"""
    )
    service = "s:service:/reset"
    assert sorted(edges) == [["n:" + listener, service], [service, "n:" + talker]]
    answered = page.locator("body").get_attribute("data-query")
    app.choose("a.launch:listen=false", "select")
    page.wait_for_selector(f'body:not([data-query="{answered}"])')
    assert page.locator("#query-status").text_content() == "0 results"
    assert red_units(app) == [] and page.locator("#query-results").is_hidden()


def test_the_checks_panel_lists_findings_and_marks_a_clicked_one(page: Any, small: Live) -> None:
    app = App(page, small)
    page.wait_for_selector("body[data-checks]")
    page.locator("#checks-toggle").click()
    finding = page.locator("#checks-list li", has_text="no launched node subscribes to")
    assert "note" in finding.text_content() and "when ¬listen" in finding.text_content()
    assert red_units(app) == []
    finding.click()
    [talker] = [n["id"] for n in app.whole["graph"]["nodes"] if n["name"] == "/talker"]
    assert drawn(app, talker) in red_units(app) and "t:topic:/chatter" in red_units(app)
    answered = page.locator("body").get_attribute("data-checks")
    app.choose("a.launch", "select")
    page.wait_for_selector(f'body:not([data-checks="{answered}"])')
    assert finding.get_attribute("class") == "finding note chosen"  # kept across steps
    answered = page.locator("body").get_attribute("data-checks")
    app.choose("a.launch:listen=true", "select")
    page.wait_for_selector(f'body:not([data-checks="{answered}"])')
    assert finding.count() == 0 and red_units(app) == []


def test_the_checks_panel_never_shows_the_counts_of_an_earlier_state(
    page: Any, ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The counts of a state stay shown only until the next step: while the server judges
    the new state (seconds on a large workspace) the panel says it is checking, then shows
    the counts of the state the page shows."""
    small_workspace(ws)
    judged = inspection.Inspector.checks
    gate = threading.Event()
    gate.set()

    def slow(self: inspection.Inspector, state: Any, *args: Any) -> dict[str, object]:
        if state.complete:  # the finished state's checks wait (under the engine's lock)
            gate.wait(30)
        return judged(self, state, *args)

    monkeypatch.setattr(inspection.Inspector, "checks", slow)
    with running(configurator(ws, interfaces=True)) as live:
        app = App(page, live)
        page.wait_for_selector("body[data-checks]")
        count = page.locator("#checks-count")
        before = count.inner_text()
        assert before == counted(checks(live, app.session))
        gate.clear()
        app.choose("a.launch", "select")
        app.wait_for_update(lambda: page.click("#finish"))
        assert count.inner_text() == "…" and page.locator("#checks-list.stale").count() == 1
        answered = page.locator("body").get_attribute("data-checks")
        gate.set()
        page.wait_for_selector(f'body:not([data-checks="{answered}"])')
        server = checks(live, app.session)
        assert server["choices"] == app.server_state()["choices"]
        assert count.inner_text() == counted(server) != before


def counted(answer: dict[str, Any]) -> str:
    """The checks' counts as the panel shows them."""
    counts = answer["counts"]
    return f"{counts['error']} errors · {counts['warning']} warnings · {counts['note']} notes"


def test_no_checks_are_asked_while_a_step_is_answered(
    page: Any, ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The checks are asked again every second while the findings are listed; a question
    sent during a step would be answered under the engine's lock before the step's own
    requests (the graph's members): none is sent from the click until the step's state."""
    small_workspace(ws)
    monkeypatch.setattr(inspection._Findings, "listed", lambda self: None)  # listed forever
    applied = Session.apply

    def slow(self: Session, choice: Any) -> Any:
        time.sleep(2.5)  # several of the page's questions while listing
        return applied(self, choice)

    monkeypatch.setattr(Session, "apply", slow)
    with running(configurator(ws, interfaces=True)) as live:
        app = App(page, live)
        page.wait_for_selector("#checks-count:has-text('listing')")
        events: list[str] = []
        page.on("request", lambda request: events.append(f"asked {request.url}"))
        page.on("response", lambda response: events.append(f"answered {response.url}"))
        app.choose("a.launch", "select")
        page.wait_for_timeout(1500)  # the checks are asked again once the state is shown
        asked = events.index(f"asked {live.url}api/choose")
        answered = events.index(f"answered {live.url}api/choose")
        assert not [e for e in events[asked:answered] if e.endswith("/api/checks")]
        assert f"asked {live.url}api/checks" in events[answered:]


def checked(root: Path, capsys: pytest.CaptureFixture[str]) -> list[dict[str, Any]]:
    """The findings of ``rosvar check --all`` of ``root``."""
    main(["check", str(root), "--format", "json", "--all"])
    findings: list[dict[str, Any]] = json.loads(capsys.readouterr().out)["findings"]
    return findings


def served(root: Path) -> Configurator:
    """The engine ``rosvar serve root`` runs (interfaces and the catalogue read)."""
    analysis = Analysis(discover([str(root)], ament_prefix_path=""))
    options = argparse.Namespace(catalogue=True, hints=None)
    interfaces = interfaces_of(analysis.workspace, options)
    return Configurator(
        analysis, extract(analysis, products=True), interfaces=interfaces, render=render
    )


def test_the_page_s_checks_and_queries_are_those_of_the_commands(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A spawner's controllers are uses of the simulation, which ``rosvar check`` and
    ``rosvar query`` read: the page's checks and queries read the same inputs, so its
    findings are those of ``rosvar check --json`` and its topics those of ``rosvar query``
    (here the controllers' ``cmd_vel`` input nobody provides, and their ``joint_states``)."""
    from ros2.test_controllers import CONTROL, _workspace

    _workspace(tmp_path, CONTROL)
    command = checked(tmp_path, capsys)
    main(["query", str(tmp_path), "topics", "--json"])
    topics = {r["name"] for r in json.loads(capsys.readouterr().out)["results"]}
    with running(served(tmp_path)) as live:
        session = live.open()["session"]
        page = checks(live, session)["findings"]
        shown = {r["name"] for r in ask(live, session, "topics")}
    assert {(f["check"], f["severity"], f["name"], f["message"]) for f in page} == {
        (f["check"], f["severity"], f["name"], f["message"]) for f in command
    }
    assert any("controller base_controller" in f["message"] for f in command)
    assert shown == topics and "/robot/platform/joint_states" in topics
