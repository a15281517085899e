"""Take the screenshot of the web UI shown in docs/web.md (``docs/web-ui.png``).

    python docs/screenshot.py [--out FILE] [PATH...]

Serves PATH (default: the bundled ``examples/``) in-process on a free loopback port, opens it
in headless Chromium (Debian's ``/usr/bin/chromium`` through Playwright, as the browser tests
do), makes a few choices as a user would and saves the page.
"""

from __future__ import annotations

import argparse
import threading
from pathlib import Path

from playwright.sync_api import Page, sync_playwright

from rosvar.analyses.features import extract
from rosvar.configuration.engine import Configurator
from rosvar.interpreter.analysis import Analysis
from rosvar.outputs.web.server import make_server
from rosvar.workspace import discover

DOCS = Path(__file__).resolve().parent
CHROMIUM = "/usr/bin/chromium"


def next_step(page: Page, act: object) -> None:
    before = page.locator("body").get_attribute("data-step")
    act()  # type: ignore[operator]
    page.wait_for_selector(f'body:not([data-step="{before}"])')


def choose(page: Page, feature: str, action: str) -> None:
    row = page.locator(f'.feature[data-id="{feature}"]').first
    own = row.locator(":scope > summary, :scope > .row").first
    next_step(page, own.locator(f'.choose button[data-action="{action}"]').click)


def stage(page: Page) -> None:
    """Robot launch chosen, its model set, one node's details open: the UI at work."""
    features = page.evaluate("window.rosvar.state.features")
    robot = next(k for k, f in features.items() if k.endswith("robot.launch"))
    choose(page, robot, "select")
    page.locator(f'.feature[data-id="{robot}"] > summary .name').click()
    page.locator(f'.feature[data-id="{robot}:model"] > summary .name').click()
    choose(page, f"{robot}:model=husky", "select")
    node = page.evaluate(
        """() => window.rosvar.state.graph.nodes.find((n) => n.name === '/husky').id"""
    )
    where = page.evaluate(
        "(id) => window.rosvar.graph.cy.getElementById('n:' + id).renderedPosition()", node
    )
    box = page.locator("#graph").bounding_box()
    assert box is not None
    page.mouse.click(box["x"] + where["x"], box["y"] + where["y"])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("paths", nargs="*", default=[str(DOCS.parent / "examples")])
    parser.add_argument("--out", default=str(DOCS / "web-ui.png"))
    options = parser.parse_args()
    analysis = Analysis(discover(options.paths))
    server = make_server(Configurator(analysis, extract(analysis, products=True)), port=0)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=CHROMIUM)
            page = browser.new_page(viewport={"width": 1400, "height": 820})
            page.goto(server.url)
            page.wait_for_selector("body[data-step]")
            stage(page)
            page.screenshot(path=options.out)
            browser.close()
    finally:
        server.shutdown()
        server.server_close()
    print(f"wrote {options.out}")


if __name__ == "__main__":
    main()
