"""Configuration sessions of the web server, one per browser tab, bounded in number.

A tab keeps its session id in ``sessionStorage``, so two tabs never share choices. The store
forgets the least recently used session beyond its capacity: a forgotten tab simply starts
over (the API answers 404 and the app opens a new session).
"""

from __future__ import annotations

import secrets
from collections import OrderedDict

from rosvar.configuration.engine import Configurator
from rosvar.configuration.session import Session

DEFAULT_CAPACITY = 64


class SessionStore:
    """Sessions by id, least recently used first; not thread-safe (the API serialises calls)."""

    def __init__(self, configurator: Configurator, capacity: int = DEFAULT_CAPACITY) -> None:
        if capacity < 1:
            raise ValueError("a session store holds at least one session")
        self.configurator = configurator
        self.capacity = capacity
        self._sessions: OrderedDict[str, Session] = OrderedDict()

    def create(self) -> tuple[str, Session]:
        key = secrets.token_urlsafe(16)
        session = Session(self.configurator)
        self._sessions[key] = session
        while len(self._sessions) > self.capacity:
            self._sessions.popitem(last=False)
        return key, session

    def get(self, key: str) -> Session | None:
        session = self._sessions.get(key)
        if session is not None:
            self._sessions.move_to_end(key)
        return session

    def __len__(self) -> int:
        return len(self._sessions)
