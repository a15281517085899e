"""A configuration step's document: an unchanged feature is the same dict from one state to
the next (the web UI's deltas compare it by identity), a changed one a new dict."""

from __future__ import annotations

from typing import TYPE_CHECKING

from configuration.helpers import configurator, run
from rosvar.outputs.documents.state import state_document

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


def test_an_unchanged_feature_keeps_its_document_and_a_changed_one_gets_a_new_one(
    ws: LaunchWorkspace,
) -> None:
    ws.launch("a.launch", '  <arg name="x" default="1"/>\n  <node pkg="p" type="t" name="n"/>')
    ws.launch("b.launch", '  <node pkg="p" type="t" name="m"/>')
    engine = configurator(ws)
    before = state_document(run(engine))["features"]
    after = state_document(run(engine, "select a.launch"))["features"]
    assert isinstance(before, dict) and isinstance(after, dict)
    assert after["b.launch"] is before["b.launch"]
    assert after["a.launch"] is not before["a.launch"]
    assert (before["a.launch"]["state"], after["a.launch"]["state"]) == ("unselected", "selected")
