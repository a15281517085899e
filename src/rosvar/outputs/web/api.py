"""The JSON API of ``rosvar serve``: validated requests in, configuration states out.

Every route is one entry of a table (method, path) → handler; every handler checks its
fields before the engine sees them (known session, known action, known feature id, bounded
text), and a bad request becomes an :class:`ApiError` with a 4xx status and a message.
A request that names the ``version`` of the state its tab holds is answered with a delta
against it (:mod:`rosvar.outputs.web.sessions`); the others get the whole state.
Engine calls are serialised by one lock: the BDD manager is not thread-safe, and the HTTP
server runs API calls in several threads. They run with the cyclic collector paused, as the
engine's steps do: what a call keeps (verdicts, views, documents) joins the engine's heap,
and CPython, which counts only what its own young collections promote, ran full collections
of that whole heap inside the calls (docs/performance.md). A call waits for the engine at most
``ENGINE_WAIT`` (its time budget), then is answered 503, which the page tries again: a slow
step of one client never keeps another's request waiting without end. The catalog needs no
engine: it is answered at once.
"""

from __future__ import annotations

import functools
import threading
from collections.abc import Callable, Mapping
from http import HTTPStatus
from typing import TypeVar

from rosvar.analyses.feature_model.features import FeatureKind
from rosvar.analyses.query.parser import QueryError
from rosvar.configuration.choices import Action, ChoiceError, UserChoice
from rosvar.configuration.engine import ConfigurationState, Configurator
from rosvar.configuration.session import Session
from rosvar.interpreter.workspace_models import collector_paused
from rosvar.outputs.documents.state import state_document
from rosvar.outputs.web.inspection import Inspector
from rosvar.outputs.web.overview import Grouping, MemberKind, catalog, compact, links, members
from rosvar.outputs.web.sessions import DEFAULT_CAPACITY, SessionStore, Tab

MAX_TEXT = 4096
"""Longest accepted string field (feature ids and typed values are far shorter)."""

MAX_PAGE = 100_000
MAX_GROUPS = 10_000
"""Most groups whose links one request asks for (the page asks for the boxes it draws)."""
ENGINE_WAIT = 20.0
"""Seconds a call waits for the engine, busy with another's, before it is answered 503."""
StrEnumT = TypeVar("StrEnumT", Grouping, MemberKind)

Body = Mapping[str, object]
Query = Mapping[str, str]
Reply = dict[str, object]


class ApiError(Exception):
    """A request the API refuses: ``status`` is a 4xx code, ``message`` says why, ``extra``
    fields of the answer say where (a query's error position)."""

    def __init__(self, status: HTTPStatus, message: str, **extra: object) -> None:
        super().__init__(message)
        self.status = status
        self.message = message
        self.extra = extra


def _text(fields: Mapping[str, object], name: str) -> str:
    value = fields.get(name)
    if not isinstance(value, str):
        raise ApiError(HTTPStatus.BAD_REQUEST, f"field {name!r} must be a string")
    if len(value) > MAX_TEXT:
        raise ApiError(HTTPStatus.BAD_REQUEST, f"field {name!r} is longer than {MAX_TEXT}")
    return value


def _version(fields: Mapping[str, object]) -> int | None:
    """The version of the state the tab holds, if it says."""
    value = fields.get("version")
    if value is None or (isinstance(value, int) and not isinstance(value, bool)):
        return value
    raise ApiError(HTTPStatus.BAD_REQUEST, "field 'version' must be an integer")


def _choice_of(fields: Mapping[str, object], name: str, kinds: type[StrEnumT]) -> StrEnumT:
    text = _text(fields, name)
    try:
        return kinds(text)
    except ValueError:
        known = ", ".join(kinds)
        raise ApiError(HTTPStatus.BAD_REQUEST, f"field {name!r} must be one of {known}") from None


def _page(fields: Mapping[str, object]) -> int:
    value = fields.get("page", 0)
    if isinstance(value, int) and not isinstance(value, bool) and 0 <= value <= MAX_PAGE:
        return value
    raise ApiError(HTTPStatus.BAD_REQUEST, f"field 'page' must be an integer in 0..{MAX_PAGE}")


def _only(fields: Mapping[str, object], allowed: set[str]) -> None:
    unknown = sorted(set(fields) - allowed)
    if unknown:
        raise ApiError(HTTPStatus.BAD_REQUEST, f"unknown field(s): {', '.join(unknown)}")


class _Asking:
    """The requests in ``Api.handle``, answered or waiting for the lock: the findings' listing
    gives way to them. Apart from the API: a closure over it would make it a reference
    cycle (see ``ROUTES``)."""

    def __init__(self) -> None:
        self.count = 0

    def any(self) -> bool:
        return self.count > 0


class Api:
    """Sessions of one :class:`Configurator`, reached through the route table."""

    def __init__(self, configurator: Configurator, capacity: int = DEFAULT_CAPACITY) -> None:
        self._configurator = configurator
        self._store = SessionStore(configurator, capacity)
        self._lock = threading.Lock()
        features = configurator.state([]).features  # the ids never change: known once
        configurator.derivation.prepare_counts()
        self._kinds = {key: feature.kind for key, feature in features.items()}
        self._asking = _Asking()
        self._inspector = Inspector(configurator, self._lock, self._asking.any)
        self._rows = catalog(configurator)  # the catalog's answer, served without the lock

    def handle(self, method: str, path: str, query: Query, body: Body) -> Reply:
        route = ROUTES.get((method, path))
        if route is None:
            if any(known == path for _, known in ROUTES):
                raise ApiError(HTTPStatus.METHOD_NOT_ALLOWED, f"{method} not allowed on {path}")
            raise ApiError(HTTPStatus.NOT_FOUND, f"no such API: {path}")
        if (method, path) in UNLOCKED:
            return route(self, query, body)
        self._asking.count += 1  # the findings' listing gives way (Inspector)
        try:
            if not self._lock.acquire(timeout=ENGINE_WAIT):
                raise ApiError(
                    HTTPStatus.SERVICE_UNAVAILABLE,
                    f"the engine is busy with another request (over {ENGINE_WAIT:.0f} s): "
                    "try again",
                )
            try:
                with collector_paused():  # (the module's docstring says why)
                    return route(self, query, body)
            finally:
                self._lock.release()
        finally:
            self._asking.count -= 1

    @property
    def sessions(self) -> int:
        return len(self._store)

    # -- routes ------------------------------------------------------------------------------
    def _open(self, query: Query, body: Body) -> Reply:
        """A new session; ``{"overview": GROUPING}`` asks for states in overview mode."""
        _only(query, set())
        _only(body, {"overview"})
        grouping = None if body.get("overview") is None else _choice_of(body, "overview", Grouping)
        key, tab = self._store.create()
        tab.grouping = grouping
        return self._reply(key, tab, tab.session.current(), None)

    def _catalog(self, query: Query, body: Body) -> Reply:
        """The feature tree's fixed part, for sessions in overview mode."""
        _only(query, set())
        return {"features": self._rows}

    def _grouping(self, query: Query, body: Body) -> Reply:
        """The state grouped another way (the session goes to overview mode)."""
        _only(query, set())
        _only(body, {"session", "version", "grouping"})
        key, tab = self._session(body)
        known = _version(body)
        tab.grouping = _choice_of(body, "grouping", Grouping)
        return self._reply(key, tab, tab.session.current(), known)

    def _group(self, query: Query, body: Body) -> Reply:
        """A page of one group's members in the session's current state."""
        _only(query, set())
        _only(body, {"session", "group", "kind", "page"})
        _key, tab = self._session(body)
        if tab.grouping is None:
            raise ApiError(HTTPStatus.BAD_REQUEST, "the session is not in overview mode")
        group = _text(body, "group")
        kind = MemberKind.NODES if "kind" not in body else _choice_of(body, "kind", MemberKind)
        state = tab.session.current()
        document = state_document(state, state.outline)
        return members(document, tab.grouping, group, kind, _page(body), state.described)

    def _links(self, query: Query, body: Body) -> Reply:
        """The links between the given groups in the session's current state."""
        _only(query, set())
        _only(body, {"session", "groups"})
        _key, tab = self._session(body)
        if tab.grouping is None:
            raise ApiError(HTTPStatus.BAD_REQUEST, "the session is not in overview mode")
        groups = body.get("groups")
        if (
            not isinstance(groups, list)
            or len(groups) > MAX_GROUPS
            or not all(isinstance(key, str) and len(key) <= MAX_TEXT for key in groups)
        ):
            raise ApiError(
                HTTPStatus.BAD_REQUEST, f"field 'groups' must be a list of at most {MAX_GROUPS} ids"
            )
        state = tab.session.current()
        return {"links": links(state_document(state, state.outline), tab.grouping, groups)}

    def _state(self, query: Query, body: Body) -> Reply:
        _only(query, {"session"})
        key, tab = self._session(query)
        return self._reply(key, tab, tab.session.current(), None)

    def _choose(self, query: Query, body: Body) -> Reply:
        _only(query, set())
        _only(body, {"session", "version", "action", "feature", "value"})
        key, tab = self._session(body)
        known = _version(body)
        choice = self._choice(body)
        try:
            state = tab.session.apply(choice)
        except ChoiceError as error:  # well-formed but meaningless to the engine
            raise ApiError(HTTPStatus.BAD_REQUEST, str(error)) from None
        return self._reply(key, tab, state, known)

    def _finish(self, query: Query, body: Body) -> Reply:
        """Every feature left at its default, as ordinary choices (undone one at a time)."""
        _only(query, set())
        _only(body, {"session", "version"})
        key, tab = self._session(body)
        known = _version(body)
        state = tab.session.current()
        for choice in self._configurator.completion(state.choices):
            state = tab.session.apply(choice)
        return self._reply(key, tab, state, known)

    def _step(
        self, query: Query, body: Body, step: Callable[[Session], ConfigurationState]
    ) -> Reply:
        _only(query, set())
        _only(body, {"session", "version"})
        key, tab = self._session(body)
        known = _version(body)
        return self._reply(key, tab, step(tab.session), known)

    def _query(self, query: Query, body: Body) -> Reply:
        """The elements a query selects under the tab's choices (docs/web.md)."""
        _only(query, set())
        _only(body, {"session", "expression"})
        _key, tab = self._session(body)
        try:
            expression = _text(body, "expression")
            return self._inspector.query(expression, tab.session.current(), tab.grouping)
        except QueryError as error:
            raise ApiError(HTTPStatus.BAD_REQUEST, str(error), position=error.col) from None

    def _checks(self, query: Query, body: Body) -> Reply:
        """The findings of ``rosvar check`` under the tab's choices."""
        _only(query, set())
        _only(body, {"session"})
        _key, tab = self._session(body)
        return self._inspector.checks(tab.session.current(), tab.grouping)

    # -- checks ------------------------------------------------------------------------------
    def _session(self, fields: Mapping[str, object]) -> tuple[str, Tab]:
        key = _text(fields, "session")
        tab = self._store.get(key)
        if tab is None:
            raise ApiError(HTTPStatus.NOT_FOUND, "unknown or expired session")
        return key, tab

    def _choice(self, body: Body) -> UserChoice:
        text = _text(body, "action")
        try:
            action = Action(text)
        except ValueError:
            raise ApiError(HTTPStatus.BAD_REQUEST, f"unknown action {text!r}") from None
        feature = _text(body, "feature")
        kind = self._kinds.get(feature)
        if kind is None:
            raise ApiError(HTTPStatus.BAD_REQUEST, f"unknown feature {feature!r}")
        if action != Action.SET:
            if body.get("value") is not None:
                raise ApiError(HTTPStatus.BAD_REQUEST, f"{text!r} takes no value")
            return UserChoice(action, feature)
        if kind != FeatureKind.ARG:
            raise ApiError(HTTPStatus.BAD_REQUEST, "'set' needs an arg feature (FILE:ARG)")
        return UserChoice(action, feature, _text(body, "value"))

    def _reply(self, key: str, tab: Tab, state: ConfigurationState, known: int | None) -> Reply:
        """The state's document for the tab: whole, or in overview mode (its graph's
        conditions not described: the summaries do not show them)."""
        overview = tab.grouping is not None
        document = {
            **state_document(state, state.outline if overview else None),
            "can_undo": tab.session.can_undo,
            "can_redo": tab.session.can_redo,
        }
        if tab.grouping is not None:
            document = compact(document, tab.grouping)
        return {"session": key, **tab.answer(document, known)}


Route = Callable[[Api, Query, Body], Reply]
ROUTES: dict[tuple[str, str], Route] = {
    ("POST", "/api/session"): Api._open,
    ("GET", "/api/state"): Api._state,
    ("POST", "/api/choose"): Api._choose,
    ("POST", "/api/finish"): Api._finish,
    ("GET", "/api/catalog"): Api._catalog,
    ("POST", "/api/grouping"): Api._grouping,
    ("POST", "/api/group"): Api._group,
    ("POST", "/api/links"): Api._links,
    ("POST", "/api/undo"): functools.partial(Api._step, step=Session.undo),
    ("POST", "/api/redo"): functools.partial(Api._step, step=Session.redo),
    ("POST", "/api/reset"): functools.partial(Api._step, step=Session.reset),
    ("POST", "/api/query"): Api._query,
    ("POST", "/api/checks"): Api._checks,
}
"""The route table: functions of the API, not its bound methods, which would make every
:class:`Api` a reference cycle (freed by the cycle collector, CUDD's manager before the
engine's diagrams)."""
UNLOCKED = frozenset({("GET", "/api/catalog")})
"""Routes answered without the engine (what they read is made once, at start)."""
