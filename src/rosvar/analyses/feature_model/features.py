"""The features and constraints of a feature model: files, their args and the args' values
(each a variable of the analysis' condition space), and the cross-tree constraints between
files. Below the model and its solver, which both read them.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from enum import StrEnum

from rosvar.diagnostics import Location
from rosvar.logic.bdd import BDD
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, Slot


class FeatureKind(StrEnum):
    """A feature's level in the tree: a launch file, one of its args, one of an arg's values."""

    FILE = "file"
    ARG = "arg"
    VALUE = "value"


@dataclass
class ValueFeature:
    id: str
    value: str
    slot: Slot
    default: bool
    variable: BDD


@dataclass
class ArgFeature:
    id: str
    file: str
    name: str
    input: ArgInput
    default: str | None
    boolean: bool
    location: Location | None
    doc: str | None = None  # what the file says the arg is for (``doc``, ROS 2 ``description``)
    values: list[ValueFeature] = field(default_factory=list)


@dataclass
class FileFeature:
    id: str
    file: str
    variable: BDD
    args: list[ArgFeature] = field(default_factory=list)

    def variable_names(self) -> list[str]:
        """The file's variable, then its args' values: a block of the solver's order (the
        names are the same in the analysis' manager and the solver's)."""
        return [name_of(self.variable)] + [name_of(v.variable) for a in self.args for v in a.values]


class ConstraintKind(StrEnum):
    """What a cross-tree constraint says: an include needs its file, clashing files exclude."""

    REQUIRES = "requires"
    EXCLUDES = "excludes"


@dataclass
class Constraint:
    """A cross-tree constraint: ``formula`` must hold; ``text`` says why, for people."""

    kind: ConstraintKind
    files: tuple[str, ...]
    formula: BDD
    condition: BDD  # when it bites (include condition, clash condition)
    text: str
    locations: tuple[Location, ...] = ()
    unconditional: bool = False


@dataclass(frozen=True)
class ModelPart:
    """Files the model's constraints link (includes, names declared in several of them),
    which the solver would have to solve together: how many, and their packages, the
    most files first (the package's folder: what to configure on its own)."""

    files: int
    package_count: int
    packages: tuple[tuple[str, str, int], ...]  # the first few: name, folder, its files


class ModelTooLarge(Exception):
    """The solver's BDDs would outgrow their budget: the model is listed, not solved.

    ``parts``: the largest groups of files its constraints link, when known (extraction
    tells them): what a narrower analysis could take on its own."""

    def __init__(self, message: str, parts: Sequence[ModelPart] = ()) -> None:
        super().__init__(message)
        self.parts = tuple(parts)


def launched_conditions(
    files: Sequence[FileFeature], requires: Sequence[Constraint]
) -> dict[str, BDD]:
    """File → when it is *launched*: selected, and not included by a selected file that
    includes it there (its elements are then that file's)."""
    by_id = {f.id: f for f in files}
    launched = {f.file: f.variable for f in files}
    for constraint in requires:
        if constraint.kind != ConstraintKind.REQUIRES:
            continue
        source, target = (by_id[i] for i in constraint.files)
        launched[target.file] &= ~(source.variable & constraint.condition)
    return launched


def name_of(variable: BDD) -> str:
    """The name of a feature variable: the same in the analysis' manager and the solver's."""
    return str(variable.var)


def value_text(slot: Slot, default_text: str | None) -> str:
    """How a value feature shows ``slot``."""
    if slot is OTHER:
        return "<other>"
    if slot is UNSET:
        return f"<default: {default_text}>" if default_text else "<unset>"
    return str(slot)
