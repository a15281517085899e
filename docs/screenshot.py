"""Take the screenshot of the web UI shown in docs/web.md (``docs/web-ui.png``).

    python docs/screenshot.py [--out FILE] [--corpus DIR]

Serves Husky (``DIR/husky``, its dependencies in ``DIR/_external``; default: the shared
corpus next to the repository, or ``$ROSVAR_CORPUS``) with ``rosvar serve --port 0`` as a
user runs it (node interfaces, catalogue and checks included), opens it in headless Chromium
(Debian's ``/usr/bin/chromium`` through Playwright, as the browser tests do) at 1400×900,
makes a few choices as a user would (a world, a robot description, one node's details: a
configuration half done) and saves the page.
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
from pathlib import Path

from playwright.sync_api import Page, sync_playwright

DOCS = Path(__file__).resolve().parent
CORPUS = Path(os.environ.get("ROSVAR_CORPUS", DOCS.parent.parent / "shared" / "corpus"))
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
    """Husky's playpen world chosen, the empty world left out, the playpen's args unfolded
    in the tree: a configuration half done, its own nodes drawn first."""
    features = page.evaluate("window.rosvar.state.features")

    def named(end: str) -> str:
        return next(k for k, f in features.items() if f["kind"] == "file" and k.endswith(end))

    playpen = named("husky_gazebo/launch/husky_playpen.launch")
    choose(page, playpen, "select")
    choose(page, named("husky_gazebo/launch/husky_empty_world.launch"), "deselect")
    page.locator(f'.feature[data-id="{playpen}"] > summary .name').click()
    page.locator(f'.feature[data-id="{playpen}"]').scroll_into_view_if_needed()
    page.wait_for_selector('#graph[data-layout="done"]')
    page.wait_for_load_state("networkidle")  # the checks and the group members answered


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", type=Path, default=CORPUS)
    parser.add_argument("--out", default=str(DOCS / "web-ui.png"))
    options = parser.parse_args()
    command = [sys.executable, "-m", "rosvar", "serve", str(options.corpus / "husky")]
    command += ["--deps", str(options.corpus / "_external"), "--port", "0"]
    server = subprocess.Popen(command, stdout=subprocess.PIPE, text=True)
    try:
        assert server.stdout is not None
        address = next(m[1] for line in server.stdout if (m := re.search(r"(http://\S+)", line)))
        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=CHROMIUM)
            page = browser.new_page(viewport={"width": 1400, "height": 900})
            page.goto(address)
            page.wait_for_selector("body[data-step]")
            stage(page)
            page.screenshot(path=options.out)
            browser.close()
    finally:
        server.terminate()
        server.wait()
    print(f"wrote {options.out}")


if __name__ == "__main__":
    main()
