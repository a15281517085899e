"""A random walk through Husky's page to a complete product, as a user clicking around.

Seeded random clicks in the feature tree (files in or out, values, typed ``<other>`` texts),
then "Finish with defaults" and the texts still asked for. After every step the page shows
the server's state, no placeholder in the command box or in a label of the graph, no ⚠ while
the product has no conflict, and the command once complete; the graph reads well (no
overlaps, a legible zoom) at the start, midway and at the end.
"""

from __future__ import annotations

import random
from typing import Any

from outputs.web.live import Live
from outputs.web.test_app import LEGIBLE_ZOOM, OTHER, App, overlapping

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
    app.wait_for_layout()
    assert app.page.evaluate("window.rosvar.graph.cy.zoom()") >= LEGIBLE_ZOOM
    assert overlapping(app) == []
