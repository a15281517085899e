"""Undo, redo and reset over a session's choices; refused choices leave no trace."""

from __future__ import annotations

from typing import TYPE_CHECKING

from configuration.helpers import configurator, states
from rosvar.configuration.choices import Action, UserChoice
from rosvar.configuration.session import Session

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def test_undo_redo_reset(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch", '  <arg name="x" default="1"/>\n  <node pkg="p" type="t" name="n$(arg x)"/>'
    )
    ws.launch("b.launch", '  <node pkg="p" type="t" name="n1"/>')
    session = Session(configurator(ws))
    assert not session.can_undo and not session.can_redo
    first = states(session.apply(UserChoice(Action.SELECT, "a.launch")))
    second = states(session.apply(UserChoice.parse("set", "a.launch:x=1")))
    assert second["b.launch"] == "deselected*" and "b.launch" not in first
    refused = session.apply(UserChoice(Action.SELECT, "b.launch"))
    assert refused.refused and [c.feature for c in refused.choices] == ["a.launch", "a.launch:x"]
    assert states(session.current()) == second  # the refusal changed nothing
    assert states(session.undo()) == first and session.can_redo
    assert states(session.redo()) == second and not session.can_redo
    session.undo()
    session.apply(UserChoice(Action.DESELECT, "b.launch"))
    assert not session.can_redo  # a new choice drops what was undone
    assert states(session.reset()) == {} and not session.can_undo
    assert states(session.undo()) == {}  # nothing to undo: unchanged
