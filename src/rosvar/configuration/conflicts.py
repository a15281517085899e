"""Name clashes under the user's choices: certain, possible, or gone.

A clash is judged on the feature tree and the *requires* constraints only (the exclude
constraints say the clash must not happen, so they would hide it): ``S = tree ∧ requires
∧ decided literals``. It is gone when no configuration of ``S`` has both files and the clash
condition, certain when every configuration of ``S`` with both files has it, and possible
otherwise, with its condition simplified under the decided values. The decided literals
(the choices and what the solver derived from them) are what the user sees of the
product: a clash the choices still allowed but the solver ruled out (two files both in,
and the value that made them clash derived away) is gone. What a user is shown
(:meth:`Conflicts.shown`) is about the product: no clash of a file out of it, and none certain
before both files are in.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass
from enum import StrEnum
from itertools import count

from rosvar.analyses.conflicts import Clash, DeclarationKind
from rosvar.analyses.feature_model.features import ConstraintKind, name_of
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.configuration.derivation import Decisions
from rosvar.configuration.judgement import Typed
from rosvar.configuration.lowering import Lowering
from rosvar.logic.bdd import BDD, conjoin, meets, walked_support
from rosvar.logic.bdd import cube as cube_of

REQUIRES_LIMIT = 100_000
"""Nodes of a component's formula above which its requires are left out of clash judgements."""
BLOCK_LIMIT = 20_000
"""Nodes of a block's ``tree ∧ requires`` above which its requires are left out: the corpus's
blocks stay far below it, while files linked by includes make the diagram grow with their
number, and every clash of those files would be conjoined with it (docs/configure.md)."""


class Certainty(StrEnum):
    """Whether a conflict happens in every valid configuration left, or only in some."""

    CERTAIN = "certain"
    POSSIBLE = "possible"


@dataclass(frozen=True)
class Clashing:
    """Two files (the same one twice for a clash inside a file) and where they clash."""

    files: tuple[str, str]  # spelled ids
    paths: tuple[str, str]  # the files' paths (their typed texts' keys)
    names: tuple[str, ...]
    file_variables: tuple[str, str]
    component: int
    variables: frozenset[str]  # of the blocks it is judged on
    within: BDD  # the blocks' conjunction (shared by the pairs judged on the same blocks)
    possible: BDD  # both files ∧ the clash may happen (the blocks not conjoined)
    escapes: BDD  # both files ∧ the clash may not happen
    condition: BDD  # analysis manager, fixed atoms substituted
    both: BDD
    open: bool  # the clash depends on texts typed for <other> values


@dataclass(frozen=True)
class ConflictState:
    files: tuple[str, str]
    names: tuple[str, ...]
    status: Certainty
    condition: str | None


class Conflicts:
    """Every clashing pair of the model, judged against ``tree ∧ requires``.

    The tree is a conjunction of one part per file, so ``tree ∧ requires`` falls apart
    into *blocks*: files linked by requires constraints (each file alone where a
    component's requires are left out). The blocks are satisfiable under any valid
    choices, so a pair's status only depends on the blocks its files and condition
    touch: it is judged on their conjunction, small, and only again when a user
    literal on their variables changes.
    """

    def __init__(
        self, model: FeatureModel, lowering: Lowering, file_ids: Mapping[str, str]
    ) -> None:
        solver = model.solver
        self.manager = manager = solver.manager
        component_of = {f: i for i, c in enumerate(solver.components) for f in c.files}
        blocks = _blocks(model, component_of)
        block_of = {v: n for n, (variables, _formula) in enumerate(blocks) for v in variables}
        groups: dict[tuple[str, str], list[Clash]] = {}
        for clash in model.clashes:
            if clash.first.file != clash.second.file or clash.kind == DeclarationKind.NODE:
                key = tuple(sorted(clash.files))
                groups.setdefault(key, []).append(clash)  # type: ignore[arg-type]
        features = {f.file: f for f in model.files}
        space = lowering.space
        self.lowering = lowering
        self.pairs: list[Clashing] = []
        self._reading: dict[str, list[int]] = {}  # variable → the pairs whose blocks hold it
        members = [set(c.variables) for c in solver.components]
        withins: dict[tuple[int, ...], tuple[BDD, frozenset[str]]] = {}
        for (first, second), clashes in sorted(groups.items()):
            condition = model.space.false
            for clash in clashes:
                condition |= clash.condition
            fixed, bounds = lowering.lower(condition)
            if bounds.may == manager.false:
                continue
            a, b = features[first], features[second]
            pair = (solver.var(a.variable), solver.var(b.variable))
            both = pair[0] & pair[1]
            # the bounds are ``fixed`` copied with atoms quantified: no other variables
            support = space.support(fixed) | {name_of(a.variable), name_of(b.variable)}
            touched = tuple(sorted({block_of[v] for v in support & members[component_of[a.id]]}))
            if touched not in withins:
                withins[touched] = (
                    conjoin(manager, [blocks[n][1] for n in touched]),
                    frozenset(v for n in touched for v in blocks[n][0]),
                )
            within, variables = withins[touched]
            for variable in variables:
                self._reading.setdefault(variable, []).append(len(self.pairs))
            self.pairs.append(
                Clashing(
                    (file_ids[first], file_ids[second]),
                    (first, second),
                    tuple(sorted({f"{c.kind} {c.name}" for c in clashes})),
                    (str(pair[0].var), str(pair[1].var)),
                    component_of[a.id],
                    variables,
                    within,
                    both & bounds.may,
                    both & ~bounds.must,
                    fixed,
                    both,
                    not bounds.exact,
                )
            )

    def judge(
        self,
        decisions: Decisions,
        typed: Typed,
        describe: Callable[[BDD, Mapping[str, bool]], str],
        before: tuple[Decisions, Typed, Sequence[ConflictState | None]] | None = None,
    ) -> list[ConflictState | None]:
        """Each pair's state (None: gone), judged again only where a decided variable of
        its blocks differs from ``before`` (an earlier step, its texts and its answer), or,
        for a clash on ``<other>`` values, where the texts typed changed.

        When ``before``'s decided literals are among these (a session's next click) and the
        texts are the same, they only remove configurations: a clash gone stays gone, and a
        certain one is certain or gone.
        """
        if before is None:
            again: Iterable[int] = range(len(self.pairs))
            found: list[ConflictState | None] = [None] * len(self.pairs)
            more = False
        else:
            earlier, texts, answer = before
            changed = decisions.decided.items() ^ earlier.decided.items()
            numbers = {n for v, _ in changed for n in self._reading.get(v, ())}
            if texts != typed:
                numbers.update(n for n, pair in enumerate(self.pairs) if pair.open)
            again = sorted(numbers)
            found = list(answer)
            more = texts == typed and earlier.decided.items() <= decisions.decided.items()
        cubes: dict[frozenset[str], BDD] = {}  # pairs judged on the same blocks share one
        for number in again:
            was, pair = found[number], self.pairs[number]
            cube = cubes.get(pair.variables)
            if cube is None:
                cube = cubes[pair.variables] = self._decided(pair, decisions)
            if not more or (was is not None and was.status != Certainty.CERTAIN):
                found[number] = self._status(pair, decisions, cube, typed, describe)
            elif was is not None and not self._meets(self._bounds(pair, typed)[0], pair, cube):
                found[number] = None
        return found

    def _bounds(self, pair: Clashing, typed: Typed) -> tuple[BDD, BDD]:
        """The pair's ``possible`` and ``escapes``, decided by the texts typed for ``<other>``
        values (a text that cannot clash rules the clash out): its files' args, and those of
        the files that include them (whether a file is launched reads its includers')."""
        if not pair.open:
            return pair.possible, pair.escapes
        texts = {i: t for mine in typed.values() for i, t in mine.items()}
        if not texts:
            return pair.possible, pair.escapes
        bounds = self.lowering.decide(pair.condition, texts)
        return pair.both & bounds.may, pair.both & ~bounds.must

    def shown(
        self, found: Sequence[ConflictState | None], decisions: Decisions
    ) -> list[ConflictState]:
        """The pairs' states (``judge``'s answer) as they bear on the product: a pair with a
        file deselected, by the user or derived, is not in it; one certain given both
        files is only possible while a file is still open."""
        decided = decisions.decided
        shown = []
        for pair, state in zip(self.pairs, found, strict=True):
            if state is None:
                continue
            first, second = (decided.get(v) for v in pair.file_variables)
            if first is False or second is False:
                continue
            if state.status == Certainty.CERTAIN and not (first and second):
                state = ConflictState(pair.files, pair.names, Certainty.POSSIBLE, None)
            shown.append(state)
        return shown

    def _decided(self, pair: Clashing, decisions: Decisions) -> BDD:
        """The decided literals of the pair's blocks and the user literals of its component
        (those outside the blocks change nothing), conjoined."""
        decided = decisions.decided
        values = {v: decided[v] for v in pair.variables if v in decided}
        return decisions.cubes[pair.component] & cube_of(self.manager, values)

    def _meets(self, u: BDD, pair: Clashing, cube: BDD) -> bool:
        """Some configuration of the pair's blocks and ``u`` (its ``possible`` or
        ``escapes``) has the literals of ``cube`` (``_decided``).

        Asked without building ``within ∧ (u ∧ cube)`` (``bdd.meets``): the blocks' diagram
        may reach ``BLOCK_LIMIT`` nodes, and conjoining it with the clash at build and with
        the choices at each step made as many new nodes each time, which dominated the
        engine's construction and its steps on large workspaces."""
        return meets(pair.within, u & cube)

    def _status(
        self,
        pair: Clashing,
        decisions: Decisions,
        cube: BDD,
        typed: Typed,
        describe: Callable[[BDD, Mapping[str, bool]], str],
    ) -> ConflictState | None:
        possible, escapes = self._bounds(pair, typed)
        if not self._meets(possible, pair, cube):
            return None
        if not self._meets(escapes, pair, cube):
            return ConflictState(pair.files, pair.names, Certainty.CERTAIN, None)
        decided = decisions.decided
        # when both files are in: the clash is about them (a file's condition to be launched,
        # not included by another file, stays)
        literals = {v: decided[v] for v in pair.variables if v in decided}
        literals.update(dict.fromkeys(pair.file_variables, True))
        return ConflictState(
            pair.files, pair.names, Certainty.POSSIBLE, describe(pair.condition, literals)
        )


def _blocks(
    model: FeatureModel, component_of: Mapping[str, int]
) -> list[tuple[frozenset[str], BDD]]:
    """The files' variables linked by requires constraints, each set with its formula.

    A component whose formula is too large a diagram keeps its requires out: ``tree ∧
    requires`` would be as large and slow to build, so its files are judged on the tree.
    So does a block whose conjunction outgrows ``BLOCK_LIMIT`` as it is merged: its files
    go back to blocks of their own, and later requires on them are left out too — every
    clash of theirs is conjoined with the block, at build and at each step.
    """
    solver = model.solver
    manager = solver.manager
    large = {i for i, c in enumerate(solver.components) if c.larger_than(REQUIRES_LIMIT)}
    alone = {f.id: (frozenset(f.variable_names()), solver.file_tree(f)) for f in model.files}
    numbers = count()  # a block's key: merged blocks get a new one
    blocks = {next(numbers): (v, formula, {file}) for file, (v, formula) in alone.items()}
    block_of = {v: n for n, (variables, _formula, _files) in blocks.items() for v in variables}
    left_out: set[str] = set()  # variables of the files whose requires are left out
    for constraint, formula in zip(model.constraints, solver.constraints, strict=True):
        if constraint.kind != ConstraintKind.REQUIRES or component_of[constraint.files[0]] in large:
            continue
        support = walked_support(formula)
        if support & left_out:
            continue
        linked = [blocks.pop(n) for n in sorted({block_of[v] for v in support if v in block_of})]
        merged = conjoin(manager, [*(b[1] for b in linked), formula])
        files = set().union(*(b[2] for b in linked))
        variables = frozenset().union(*(b[0] for b in linked))
        if merged.dag_size > BLOCK_LIMIT:
            left_out |= variables
            parts = [(alone[file][0], alone[file][1], {file}) for file in files]
        else:
            parts = [(variables, merged, files)]
        for part in parts:
            number = next(numbers)
            blocks[number] = part
            block_of.update(dict.fromkeys(part[0], number))
    return [(variables, formula) for variables, formula, _files in blocks.values()]
