"""The session store: fresh ids, least recently used sessions forgotten beyond the capacity."""

from __future__ import annotations

import pytest

from rosvar.configuration.engine import Configurator
from rosvar.outputs.web.sessions import SessionStore


def test_least_recently_used_session_is_forgotten(examples_engine: Configurator) -> None:
    store = SessionStore(examples_engine, capacity=2)
    first, _ = store.create()
    second, _ = store.create()
    assert first != second
    assert store.get(first) is not None  # first is now the most recently used
    third, _ = store.create()
    assert store.get(second) is None
    assert store.get(first) is not None and store.get(third) is not None
    assert len(store) == 2


def test_capacity_must_hold_a_session(examples_engine: Configurator) -> None:
    with pytest.raises(ValueError):
        SessionStore(examples_engine, capacity=0)


def test_a_tab_gets_deltas_against_the_documents_it_may_hold(
    examples_engine: Configurator,
) -> None:
    _, tab = SessionStore(examples_engine).create()
    first = {"unselected": 3, "complete": False}
    assert tab.answer(first, None) == {"version": 1, **first}
    second = tab.answer({"unselected": 2, "complete": False}, 1)
    assert second == {"version": 2, "base": 1, "unselected": 2}
    third = tab.answer({"unselected": 1, "complete": False}, 1)  # a second reader came between
    assert third == {"version": 3, "base": 1, "unselected": 1}
    assert "base" not in tab.answer({"unselected": 0, "complete": True}, 1)  # 1 is forgotten
    assert "base" not in tab.answer({"unselected": 0, "complete": True}, 99)
