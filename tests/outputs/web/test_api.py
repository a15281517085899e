"""The JSON API over plain HTTP: sessions per tab, choices, undo/redo/reset, refused requests."""

from __future__ import annotations

import gc
from pathlib import Path
from typing import Any

import pytest

from outputs.web.live import Live, configurator, running
from rosvar.analyses.feature_model import counting
from rosvar.configuration.engine import Configurator
from rosvar.outputs.documents.state import state_document
from rosvar.outputs.web import api
from rosvar.outputs.web.api import MAX_TEXT, Api


def states(reply: dict[str, Any]) -> dict[str, tuple[str, bool]]:
    return {key: (f["state"], f["derived"]) for key, f in reply["features"].items()}


def first_of(reply: dict[str, Any], kind: str) -> str:
    return str(next(key for key, f in reply["features"].items() if f["kind"] == kind))


def test_new_session_has_the_engine_state(examples: Live, examples_engine: Configurator) -> None:
    reply = examples.open()
    assert isinstance(reply["session"], str) and reply["session"]
    expected = state_document(examples_engine.state([]))
    assert {key: reply[key] for key in expected} == expected
    assert (reply["can_undo"], reply["can_redo"]) == (False, False)


def test_choose_applies_a_choice(examples: Live) -> None:
    reply = examples.open()
    file = first_of(reply, "file")
    after = examples.post(
        "/api/choose", {"session": reply["session"], "action": "select", "feature": file}
    )
    assert after["features"][file]["state"] == "selected"
    assert after["features"][file]["derived"] is False
    assert after["session"] == reply["session"]
    assert (after["can_undo"], after["can_redo"]) == (True, False)


def test_a_tab_naming_its_version_gets_only_what_changed(examples: Live) -> None:
    reply = examples.open()
    file = first_of(reply, "file")
    body = {"session": reply["session"], "version": reply["version"]}
    after = examples.post("/api/choose", {**body, "action": "select", "feature": file})
    assert after["base"] == reply["version"] and after["version"] > reply["version"]
    whole = examples.call("GET", f"/api/state?session={reply['session']}").json()
    changed = {k for k, f in whole["features"].items() if f != reply["features"][k]}
    assert file in changed and set(after["features"]) == changed
    assert "configurations" in after
    for field in ("conflicts", "graph", "command"):  # unchanged fields are left out
        assert (field in after) == (whole[field] != reply[field]), field


def test_the_catalog_marks_each_args_default_value(examples: Live) -> None:
    features = examples.open()["features"]
    rows = examples.call("GET", "/api/catalog").json()["features"]
    defaults = {rows[row[5]][0]: row[0] for row in rows if row[6]}
    # robot.launch: <arg name="model" default="kobuki"/>; control.xml: use_teleop default true
    robot = next(
        k for k, f in features.items() if k.endswith("robot.launch") and f["kind"] == "file"
    )
    assert defaults[f"{robot}:model"] == f"{robot}:model=kobuki"
    assert all(features[arg]["kind"] == "arg" for arg in defaults)
    assert all(features[value]["parent"] == arg for arg, value in defaults.items())
    assert all(features[value]["value"] != "<other>" for value in defaults.values())


def test_two_sessions_never_see_each_others_choices(examples: Live) -> None:
    one, two = examples.open(), examples.open()
    assert one["session"] != two["session"]
    file = first_of(one, "file")
    examples.post("/api/choose", {"session": one["session"], "action": "deselect", "feature": file})
    other = examples.call("GET", f"/api/state?session={two['session']}").json()
    assert states(other) == states(two)
    assert other["can_undo"] is False
    mine = examples.call("GET", f"/api/state?session={one['session']}").json()
    assert mine["features"][file]["state"] == "deselected"


def test_undo_redo_reset(examples: Live) -> None:
    start = examples.open()
    key = start["session"]
    file = first_of(start, "file")
    chosen = examples.post("/api/choose", {"session": key, "action": "select", "feature": file})
    undone = examples.post("/api/undo", {"session": key})
    assert states(undone) == states(start)
    assert (undone["can_undo"], undone["can_redo"]) == (False, True)
    redone = examples.post("/api/redo", {"session": key})
    assert states(redone) == states(chosen)
    reset = examples.post("/api/reset", {"session": key})
    assert states(reset) == states(start)
    assert reset["can_redo"] is False


def test_set_with_a_typed_value_selects_the_other_slot(examples: Live) -> None:
    reply = examples.open()
    arg = next(
        key
        for key, f in reply["features"].items()
        if f["kind"] == "arg" and f"{key}=<other>" in reply["features"]
    )
    after = examples.post(
        "/api/choose",
        {"session": reply["session"], "action": "set", "feature": arg, "value": "typed by a test"},
    )
    assert after["features"][f"{arg}=<other>"]["state"] == "selected"
    assert after["features"][f"{arg}=<other>"]["derived"] is False


def test_finish_completes_with_choices_undone_one_by_one(examples: Live) -> None:
    reply = examples.open()
    key = reply["session"]
    file = first_of(reply, "file")
    examples.post("/api/choose", {"session": key, "action": "select", "feature": file})
    done = examples.post("/api/finish", {"session": key})
    assert done["complete"] and done["unselected"] == 0 and done["command"]
    assert len(done["choices"]) > 1 and done["choices"][0]["feature"] == file
    back = examples.post("/api/undo", {"session": key})
    assert back["choices"] == done["choices"][:-1]
    assert back["can_redo"] is True


def test_expired_sessions_are_forgotten(examples_engine: Configurator) -> None:
    with running(examples_engine, capacity=2) as live:
        oldest = live.open()["session"]
        live.open()
        live.open()
        reply = live.call("POST", "/api/undo", {"session": oldest})
        assert reply.status == 404
        assert "session" in reply.json()["error"]
        assert live.server.api.sessions == 2


BAD_CHOICES: dict[str, tuple[dict[str, object], int]] = {
    "unknown action": ({"action": "explode", "feature": "FILE"}, 400),
    "unknown feature": ({"action": "select", "feature": "no/such.launch"}, 400),
    "feature not a string": ({"action": "select", "feature": 3}, 400),
    "missing feature": ({"action": "select"}, 400),
    "select with a value": ({"action": "select", "feature": "FILE", "value": "x"}, 400),
    "set on a file": ({"action": "set", "feature": "FILE", "value": "x"}, 400),
    "set without a value": ({"action": "set", "feature": "ARG"}, 400),
    "too long a value": ({"action": "set", "feature": "ARG", "value": "x" * (MAX_TEXT + 1)}, 400),
    "unknown field": ({"action": "select", "feature": "FILE", "why": "not"}, 400),
    "version not a number": ({"action": "select", "feature": "FILE", "version": "1"}, 400),
}


@pytest.mark.parametrize("case", sorted(BAD_CHOICES))
def test_bad_choices_are_refused(examples: Live, case: str) -> None:
    reply = examples.open()
    ids = {"FILE": first_of(reply, "file"), "ARG": first_of(reply, "arg")}
    fields, status = BAD_CHOICES[case]
    body = {
        "session": reply["session"],
        **{k: ids.get(v, v) if isinstance(v, str) else v for k, v in fields.items()},
    }
    answer = examples.call("POST", "/api/choose", body)
    assert answer.status == status
    assert isinstance(answer.json()["error"], str)
    unchanged = examples.call("GET", f"/api/state?session={reply['session']}").json()
    assert states(unchanged) == states(reply)
    assert unchanged["can_undo"] is False


BAD_REQUESTS: dict[str, tuple[str, str, object, int]] = {
    "unknown session": ("POST", "/api/undo", {"session": "nope"}, 404),
    "session missing": ("POST", "/api/undo", {}, 400),
    "session not a string": ("POST", "/api/redo", {"session": ["x"]}, 400),
    "state without session": ("GET", "/api/state", None, 400),
    "state with extra query": ("GET", "/api/state?session=a&x=1", None, 400),
    "body not an object": ("POST", "/api/session", [1, 2], 400),
    "fields when opening": ("POST", "/api/session", {"session": "mine"}, 400),
    "unknown API": ("POST", "/api/finish-everything", {}, 404),
    "GET on a POST route": ("GET", "/api/choose", None, 405),
    "POST on a GET route": ("POST", "/api/state", {}, 405),
}


@pytest.mark.parametrize("case", sorted(BAD_REQUESTS))
def test_bad_requests_get_4xx_and_a_message(examples: Live, case: str) -> None:
    method, path, body, status = BAD_REQUESTS[case]
    reply = examples.call(method, path, body)
    assert reply.status == status
    assert reply.headers["Content-Type"].startswith("application/json")
    assert isinstance(reply.json()["error"], str) and reply.json()["error"]


def test_a_new_api_prepares_the_counts(
    examples_engine: Configurator, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The counts after clicks are made ready when the server starts, not on a click."""
    monkeypatch.setattr(counting, "VECTOR_FROM", 0)  # the example's diagrams are small
    diagrams = [c.counted_diagram for c in examples_engine.model.solver.components]
    assert not any("_residues" in vars(diagram) for diagram in diagrams)
    Api(examples_engine)
    assert all("_residues" in vars(diagram) for diagram in diagrams)


def test_calls_run_with_the_collector_paused(
    examples_engine: Configurator, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A call's documents are made with the cyclic collector paused (it ran full
    collections of the engine's heap inside the calls) and it runs again afterwards."""
    made: list[bool] = []

    def document(*args: Any) -> dict[str, object]:
        made.append(gc.isenabled())
        return state_document(*args)

    monkeypatch.setattr(api, "state_document", document)
    enabled = gc.isenabled()
    gc.enable()
    try:
        served = Api(examples_engine)
        key = str(served.handle("POST", "/api/session", {}, {})["session"])
        served.handle("POST", "/api/session", {}, {"overview": "package"})
        served.handle("GET", "/api/state", {"session": key}, {})
        assert made == [False, False, False]
        assert gc.isenabled()
    finally:
        if not enabled:
            gc.disable()


def test_a_ros2_workspace_is_served_with_its_ros2_launch_command(tmp_path: Path) -> None:
    package = tmp_path / "pkg"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>pkg</name>'
        "<export><build_type>ament_cmake</build_type></export></package>"
    )
    (package / "launch" / "main.launch.xml").write_text(
        '<launch><arg name="robot" default="a" description="Which robot">'
        '<choice value="a"/><choice value="b"/></arg>'
        '<node pkg="pkg" exec="e" name="$(var robot)"/></launch>'
    )
    with running(configurator([tmp_path])) as live:
        reply = live.open()
        file = first_of(reply, "file")
        # the tree's package and the arg's description, as the file gives them
        assert reply["features"][file]["package"] == "pkg"
        assert reply["features"][f"{file}:robot"]["doc"] == "Which robot"
        body = {"session": reply["session"], "action": "select", "feature": file}
        after = live.post("/api/choose", body)
        value = next(
            key
            for key, f in after["features"].items()
            if f["kind"] == "value" and f.get("value") == "b"
        )
        done = live.post("/api/choose", {**body, "feature": value})
    assert done["command"] == "ros2 launch pkg main.launch.xml robot:=b"


def test_memory_stays_bounded_over_many_distinct_clicks(monkeypatch: pytest.MonkeyPatch) -> None:
    """Issue 16: every click types a text never seen before, sessions come and go; the
    engine's memos and per-step caches stay within their bounds, no BDD node is kept for
    evicted entries, and the traced heap stops growing once the bounds are reached."""
    import gc
    import tracemalloc

    from outputs.web.live import REPO, configurator
    from rosvar import memo
    from rosvar.configuration import engine as engine_module

    monkeypatch.setattr(memo, "CAPACITY", 40)
    monkeypatch.setattr(engine_module, "CACHED_FEATURES", 1)  # MIN_CACHED_STEPS steps
    engine = configurator([REPO / "examples"])
    api = Api(engine, capacity=2)
    args = list(engine.catalog.args)
    managers = (engine.derivation.manager, engine.analysis.space.bdd)
    session = ""

    def click(number: int) -> None:
        nonlocal session
        if number % 20 == 0:
            session = str(api.handle("POST", "/api/session", {}, {})["session"])
        feature = args[number % len(args)]
        body = {"session": session, "action": "set", "feature": feature, "value": f"v{number}"}
        api.handle("POST", "/api/choose", {}, body)

    for number in range(300):  # past every bound
        click(number)
    tracemalloc.start()
    try:  # the first round replaces what was allocated before tracing (untraced when freed)
        for number in range(300, 600):
            click(number)
        gc.collect()
        before = tracemalloc.get_traced_memory()[0]
        nodes = [len(manager) for manager in managers]  # memos lowered lazily are warm by now
        for number in range(600, 900):
            click(number)
        gc.collect()
        grown = tracemalloc.get_traced_memory()[0] - before
    finally:
        tracemalloc.stop()
    steps = engine_module.MIN_CACHED_STEPS
    assert api.sessions == 2
    ours = [found for found in memo.memos() if found.capacity == 40]  # other engines' too
    assert all(len(found) <= 40 for found in ours)
    full = 40 - 40 // memo.EVICTED  # a full memo forgets an eighth of it at once
    assert sum(len(found) >= full for found in ours) >= 3  # the bound was reached
    for cache in (engine._steps, engine._replays, engine.views._views):
        assert len(cache._items) <= steps
    assert all(len(manager) <= count for manager, count in zip(managers, nodes, strict=True)), (
        [len(manager) for manager in managers],
        nodes,
    )
    assert grown < 1_000_000  # unbounded, the memos alone held 4 MB more per 300 clicks
