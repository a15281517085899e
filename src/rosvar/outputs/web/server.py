"""The HTTP side of ``rosvar serve``: the app's own files and the JSON API, nothing else.

Requests are checked before they reach the API: the ``Host`` header must name the loopback
when the server is bound to it (a page elsewhere cannot reach the API through DNS
rebinding), POST bodies must be JSON objects of bounded size with the JSON content type (a
plain HTML form cannot post one) whose ``Origin``, when a browser sends one, is this server
(another page cannot change a session), and every refusal is a 4xx answer
``{"error": message}``. Bodies are parsed within limits (nesting, number lengths), and
connections are served by a bounded pool of threads, each connection with a timeout: a
client holding connections open cannot make the server start threads without end.
"""

from __future__ import annotations

import ipaddress
import json
import sys
from collections.abc import Mapping
from concurrent.futures import ThreadPoolExecutor
from http import HTTPStatus
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any
from urllib.parse import parse_qsl, urlsplit

from rosvar.configuration.engine import Configurator
from rosvar.outputs.web.api import Api, ApiError
from rosvar.outputs.web.assets import Asset, load_assets
from rosvar.outputs.web.sessions import DEFAULT_CAPACITY

MAX_BODY = 64 * 1024
MAX_JSON_DEPTH = 32
"""Arrays and objects nested in a request body (the API's bodies nest two or three)."""
MAX_NUMBER_CHARS = 100
"""Characters of a number in a request body (Python's int() of a long one is quadratic)."""
WORKERS = 16
"""Threads serving connections; more connections wait in the listen queue."""
LISTEN_BACKLOG = 128
CONNECTION_TIMEOUT = 10.0
"""Seconds a connection may stay silent (between or within requests) before it is closed."""
API_PREFIX = "/api/"
LOOPBACK_NAMES = ("localhost", "127.0.0.1", "[::1]")

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


class WebServer(ThreadingHTTPServer):
    """One configurator's API and the app's files, on one address; connections served by a
    pool of :data:`WORKERS` threads."""

    daemon_threads = True
    request_queue_size = LISTEN_BACKLOG

    def __init__(self, api: Api, host: str, port: int) -> None:
        self.api = api
        self.assets: dict[str, Asset] = load_assets()
        self.host = host
        self.loopback = is_loopback(host)
        self._pool = ThreadPoolExecutor(WORKERS, thread_name_prefix="rosvar-http")
        super().__init__((host, port), _Handler)

    def process_request(self, request: Any, client_address: Any) -> None:
        """Hand the connection to the pool (``ThreadingMixIn`` starts a thread for each)."""
        self._pool.submit(self.process_request_thread, request, client_address)

    def server_close(self) -> None:
        super().server_close()
        self._pool.shutdown(wait=False, cancel_futures=True)

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
        """A browser that drops its connection (a closed tab, a reload) is no server error."""
        if isinstance(sys.exc_info()[1], ConnectionError):
            return
        super().handle_error(request, client_address)  # type: ignore[arg-type]


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


class _Handler(BaseHTTPRequestHandler):
    server: WebServer
    timeout = CONNECTION_TIMEOUT
    protocol_version = "HTTP/1.1"
    server_version = "rosvar"
    sys_version = ""
    # headers and body are two writes: with Nagle's algorithm the body's last segment could
    # wait for the client's delayed ACK (tens of ms per click on loopback)
    disable_nagle_algorithm = True

    def do_GET(self) -> None:
        self._dispatch("GET")

    def do_POST(self) -> None:
        self._dispatch("POST")

    def _refuse_method(self) -> None:
        self.close_connection = True  # a body, if any, is left unread
        self._error(HTTPStatus.METHOD_NOT_ALLOWED, f"method {self.command} not allowed")

    do_PUT = do_DELETE = do_PATCH = do_OPTIONS = do_HEAD = _refuse_method

    def log_message(self, format: str, *args: Any) -> None:
        """Quiet: the terminal shows the URL, not one line per click."""

    # -- dispatch ----------------------------------------------------------------------------
    def _dispatch(self, method: str) -> None:
        try:
            if not self.server.allows_host(self.headers.get("Host")):
                raise ApiError(HTTPStatus.FORBIDDEN, "requests must address the loopback host")
            if method != "GET" and not self.server.allows_origin(
                self.headers.get("Origin"), self.headers.get("Host")
            ):
                raise ApiError(HTTPStatus.FORBIDDEN, "requests from other origins are refused")
            url = urlsplit(self.path)
            if url.path.startswith(API_PREFIX):
                body = self._body() if method == "POST" else {}
                query = self._query(url.query)
                self._send_json(
                    HTTPStatus.OK, self.server.api.handle(method, url.path, query, body)
                )
            elif method == "GET" and not url.query and url.path in self.server.assets:
                self._send_asset(self.server.assets[url.path])
            else:
                raise ApiError(HTTPStatus.NOT_FOUND, f"not found: {url.path}")
        except ApiError as error:
            self._error(error.status, error.message, error.extra)

    @staticmethod
    def _query(text: str) -> dict[str, str]:
        try:
            pairs = parse_qsl(text, strict_parsing=bool(text), max_num_fields=8)
        except ValueError as error:
            raise ApiError(HTTPStatus.BAD_REQUEST, f"bad query string: {error}") from None
        query = dict(pairs)
        if len(query) != len(pairs):
            raise ApiError(HTTPStatus.BAD_REQUEST, "repeated query parameter")
        return query

    def _body(self) -> dict[str, object]:
        content_type = self.headers.get("Content-Type", "").split(";")[0].strip().lower()
        if content_type != "application/json":
            raise ApiError(HTTPStatus.UNSUPPORTED_MEDIA_TYPE, "body must be application/json")
        length_header = self.headers.get("Content-Length")
        if length_header is None or not length_header.isdigit():
            raise ApiError(HTTPStatus.LENGTH_REQUIRED, "Content-Length required")
        length = int(length_header)
        if length > MAX_BODY:
            self.close_connection = True  # the unread body must not be taken for a request
            raise ApiError(HTTPStatus.REQUEST_ENTITY_TOO_LARGE, f"body over {MAX_BODY} bytes")
        try:
            data = self.rfile.read(length)
        except TimeoutError:
            self.close_connection = True
            raise ApiError(HTTPStatus.REQUEST_TIMEOUT, "body not received in time") from None
        body = parse_json(data or b"{}")
        if not isinstance(body, dict):
            raise ApiError(HTTPStatus.BAD_REQUEST, "body must be a JSON object")
        return body

    # -- answers -----------------------------------------------------------------------------
    def _send(self, status: HTTPStatus, body: bytes, content_type: str, cache: str) -> None:
        self.send_response(status)
        self.send_header("Content-Type", content_type)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("Cache-Control", cache)
        for name, value in SECURITY_HEADERS.items():
            self.send_header(name, value)
        self.end_headers()
        self.wfile.write(body)

    def _send_json(self, status: HTTPStatus, document: object) -> None:
        body = json.dumps(document, separators=(",", ":")).encode()  # ASCII: the fast path
        self._send(status, body, "application/json; charset=utf-8", "no-store")

    def _send_asset(self, asset: Asset) -> None:
        self._send(HTTPStatus.OK, asset.body, asset.content_type, "no-cache")

    def _error(
        self, status: HTTPStatus, message: str, extra: Mapping[str, object] | None = None
    ) -> None:
        self._send_json(status, {"error": message, **(extra or {})})
