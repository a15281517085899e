"""Presence conditions in readable form: a short formula such as ``use_teleop=true ∧ ¬sim``.

A condition is printed modulo the facts of its space: simplified under them, split into
cubes grouped by input (``x∈{a,b}``), each cube widened while it stays inside the condition,
and the redundant cubes left out.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from typing import cast

from rosvar.logic.bdd import BDD, cofactors, restrict
from rosvar.logic.conditions import PREDICATES, ConditionSpace, FileAtom, PredicateAtom, SlotAtom
from rosvar.logic.inputs import OTHER, ArgInput, EnvInput, Input, Slot

BOOLEAN_WORDS = ("true", "false")
MAX_FULL = 200  # longer formulas over <other> values help nobody
MAX_CUBES = 256  # beyond this many disjuncts a formula is no longer readable


class _TooComplex(Exception):
    """The condition has too many disjuncts to print usefully."""


def describe(
    space: ConditionSpace, condition: BDD, qualify: bool = False, known_only: bool = True
) -> str:
    """A short readable formula, e.g. ``use_teleop=true ∧ ¬sim``, modulo validity.

    With ``known_only`` (the default) arg inputs are assumed to hold one of the
    values analysis knows, which hides the rarely useful ``<other>`` refinements;
    a condition that this view would show as ``true`` but that fails for some
    other value is shown in full.
    """
    # the facts over the condition and their variables, found once: walking a BDD's
    # support in Python is most of describing an undetermined condition in the engine
    local = space.care(condition)
    if condition == space.false or (condition & local) == space.false:  # unsatisfiable
        return "false"
    variables = space.support(local)
    involved = _inputs_of(space, variables)
    if known_only:
        others = {
            name: False
            for name in variables
            if isinstance(atom := space.atom_of(name), SlotAtom)
            and atom.slot is OTHER
            and isinstance(atom.input, ArgInput)
        }
        known = space.cofactor(condition, others)
        care = space.cofactor(local, others)
        if (known & care) == space.false:
            return "only for other values"
        if (care & ~known) == space.false and (local & ~condition) != space.false:
            full = describe(space, condition, qualify, known_only=False)
            return full if len(full) <= MAX_FULL else "true for every known value"
        domains = {
            input_: tuple(
                s for s in space.domain(input_) if s is not OTHER or isinstance(input_, EnvInput)
            )
            for input_ in involved
        }
    else:
        known, care = condition, local
        domains = {input_: space.domain(input_) for input_ in involved}
    simplified = restrict(known, care)
    if simplified == space.true or (care & ~known) == space.false:
        return "true"
    try:
        cubes = _prime_cubes(space, simplified, known, care, domains)
    except _TooComplex:
        names = sorted({str(i) for i in _inputs_of(space, space.support(simplified))})
        shown = ", ".join(names[:6]) + (", …" if len(names) > 6 else "")
        return f"a condition over {len(names)} inputs ({shown})"
    rendered = [_render_cube(space, cube, qualify, domains) for cube in cubes]
    if len(rendered) == 1:
        return rendered[0]
    return " ∨ ".join(f"({r})" if "∧" in r else r for r in sorted(rendered))


def _inputs_of(space: ConditionSpace, variables: Iterable[str]) -> set[Input]:
    return {
        atom.input
        for atom in (space.atom_of(name) for name in variables)
        if isinstance(atom, SlotAtom)
    }


def _prime_cubes(
    space: ConditionSpace,
    simplified: BDD,
    target: BDD,
    care: BDD,
    domains: Mapping[Input, tuple[Slot, ...]],
) -> list[dict[object, frozenset[Slot] | bool]]:
    """Cubes of ``simplified``, each widened while it stays inside ``target`` (mod care)."""
    cubes = _merge_cubes(_grouped_cubes(space, simplified, domains), domains)
    widened: list[dict[object, frozenset[Slot] | bool]] = []
    outside = care & ~target
    for cube in cubes:
        for key in sorted(cube, key=_sort_key):
            trial = {k: v for k, v in cube.items() if k != key}
            if (_cube_bdd(space, trial) & outside) == space.false:
                cube = trial
        if cube not in widened:
            widened.append(cube)
    covered = [_cube_bdd(space, c) for c in widened]
    result = []
    for index, cube in enumerate(widened):
        others = space.false
        for j, bdd in enumerate(covered):
            if j != index and (j > index or widened[j] in result):
                others |= bdd
        if ((covered[index] & care) & ~others) != space.false:
            result.append(cube)
    return result or widened


def _cube_bdd(space: ConditionSpace, cube: Mapping[object, frozenset[Slot] | bool]) -> BDD:
    result = space.true
    for key, value in cube.items():
        if isinstance(key, PredicateAtom | FileAtom):
            atom = space.bdd.var(space.variable_name(key))
            result &= atom if value else ~atom
        else:
            assert isinstance(value, frozenset)
            any_slot = space.false
            for slot in value:
                any_slot |= space.slot(key, slot)  # type: ignore[arg-type]
            result &= any_slot
    return result


def _paths(
    space: ConditionSpace, u: BDD, budget: list[int] | None = None
) -> Iterator[dict[str, bool]]:
    if budget is None:
        budget = [MAX_CUBES]
    if u == space.false:
        return
    if u == space.true:
        budget[0] -= 1
        if budget[0] < 0:
            raise _TooComplex
        yield {}
        return
    var = u.var
    for value, child in zip((False, True), cofactors(u), strict=True):
        for path in _paths(space, child, budget):
            yield {var: value, **path}


def _grouped_cubes(
    space: ConditionSpace, u: BDD, domains: Mapping[Input, tuple[Slot, ...]]
) -> list[dict[object, frozenset[Slot] | bool]]:
    cubes: list[dict[object, frozenset[Slot] | bool]] = []
    for path in _paths(space, u):
        cube: dict[object, frozenset[Slot] | bool] = {}
        negated: dict[Input, set[Slot]] = {}
        for name, value in path.items():
            atom = space.atom_of(name)
            if isinstance(atom, PredicateAtom | FileAtom):
                cube[atom] = value
            elif value:
                cube[atom.input] = frozenset([atom.slot])
            else:
                negated.setdefault(atom.input, set()).add(atom.slot)
        for input_, slots in negated.items():
            if input_ not in cube:
                cube[input_] = frozenset(s for s in domains[input_] if s not in slots)
        cubes.append(cube)
    return cubes


def _render_cube(
    space: ConditionSpace,
    cube: Mapping[object, frozenset[Slot] | bool],
    qualify: bool,
    domains: Mapping[Input, tuple[Slot, ...]],
) -> str:
    parts = []
    for key, value in sorted(cube.items(), key=lambda kv: _sort_key(kv[0])):
        if isinstance(key, FileAtom):
            parts.append(key.label if value else f"¬{key.label}")
        elif isinstance(key, PredicateAtom):
            _test, display = PREDICATES[key.test]
            text = display.format(key.term)
            parts.append(text if value else f"¬({text})")
        else:
            assert isinstance(value, frozenset)
            input_ = cast(Input, key)
            parts.append(_render_slots(input_, value, domains[input_], qualify))
    return " ∧ ".join(parts)


def _sort_key(key: object) -> tuple[int, str]:
    if isinstance(key, FileAtom):
        return (-1, key.label)
    if isinstance(key, PredicateAtom):
        return (1, str(key.term))
    return (0, str(key))


def _merge_cubes(
    cubes: list[dict[object, frozenset[Slot] | bool]], domains: Mapping[Input, tuple[Slot, ...]]
) -> list[dict[object, frozenset[Slot] | bool]]:
    """Join cubes that differ only in the slots of one input (x=a ∨ x=b → x∈{a,b}).

    Cubes are bucketed by everything but one key, so each round is linear in the
    number of cubes rather than quadratic.
    """
    changed = True
    while changed and len(cubes) > 1:
        changed = False
        keys = {key for cube in cubes for key in cube}
        for key in sorted(keys, key=_sort_key):
            buckets: dict[frozenset[tuple[object, object]], list[int]] = {}
            for index, cube in enumerate(cubes):
                rest = frozenset((k, v) for k, v in cube.items() if k != key)
                buckets.setdefault(rest, []).append(index)
            merged_any = False
            result: list[dict[object, frozenset[Slot] | bool]] = []
            for members in buckets.values():
                current = cubes[members[0]]
                for other_index in members[1:]:
                    joined = _merge_pair(current, cubes[other_index], domains)
                    if joined is None:
                        result.append(cubes[other_index])
                    else:
                        current = joined
                        merged_any = True
                result.append(current)
            if merged_any:
                cubes = result
                changed = True
    return cubes


def _merge_pair(
    a: dict[object, frozenset[Slot] | bool],
    b: dict[object, frozenset[Slot] | bool],
    domains: Mapping[Input, tuple[Slot, ...]],
) -> dict[object, frozenset[Slot] | bool] | None:
    keys = set(a) | set(b)
    differing = [k for k in keys if a.get(k) != b.get(k)]
    if len(differing) != 1:
        return None
    key = differing[0]
    va, vb = a.get(key), b.get(key)
    if isinstance(key, PredicateAtom | FileAtom) or va is None or vb is None:
        # p ∧ rest ∨ ¬p ∧ rest = rest
        if isinstance(va, bool) and isinstance(vb, bool):
            return {k: v for k, v in a.items() if k != key}
        return None
    assert isinstance(va, frozenset) and isinstance(vb, frozenset)
    union = va | vb
    merged = dict(a)
    if len(union) == len(domains[key]):  # type: ignore[index]
        del merged[key]
    else:
        merged[key] = union
    return merged


def _slot_text(slot: Slot) -> str:
    return slot if isinstance(slot, str) else repr(slot)


def _render_slots(
    input_: Input, slots: frozenset[Slot], domain: tuple[Slot, ...], qualify: bool
) -> str:
    name = str(input_)
    if qualify and isinstance(input_, ArgInput):
        name = f"{input_.file}:{input_.name}"
    if len(slots) == 1:
        (slot,) = slots
        if isinstance(slot, str) and slot.lower() in BOOLEAN_WORDS and _is_boolean(domain):
            return name if slot.lower() == "true" else f"¬{name}"
        return f"{name}={_slot_text(slot)}"
    excluded = [s for s in domain if s not in slots]
    if len(excluded) == 1:
        return f"{name}≠{_slot_text(excluded[0])}"
    ordered = [s for s in domain if s in slots]
    return f"{name}∈{{{', '.join(_slot_text(s) for s in ordered)}}}"


def _is_boolean(domain: tuple[Slot, ...]) -> bool:
    words = {s.lower() for s in domain if isinstance(s, str)}
    return bool(words) and words <= {"true", "false"}
