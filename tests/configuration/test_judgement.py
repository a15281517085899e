"""Presences carried from step to step against presences judged at once.

An engine answers a list of choices from its answer for the longest earlier list, carrying
most verdicts with repaired witnesses; a fresh engine judges the whole list from nothing.
Both must show the same graph after every step of random sessions (a YAML load gives one
symbolic entry until its inputs are known, then one per key).
"""

from __future__ import annotations

import random
from typing import TYPE_CHECKING

from configuration.helpers import configurator
from rosvar.configuration.choices import Action, UserChoice
from rosvar.outputs.documents.state import conflict_document, graph_document

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

FILES = {
    "a.launch": '  <arg name="x" default="1"/>\n  <arg name="cam" default="false"/>\n'
    '  <node pkg="p" type="t" name="n$(arg x)"><remap if="$(arg cam)" from="in" to="c_$(arg x)"/>'
    '<env unless="$(arg cam)" name="E" value="$(arg x)"/></node>\n'
    '  <include file="$(find pkg)/launch/b.launch" if="$(arg cam)"/>\n'
    '  <include file="$(find pkg)/launch/e.launch" unless="$(arg cam)"/>',
    "b.launch": '  <arg name="y" default="u"/>\n  <node pkg="p" type="t" name="cam_$(arg y)"/>\n'
    '  <param name="rate" value="$(arg y)"/>',
    "c.launch": '  <arg name="w" default="true"/>\n'
    '  <node pkg="p" type="t" name="n1" if="$(arg w)"/>\n'
    '  <node pkg="p" type="t" name="cam_u" unless="$(arg w)"/>',
    "d.launch": '  <arg name="z" default="true"/>\n  <arg name="v" default="a"/>\n'
    '  <node pkg="p" type="t" name="d_$(arg v)" if="$(arg z)"/>\n'
    '  <rosparam subst_value="true">{gain: $(arg v), rate: 2}</rosparam>\n'
    '  <include file="$(find pkg)/launch/b.launch" if="$(arg z)"><arg name="y" value="$(arg v)"/>'
    "</include>",
    "e.launch": '  <arg name="k" default="0"/>\n  <param name="rate" value="$(arg k)"/>\n'
    '  <node pkg="p" type="t" name="n$(arg k)"/>',
}


def test_carried_presences_equal_presences_judged_at_once(ws: LaunchWorkspace) -> None:
    for name, body in FILES.items():
        ws.launch(name, body)
    engine = configurator(ws)
    rng = random.Random(5)
    for _session in range(12):
        chosen: list[UserChoice] = []
        while True:
            state = engine.state(chosen)
            at_once = configurator(ws).state(chosen)
            assert graph_document(state.graph) == graph_document(at_once.graph)
            assert [conflict_document(c) for c in state.conflicts] == [
                conflict_document(c) for c in at_once.conflicts
            ]
            open_ = [f for f in engine.catalog if state.features[f.id].state == "unselected"]
            known = [f for f in open_ if f.value != "<other>"]
            if not known:
                break
            feature = rng.choice(known)
            action = (
                Action.SELECT
                if feature.kind == "value"
                else rng.choice((Action.SELECT, Action.DESELECT))
            )
            chosen.append(UserChoice(action, feature.id))
