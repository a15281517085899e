"""The HTTP side of ``rosvar serve``: the app's own files and the JSON API, nothing else.

Requests are checked before they reach the API: the ``Host`` header must name the loopback
when the server is bound to it (a page elsewhere cannot reach the API through DNS
rebinding), POST bodies must be JSON objects of bounded size with the JSON content type (a
plain HTML form cannot post one) whose ``Origin``, when a browser sends one, is this server
(another page cannot change a session), and every refusal is a 4xx answer
``{"error": message}``. Bodies are parsed within limits (nesting, number lengths).

Connections are read by one event loop (``asyncio``), never by a thread each: a client that
sends slowly, or holds its connection open, costs no thread, and cannot keep the others
waiting. A request must arrive whole within ``REQUEST_DEADLINE`` of the server starting to
wait for it (an idle connection is closed then). Only the API's calls go to a pool of threads,
where they wait for the engine (``Api``: at most ``ENGINE_WAIT``, then a 503 the page tries
again); the app's files and the catalog are answered at once, whatever the engine is doing.
"""

from __future__ import annotations

import asyncio
import ipaddress
import json
import socket
import sys
import threading
import traceback
from collections.abc import Mapping
from concurrent.futures import ThreadPoolExecutor
from http import HTTPStatus
from typing import Any
from urllib.parse import parse_qsl, urlsplit

from rosvar.configuration.engine import Configurator
from rosvar.outputs.web.api import Api, ApiError
from rosvar.outputs.web.assets import Asset, load_assets
from rosvar.outputs.web.sessions import DEFAULT_CAPACITY

MAX_BODY = 64 * 1024
MAX_HEADERS = 16 * 1024
"""Bytes of a request's line and headers together (a browser's are under 2 KB)."""
MAX_JSON_DEPTH = 32
"""Arrays and objects nested in a request body (the API's bodies nest two or three)."""
MAX_NUMBER_CHARS = 100
"""Characters of a number in a request body (Python's int() of a long one is quadratic)."""
WORKERS = 16
"""Threads that run API calls (they wait in turn for the engine)."""
MAX_PENDING = 64
"""API calls waiting for a thread or for the engine; more are answered 503 at once."""
MAX_CONNECTIONS = 1024
"""Open connections; a new one beyond is closed at once (the page keeps a few)."""
LISTEN_BACKLOG = 128
REQUEST_DEADLINE = 10.0
"""Seconds from waiting for a request to having it whole (line, headers and body): an idle
connection, or one sending too slowly, is closed then."""
API_PREFIX = "/api/"
LOOPBACK_NAMES = ("localhost", "127.0.0.1", "[::1]")
METHODS = frozenset({"GET", "POST"})

SECURITY_HEADERS = {
    "X-Content-Type-Options": "nosniff",
    "X-Frame-Options": "DENY",
    "Referrer-Policy": "no-referrer",
    # scripts only from this server; Cytoscape sets inline styles on its canvas
    "Content-Security-Policy": (
        "default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; "
        "img-src 'self' data:; connect-src 'self'; frame-ancestors 'none'"
    ),
}


def is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


class WebServer:
    """One configurator's API and the app's files, on one address: connections read by an
    event loop (``serve_forever``), API calls run by :data:`WORKERS` threads."""

    request_queue_size = LISTEN_BACKLOG

    def __init__(self, api: Api, host: str, port: int) -> None:
        self.api = api
        self.assets: dict[str, Asset] = load_assets()
        self.host = host
        self.loopback = is_loopback(host)
        self.socket = socket.create_server(
            (host, port),
            family=socket.AF_INET6 if ":" in host else socket.AF_INET,
            backlog=LISTEN_BACKLOG,
        )
        self.server_address: tuple[Any, ...] = self.socket.getsockname()
        self._pool = ThreadPoolExecutor(WORKERS, thread_name_prefix="rosvar-api")
        self._loop = asyncio.new_event_loop()
        self._stop: asyncio.Event | None = None
        self._stopped = threading.Event()
        self._tasks: set[asyncio.Task[None]] = set()  # the open connections'
        self._pending = 0

    def __enter__(self) -> WebServer:
        return self

    def __exit__(self, *_exception: object) -> None:
        self.server_close()

    def serve_forever(self) -> None:
        """Serve until :meth:`shutdown` (or Ctrl-C, raised from here)."""
        self._stopped.clear()
        try:
            self._loop.run_until_complete(self._serve())
        finally:
            self._stopped.set()

    async def _serve(self) -> None:
        self._stop = asyncio.Event()
        server = await asyncio.start_server(
            self._connection, sock=self.socket, limit=MAX_HEADERS, backlog=LISTEN_BACKLOG
        )
        try:
            await self._stop.wait()
        finally:
            server.close()
            for task in self._tasks:  # open connections end with the server
                task.cancel()
            await asyncio.gather(*self._tasks, return_exceptions=True)

    def shutdown(self) -> None:
        """Stop :meth:`serve_forever` (from another thread) and wait until it returns."""
        stop = self._stop
        if stop is not None:
            self._loop.call_soon_threadsafe(stop.set)
            self._stopped.wait()

    def server_close(self) -> None:
        self.socket.close()
        self._pool.shutdown(wait=False, cancel_futures=True)
        if not self._loop.is_running():
            self._loop.close()

    def allows_origin(self, origin: str | None, host: str | None) -> bool:
        """A state-changing request from a browser comes from this server's own page: its
        ``Origin`` names the host it addresses (clients other than browsers send none)."""
        if origin is None:
            return True
        parts = urlsplit(origin)
        return parts.scheme == "http" and host is not None and parts.netloc == host

    @property
    def url(self) -> str:
        shown = f"[{self.host}]" if ":" in self.host else self.host
        return f"http://{shown}:{self.server_address[1]}/"

    def allows_host(self, header: str | None) -> bool:
        """On loopback, only requests addressed to a loopback name (no DNS rebinding)."""
        if not self.loopback:
            return True
        if header is None:
            return False
        name = header.rsplit(":", 1)[0] if not header.endswith("]") else header
        return name.lower() in LOOPBACK_NAMES

    def handle_error(self, request: object, client_address: object) -> None:
        """A failure answering a request, said on stderr with its traceback; a browser that
        drops its connection (a closed tab, a reload) is no server error."""
        if isinstance(sys.exc_info()[1], ConnectionError):
            return
        print(f"rosvar: error answering {client_address}:", file=sys.stderr)
        traceback.print_exc()

    # -- connections -------------------------------------------------------------------------
    async def _connection(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        """One connection's requests, one after the other (HTTP/1.1 keeps it open)."""
        task = asyncio.current_task()
        assert task is not None
        self._tasks.add(task)
        try:
            if len(self._tasks) > MAX_CONNECTIONS:
                return
            while True:
                try:
                    request = await asyncio.wait_for(_Request.read(reader), REQUEST_DEADLINE)
                except (TimeoutError, asyncio.IncompleteReadError, ConnectionError):
                    return  # idle, too slow, or gone
                except ApiError as error:  # unreadable: answered, and the connection closed
                    await self._send(writer, _error_reply(error), keep=False)
                    return
                reply = await self._answer(request)
                keep = request.keep_alive and reply.keep
                await self._send(writer, reply, keep)
                if not keep:
                    return
        except (ConnectionError, asyncio.CancelledError):  # gone, or the server stopping
            return
        except Exception:
            self.handle_error(None, writer.get_extra_info("peername"))
        finally:
            self._tasks.discard(task)
            writer.close()

    async def _answer(self, request: _Request) -> _Reply:
        try:
            if not self.allows_host(request.headers.get("host")):
                raise ApiError(HTTPStatus.FORBIDDEN, "requests must address the loopback host")
            if request.method != "GET" and not self.allows_origin(
                request.headers.get("origin"), request.headers.get("host")
            ):
                raise ApiError(HTTPStatus.FORBIDDEN, "requests from other origins are refused")
            url = urlsplit(request.target)
            if url.path.startswith(API_PREFIX):
                body = request.json() if request.method == "POST" else {}
                query = _query(url.query)
                document = await self._call(request.method, url.path, query, body)
                return _json_reply(HTTPStatus.OK, document)
            if request.method == "GET" and not url.query and url.path in self.assets:
                asset = self.assets[url.path]
                return _Reply(HTTPStatus.OK, asset.body, asset.content_type, "no-cache")
            raise ApiError(HTTPStatus.NOT_FOUND, f"not found: {url.path}")
        except ApiError as error:
            return _error_reply(error)

    async def _call(self, method: str, path: str, query: dict[str, str], body: Any) -> Any:
        """The API's answer, computed by a thread of the pool (it may wait for the engine)."""
        if self._pending >= MAX_PENDING:
            raise ApiError(HTTPStatus.SERVICE_UNAVAILABLE, "the server is busy: try again")
        self._pending += 1
        try:
            return await self._loop.run_in_executor(
                self._pool, self.api.handle, method, path, query, body
            )
        finally:
            self._pending -= 1

    async def _send(self, writer: asyncio.StreamWriter, reply: _Reply, keep: bool) -> None:
        status = HTTPStatus(reply.status)
        lines = [
            f"HTTP/1.1 {status.value} {status.phrase}",
            "Server: rosvar",
            f"Content-Type: {reply.content_type}",
            f"Content-Length: {len(reply.body)}",
            f"Cache-Control: {reply.cache}",
            *(f"{name}: {value}" for name, value in SECURITY_HEADERS.items()),
            *(f"{name}: {value}" for name, value in reply.headers.items()),
            "Connection: keep-alive" if keep else "Connection: close",
        ]
        writer.write(("\r\n".join(lines) + "\r\n\r\n").encode("latin-1") + reply.body)
        await writer.drain()


class _Reply:
    """An answer: status, body and how it may be cached; ``keep`` False closes the
    connection after it (a body left unread must not be taken for a request)."""

    def __init__(
        self,
        status: HTTPStatus,
        body: bytes,
        content_type: str,
        cache: str,
        keep: bool = True,
        headers: Mapping[str, str] | None = None,
    ) -> None:
        self.status = status
        self.body = body
        self.content_type = content_type
        self.cache = cache
        self.keep = keep
        self.headers = headers or {}


def _json_reply(status: HTTPStatus, document: object, keep: bool = True) -> _Reply:
    body = json.dumps(document, separators=(",", ":")).encode()  # ASCII: the fast path
    headers = {"Retry-After": "1"} if status == HTTPStatus.SERVICE_UNAVAILABLE else {}
    return _Reply(status, body, "application/json; charset=utf-8", "no-store", keep, headers)


def _error_reply(error: ApiError) -> _Reply:
    keep = error.status not in _CLOSING
    return _json_reply(error.status, {"error": error.message, **error.extra}, keep)


_CLOSING = frozenset(
    {
        HTTPStatus.METHOD_NOT_ALLOWED,
        HTTPStatus.REQUEST_ENTITY_TOO_LARGE,
        HTTPStatus.LENGTH_REQUIRED,
        HTTPStatus.UNSUPPORTED_MEDIA_TYPE,
        HTTPStatus.BAD_REQUEST,
        HTTPStatus.REQUEST_HEADER_FIELDS_TOO_LARGE,
    }
)
"""Refusals after which the connection is closed: the body, if any, is left unread."""


class _Request:
    """A request as read off a connection: method, target, headers (lower-case names) and
    the body's bytes (POST)."""

    def __init__(self, method: str, target: str, version: str, headers: dict[str, str]) -> None:
        self.method = method
        self.target = target
        self.headers = headers
        self.body = b""
        connection = headers.get("connection", "").lower()
        self.keep_alive = connection != "close" and (
            version == "HTTP/1.1" or connection == "keep-alive"
        )

    @classmethod
    async def read(cls, reader: asyncio.StreamReader) -> _Request:
        """The next request; :class:`ApiError` for one that cannot be read or is refused
        before its body is."""
        try:
            line = await reader.readline()
            if not line:
                raise asyncio.IncompleteReadError(b"", None)
            parts = line.decode("latin-1").split()
            if len(parts) != 3 or not parts[2].startswith("HTTP/1."):
                raise ApiError(HTTPStatus.BAD_REQUEST, "bad request line")
            headers: dict[str, str] = {}
            size = len(line)
            while True:
                field = await reader.readline()
                size += len(field)
                if size > MAX_HEADERS:
                    raise ApiError(HTTPStatus.REQUEST_HEADER_FIELDS_TOO_LARGE, "headers too large")
                if field in (b"\r\n", b"\n"):
                    break
                if not field.endswith(b"\n"):
                    raise asyncio.IncompleteReadError(field, None)
                name, colon, value = field.decode("latin-1").partition(":")
                if not colon:
                    raise ApiError(HTTPStatus.BAD_REQUEST, "bad header line")
                headers[name.strip().lower()] = value.strip()
        except (ValueError, asyncio.LimitOverrunError):  # a line over the reader's limit
            raise ApiError(
                HTTPStatus.REQUEST_HEADER_FIELDS_TOO_LARGE, "headers too large"
            ) from None
        request = cls(parts[0], parts[1], parts[2], headers)
        if request.method not in METHODS:
            raise ApiError(HTTPStatus.METHOD_NOT_ALLOWED, f"method {request.method} not allowed")
        if request.method == "POST" and urlsplit(request.target).path.startswith(API_PREFIX):
            request.body = await request._body(reader)
        elif request.headers.get("content-length", "0") != "0":
            request.keep_alive = False  # a body left unread must not be taken for a request
        return request

    async def _body(self, reader: asyncio.StreamReader) -> bytes:
        content_type = self.headers.get("content-type", "").split(";")[0].strip().lower()
        if content_type != "application/json":
            raise ApiError(HTTPStatus.UNSUPPORTED_MEDIA_TYPE, "body must be application/json")
        length = self.headers.get("content-length")
        if length is None or not length.isdigit():
            raise ApiError(HTTPStatus.LENGTH_REQUIRED, "Content-Length required")
        if int(length) > MAX_BODY:
            raise ApiError(HTTPStatus.REQUEST_ENTITY_TOO_LARGE, f"body over {MAX_BODY} bytes")
        return await reader.readexactly(int(length))

    def json(self) -> dict[str, object]:
        body = parse_json(self.body or b"{}")
        if not isinstance(body, dict):
            raise ApiError(HTTPStatus.BAD_REQUEST, "body must be a JSON object")
        return body


def _query(text: str) -> dict[str, str]:
    try:
        pairs = parse_qsl(text, strict_parsing=bool(text), max_num_fields=8)
    except ValueError as error:
        raise ApiError(HTTPStatus.BAD_REQUEST, f"bad query string: {error}") from None
    query = dict(pairs)
    if len(query) != len(pairs):
        raise ApiError(HTTPStatus.BAD_REQUEST, "repeated query parameter")
    return query


def parse_json(data: bytes) -> object:
    """A request body as JSON within :data:`MAX_JSON_DEPTH` and :data:`MAX_NUMBER_CHARS`,
    else :class:`ApiError` 400 (never an exception from the parser)."""
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as error:
        raise ApiError(HTTPStatus.BAD_REQUEST, f"body is not JSON: {error}") from None
    depth, inside, escaped = 0, False, False
    for char in text:  # nesting counted outside strings, before the recursive parser runs
        if inside:
            if escaped:
                escaped = False
            elif char == "\\":
                escaped = True
            elif char == '"':
                inside = False
        elif char == '"':
            inside = True
        elif char in "[{":
            depth += 1
            if depth > MAX_JSON_DEPTH:
                raise ApiError(HTTPStatus.BAD_REQUEST, f"body nested over {MAX_JSON_DEPTH} deep")
        elif char in "]}":
            depth -= 1
    try:
        return json.loads(text, parse_int=_number(int), parse_float=_number(float))
    except (json.JSONDecodeError, _NumberTooLong) as error:
        raise ApiError(HTTPStatus.BAD_REQUEST, f"body is not JSON: {error}") from None


class _NumberTooLong(ValueError):
    pass


def _number(convert: type[int] | type[float]) -> Any:
    def parse(text: str) -> int | float:
        if len(text) > MAX_NUMBER_CHARS:
            raise _NumberTooLong(f"a number over {MAX_NUMBER_CHARS} characters")
        return convert(text)

    return parse


def make_server(
    configurator: Configurator,
    host: str = "127.0.0.1",
    port: int = 0,
    capacity: int = DEFAULT_CAPACITY,
) -> WebServer:
    """A bound server (``port=0`` picks a free port; see ``.url``), not yet serving."""
    return WebServer(Api(configurator, capacity), host, port)
