"""Lowering: analysis conditions as solver bounds, the environment and unset args fixed."""

from __future__ import annotations

import itertools
from typing import TYPE_CHECKING

from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.lowering import Bounds, Lowering
from rosvar.logic.bdd import BDD, transfer
from rosvar.logic.inputs import UNSET, ArgInput, EnvInput

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

LAUNCH = """
  <arg name="robot" default="kobuki"/>
  <node pkg="p" type="t" name="cam" if="$(optenv USE_CAM false)"/>
  <node pkg="p" type="t" name="s" if="$(eval arg('robot').startswith('s'))"/>
"""


def _lowering(ws: LaunchWorkspace, env: dict[str, str]) -> tuple[Lowering, BDD, BDD]:
    """The lowering under ``env``, and the conditions of the nodes ``cam`` and ``s``."""
    path = ws.launch("a.launch", LAUNCH)
    analysis = ws.analysis()
    lowering = Lowering(analysis, extract(analysis), env)
    cam, s = (node.condition for node in analysis.model(path).nodes)
    return lowering, cam, s


def test_the_environment_is_fixed_as_given_else_unset(ws: LaunchWorkspace) -> None:
    for env, present in (({"USE_CAM": "true"}, True), ({}, False)):
        lowering, cam, _s = _lowering(ws, env)
        space = lowering.space
        assert lowering.fix(cam) == (space.true if present else space.false)
        bounds = lowering.bounds(cam)
        assert bounds.exact
        assert bounds.may == (lowering.manager.true if present else lowering.manager.false)


def test_a_predicate_on_an_other_text_is_open_until_the_text_is_typed(
    ws: LaunchWorkspace,
) -> None:
    lowering, _cam, s = _lowering(ws, {})
    bounds = lowering.bounds(s)
    assert not bounds.exact  # some <other> text starts with s, some does not
    [robot] = [i for i in lowering.feature_inputs if isinstance(i, ArgInput) and i.name == "robot"]
    starts = lowering.decide(s, {robot: "spot"})
    other = lowering.decide(s, {robot: "husky"})
    assert starts.exact and other.exact
    assert starts.may != other.may  # the typed text decided the predicate both ways
    for decided in (starts, other):  # within the bounds before the text was typed
        assert decided.may & ~bounds.may == lowering.manager.false
        assert bounds.must & ~decided.must == lowering.manager.false


FACTORS = """
  <arg name="robot" default="kobuki"/>
  <arg name="arm" default="none"/>
  <node pkg="p" type="t" name="a" if="$(eval arg('robot').startswith('s'))"/>
  <node pkg="p" type="t" name="b" if="$(eval arg('arm').startswith('g'))"/>
  <node pkg="p" type="t" name="c" unless="$(eval arg('robot').startswith('s'))"/>
  <node pkg="p" type="t" name="d" if="$(eval arg('robot') == 'kobuki')"/>
  <node pkg="p" type="t" name="e" if="$(optenv USE_CAM false)"/>
"""


def test_a_conjunction_of_factors_lowers_as_the_whole_conjunction(ws: LaunchWorkspace) -> None:
    """Factors sharing an open atom (a and c) or not (a and b), exact ones (d, e): the
    conjunction and its bounds are those of the conjunction lowered whole, without the
    copies kept between conditions."""
    path = ws.launch("a.launch", FACTORS)
    analysis = ws.analysis()
    model = extract(analysis)
    conditions = [node.condition for node in analysis.model(path).nodes]
    space, manager = analysis.space, model.solver.manager
    opened = 0
    for first, second in itertools.combinations(conditions, 2):
        lowering = Lowering(analysis, model, {})
        conjoined = lowering.conjunction([lowering.fix(first), lowering.fix(second)])
        whole = Lowering(analysis, model, {}).fix(first & second)
        assert conjoined == whole
        hidden = space.support(whole) & lowering.open
        may = transfer(whole, manager, hidden)
        must = ~transfer(~whole, manager, hidden)
        assert lowering.bounds(conjoined) == Bounds(must, may)
        opened += must != may
    assert opened  # some pairs are open: both bounds are checked


def test_an_input_declared_after_the_lowering_is_fixed_by_its_value(ws: LaunchWorkspace) -> None:
    """The checks' simulation may read an environment variable first (a robot description's
    ``$(optenv)``) once the engine's lowering exists: its slots are fixed by the variable as
    given, as those of the inputs known at the start are."""
    for env, present in (({"LATE": "yes"}, True), ({}, False)):
        lowering, _cam, _s = _lowering(ws, env)
        space = lowering.space
        late = EnvInput("LATE")
        space.declare_input(late, ["yes", UNSET])
        assert lowering.fix(space.slot(late, "yes")) == (space.true if present else space.false)
        assert lowering.fix(space.slot(late, UNSET)) == (space.false if present else space.true)
