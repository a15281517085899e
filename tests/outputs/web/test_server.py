"""The HTTP layer: only the app's own files, loopback Host, JSON bodies of bounded size."""

from __future__ import annotations

import contextlib
import json
import socket
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

from outputs.web.live import Live
from rosvar.outputs.web import server
from rosvar.outputs.web.assets import load_assets
from rosvar.outputs.web.server import MAX_BODY, is_loopback, parse_json


def test_page_and_assets_are_served(examples: Live) -> None:
    for url, asset in load_assets().items():
        reply = examples.call("GET", url)
        assert reply.status == 200, url
        assert reply.body == asset.body
        assert reply.headers["Content-Type"] == asset.content_type
    page = examples.call("GET", "/")
    assert "script-src 'self'" in page.headers["Content-Security-Policy"]
    assert page.headers["X-Content-Type-Options"] == "nosniff"


TRAVERSALS = [
    "/assets/../assets.py",
    "/assets/%2e%2e/server.py",
    "/assets/js/../../api.py",
    "/assets/vendor/%2E%2E%2F%2E%2E%2Fsessions.py",
    "/static/index.html",
    "/index.html",
    "//etc/passwd",
    "/assets//etc/passwd",
    "/assets/",
    "/assets/js",
    "/assets/style.css?x=1",
    "/etc/passwd",
    "/../../../../etc/passwd",
]


@pytest.mark.parametrize("path", TRAVERSALS)
def test_nothing_outside_the_app_is_served(examples: Live, path: str) -> None:
    reply = examples.call("GET", path)
    assert reply.status == 404
    assert "error" in reply.json()
    assert b"import" not in reply.body and b"root:" not in reply.body


def test_host_header_must_name_the_loopback(examples: Live) -> None:
    port = examples.server.server_address[1]
    for host in ("evil.example", f"evil.example:{port}", "127.0.0.1.evil.example"):
        reply = examples.call("GET", "/", headers={"Host": host})
        assert reply.status == 403, host
    for host in (f"localhost:{port}", f"127.0.0.1:{port}", "localhost"):
        assert examples.call("GET", "/", headers={"Host": host}).status == 200, host


def test_loopback_addresses() -> None:
    assert all(is_loopback(h) for h in ("127.0.0.1", "127.8.0.1", "::1", "localhost"))
    assert not any(is_loopback(h) for h in ("0.0.0.0", "192.168.1.2", "::", "example.org"))


def test_body_must_be_json_of_bounded_size(examples: Live) -> None:
    wrong_type = examples.call(
        "POST", "/api/session", raw=b"{}", headers={"Content-Type": "text/plain"}
    )
    assert wrong_type.status == 415
    form = examples.call(
        "POST", "/api/session", raw=b"a=b",
        headers={"Content-Type": "application/x-www-form-urlencoded"},
    )  # fmt: skip
    assert form.status == 415
    broken = examples.call(
        "POST", "/api/session", raw=b"{not json", headers={"Content-Type": "application/json"}
    )
    assert broken.status == 400
    big = json.dumps({"session": "x" * MAX_BODY}).encode()
    too_big = examples.call(
        "POST", "/api/undo", raw=big, headers={"Content-Type": "application/json"}
    )
    assert too_big.status == 413
    assert "error" in too_big.json()


def test_body_needs_a_length(examples: Live) -> None:
    host, port = examples.server.server_address[:2]
    with socket.create_connection((str(host), port), timeout=30) as connection:
        connection.sendall(
            b"POST /api/session HTTP/1.1\r\nHost: 127.0.0.1\r\n"
            b"Content-Type: application/json\r\nConnection: close\r\n\r\n"
        )
        answer = b""
        while chunk := connection.recv(65536):
            answer += chunk
    status_line, _, rest = answer.partition(b"\r\n")
    assert status_line.split()[1] == b"411"
    assert "error" in json.loads(rest.partition(b"\r\n\r\n")[2])


@pytest.mark.parametrize("method", ["PUT", "DELETE", "PATCH", "OPTIONS"])
def test_other_methods_are_not_allowed(examples: Live, method: str) -> None:
    reply = examples.call(method, "/api/session", raw=b"")
    assert reply.status == 405
    assert "error" in reply.json()


def test_dropped_connections_are_not_logged_as_errors(
    examples: Live, capsys: pytest.CaptureFixture[str]
) -> None:
    """A closed tab resets its connection: no traceback; a real failure still has one."""
    for error, logged in ((ConnectionResetError(104, "reset"), False), (KeyError("bug"), True)):
        try:
            raise error
        except Exception:
            examples.server.handle_error(None, ("127.0.0.1", 1))
        assert ("Traceback" in capsys.readouterr().err) is logged


JSON = {"Content-Type": "application/json"}


@pytest.mark.parametrize(
    "raw",
    [
        b"[" * 100_000 + b"]" * 100_000,
        b'{"a": ' + b"[" * 40 + b"]" * 40 + b"}",
        b'{"session": ' + b"9" * 60_000 + b"}",
        b'{"session": 1.' + b"5" * 60_000 + b"}",
        b'{"a": "\\"[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[", "b": '
        + b"9" * 200
        + b"}",
    ],
)
def test_hostile_json_bodies_are_400s(examples: Live, raw: bytes) -> None:
    if len(raw) > MAX_BODY:
        raw = raw[:MAX_BODY]
    reply = examples.call("POST", "/api/session", raw=raw, headers=JSON)
    assert reply.status == 400
    assert "error" in reply.json()
    assert examples.call("GET", "/").status == 200  # the server goes on


def test_brackets_inside_strings_are_not_nesting() -> None:
    text = json.dumps({"a": "[" * 1000, "b": '\\"{' * 100})
    assert parse_json(text.encode()) == json.loads(text)


def test_state_changes_from_other_origins_are_refused(examples: Live) -> None:
    port = examples.server.server_address[1]
    for origin in ("http://evil.example", f"http://evil.example:{port}", "null"):
        headers = {**JSON, "Origin": origin}
        reply = examples.call("POST", "/api/session", raw=b"{}", headers=headers)
        assert reply.status == 403, origin
    own = {**JSON, "Origin": f"http://127.0.0.1:{port}", "Host": f"127.0.0.1:{port}"}
    assert examples.call("POST", "/api/session", raw=b"{}", headers=own).status == 200
    assert examples.call("POST", "/api/session", raw=b"{}", headers=JSON).status == 200


def test_many_concurrent_connections_are_all_answered(examples: Live) -> None:
    """More clients than worker threads at once: they wait in the listen queue, none is reset."""

    def fetch(_index: int) -> int:
        return examples.call("GET", "/").status

    with ThreadPoolExecutor(64) as pool:
        statuses = list(pool.map(fetch, range(200)))
    assert statuses == [200] * 200
    assert examples.server.request_queue_size >= 128


def test_idle_connections_are_closed(examples: Live, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(server, "REQUEST_DEADLINE", 0.5)
    host, port = examples.server.server_address[:2]
    with socket.create_connection((str(host), port), timeout=30) as connection:
        connection.sendall(b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n")  # never finished
        assert connection.recv(65536) == b""  # closed by the server, not left waiting


def test_slowly_sending_clients_keep_no_other_waiting(examples: Live) -> None:
    """issue 30.5: 30 connections that send a request a byte at a time held every thread of
    the server (one per connection, each waiting on its socket): now an event loop reads
    them, and a request must arrive whole within ``REQUEST_DEADLINE``."""
    host, port = examples.server.server_address[:2]
    slow = [socket.create_connection((str(host), port), timeout=30) for _ in range(30)]
    stop = threading.Event()

    def trickle() -> None:
        line = b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: " + b"x" * 1000
        for byte in line:
            if stop.is_set():
                return
            for connection in slow:
                with contextlib.suppress(OSError):
                    connection.send(bytes([byte]))
            time.sleep(0.05)

    sender = threading.Thread(target=trickle, daemon=True)
    sender.start()
    try:
        time.sleep(0.5)
        started = time.monotonic()
        assert examples.call("GET", "/").status == 200
        assert examples.call("POST", "/api/session", {}).status == 200
        assert time.monotonic() - started < 5
    finally:
        stop.set()
        sender.join()
        for connection in slow:
            connection.close()
