"""Derived states and presences against the plain solver: ``formula ∧ literals ∧ v`` built."""

from __future__ import annotations

import random
from collections.abc import Callable
from typing import TYPE_CHECKING

import pytest

from rosvar.analyses.feature_model.counting import CountedDiagram
from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.configuration.derivation import Derivation
from rosvar.configuration.lowering import Bounds
from rosvar.configuration.presence import Presence, PresenceVerdict
from rosvar.logic.bdd import BDD

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

FILES = {
    "a.launch": '  <arg name="x" default="1"/>\n  <arg name="cam" default="false"/>\n'
    '  <node pkg="p" type="t" name="n$(arg x)"/>\n'
    '  <include file="$(find pkg)/launch/b.launch" if="$(arg cam)"/>',
    "b.launch": '  <arg name="y" default="u"/>\n  <node pkg="p" type="t" name="cam_$(arg y)"/>',
    "c.launch": '  <node pkg="p" type="t" name="n1"/>\n  <node pkg="p" type="t" name="cam_u"/>',
    "d.launch": '  <arg name="z" default="true"/>\n'
    '  <node pkg="p" type="t" name="d" if="$(arg z)"/>',
}


def derived(ws: LaunchWorkspace) -> tuple[FeatureModel, Derivation]:
    """The model of ``FILES`` and its derivation."""
    for name, body in FILES.items():
        ws.launch(name, body)
    model = extract(ws.analysis())
    return model, Derivation(model)


def holding(model: FeatureModel, derivation: Derivation) -> Callable[[BDD, int], bool]:
    """Whether a condition holds in a configuration given as the derivation's bit mask
    (evaluated by dd, not by the code under test)."""
    solver, position = model.solver, derivation.position

    def holds(u: BDD, bits: int) -> bool:
        values = {v: bool(bits >> position[v] & 1) for v in solver.variables}
        return bool(solver.manager.let(values, u) == solver.manager.true)

    return holds


def test_decisions_agree_with_the_built_formula(ws: LaunchWorkspace) -> None:
    model, derivation = derived(ws)
    solver = model.solver
    manager, formula = solver.manager, solver.formula
    rng = random.Random(3)
    for _ in range(30):
        decisions = derivation.initial
        conditions = [
            manager.var(rng.choice(solver.variables)) | manager.var(rng.choice(solver.variables))
            for _ in range(3)
        ]
        earlier: list[PresenceVerdict | None] = [None] * len(conditions)
        for _ in range(rng.randint(0, 4)):
            variable, value = rng.choice(solver.variables), rng.random() < 0.5
            found = derivation.add(decisions, variable, value)
            literal = manager.var(variable) if value else ~manager.var(variable)
            possible = (formula & decisions.cube & literal) != manager.false
            assert (found is not None) == possible
            decisions = found or decisions
            restricted = formula & decisions.cube
            for variable in solver.variables:
                atom = manager.var(variable)
                expected = (
                    False if (restricted & atom) == manager.false
                    else True if (restricted & ~atom) == manager.false
                    else None
                )  # fmt: skip
                assert decisions.decided.get(variable) is expected, variable
            # judged with the verdicts of the step before as hints (their witnesses repaired)
            asked = [(Bounds(c, c), e) for c, e in zip(conditions, earlier, strict=True)]
            verdicts = derivation.presences(asked, decisions)
            earlier = list(verdicts)
            for condition, verdict in zip(conditions, verdicts, strict=True):
                expected_presence = (
                    Presence.PRESENT if (restricted & ~condition) == manager.false
                    else Presence.ABSENT if (restricted & condition) == manager.false
                    else Presence.UNDETERMINED
                )  # fmt: skip
                assert verdict.presence == expected_presence


def test_prepared_counts_are_those_of_every_component(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    model, derivation = derived(ws)
    prepared: list[CountedDiagram] = []
    monkeypatch.setattr(CountedDiagram, "prepare", lambda diagram: prepared.append(diagram))
    derivation.prepare_counts()
    components = model.solver.components
    assert len(components) > 1
    assert prepared == [component.counted_diagram for component in components]


def test_witnesses_of_conjunctions_are_valid_configurations(ws: LaunchWorkspace) -> None:
    """Variants' conditions are conjunctions of a file and arg values: their examples are
    mostly made from earlier ones without the solver (``_mutated``), and each must still be
    a valid configuration that shows its verdict."""
    model, derivation = derived(ws)
    solver = model.solver
    manager, formula = solver.manager, solver.formula
    holds = holding(model, derivation)

    rng = random.Random(5)
    decisions = derivation.initial
    for _ in range(60):
        condition = manager.true
        for variable in rng.sample(solver.variables, rng.randint(1, 4)):
            atom = manager.var(variable)
            condition &= atom if rng.random() < 0.7 else ~atom
        (verdict,) = derivation.presences([(Bounds(condition, condition), None)], decisions)
        restricted = formula & decisions.cube
        expected = (
            Presence.PRESENT if (restricted & ~condition) == manager.false
            else Presence.ABSENT if (restricted & condition) == manager.false
            else Presence.UNDETERMINED
        )  # fmt: skip
        assert verdict.presence == expected
        if verdict.witnesses is not None:
            without, within = verdict.witnesses
            assert holds(formula, without) and holds(formula, within)
            assert not holds(condition, without) and holds(condition, within)


def test_examples_over_several_components_are_valid_configurations(ws: LaunchWorkspace) -> None:
    """A goal over several components is sought with the largest one's solver under
    witnesses of the others (``_combined``), not with the whole workspace's: each example
    must be a valid configuration under the literals where the goal holds."""
    model, derivation = derived(ws)
    solver = model.solver
    manager, formula = solver.manager, solver.formula
    components = solver.components
    assert len(components) > 1
    holds = holding(model, derivation)

    rng = random.Random(6)
    found = 0
    for _ in range(60):
        decisions = derivation.initial
        for _ in range(rng.randint(0, 2)):
            variable = rng.choice(solver.variables)
            decisions = derivation.add(decisions, variable, rng.random() < 0.5) or decisions
        one, other = rng.sample(range(len(components)), 2)
        atoms = [manager.var(rng.choice(list(components[c].variables))) for c in (one, other)]
        atoms = [atom if rng.random() < 0.6 else ~atom for atom in atoms]
        goal = atoms[0] | atoms[1] if rng.random() < 0.5 else atoms[0] & atoms[1]
        example = derivation._combined(decisions, goal)
        if example is None:  # the whole workspace's solver is asked
            continue
        found += 1
        involved = {solver.component_of[v] for v in manager.support(goal)}
        for n in set(range(len(components))) - involved:  # the others: any witness
            example |= decisions.witnesses[n][0]
        assert holds(formula & decisions.cube & goal, example)
    assert found > 20


def test_repaired_witnesses_are_valid_configurations(ws: LaunchWorkspace) -> None:
    """A repair copies the files that disagree with new literals from a current witness and
    checks only the constraints leaving the copied files whose variables the copy changed
    (``_broken``): every repaired witness must still satisfy the whole formula and
    the literals of its component."""
    model, derivation = derived(ws)
    solver = model.solver
    formula = solver.formula
    holds = holding(model, derivation)

    rng = random.Random(8)
    repaired = 0
    for _ in range(40):
        decisions = derivation.initial
        earlier = {c: list(w) for c, w in decisions.witnesses.items()}
        for _ in range(rng.randint(1, 4)):
            variable, value = rng.choice(solver.variables), rng.random() < 0.5
            decisions = derivation.add(decisions, variable, value) or decisions
            for component, witnesses in earlier.items():
                found = derivation.repaired(component, witnesses, decisions)
                for witness, repair in found.items():
                    assert holds(formula, witness)
                    if repair is not None:
                        assert holds(formula & decisions.cubes[component], repair)
                        repaired += repair != witness
                earlier[component] += decisions.witnesses[component]
    assert repaired > 10
