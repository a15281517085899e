"""Name clashes between launch files, found through an index by resolved name.

Two declarations clash when they give a node (or a parameter) the same fully
resolved name and can be present together. Instead of comparing every pair of
files (quadratic), every declaration is put in a bucket keyed by its name; only
declarations sharing a bucket are compared. A ``$(anon)`` name never clashes with another
file's: roslaunch draws its random part anew for each file of a command line (each top-level
file gets a fresh substitution context), so only a file's includes share it.

The paper's model takes each file's own declarations (Algorithm 1's GETELEMENTS); the
configuration engine's, what each file loads when it is on a command line
(``declared_occurrences``' ``launched``): two launched files that include one file load its
nodes twice, and roslaunch refuses them ("multiple nodes named").
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, replace
from enum import StrEnum

from rosvar.diagnostics import Location
from rosvar.interpreter.model import LaunchModel, NodeDecl, ParamDecl, anon_pattern
from rosvar.logic.bdd import BDD
from rosvar.workspace.paths import real_path


class DeclarationKind(StrEnum):
    """What a clashing name names: nodes and parameters live in separate name spaces."""

    NODE = "node"
    PARAM = "param"


@dataclass(frozen=True)
class Occurrence:
    """A declaration in ``file`` naming ``name`` when ``condition`` (over ``file``'s args) holds."""

    kind: DeclarationKind
    name: str
    file: str
    location: Location
    condition: BDD
    anonymous: bool = False  # the name holds a ``$(anon)`` part, random per entry file


@dataclass(frozen=True)
class Clash:
    """Two different declarations with one name; ``condition`` is when both are present."""

    kind: DeclarationKind
    name: str
    first: Occurrence
    second: Occurrence
    condition: BDD

    @property
    def files(self) -> tuple[str, str]:
        return (self.first.file, self.second.file)


class _WrittenIn:
    """Whether a location's file is ``file``, symlinks resolved once per distinct path
    (a model holds thousands of elements from a handful of included files)."""

    def __init__(self, file: str) -> None:
        self._target = real_path(file)
        self._seen = {file: True}

    def __call__(self, other: str) -> bool:
        found = self._seen.get(other)
        if found is None:
            found = self._seen[other] = real_path(other) == self._target
        return found


def _clashes(node: NodeDecl) -> bool:
    """Whether two such nodes of one name are a conflict: roslaunch refuses to start them (a
    ``<test>`` is run apart); ``ros2 launch`` starts both (``rosvar check`` warns of them)."""
    return not node.is_test and not node.ros2


def declared_occurrences(model: LaunchModel, launched: BDD | None = None) -> Iterable[Occurrence]:
    """Nodes and params written in ``model.file`` itself (Algorithm 1's GETELEMENTS).

    With ``launched`` (when the file is launched: in the product and not included by another
    file of it), the nodes are every node its model loads, wherever written, each under
    ``launched``: a file included by two launched files is loaded by each."""
    own = _WrittenIn(model.file)
    anon = anon_pattern(model.anon_ids)
    found: list[Occurrence] = []
    for node in model.nodes:
        if not _clashes(node):
            continue
        if launched is not None:
            found.extend(
                replace(o, condition=launched & o.condition) for o in node_occurrences(model, node)
            )
        elif own(node.location.file):
            found.extend(node_occurrences(model, node))
    for param in model.params:
        if not isinstance(param, ParamDecl) or not own(param.location.file):
            continue
        for condition, param_name in param.name:
            if isinstance(param_name, str):
                found.append(
                    Occurrence(
                        DeclarationKind.PARAM,
                        param_name,
                        model.file,
                        param.location,
                        param.condition & condition,
                    )
                )
    if anon is None:
        return found
    return [replace(o, anonymous=True) if anon.search(o.name) else o for o in found]


def node_occurrences(model: LaunchModel, node: NodeDecl) -> Iterator[Occurrence]:
    """The node's resolved names, where known (a ROS 2 node's is its pushed namespace
    composed with its own, as ``ros2 launch`` names it)."""
    for condition, name in node.value(node.schema.full_name):
        if isinstance(name, str):
            yield Occurrence(
                DeclarationKind.NODE, name, model.file, node.location, node.condition & condition
            )


def repeated_inclusions(model: LaunchModel, started: bool = False) -> list[Clash]:
    """One node declaration loaded twice by ``model.file`` (a file included twice).

    Clashes between different declarations are found between the files that write
    them; only a declaration meeting itself, through two includes, is the entry
    file's own clash. With ``started``, ROS 2 nodes too (``ros2 launch`` starts both:
    not a conflict, a finding of ``rosvar check``).
    """
    own = _WrittenIn(model.file)
    seen: dict[tuple[str, Location], list[Occurrence]] = defaultdict(list)
    found: list[Clash] = []
    for node in model.nodes:
        if node.is_test or not (started or _clashes(node)) or own(node.location.file):
            continue
        for occurrence in node_occurrences(model, node):
            earlier = seen[(occurrence.name, occurrence.location)]
            for first in earlier:
                both = first.condition & occurrence.condition
                if both != both.bdd.false:
                    found.append(
                        Clash(DeclarationKind.NODE, occurrence.name, first, occurrence, both)
                    )
            earlier.append(occurrence)
    return found


def index(
    models: Iterable[LaunchModel], launched: Mapping[str, BDD] | None = None
) -> dict[tuple[str, str], list[Occurrence]]:
    """Every file's own declarations, by kind and resolved name (with ``launched``, file →
    when it is launched: the nodes each file loads, ``declared_occurrences``)."""
    buckets: dict[tuple[str, str], list[Occurrence]] = defaultdict(list)
    for model in models:
        when = None if launched is None else launched[model.file]
        for occurrence in declared_occurrences(model, when):
            buckets[(occurrence.kind, occurrence.name)].append(occurrence)
    return buckets


def internal_clashes(buckets: Mapping[tuple[str, str], Sequence[Occurrence]]) -> list[Clash]:
    """``clashes`` of two node declarations one file loads (the file alone fails)."""
    found: list[Clash] = []
    for (kind, name), occurrences in buckets.items():
        if kind != DeclarationKind.NODE or len(occurrences) < 2:
            continue
        by_file: dict[str, list[Occurrence]] = defaultdict(list)
        for occurrence in occurrences:
            by_file[occurrence.file].append(occurrence)
        for mine in by_file.values():
            found.extend(c for c in clashes({(kind, name): mine}) if c.files[0] == c.files[1])
    return found


def clashes(buckets: Mapping[tuple[str, str], Sequence[Occurrence]]) -> list[Clash]:
    """Every pair of distinct declarations sharing a bucket and possibly present together (one
    declaration loaded by two files is two)."""
    found: list[Clash] = []
    for (_, name), occurrences in buckets.items():
        if len(occurrences) < 2:
            continue
        for i, first in enumerate(occurrences):
            for second in occurrences[i + 1 :]:
                if first.location == second.location and first.file == second.file:
                    continue
                if (first.anonymous or second.anonymous) and first.file != second.file:
                    continue
                both = first.condition & second.condition
                if both != both.bdd.false:
                    found.append(Clash(first.kind, name, first, second, both))
    return found
