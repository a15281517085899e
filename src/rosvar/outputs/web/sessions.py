"""Configuration sessions of the web server, one per browser tab, bounded in number.

A tab keeps its session id in ``sessionStorage``, so two tabs never share choices. The store
forgets the least recently used session beyond its capacity: a forgotten tab simply starts
over (the API answers 404 and the app opens a new session).

Each answer carries a version; a request naming the version of a document the server still
holds for the tab is answered with a delta against it (:mod:`rosvar.outputs.web.delta`).
The last two documents are held, so one extra reader of the session (a page reloading, a
script fetching the state) does not push the tab back to whole documents.
"""

from __future__ import annotations

import secrets
from collections import OrderedDict
from dataclasses import dataclass, field

from rosvar.configuration.engine import Configurator
from rosvar.configuration.session import Session
from rosvar.outputs.web.delta import BASE, Document, diff
from rosvar.outputs.web.overview import Grouping

DEFAULT_CAPACITY = 64
KEPT_DOCUMENTS = 2


@dataclass
class Tab:
    """A tab's session and the documents last sent for it, by version; ``grouping``: its
    states go in overview mode, grouped so (:mod:`rosvar.outputs.web.overview`)."""

    session: Session
    grouping: Grouping | None = None
    version: int = 0
    sent: OrderedDict[int, Document] = field(default_factory=OrderedDict)

    def answer(self, document: Document, known: int | None) -> Document:
        """``document`` under a new version: a delta when the tab holds version ``known``."""
        before = self.sent.get(known) if known is not None else None
        self.version += 1
        self.sent[self.version] = document
        while len(self.sent) > KEPT_DOCUMENTS:
            self.sent.popitem(last=False)
        if before is None:
            return {"version": self.version, **document}
        return {"version": self.version, BASE: known, **diff(before, document)}


class SessionStore:
    """Tabs by session id, least recently used first; not thread-safe (the API serialises calls)."""

    def __init__(self, configurator: Configurator, capacity: int = DEFAULT_CAPACITY) -> None:
        if capacity < 1:
            raise ValueError("a session store holds at least one session")
        self.configurator = configurator
        self.capacity = capacity
        self._tabs: OrderedDict[str, Tab] = OrderedDict()

    def create(self) -> tuple[str, Tab]:
        key = secrets.token_urlsafe(16)
        tab = Tab(Session(self.configurator))
        self._tabs[key] = tab
        while len(self._tabs) > self.capacity:
            self._tabs.popitem(last=False)
        return key, tab

    def get(self, key: str) -> Tab | None:
        tab = self._tabs.get(key)
        if tab is not None:
            self._tabs.move_to_end(key)
        return tab

    def __len__(self) -> int:
        return len(self._tabs)
