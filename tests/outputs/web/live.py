"""A live ``rosvar serve`` server in a thread of the test process, and a plain HTTP client.

A server listens on a free loopback port (port 0) with the real engine; :meth:`Live.call`
sends exactly the request given (raw paths, headers and bodies), so refusals can be tested.
"""

from __future__ import annotations

import http.client
import json
import os
import threading
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.engine import Configurator
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.documents.state import state_document
from rosvar.outputs.web.entries import render
from rosvar.outputs.web.server import WebServer, make_server
from rosvar.workspace import discover

REPO = Path(__file__).resolve().parents[3]
CORPUS = Path(os.environ.get("ROSVAR_CORPUS", REPO.parent / "shared" / "corpus")).resolve()


@dataclass
class Reply:
    status: int
    headers: Mapping[str, str]
    body: bytes

    def json(self) -> Any:
        return json.loads(self.body)


@dataclass
class Live:
    """A running server and a small HTTP client for it."""

    server: WebServer

    @property
    def url(self) -> str:
        return self.server.url

    def call(
        self,
        method: str,
        path: str,
        body: object = None,
        headers: Mapping[str, str] | None = None,
        raw: bytes | None = None,
    ) -> Reply:
        """One request; ``body`` is sent as JSON, ``raw`` as given (with its own headers)."""
        host, port = self.server.server_address[:2]
        connection = http.client.HTTPConnection(str(host), port, timeout=60)
        sent = dict(headers or {})
        data = raw
        if body is not None:
            data = json.dumps(body).encode()
            sent.setdefault("Content-Type", "application/json")
        try:
            connection.request(method, path, body=data, headers=sent)
            response = connection.getresponse()
            return Reply(response.status, dict(response.getheaders()), response.read())
        finally:
            connection.close()

    def post(self, path: str, body: object) -> Any:
        """A POST that must succeed; its JSON answer."""
        reply = self.call("POST", path, body)
        assert reply.status == 200, reply.body
        return reply.json()

    def open(self) -> Any:
        return self.post("/api/session", {})

    def whole(self, session: str) -> dict[str, Any]:
        """A tab's current state whole, every graph entry with it (what a session not in
        overview mode is sent): what the page, which fetches only what it draws, must
        account for. Read in-process, under the API's lock."""
        api = self.server.api
        with api._lock:
            tab = api._store.get(session)
            assert tab is not None, "no such session"
            document = state_document(tab.session.current())
        whole: dict[str, Any] = json.loads(json.dumps(document))
        return whole


def configurator(paths: list[Path], package_path: str = "") -> Configurator:
    analysis = Analysis(discover([str(p) for p in paths], ros_package_path=package_path))
    return Configurator(analysis, extract(analysis, products=True), render=render)


@contextmanager
def running(engine: Configurator, capacity: int = 64) -> Iterator[Live]:
    server = make_server(engine, "127.0.0.1", 0, capacity)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield Live(server)
    finally:
        server.shutdown()
        server.server_close()
        thread.join(timeout=10)


def corpus_system(name: str) -> Path:
    root = CORPUS / name
    if not root.is_dir():
        pytest.skip(f"corpus system {name} not found at {root}")
    return root
