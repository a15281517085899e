"""Random walks to complete products on the four corpus systems (issues 15 and 30).

A walk clicks as a user would — selects and deselects files and values, sets args to known
values, to their substituted default (``<default: $(…)>``) and to typed ``<other>`` texts —
and, after a while, finishes with defaults as ``--finish`` does. A typed text the engine
refuses (every product left would fail by it) is typed again as another (a word, a digit,
a boolean). Walks are seeded by the system's name and their number, never by the checkout's
path: the same walks everywhere. At every step:

* no placeholder (``⟨``, ``<default:``, ``<other>``, ``$(``) in the command, nor in the name,
  namespace or remapped topic of a present element once no ``<other>`` value waits for a text;
* every conflict shown is about the product as the solver sees it, checked by a SAT solver of
  its own over ``tree ∧ requires ∧`` the decided features (and the typed texts): a certain one
  holds in every such configuration with both files, a possible one in some; none has a
  deselected file, and a complete product none between two files;
* a complete product has a command, or says what is open (an ``<other>`` value's text);

and a complete product's graph is ``rosvar resolve`` of its command.
"""

from __future__ import annotations

import random
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from configuration.helpers import TEXTS, same_as_resolve, typed_in
from json_view import read
from rosvar.analyses.feature_model.extraction import extract
from rosvar.configuration.choices import Action, UserChoice
from rosvar.configuration.conflicts import Certainty, ConflictState
from rosvar.configuration.engine import ConfigurationState, Configurator, Selection
from rosvar.configuration.sat import Sat
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.inputs import OTHER, UNSET, Input
from rosvar.outputs.web.entries import render
from rosvar.workspace import discover

CORPUS = Path(__file__).resolve().parents[3] / "shared" / "corpus"
SYSTEMS = ("husky", "kobuki", "lizi", "turtlebot2")
PLACEHOLDERS = ("⟨", "<default:", "<other>", "$(")
WALKS = 3  # per system in the quick run
MANY_WALKS = 50  # per system in the slow run (its figures: docs/configure.md)
CLICKS = 20  # random choices before finishing with defaults


@pytest.fixture(scope="module", params=SYSTEMS)
def system(request: pytest.FixtureRequest) -> tuple[str, Analysis, Configurator]:
    root = CORPUS / request.param
    if not root.is_dir() or not (CORPUS / "_external").is_dir():
        pytest.skip(f"corpus not found at {CORPUS}")
    analysis = Analysis(discover([root], deps=[CORPUS / "_external"]))
    engine = Configurator(analysis, extract(analysis, products=True), render=render)
    return request.param, analysis, engine


def test_random_walks_show_no_placeholder_no_false_conflict_and_end_in_a_command(
    system: tuple[str, Analysis, Configurator],
) -> None:
    assert walks(system, range(WALKS))["conflicts"] > 0  # the oracle had something to check


@pytest.mark.slow
def test_many_random_walks(system: tuple[str, Analysis, Configurator]) -> None:
    """``MANY_WALKS`` walks per system, typed texts among their clicks; how many products
    failed (and agree with ``rosvar resolve`` that they do) is in docs/configure.md."""
    found = walks(system, range(WALKS, WALKS + MANY_WALKS))
    print(f"{system[0]}: {found}")  # the figures of docs/configure.md (pytest -s)
    assert found["typed"] > 0  # the walks typed texts


def walks(system: tuple[str, Analysis, Configurator], numbers: range) -> dict[str, int]:
    """Walks ``numbers`` on ``system``, checked at every step; what they met, counted."""
    name, analysis, engine = system
    oracle = ClashOracle(engine)
    found = dict.fromkeys(("conflicts", "typed", "refused texts", "no text loads", "failing"), 0)
    for number in numbers:
        rng = random.Random(f"walks:{name}:{number}")  # the same walks in every checkout
        for state in walk(engine, rng):
            assert_no_placeholder(state)
            found["conflicts"] += oracle.check(state)
        if state.untyped:  # no text the walk knows loads: the engine refused each, and why
            assert all("roslaunch would stop" in r.reason for r in state.refused[-len(TEXTS) :])
            found["no text loads"] += 1
            continue
        assert state.complete
        # one configuration is left, and the solver never lets two files of it clash but on
        # a text typed for an <other> value (it takes such a value as able to avoid each
        # clash): the product then says it does not launch
        between = [c for c in state.conflicts if c.files[0] != c.files[1]]
        assert all(open_pair(engine, c) for c in between), between
        assert not between or state.launches is False
        launched = [f for f in engine.catalog.files if state.features[f.id].state == "selected"]
        assert state.command is not None or not launched, "a complete product without command"
        same_as_resolve(analysis, state)
        typed = [c for c in state.choices if c.action == Action.SET and c.value is not None]
        found["typed"] += sum(c.value not in _known(engine, c.feature) for c in typed)
        found["refused texts"] += sum("roslaunch would stop" in r.reason for r in state.refused)
        found["failing"] += any(e["presence"] == "present" for e in state.graph.errors)
    return found


def open_pair(engine: Configurator, conflict: ConflictState) -> bool:
    """Whether ``conflict``'s clash depends on texts typed for ``<other>`` values."""
    return any(p.open for p in engine.conflicts.pairs if p.files == conflict.files)


def _known(engine: Configurator, arg: str) -> set[str | None]:
    return {v.value for _f, v in engine.catalog.values_of(arg)}


def walk(engine: Configurator, rng: random.Random) -> Iterator[ConfigurationState]:
    """The states of one walk, the last one complete with every ``<other>`` value typed."""
    chosen: list[UserChoice] = []
    for _ in range(CLICKS):
        state = engine.state(chosen)
        yield state
        if state.complete:
            break
        chosen.append(click(engine, state, rng))
    chosen += engine.completion(chosen)
    yield typed_in(engine, chosen, rng)


def text(rng: random.Random) -> str:
    """A text typed for an ``<other>`` value (the first of ``TEXTS``)."""
    return TEXTS[0].format(rng.randint(0, 9))


def click(engine: Configurator, state: ConfigurationState, rng: random.Random) -> UserChoice:
    """One random choice on an open feature (a text for an untyped ``<other>`` first)."""
    if state.untyped:
        return UserChoice(Action.SET, state.untyped[0], text(rng))
    open_ = [f for f in engine.catalog if state.features[f.id].state == Selection.UNSELECTED]
    feature = rng.choice(open_)
    if feature.kind == "file":
        return UserChoice(Action.SELECT if rng.random() < 0.3 else Action.DESELECT, feature.id)
    if feature.kind == "value":
        return UserChoice(Action.SELECT if rng.random() < 0.7 else Action.DESELECT, feature.id)
    values = [
        v
        for f, v in engine.catalog.values_of(feature.id)
        if state.features[f.id].state != Selection.DESELECTED
    ]
    value = rng.choice(values)
    if value.slot is OTHER:
        return UserChoice(Action.SET, feature.id, text(rng))
    known = value.value if value.slot is UNSET else str(value.slot)  # <default: …> by its text
    return UserChoice(Action.SET, feature.id, known)


def assert_no_placeholder(state: ConfigurationState) -> None:
    if state.command is not None:
        assert not any(p in state.command for p in PLACEHOLDERS), state.command
    if state.untyped:
        return  # an <other> value without its text yet is shown as ⟨arg⟩
    texts: list[Any] = []
    for node in read([*state.graph.nodes, *state.graph.tests]):
        if node["presence"] == "present":
            texts += [node["name"], node["namespace"], *(t for _s, t in node["remaps"])]
    texts += [p["name"] for p in state.graph.params if p["presence"] == "present"]
    texts += [t["name"] for t in state.graph.topics if t["presence"] == "present"]
    shown = [t for t in texts if any(p in str(t) for p in PLACEHOLDERS)]
    assert shown == [], f"placeholders after {[str(c) for c in state.choices]}"


class ClashOracle:
    """Judges shown conflicts on its own: a SAT solver over the feature tree and the
    *requires* constraints, with the decided features as assumptions."""

    def __init__(self, engine: Configurator) -> None:
        model, solver = engine.model, engine.model.solver
        self.engine = engine
        requires = [
            formula
            for constraint, formula in zip(model.constraints, solver.constraints, strict=True)
            if constraint.kind == "requires"
        ]
        trees = [part for file in model.files for part in solver.arg_trees(file)]
        self.sat = Sat(solver.manager, solver.variables, 0, [*requires, *trees])
        by_path = {entry.path: entry for entry in engine.catalog.files}
        self.clashes: dict[tuple[str, ...], BDD] = {}  # two files → condition
        grouped: dict[tuple[str, ...], BDD] = {}
        for clash in model.clashes:
            if clash.first.file == clash.second.file and clash.kind != "node":
                continue  # the engine's conflicts: between files, or two nodes of one file
            key = tuple(sorted(by_path[f].id for f in clash.files))
            assert len(key) == 2
            grouped[key] = grouped.get(key, model.space.false) | clash.condition
        self.clashes = grouped

    def check(self, state: ConfigurationState) -> int:
        """Checks every conflict ``state`` shows; returns how many."""
        catalog, manager = self.engine.catalog, self.sat.manager
        decided = [
            self.sat.atom(f.variable, s.state == Selection.SELECTED)
            for f in catalog
            if f.kind != "arg" and (s := state.features[f.id]).state != Selection.UNSELECTED
        ]
        for conflict in state.conflicts:
            files = [catalog.features[f] for f in conflict.files]
            assert all(state.features[f.id].state != Selection.DESELECTED for f in files)
            both = manager.true
            for file in files:
                both &= manager.var(file.variable)
            condition = self.clashes[tuple(sorted(conflict.files))]
            bounds = self.engine.lowering.decide(condition, self.typed(state))
            may, must = bounds.may, bounds.must
            if conflict.status == Certainty.CERTAIN:
                assert all(state.features[f.id].state == Selection.SELECTED for f in files)
                assert self.sat.model(decided, both & ~must) is None, conflict
            else:
                assert self.sat.model(decided, both & may) is not None, conflict
        return len(state.conflicts)

    def typed(self, state: ConfigurationState) -> dict[Input, str]:
        """The texts of the args at ``<other>``: their last ``set`` (the value it went to)."""
        texts: dict[Input, str] = {}
        for choice in state.choices:
            if choice.action == Action.SET and choice.value is not None:
                arg, values = self.engine.catalog.args[choice.feature]
                other = next((f for f, v in values if v.slot is OTHER), None)
                known = {v.value for _f, v in values if v.slot is not OTHER}
                if other is not None and choice.value not in known:
                    texts[arg.input] = choice.value
                else:
                    texts.pop(arg.input, None)
        return texts
