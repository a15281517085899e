"""Walks through a page to a complete product, as a user clicking around.

Husky (ROS 1): seeded random clicks in the feature tree (files in or out, values, typed
``<other>`` texts), then "Finish with defaults" and the texts still asked for. After every
step the page shows the server's state, no placeholder in the command box or in a label of
the graph, no ⚠ while the product has no conflict, and the command once complete; the graph
reads well (no overlaps, all of it in view at a readable zoom) at the start, midway and at the end.

ROS 2 (``tests/data/ros2``): a bringup file configured step by step, its ``ros2 launch``
command read off the page and run by the real ros2/launch (the ROS 2 oracle), whose nodes
must be those the page's product has.
"""

from __future__ import annotations

import json
import random
import shlex
from pathlib import Path
from typing import Any

import pytest

from oracle.ros2_client import ORACLE, run_oracle
from outputs.web.live import REPO, Live, configurator, running
from outputs.web.test_app import OTHER, READABLE_ZOOM, App, beyond_the_canvas, overlapping, zoom
from rosvar.workspace import discover

PLACEHOLDERS = ("⟨", "<default:", "<other>", "$(")
CLICKS = 8
FINISH_TIMEOUT_S = 180  # a few dozen engine steps; the machine running the tests may be busy


def test_husky_random_walk_to_a_complete_product(page: Any, husky: Live) -> None:
    app = App(page, husky)
    rng = random.Random("husky-walk")
    assert_readable(app)
    for _ in range(CLICKS):
        click(app, rng)
        check(app)
    assert_readable(app)
    app.wait_for_update(lambda: page.click("#finish"), FINISH_TIMEOUT_S)
    check(app)
    while untyped := app.state["untyped"]:
        app.type_other(untyped[0], f"typed{rng.randint(0, 9)}")
        check(app)
    server = app.assert_shows_server_state()
    assert server["complete"] and server["command"]
    # one configuration is left, and the solver never lets two files of it clash
    assert [c for c in server["conflicts"] if c["files"][0] != c["files"][1]] == []
    assert page.locator("#command").inner_text() == server["command"]
    assert_readable(app)


def click(app: App, rng: random.Random) -> None:
    """One random choice on an open file or value (a text for an ``<other>`` value)."""
    features = app.features
    open_ = [k for k, f in features.items() if f["state"] == "unselected" and f["kind"] != "arg"]
    feature = rng.choice(open_)
    if features[feature]["kind"] == "file":
        app.choose(feature, "select" if rng.random() < 0.3 else "deselect")
    elif features[feature]["value"] == OTHER:
        app.type_other(str(features[feature]["parent"]), f"typed{rng.randint(0, 9)}")
    else:
        app.choose(feature, "select")


def check(app: App) -> None:
    server = app.assert_shows_server_state()
    command = app.page.locator("#command").inner_text()
    assert not any(p in command for p in PLACEHOLDERS), command
    labels: list[tuple[str, str, bool]] = app.page.evaluate(
        """() => window.rosvar.graph.cy.nodes().map((n) =>
             [n.data('label'), (n.data('element') || {}).presence || '', n.hasClass('conflict')])"""
    )
    if not server["untyped"]:  # an <other> value without its text is shown as ⟨arg⟩ till then
        shown = [label for label, presence, _ in labels if presence == "present"]
        assert [t for t in shown if any(p in t for p in PLACEHOLDERS)] == []
    if not server["conflicts"]:
        assert [label for label, _, conflict in labels if conflict or "⚠" in label] == []
        assert app.warned_files() == set()
    if server["complete"] and not server["untyped"]:
        assert command == server["command"] and command


def assert_readable(app: App) -> None:
    assert beyond_the_canvas(app) == {} and zoom(app) >= READABLE_ZOOM
    assert overlapping(app) == []


# -- ROS 2: a bringup configured in the page, launched by the real ros2/launch ------------------
ROS2_DATA = REPO / "tests" / "data" / "ros2"


BRINGUPS = {  # repository: (launch file, values clicked in the tree, the command's arguments)
    "ros2_control_demos": (
        "example_2/bringup/launch/diffbot.launch.xml",
        ["gui=false"],
        {"gui": "false"},
    ),
    "husky": ("husky_control/launch/teleop_base.launch.py", [], {}),
}


@pytest.mark.oracle
@pytest.mark.skipif(not ORACLE.is_dir(), reason=f"the ROS 2 oracle {ORACLE} is absent")
@pytest.mark.parametrize("repository", sorted(BRINGUPS))
def test_ros2_bringup_configured_in_the_page_launches_the_graph_it_showed(
    page: Any, repository: str
) -> None:
    """A bringup file selected in the tree, values clicked, the rest finished with defaults;
    the command on the page, run by the oracle, starts the nodes of the page's product
    (package, executable, name, namespace, parameters, remaps, arguments)."""
    root = ROS2_DATA / repository
    file, clicks, arguments = BRINGUPS[repository]
    with running(configurator([root])) as live:
        app = App(page, live)
        bringup = next(
            key for key, f in app.features.items()
            if f["kind"] == "file" and key.endswith(f"{repository}/{file}")
        )  # fmt: skip
        app.choose(bringup, "select")
        for value in clicks:
            app.choose(f"{bringup}:{value}", "select")
        app.wait_for_update(lambda: page.click("#finish"))
        server = app.assert_shows_server_state()
        command = page.locator("#command").inner_text()
        assert server["complete"] and command == server["command"]
        assert page.locator("#copy").is_enabled()
        shown = product_nodes(live, server, command)
        words = shlex.split(command)
        # the tree names the package as the command does; a clicked arg shows its description
        packages = [
            text.split()[0] for text in page.locator(".package > summary").all_inner_texts()
        ]
        assert words[2] in packages
        for value in clicks:
            arg = f"{bringup}:{value.split('=')[0]}"
            doc = page.locator(f'.feature[data-id="{arg}"] > p.doc').inner_text()
            assert doc == server["features"][arg]["doc"] and doc
    assert words[:2] == ["ros2", "launch"] and len(words) >= 4, command
    assert dict(word.split(":=", 1) for word in words[4:]) == arguments
    launched = launch_file(root, words[2], words[3])
    assert launched == root / file
    expected = run_oracle(launched, arguments, [root], strict=False)
    assert expected["ok"], expected.get("error")
    assert expected["nodes"]
    assert sorted(map(oracle_node, expected["nodes"])) == sorted(map(page_node, shown))


def launch_file(root: Path, package: str, name: str) -> Path:
    """The file ``ros2 launch PACKAGE NAME`` starts: the one of that name in the package."""
    folder = Path(discover([str(root)]).packages[package].path)
    found = [path for path in folder.rglob(name) if path.is_file()]
    assert len(found) == 1, found
    return found[0]


def product_nodes(live: Live, server: dict[str, Any], command: str) -> list[dict[str, Any]]:
    """The present nodes of the page's product: the page's choices replayed in a session of
    the same server that sends whole graphs (the page may draw groups fetched on demand)."""
    session = live.open()["session"]
    state: dict[str, Any] = {}
    for choice in server["choices"]:
        state = live.post("/api/choose", {"session": session, **choice})
    assert state["command"] == command
    return [node for node in state["graph"]["nodes"] if node["presence"] == "present"]


Node = tuple[str, str, str | None, str, str, str, str]


def oracle_node(node: dict[str, Any]) -> Node:
    return (
        node["package"], node["executable"], node["fqn"], node["namespace"] or "/",
        json.dumps(node["parameters"], sort_keys=True),
        json.dumps(sorted(node["remappings"])), json.dumps(node["arguments"]),
    )  # fmt: skip


def page_node(node: dict[str, Any]) -> Node:
    return (
        node["package"], node["type"], node["fqn"], node["namespace"],
        json.dumps(node["parameters"], sort_keys=True),
        json.dumps(sorted(node["remaps"])), json.dumps(shlex.split(node.get("args") or "")),
    )  # fmt: skip
