"""The excludes constraints as the solver builds them: per clashing name, not per pair.

Files that redeclare a name exclude each other pairwise (``FeatureModel.constraints``); the
solver takes them per name instead, as one at-most-one constraint, and finds the pairs of
files they link per name too, so that no pairwise work is done unless asked for.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence

from rosvar.analyses.conflicts import Clash, Occurrence
from rosvar.analyses.feature_model.features import FileFeature, name_of
from rosvar.logic.bdd import BDD, Manager, transfer
from rosvar.logic.conditions import ConditionSpace


def declaring(
    space: ConditionSpace,
    files: Mapping[str, FileFeature],
    buckets: Mapping[tuple[str, str], Sequence[Occurrence]],
) -> list[dict[str, BDD]]:
    """For each name declared by two files or more, when each of them declares it; names
    declared alike (a moveit configuration's files share dozens of parameter names, all
    under the same conditions) once for all."""
    done: set[frozenset[tuple[str, BDD]]] = set()
    found = []
    for occurrences in buckets.values():
        when: dict[str, BDD] = {}
        for occurrence in occurrences:
            if occurrence.file in files:
                when[occurrence.file] = (
                    when.get(occurrence.file, space.false) | occurrence.condition
                )
        alike = frozenset(when.items())
        if len(when) >= 2 and alike not in done:
            done.add(alike)
            found.append(when)
    return found


def excluding(declaring: Iterable[Mapping[str, BDD]]) -> list[tuple[str, str]]:
    """The pairs of files (paths) declaring a common name under conditions that can hold
    together: the files of the ``excludes`` constraints (``conflicts.clashes``' pairs of
    declarations, taken per file: the conjunction of two disjunctions is satisfiable
    when one pair of their terms is)."""
    pairs: set[tuple[str, str]] = set()
    for when in declaring:
        files = sorted(when)
        for position, first in enumerate(files):
            for second in files[position + 1 :]:
                if (first, second) in pairs:
                    continue
                both = when[first] & when[second]
                if both != both.bdd.false:
                    pairs.add((first, second))
    return sorted(pairs)


def exclusions(
    space: ConditionSpace,
    manager: Manager,
    files: Mapping[str, FileFeature],
    declaring: Iterable[Mapping[str, BDD]],
    kept: set[str],
    translate: Callable[[BDD], BDD],
    internal: Iterable[Clash] = (),
) -> Iterator[tuple[list[str], BDD]]:
    """The excludes constraints, as one at-most-one per clashing name (plus rare pairs).

    The pairs of files clashing on a name ``n`` exclude each other exactly when at
    most one file ``f`` has ``F ∧ C_f`` (``C_f``: when ``f`` declares ``n``) —
    one BDD linear in the files instead of one constraint per pair, which is what
    makes clone-and-own systems (cliques of files redeclaring the same names)
    cheap. Where ``C_f`` mentions atoms that are not features, quantifying them
    out does not distribute over the names, so such files keep the pairwise
    constraint, restricted to those names: together this is the conjunction of
    the pairwise ``excludes`` exactly. ``internal`` clashes (one file loading two nodes of
    one name) exclude their file under their condition.
    """
    dirty: dict[tuple[str, str], BDD] = {}
    literals: dict[tuple[str, BDD], BDD | None] = {}  # F ∧ C_F in the solver; None: unclean
    for when in declaring:
        clean: list[tuple[str, BDD]] = []
        unclean: list[str] = []
        for file, condition in when.items():
            if (file, condition) not in literals:
                literals[file, condition] = (
                    transfer(files[file].variable & condition, manager)
                    if space.support(condition) <= kept
                    else None
                )
            literal = literals[file, condition]
            if literal is None:
                unclean.append(file)
            else:
                clean.append((file, literal))
        for position, file in enumerate(unclean):
            for other in [*unclean[position + 1 :], *(f for f, _x in clean)]:
                pair = (file, other) if file < other else (other, file)
                dirty[pair] = dirty.get(pair, space.false) | (when[file] & when[other])
        if len(clean) >= 2:
            clean.sort(key=lambda item: manager.level_of_var(name_of(files[item[0]].variable)))
            yield [files[f].id for f, _x in clean], _at_most_one(manager, [x for _f, x in clean])
    for clash in internal:
        dirty[clash.files] = dirty.get(clash.files, space.false) | clash.condition
    for (first, second), condition in dirty.items():
        a, b = files[first], files[second]
        if condition != space.false:
            yield [a.id, b.id], translate(~(a.variable & b.variable & condition))


def _at_most_one(manager: Manager, literals: Sequence[BDD]) -> BDD:
    """At most one of ``literals`` holds: a chain built from the last literal up."""
    result, none = manager.true, manager.true
    for literal in reversed(literals):
        result = (literal & none) | (~literal & result)
        none &= ~literal
    return result
