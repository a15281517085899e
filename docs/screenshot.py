"""Take the screenshots of the web UI shown in docs/web.md (and docs/web-ui.png, the README's).

    python docs/screenshot.py [--out-dir DIR] [--corpus DIR]

Serves Husky (``DIR/husky``) with ``rosvar serve --port 0`` as a user runs it (node
interfaces, catalogue and checks included), once with its dependencies in ``DIR/_external``
on the package path and once with ``_external`` as a second root (its launch files features
too); default corpus: the shared corpus next to the repository, or ``$ROSVAR_CORPUS``. Each
is opened in headless Chromium (Debian's ``/usr/bin/chromium`` through Playwright, as the
browser tests do) at 1600×1000 and the page saved as a user meets it:

* ``web-first.png``: Husky's first view;
* ``web-choice.png``: ``husky_playpen.launch`` selected;
* ``web-fit.png``: then zoomed in by the user (the view stays), and *Fit* pressed;
* ``web-ui.png``: then ``husky_empty_world.launch`` deselected, the playpen's row scrolled
  into view in the tree: a configuration half done (the README's picture);
* ``web-external-first.png``, ``web-external-choice.png``: Husky with ``_external`` as a
  second root, first view and ``husky_playpen.launch`` selected.
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

from playwright.sync_api import Browser, Page, sync_playwright

DOCS = Path(__file__).resolve().parent
CORPUS = Path(os.environ.get("ROSVAR_CORPUS", DOCS.parent.parent / "shared" / "corpus"))
CHROMIUM = "/usr/bin/chromium"
WAIT_MS = 600_000  # the large workspace's first state on a busy machine
PLAYPEN = "husky_gazebo/launch/husky_playpen.launch"
EMPTY_WORLD = "husky_gazebo/launch/husky_empty_world.launch"


def settled(page: Page) -> None:
    """The page's graph laid out, the view still, the group members and checks answered."""
    page.wait_for_selector('#graph[data-layout="done"]')
    page.wait_for_function("() => !window.rosvar.graph.cy.animated()")
    page.wait_for_function(
        "() => /errors/.test(document.getElementById('checks-count').textContent)"
    )
    page.wait_for_load_state("networkidle")


def next_step(page: Page, act: Callable[[], object]) -> None:
    before = page.locator("body").get_attribute("data-step")
    act()
    page.wait_for_selector(f'body:not([data-step="{before}"])')
    settled(page)


def file_id(page: Page, end: str) -> str:
    features = page.evaluate("window.rosvar.state.features")
    return str(next(k for k, f in features.items() if f["kind"] == "file" and k.endswith(end)))


def choose(page: Page, end: str, action: str) -> None:
    row = page.locator(f'.feature[data-id="{file_id(page, end)}"]').first
    own = row.locator(":scope > summary, :scope > .row").first
    next_step(page, own.locator(f'.choose button[data-action="{action}"]').click)


@contextmanager
def served(roots: list[str]) -> Iterator[str]:
    """``rosvar serve`` on ``roots`` (and options), its address while it runs."""
    command = [sys.executable, "-m", "rosvar", "serve", *roots, "--port", "0"]
    server = subprocess.Popen(command, stdout=subprocess.PIPE, text=True)
    try:
        assert server.stdout is not None
        yield next(m[1] for line in server.stdout if (m := re.search(r"(http://\S+)", line)))
    finally:
        server.terminate()
        server.wait()


def opened(browser: Browser, address: str) -> Page:
    page = browser.new_page(viewport={"width": 1600, "height": 1000})
    page.set_default_timeout(WAIT_MS)
    page.goto(address)
    page.wait_for_selector("body[data-step]")
    settled(page)
    return page


def husky(browser: Browser, corpus: Path, out: Path) -> None:
    with served([str(corpus / "husky"), "--deps", str(corpus / "_external")]) as address:
        page = opened(browser, address)
        page.screenshot(path=out / "web-first.png")
        choose(page, PLAYPEN, "select")
        page.screenshot(path=out / "web-choice.png")
        canvas = page.locator("#graph").bounding_box()
        assert canvas is not None
        page.mouse.move(canvas["x"] + canvas["width"] / 3, canvas["y"] + canvas["height"] / 3)
        for _ in range(4):
            page.mouse.wheel(0, -300)  # the user zooms in: the view is theirs until Fit
        page.click("#fit")
        settled(page)
        page.screenshot(path=out / "web-fit.png")
        choose(page, EMPTY_WORLD, "deselect")
        playpen = file_id(page, PLAYPEN)
        page.locator(f'.feature[data-id="{playpen}"]').scroll_into_view_if_needed()
        settled(page)
        page.screenshot(path=out / "web-ui.png")
        page.close()


def husky_external(browser: Browser, corpus: Path, out: Path) -> None:
    with served([str(corpus / "husky"), str(corpus / "_external")]) as address:
        page = opened(browser, address)
        page.screenshot(path=out / "web-external-first.png")
        choose(page, PLAYPEN, "select")
        page.screenshot(path=out / "web-external-choice.png")
        page.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", type=Path, default=CORPUS)
    parser.add_argument("--out-dir", type=Path, default=DOCS)
    options = parser.parse_args()
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM)
        husky(browser, options.corpus, options.out_dir)
        husky_external(browser, options.corpus, options.out_dir)
        browser.close()
    print(f"wrote the screenshots into {options.out_dir}")


if __name__ == "__main__":
    main()
