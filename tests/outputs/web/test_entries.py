"""The graph's entries: each kind of content the engine keeps, rendered with the strings the
choices fix (a deferred ``<param>`` converted, a ``<rosparam>`` with terms loaded)."""

from __future__ import annotations

from typing import TYPE_CHECKING, get_args

from configuration.helpers import configurator, run
from rosvar.configuration.graph import Content
from rosvar.outputs.web.entries import render

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

LAUNCH = """
  <arg name="rate" default="10"/>
  <param name="period" type="int" value="$(arg rate)"/>
  <rosparam subst_value="true">{gains: {p: $(arg rate)}, mode: fast}</rosparam>
"""


def test_every_kind_of_content_has_its_own_renderer() -> None:
    kinds = get_args(Content)
    fallback = render.dispatch(object)
    assert kinds and all(render.dispatch(kind) is not fallback for kind in kinds)
    assert len({render.dispatch(kind) for kind in kinds}) == len(kinds)


def test_deferred_values_show_symbolically_until_the_choices_give_their_strings(
    ws: LaunchWorkspace,
) -> None:
    ws.launch("a.launch", LAUNCH)
    engine = configurator(ws)
    params = run(engine, "select a.launch").graph.params
    open_ = {(p["name"], p["value"], p["condition"]) for p in params}
    assert {(name, value) for name, value, when in open_ if when != "rate=10"} == {
        ("/period", "⟨rate⟩"),  # a string not known yet: not converted
        ("/ (YAML)", "<yaml>"),  # its text not known yet: not loaded
    }
    params = run(engine, "select a.launch", "set a.launch:rate=25").graph.params
    shown = {p["name"]: p["value"] for p in params if p["presence"] == "present"}
    assert shown == {"/period": 25, "/gains/p": 25, "/mode": "fast"}
