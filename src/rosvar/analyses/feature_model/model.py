"""The feature model: root → launch files → their args that affect the computation graph
(AFFECTSCG) → an xor-group of each arg's values (GETVALUES: the interpreter's input domains).

Cross-tree constraints: an ``<include>`` *requires* the included file (under the include's
condition); files whose declarations clash by name *exclude* each other (under the arg values
where the clash happens). Everything is one BDD in the analysis' condition space, so counting,
core/dead features and explanations are solver questions, not enumeration.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property

from rosvar.analyses.conflicts import (
    Clash,
    DeclarationKind,
    Occurrence,
    clashes,
    repeated_inclusions,
)
from rosvar.analyses.feature_model.features import (
    Constraint,
    ConstraintKind,
    FileFeature,
    ModelTooLarge,
)
from rosvar.analyses.feature_model.solver import Solver
from rosvar.diagnostics import Diagnostic
from rosvar.interpreter.model import LaunchModel
from rosvar.logic.conditions import ConditionSpace
from rosvar.workspace.paths import real_path


class CrossTree:
    """The cross-tree constraints, the pairwise ones built on first use.

    Apart from :class:`FeatureModel` because the solver translates them when asked: a
    reference from the solver back to the model holding it would make a cycle, and the
    cycle collector may free CUDD's manager before the diagrams of the cycle."""

    def __init__(
        self,
        space: ConditionSpace,
        files: Sequence[FileFeature],
        requires: list[Constraint],
        declarations: Mapping[tuple[str, str], list[Occurrence]],
        products: bool = False,
    ) -> None:
        self.space = space
        self.files = files
        self.requires = requires
        self.declarations = declarations
        self.products = products

    @cached_property
    def clashes(self) -> list[Clash]:
        return clashes(self.declarations)

    @cached_property
    def constraints(self) -> list[Constraint]:
        return self.requires + _excludes(self.space, self.files, self.clashes, self.products)


@dataclass
class FeatureModel:
    """The feature tree and its cross-tree constraints, with the solver that answers on them.

    The pairwise views — ``clashes``, ``internal`` and the ``excludes`` entries of
    ``constraints`` — are built on first use: they grow with the square of the files
    redeclaring a name, and neither the solver nor the count needs them. ``solution``
    is the solver, or why it was not built (``solver`` raises that then).
    """

    space: ConditionSpace
    files: list[FileFeature]
    requires: list[Constraint]
    declarations: Mapping[tuple[str, str], list[Occurrence]]  # by (kind, resolved name)
    launch_models: list[LaunchModel]
    diagnostics: list[Diagnostic] = field(default_factory=list)
    products: bool = False  # built for the configuration engine (``extract``'s ``products``)
    environment: Mapping[str, str] = field(default_factory=dict)  # the products' (``env``)
    solution: Solver | ModelTooLarge = field(init=False)
    cross_tree: CrossTree = field(init=False)

    @property
    def solved(self) -> bool:
        """Whether the solver was built within its budget."""
        return not isinstance(self.solution, ModelTooLarge)

    @property
    def solver(self) -> Solver:
        if isinstance(self.solution, ModelTooLarge):
            raise ModelTooLarge(str(self.solution), self.solution.parts)
        return self.solution

    def __post_init__(self) -> None:
        self.cross_tree = CrossTree(
            self.space, self.files, self.requires, self.declarations, self.products
        )

    @property
    def clashes(self) -> list[Clash]:
        return self.cross_tree.clashes

    @cached_property
    def internal(self) -> list[Clash]:
        """Clashes inside one file: two of its nodes, or one file included twice."""
        found = [
            c
            for c in self.clashes
            if c.first.file == c.second.file and c.kind == DeclarationKind.NODE
        ]
        return found + [c for model in self.launch_models for c in repeated_inclusions(model)]

    @property
    def constraints(self) -> list[Constraint]:
        return self.cross_tree.constraints

    def feature_ids(self) -> list[str]:
        ids: list[str] = []
        for file in self.files:
            ids.append(file.id)
            for arg in file.args:
                ids.append(arg.id)
                ids.extend(v.id for v in arg.values)
        return ids


def _excludes(
    space: ConditionSpace,
    features: Sequence[FileFeature],
    found: Sequence[Clash],
    products: bool = False,
) -> list[Constraint]:
    """One ``excludes`` constraint per pair of files whose declarations clash (with
    ``products``, the engine's model, also one per file loading two nodes of one name: the
    file alone fails, ``internal_clashes``)."""
    by_file = {f.file: f for f in features}  # an occurrence's file is its model's file
    between: dict[tuple[str, str], list[Clash]] = {}
    for clash in found:
        if clash.first.file != clash.second.file or (
            products and clash.kind == DeclarationKind.NODE
        ):
            key = tuple(sorted(clash.files))
            between.setdefault(key, []).append(clash)  # type: ignore[arg-type]
    constraints = []
    for (file_a, file_b), pair_clashes in sorted(between.items()):
        a, b = by_file[file_a], by_file[file_b]
        condition = space.false
        for clash in pair_clashes:
            condition |= clash.condition
        names = sorted({f"{c.kind} {c.name}" for c in pair_clashes})
        # the engine's model counts what a file loads from the files it includes too
        written = all(
            real_path(o.location.file) == real_path(o.file)
            for c in pair_clashes
            for o in (c.first, c.second)
        )
        verb = "declare" if written else "load"
        constraints.append(
            Constraint(
                ConstraintKind.EXCLUDES,
                (a.id, b.id),
                ~(a.variable & b.variable & condition),
                condition,
                (
                    f"{a.id} loads {', '.join(names[:3])} twice"
                    if a is b
                    else f"{a.id} and {b.id} both {verb} {', '.join(names[:3])}"
                )
                + (f" (+{len(names) - 3} more)" if len(names) > 3 else ""),
                tuple(loc for c in pair_clashes for loc in (c.first.location, c.second.location)),
                space.valid_implies(condition),
            )
        )
    return constraints
