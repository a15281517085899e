"""Fixtures of the web UI tests: live ``rosvar serve`` servers and a headless Chromium.

Servers (``outputs.web.live``) run in a thread of the test process with the real engine over
``examples/`` or a corpus system. The browser is Debian's ``/usr/bin/chromium`` driven by
Playwright (its own browser builds are never downloaded). Without chromium or Playwright the
browser tests skip, except under CI (``CI=true``), where ``make test`` installs both and a
skip would hide a failure.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from typing import Any

import pytest

from outputs.web.live import REPO, Live, configurator, corpus_system, running
from rosvar.configuration.engine import Configurator

CHROMIUM = "/usr/bin/chromium"


@pytest.fixture(scope="session")
def examples_engine() -> Configurator:
    return configurator([REPO / "examples"])


@pytest.fixture(scope="module")
def examples(examples_engine: Configurator) -> Iterator[Live]:
    with running(examples_engine) as live:
        yield live


@pytest.fixture(scope="module")
def lizi() -> Iterator[Live]:
    with running(configurator([corpus_system("lizi")])) as live:
        yield live


# -- browser -------------------------------------------------------------------------------------
def _unavailable(reason: str) -> None:
    if os.environ.get("CI", "").lower() == "true":
        pytest.fail(f"browser tests cannot run under CI: {reason}")
    pytest.skip(reason)


@pytest.fixture
def browser() -> Iterator[Any]:
    """A fresh headless Chromium per test: no test inherits another's browser."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        _unavailable("Playwright is not installed (pip install -e '.[test]')")
    if not os.access(CHROMIUM, os.X_OK):
        _unavailable(f"{CHROMIUM} not found (make setup installs Debian's chromium)")
    with sync_playwright() as playwright:
        chromium = playwright.chromium.launch(
            executable_path=CHROMIUM,
            # precise: the page's heap as it is, not rounded and cached (``page``)
            args=["--disable-dev-shm-usage", "--disable-gpu", "--enable-precise-memory-info"],
        )
        yield chromium
        chromium.close()


HEAP_BOUND_MB = 1024
"""The page's JavaScript heap after a test, at most: Chromium stops a renderer whose heap
reaches its limit (3.5 GB here), which a test sees as "Target crashed". The page once held
Husky's whole states and reached it (4.3 GB); in overview mode it stays near 100 MB."""


BUSY = "the server responded with a status of 503"
"""What Chromium logs for the server's ``503`` + ``Retry-After`` while the engine computes
another client's step: an answer the page waits on and asks again (docs/web.md), no error."""


def failed(message: Any) -> bool:
    """Whether a console message of the page is an error of the page's."""
    return bool(message.type == "error" and BUSY not in message.text)


@pytest.fixture
def page(browser: Any) -> Iterator[Any]:
    """A fresh browser context (own sessionStorage) whose page errors fail the test, as does
    a JavaScript heap grown past ``HEAP_BOUND_MB``."""
    context = browser.new_context(viewport={"width": 1400, "height": 850})
    tab = context.new_page()
    errors: list[str] = []
    tab.on("pageerror", lambda error: errors.append(str(error)))
    tab.on("console", lambda message: errors.append(message.text) if failed(message) else None)
    yield tab
    heap = tab.evaluate("performance.memory.usedJSHeapSize") / 2**20
    context.close()
    assert errors == [], f"errors in the page: {errors}"
    assert heap < HEAP_BOUND_MB, f"the page's JavaScript heap is {heap:,.0f} MB"


@pytest.fixture(scope="module")
def husky() -> Iterator[Live]:
    """The largest corpus system (5 MB of state): the page must live on deltas there."""
    root, external = corpus_system("husky"), corpus_system("_external")
    with running(configurator([root], str(external))) as live:
        yield live
