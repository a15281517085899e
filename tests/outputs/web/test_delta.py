"""Deltas: applied to the state a tab holds, they give exactly the server's whole state."""

from __future__ import annotations

import json
import random
from collections.abc import Callable
from typing import Any

import pytest

from outputs.web.live import configurator, corpus_system
from rosvar.configuration.engine import Configurator
from rosvar.outputs.web.api import Api
from rosvar.outputs.web.delta import diff, patch

STEPS = ("undo", "redo", "reset", "finish")


def wire(document: dict[str, Any]) -> dict[str, Any]:
    """The document as the page receives it (tuples become lists)."""
    answer: dict[str, Any] = json.loads(json.dumps(document))
    return answer


def random_request(rng: random.Random, model: dict[str, Any]) -> tuple[str, dict[str, Any]]:
    """A click of a user: mostly a choice on an open feature, sometimes undo/redo/reset/finish."""
    key = {"session": model["session"], "version": model["version"]}
    features = model["features"]
    open_ = sorted(k for k, f in features.items() if f["state"] == "unselected")
    if not open_ or rng.random() < 0.15:
        return f"/api/{rng.choice(STEPS)}", key
    feature = rng.choice(open_)
    if features[feature]["value"] == "<other>":
        return "/api/choose", {**key, "action": "set", "feature": features[feature]["parent"],
                               "value": f"typed {rng.randrange(3)}"}  # fmt: skip
    action = rng.choice(("select", "deselect"))
    return "/api/choose", {**key, "action": action, "feature": feature}


def replay(engine: Configurator, clicks: int, seed: int) -> int:
    """Random clicks with deltas applied as the page does; returns how many came as deltas."""
    api = Api(engine)
    model = wire(api.handle("POST", "/api/session", {}, {}))
    rng = random.Random(seed)
    deltas = 0
    for _ in range(clicks):
        path, body = random_request(rng, model)
        answer = wire(api.handle("POST", path, {}, body))
        deltas += "base" in answer
        model = patch(model, answer)
        whole = wire(api.handle("GET", "/api/state", {"session": model["session"]}, {}))
        # a refusal is in the answer only, the session's state has none
        assert {**model, "version": 0, "refused": []} == {**whole, "version": 0}
        assert all(r["choice"]["feature"] == body.get("feature") for r in model["refused"])
    return deltas


def test_deltas_rebuild_every_state_of_the_example(examples_engine: Configurator) -> None:
    assert replay(examples_engine, clicks=60, seed=1) == 60


@pytest.fixture(scope="module")
def lizi_engine() -> Configurator:
    return configurator([corpus_system("lizi")])


def test_deltas_rebuild_every_state_of_lizi(lizi_engine: Configurator) -> None:
    assert replay(lizi_engine, clicks=40, seed=2) == 40


def node(key: str, x: int, presence: str = "undetermined") -> dict[str, Any]:
    return {"id": key, "x": x, "presence": presence, "condition": f"c{x}"}


DOCUMENT: dict[str, Any] = {
    "features": {"a": {"state": "unselected"}, "b": {"state": "unselected"}},
    "graph": {
        "nodes": [node("n1", 1), node("n2", 2), node("n3", 3), node("n4", 4)],
        "params": [{"id": "p1"}],
    },
    "complete": False,
    "command": None,
    "version": 1,
}


def test_a_delta_holds_only_what_changed() -> None:
    changed = {**node("n3", 3, "present"), "condition": None}
    after = {
        **DOCUMENT,
        "features": {**DOCUMENT["features"], "b": {"state": "selected"}},
        "graph": {
            "nodes": [node("n0", 0), node("n1", 1), changed, node("n4", 5)],
            "params": DOCUMENT["graph"]["params"],
        },
        "command": "roslaunch x y",
    }
    delta = wire(diff(DOCUMENT, after))
    assert delta["features"] == {"b": {"state": "selected"}}
    assert delta["graph"] == {
        "nodes": {
            "removed": ["n2"],
            "added": [[0, node("n0", 0)]],
            "changed": [
                [2, {"presence": "present", "condition": None}],  # its verdict only
                [3, node("n4", 5)],  # another field changed: whole
            ],
        }
    }
    assert set(delta) == {"features", "graph", "command"}
    assert patch(DOCUMENT, {**delta, "base": 1}) == after


def test_entries_changed_in_place_are_sent_by_place() -> None:
    nodes = DOCUMENT["graph"]["nodes"]
    fewer = {k: v for k, v in nodes[2].items() if k != "condition"}
    after = [nodes[0], {**nodes[1], "presence": "absent"}, fewer, dict(nodes[3])]
    change = diff(DOCUMENT, {**DOCUMENT, "graph": {**DOCUMENT["graph"], "nodes": after}})
    assert change["graph"]["nodes"] == {
        "removed": [nodes[2]["id"]],
        "added": [(2, fewer)],
        "changed": [(1, {"presence": "absent", "condition": nodes[1]["condition"]})],
    }


def test_entries_that_swap_places_are_sent_again() -> None:
    nodes = DOCUMENT["graph"]["nodes"]
    after = {**DOCUMENT, "graph": {**DOCUMENT["graph"], "nodes": [nodes[2], nodes[0], nodes[1]]}}
    delta = wire(diff(DOCUMENT, after))
    assert len(delta["graph"]["nodes"]["added"]) == 3
    assert patch(DOCUMENT, {**delta, "base": 1}) == after


def test_a_delta_against_another_version_is_refused() -> None:
    with pytest.raises(ValueError, match="version"):
        patch(DOCUMENT, {"base": 7, "complete": True})
    assert patch(DOCUMENT, {"complete": True}) == {"complete": True}  # a whole document


def random_lists(rng: random.Random) -> tuple[list[dict[str, Any]], list[dict[str, Any]]]:
    """Two lists of entries as states give them: some dropped, added, changed (a field more,
    less or other), or all moved; or, as most steps do, only changed in place."""
    changes: list[Callable[[dict[str, Any]], dict[str, Any]]] = [
        lambda e: e,
        lambda e: {**e, "presence": "present", "condition": None},
        lambda e: {**e, "x": -1},
        lambda e: {**e, "more": True},
        lambda e: {k: v for k, v in e.items() if k != "x"},
    ]
    before = [node(f"e{n}", n) for n in range(rng.randrange(8))]
    if rng.random() < 0.3:
        return before, [rng.choice(changes)(e) for e in before]
    after = [rng.choice(changes)(e) for e in before if rng.random() < 0.7]
    for n in range(rng.randrange(4)):
        after.insert(rng.randrange(len(after) + 1), {"id": f"new{n}", "v": 2})
    if rng.random() < 0.2:
        rng.shuffle(after)
    return before, after


def test_patching_a_diff_gives_the_new_lists() -> None:
    rng = random.Random(3)
    for _ in range(2000):
        before, after = random_lists(rng)
        old = {"graph": {"nodes": before}, "version": 5}
        new = {"graph": {"nodes": after}}
        delta = wire(diff(old, new))
        assert patch(old, {**delta, "base": 5})["graph"]["nodes"] == after


def conflict(n: int, status: str = "possible") -> dict[str, Any]:
    return {"files": [f"f{n}", "g"], "names": [f"node /n{n}"], "status": status, "condition": None}


def test_conflicts_are_sent_by_place() -> None:
    before = [conflict(n) for n in range(5)]
    judged_again = conflict(2, "certain")
    after = [before[0], judged_again, dict(before[3]), conflict(9)]  # equal, not the same
    old = {**DOCUMENT, "conflicts": before}
    delta = wire(diff(old, {**old, "conflicts": after}))
    assert delta["conflicts"] == {
        "removed": [1, 2, 4],
        "added": [[1, judged_again], [3, conflict(9)]],
    }
    assert patch(old, {**delta, "base": 1})["conflicts"] == after
    assert "conflicts" not in diff(old, {**old, "conflicts": [dict(c) for c in before]})


def test_patching_a_conflicts_diff_gives_the_new_list() -> None:
    rng = random.Random(4)
    for _ in range(2000):
        before = [conflict(rng.randrange(6)) for _ in range(rng.randrange(8))]  # repeats too
        after = [c if rng.random() < 0.8 else conflict(c["names"][0][-1], "certain")
                 for c in before if rng.random() < 0.7]  # fmt: skip
        for _ in range(rng.randrange(3)):
            after.insert(rng.randrange(len(after) + 1), conflict(rng.randrange(9)))
        if rng.random() < 0.2:
            rng.shuffle(after)
        old = {"conflicts": before, "version": 5}
        delta = wire(diff(old, {"conflicts": after}))
        assert patch(old, {**delta, "base": 5})["conflicts"] == after
