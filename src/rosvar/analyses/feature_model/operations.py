"""The questions the feature model's solver answers: the number of valid configurations,
core and dead features with the constraints why, and the simplest trigger of a condition."""

from __future__ import annotations

import os
from dataclasses import dataclass
from enum import StrEnum

from rosvar.analyses.feature_model.features import name_of, value_text
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.solver import Solver
from rosvar.logic.atoms import FileAtom, PredicateAtom, SlotAtom
from rosvar.logic.bdd import BDD, cofactors, conjoin, walked_support
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, Input, Slot


def count_configurations(model: FeatureModel) -> int | None:
    """Valid configurations, exactly (weighted model counting per component, no
    enumeration); None: unknown.

    Unknown when the model was too large to solve (``FeatureModel.solution``).
    """
    if not model.solved:
        return None
    return model.solver.count()


class VerdictKind(StrEnum):
    """Whether a feature is in every valid configuration (core) or in none (dead)."""

    CORE = "core"
    DEAD = "dead"


@dataclass
class FeatureVerdict:
    feature: str
    kind: VerdictKind
    because: list[str]


def core_and_dead(model: FeatureModel) -> list[FeatureVerdict]:
    """Features in every (core) or no (dead) valid configuration, with the constraints why.

    A value of a dead file is dead for the same reason (it needs its file): it shares the
    file's explanation instead of searching again — a file that includes one it clashes
    with has every value dead, and each search costs many conjunctions.
    """
    solver = model.solver
    verdicts: list[FeatureVerdict] = []
    possible = possible_values(solver)

    def values_of(variable: BDD) -> set[bool]:
        return possible.get(name_of(variable), {False, True})

    for file in model.files:
        variable = solver.var(file.variable)
        dead_file = True not in values_of(variable)
        if dead_file:
            because = explain(model, variable)
            verdicts.append(FeatureVerdict(file.id, VerdictKind.DEAD, because))
        elif False not in values_of(variable):
            verdicts.append(FeatureVerdict(file.id, VerdictKind.CORE, explain(model, ~variable)))
        for value in (v for arg in file.args for v in arg.values):
            variable = solver.var(value.variable)
            if dead_file:
                verdicts.append(FeatureVerdict(value.id, VerdictKind.DEAD, because))
            elif True not in values_of(variable):
                verdicts.append(
                    FeatureVerdict(value.id, VerdictKind.DEAD, explain(model, variable))
                )
            elif False not in values_of(variable):
                verdicts.append(
                    FeatureVerdict(value.id, VerdictKind.CORE, explain(model, ~variable))
                )
    return verdicts


def possible_values(solver: Solver) -> dict[str, set[bool]]:
    """For every variable, the values it takes in some valid configuration — one pass over
    each component's diagram.

    A value is possible when some path to TRUE sets it, or skips the variable's level
    (then it is free); asking the solver twice per feature instead costs two operations
    on the whole diagram each. The model is read off each component's ``counted``
    diagram, never building the full formulas, from the lists its count read
    (``CountedDiagram.taken``): a value a stand-in counts for is possible where the
    stand-in is true, and left out where it is false or, in a group of two or more,
    where another value of the group is taken instead.
    """
    manager = solver.manager
    possible: dict[str, set[bool]] = {}
    for component in solver.components:
        if component.counted == manager.false:  # no valid configuration at all
            return {name: set() for name in solver.variables}
        found = component.counted_diagram.taken()
        possible.update((name, found[name]) for name in component.counted_variables)
        for stand_in, group in component.stand_ins:
            taken = found[stand_in]
            values = {True} if True in taken else set()
            if False in taken or (True in taken and len(group) > 1):
                values.add(False)
            possible.update((name, set(values)) for name in group)
    return possible


def explain(model: FeatureModel, goal: BDD) -> list[str]:
    """A minimal set of cross-tree constraints that rules ``goal`` out (deletion-based).

    The search starts from the constraints around the feature's file and widens one
    hop of the constraint graph at a time: explanations are local in practice, and
    conjoining every constraint of a large system for each trial would be quadratic
    in expensive BDD operations. Only the tree parts of the files the constraints and
    ``goal`` mention take part: the other files' parts are satisfiable on their own.
    """
    solver = model.solver
    false = solver.manager.false
    mentioned = walked_support(goal)
    files = {f.id for f in model.files if name_of(f.variable) in mentioned} | {
        f.id
        for f in model.files
        for a in f.args
        for v in a.values
        if name_of(v.variable) in mentioned
    }
    by_id = {f.id: f for f in model.files}
    chosen: list[int] = []
    while True:
        chosen = [n for n, c in enumerate(model.constraints) if set(c.files) & files]
        involved = files | {f for n in chosen for f in model.constraints[n].files}
        tree = conjoin(solver.manager, [solver.file_tree(by_id[f]) for f in sorted(involved)])
        formula = tree & goal
        for number in chosen:
            formula &= solver.constraints[number]
        if formula == false:
            break
        wider = files | {f for n in chosen for f in model.constraints[n].files}
        if wider == files:
            return ["the whole model (no local reason found)"]
        files = wider
    kept = chosen
    position = 0
    while position < len(kept):
        trial = kept[:position] + kept[position + 1 :]
        formula = tree & goal
        for number in trial:
            formula &= solver.constraints[number]
        if formula == false:
            kept = trial
        else:
            position += 1
    return [model.constraints[n].text for n in kept] or ["the feature tree itself"]


def simplest_trigger(
    space: ConditionSpace, condition: BDD, witnesses: bool = False
) -> dict[str, str]:
    """An arg assignment making ``condition`` true with the fewest non-default choices.

    A cheapest path through the BDD, where choosing a non-default value costs 1
    and an ``<other>`` value costs 3; the inputs the path leaves open keep their
    defaults. With ``witnesses``, the path respects the space's facts and an ``<other>``
    value is a text that gives it (:func:`trigger`).
    """
    found = trigger(space, condition, witnesses)
    return {} if found is None else found.shown


@dataclass(frozen=True)
class Trigger:
    """An example configuration of a condition: what it shows, and whether an unforeseen
    value of it has no witness (no text rosvar tried gives what the path asks)."""

    shown: dict[str, str]
    unwitnessed: bool


def trigger(space: ConditionSpace, condition: BDD, witnesses: bool = True) -> Trigger | None:
    """:func:`simplest_trigger`'s path and what it shows; None where nothing satisfies
    ``condition``. With ``witnesses`` the facts over its variables hold on the path (the
    combinations the witnesses showed), and each ``<other>`` input is given the first
    witness under which the path's predicates over that input alone hold as it says."""
    if witnesses:
        target = condition & space.care(condition)
    else:
        involved = {
            atom.input
            for atom in (space.atom_of(n) for n in space.support(condition))
            if isinstance(atom, SlotAtom)
        }
        target = condition
        for input_ in involved:
            target &= space.input_constraint(input_)
    if target == space.false:
        return None
    _cost_total, path = _cheapest(space, target, {})
    texts = _witness_texts(space, path) if witnesses else {}
    chosen: dict[str, str] = {}
    for name, value in path.items():
        atom = space.atom_of(name)
        if value and isinstance(atom, SlotAtom):
            input_ = atom.input
            key = (
                f"{_short(input_.file)}:{input_.name}"
                if isinstance(input_, ArgInput)
                else str(input_)
            )
            text = texts.get(input_)
            chosen[key] = value_text(atom.slot, None) if text is None else text
        elif value and isinstance(atom, FileAtom):
            chosen[atom.label] = "selected"
    return Trigger(chosen, any(text is None for text in texts.values()))


def _witness_texts(space: ConditionSpace, path: dict[str, bool]) -> dict[Input, str | None]:
    """A text for each input the path gives an unforeseen value, under which the path's
    predicates hold as it says (:meth:`ConditionSpace.witnesses`); None each when no such
    texts were found."""
    chosen: dict[Input, Slot] = {}
    required: dict[PredicateAtom, bool] = {}
    for name, value in path.items():
        atom = space.atom_of(name)
        if isinstance(atom, SlotAtom) and value:
            chosen[atom.input] = atom.slot
        elif isinstance(atom, PredicateAtom):
            required[atom] = value
    others = [input_ for input_, slot in chosen.items() if slot is OTHER]
    if not others:
        return {}
    found = space.witnesses(chosen, required)
    return {input_: None if found is None else found[input_] for input_ in others}


Path = tuple[float, dict[str, bool]]


def _cheapest(space: ConditionSpace, u: BDD, memo: dict[BDD, Path]) -> Path:
    """The cheapest path to TRUE below ``u`` and its cost (a function of the module, not a
    closure: a recursive closure is a reference cycle, which kept the memo's diagrams)."""
    if u == space.true:
        return 0.0, {}
    if u == space.false:
        return float("inf"), {}
    if u in memo:
        return memo[u]
    var = u.var
    assert var is not None  # neither constant
    low, high = cofactors(u)
    low_cost, low_path = _cheapest(space, low, memo)
    high_cost, high_path = _cheapest(space, high, memo)
    high_cost += _cost(space, var)
    best = (
        (low_cost, {var: False, **low_path})
        if low_cost <= high_cost
        else (high_cost, {var: True, **high_path})
    )
    memo[u] = best
    return best


def _short(file: str) -> str:
    return os.path.basename(file)


def _cost(space: ConditionSpace, name: str) -> float:
    atom = space.atom_of(name)
    if not isinstance(atom, SlotAtom):
        return 0.0
    if atom.slot is OTHER:
        return 3.0
    if atom.slot is UNSET or atom.slot == _first(space, atom):
        return 0.0
    return 1.0


def _first(space: ConditionSpace, atom: SlotAtom) -> Slot:
    return space.domain(atom.input)[0]
