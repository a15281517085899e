"""What every export needs from a :class:`FeatureModel`: the system's name, the tree in
order, feature ids for solver variables and launch files, readable clash triggers.

Kept in one place so that all formats agree on names, order and the meaning of a conflict.
"""

from __future__ import annotations

import os
from dataclasses import dataclass

from rosvar.analyses.conflicts import Clash
from rosvar.analyses.feature_model.features import (
    ArgFeature,
    FeatureKind,
    FileFeature,
    ValueFeature,
)
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.analyses.feature_model.operations import simplest_trigger
from rosvar.logic.bdd import BDD


def system_name(model: FeatureModel) -> str:
    """The root feature's name: the folder(s) the launch files were found under.

    A file's id is its path relative to its root, so the root is what precedes the id in
    the file's path; several roots are joined with ``+`` in first-seen order.
    """
    roots: list[str] = []
    for file in model.files:
        path = file.file.replace(os.sep, "/")
        if file.id != path and path.endswith("/" + file.id):
            root = os.path.basename(path[: -len(file.id) - 1].rstrip("/"))
            if root and root not in roots:
                roots.append(root)
    return "+".join(roots) or "system"


@dataclass(frozen=True)
class Entry:
    """One feature of the tree, in depth-first order, with what every format shows of it."""

    kind: FeatureKind
    id: str  # the feature's id, made unique if another feature has the same one
    parent: str | None  # ``None``: a child of the root
    depth: int
    feature: FileFeature | ArgFeature | ValueFeature


class Tree:
    """The model's features in order, under ids that are unique and a root name of its own.

    Ids are the model's; only a repeated one (two roots holding the same relative path)
    gets a ``%~N`` suffix, chosen so that it equals no other id. Formats then only have to
    map unique ids to names.
    """

    def __init__(self, model: FeatureModel) -> None:
        self.model = model
        originals = set(model.feature_ids())
        taken: set[str] = set()

        def unique(wanted: str) -> str:
            name, number = wanted, 1
            while name in taken or (name != wanted and name in originals):
                number += 1
                name = f"{wanted}%~{number}"
            taken.add(name)
            return name

        self.entries: list[Entry] = []
        self.by_variable: dict[str, str] = {}  # solver variable name → feature id
        self.by_path: dict[str, str] = {}  # real path of a launch file → feature id
        self.files: dict[str, str] = {}  # a file's id in the model → its (unique) feature id
        for file in model.files:
            file_id = unique(file.id)
            self.entries.append(Entry(FeatureKind.FILE, file_id, None, 1, file))
            self.by_variable[str(file.variable.var)] = file_id
            self.by_path.setdefault(os.path.realpath(file.file), file_id)
            self.files.setdefault(file.id, file_id)
            for arg in file.args:
                arg_id = unique(arg.id)
                self.entries.append(Entry(FeatureKind.ARG, arg_id, file_id, 2, arg))
                for value in arg.values:
                    value_id = unique(value.id)
                    self.entries.append(Entry(FeatureKind.VALUE, value_id, arg_id, 3, value))
                    self.by_variable[str(value.variable.var)] = value_id
        self.root = unique(system_name(model))
        self.children: dict[str | None, list[Entry]] = {}
        for entry in self.entries:
            self.children.setdefault(entry.parent, []).append(entry)

    def file_id(self, path: str) -> str:
        return self.by_path.get(os.path.realpath(path), path)

    def names(self, reserved: str = "") -> dict[str, str]:
        """Feature id (and root) → name with ``reserved`` characters escaped (still unique)."""
        return {i: escape(i, reserved) for i in [self.root, *(e.id for e in self.entries)]}


def conflicts(model: FeatureModel) -> list[Clash]:
    """Clashes between files plus node clashes inside one file, in the model's order.

    A parameter set twice in one file is an override roslaunch allows (last wins), so those
    same-file clashes are not conflicts; a clash whose condition contradicts the inputs'
    domains cannot happen and is left out as well.
    """
    internal = {id(c) for c in model.internal}
    return [
        clash
        for clash in model.clashes
        if (clash.first.file != clash.second.file or id(clash) in internal)
        and model.space.satisfiable(clash.condition)
    ]


class Triggers:
    """``simplest_trigger`` of each conflict condition, once per distinct condition.

    Clashes between two files mostly share a condition (often ``true``), and the search is
    a walk over the condition's BDD, so a cache keyed by the BDD saves most of the work.
    """

    def __init__(self, model: FeatureModel) -> None:
        self.space = model.space
        self._cache: dict[BDD, dict[str, str]] = {}

    def __call__(self, condition: BDD) -> dict[str, str]:
        found = self._cache.get(condition)
        if found is None:
            found = dict(sorted(simplest_trigger(self.space, condition).items()))
            self._cache[condition] = found
        return found


def escape(text: str, reserved: str) -> str:
    """Percent-encode ``%``, the ``reserved`` characters and control characters.

    Percent-encoding is injective (``urllib.parse.unquote`` undoes it), so distinct ids
    stay distinct names, and characters a format forbids become visible escapes.
    """
    out: list[str] = []
    for char in text:
        if char == "%" or char in reserved or ord(char) < 0x20 or ord(char) == 0x7F:
            out.append("".join(f"%{byte:02X}" for byte in char.encode("utf-8")))
        else:
            out.append(char)
    return "".join(out)
