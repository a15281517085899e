"""Queries and checks in the web API: answered under a tab's choices, with graph entry ids."""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING, Any

import pytest

from configuration.helpers import configurator
from outputs.web.live import Live, running

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def small_workspace(ws: LaunchWorkspace) -> None:
    """A talker always, a listener when ``listen`` (its topic then has a subscriber)."""
    ws.write(
        "scripts/talker.py",
        'import rospy\nfrom std_msgs.msg import String\nrospy.Publisher("chatter", String)\n',
    )
    ws.write(
        "scripts/listener.py",
        'import rospy\nfrom std_msgs.msg import String\nrospy.Subscriber("chatter", String)\n',
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
    feature = "a.launch:listen=false"
    small.post("/api/choose", {"session": session, "action": "select", "feature": "a.launch"})
    small.post("/api/choose", {"session": session, "action": "select", "feature": feature})
    assert ask(small, session, "nodes[self.name == '/listener']") == []
    [talker] = ask(small, session, "for n in nodes where n.name != '/listener' return n")
    assert (talker["name"], talker["presence"], talker["condition"]) == ("/talker", "present", None)


def test_a_query_the_parser_refuses_is_a_400_with_its_position(small: Live) -> None:
    session = small.open()["session"]
    reply = small.call("POST", "/api/query", {"session": session, "expression": "nodes[open(1)]"})
    assert reply.status == 400
    assert reply.json()["position"] == 6 and "functions" in reply.json()["error"]
    unknown = small.call("POST", "/api/query", {"session": "nope", "expression": "nodes"})
    assert unknown.status == 404
    extra = small.call("POST", "/api/query", {"session": session, "expression": "x", "y": 1})
    assert extra.status == 400


def test_checks_follow_the_choices(small: Live) -> None:
    session = small.open()["session"]
    answer = small.post("/api/checks", {"session": session})
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
    after = small.post("/api/checks", {"session": session})
    assert "/chatter" not in {f["name"] for f in after["findings"]}
