"""What every export needs from a :class:`FeatureModel`: the system's name, the tree in
order, feature ids for solver variables and launch files, readable clash triggers.

Kept in one place so that all formats agree on names, order and the meaning of a conflict.
"""

from __future__ import annotations

import os
from dataclasses import dataclass

from rosvar.analyses.conflicts import Clash
from rosvar.analyses.features import (
    ArgFeature,
    FeatureModel,
    FileFeature,
    ValueFeature,
)
from rosvar.logic.conditions import BDD, FileAtom, PredicateAtom, SlotAtom
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, Input, Slot
from rosvar.logic.terms import Apply, Hole, Operand


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

    kind: str  # "file", "arg" or "value"
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
            self.entries.append(Entry("file", file_id, None, 1, file))
            self.by_variable[str(file.variable.var)] = file_id
            self.by_path.setdefault(os.path.realpath(file.file), file_id)
            self.files.setdefault(file.id, file_id)
            for arg in file.args:
                arg_id = unique(arg.id)
                self.entries.append(Entry("arg", arg_id, file_id, 2, arg))
                for value in arg.values:
                    value_id = unique(value.id)
                    self.entries.append(Entry("value", value_id, arg_id, 3, value))
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
    """For each conflict condition, the input values that make it hold with fewest changes.

    The reading of ``features.simplest_trigger`` (cost: one per input not at its first slot
    or unset), but searched over the inputs the condition mentions only: ``simplest_trigger``
    enumerates assignments of every atom of the analysis, so its first 257 candidates differ
    only in the last-declared inputs and it answers with ``<other>`` for all of them.
    Keys are arg names (``$NAME`` for environment variables), qualified by their file's id
    when two files' args share a name. Computed once per distinct condition.
    """

    LIMIT = 4096  # candidate assignments looked at; conditions mention few inputs

    def __init__(self, model: FeatureModel, tree: Tree | None = None) -> None:
        self.model = model
        self.tree = tree if tree is not None else Tree(model)
        self._cache: dict[BDD, dict[str, str]] = {}

    def __call__(self, condition: BDD) -> dict[str, str]:
        found = self._cache.get(condition)
        if found is None:
            found = self._search(condition)
            self._cache[condition] = found
        return found

    def _search(self, condition: BDD) -> dict[str, str]:
        space = self.model.space
        inputs: set[Input] = set()
        care: set[str] = set()
        for name in space.bdd.support(condition):
            atom = space.atom_of(name)
            if isinstance(atom, SlotAtom):
                inputs.add(atom.input)
            elif isinstance(atom, PredicateAtom):
                inputs |= _predicate_inputs(atom)
                care.add(name)
            else:
                care.add(name)
        declared = set(space.inputs())
        inputs = {i for i in inputs if i in declared}
        domains = {i: space.domain(i) for i in inputs}
        within = condition
        for input_ in inputs:
            within &= space.input_constraint(input_)
            care |= {space.variable_name(SlotAtom(input_, slot)) for slot in domains[input_]}
        ranked: list[tuple[int, int, list[str], dict[str, bool]]] = []
        for number, assignment in enumerate(space.bdd.pick_iter(within, care_vars=care)):
            if number >= self.LIMIT:
                break
            cost, others, shown = 0, 0, []
            for name, value in sorted(assignment.items()):
                atom = space.atom_of(name)
                if value and isinstance(atom, SlotAtom):
                    first = domains[atom.input][0]
                    cost += 0 if atom.slot is UNSET or atom.slot == first else 1
                    others += atom.slot is OTHER  # a value analysis knows reads better
                    shown.append(f"{atom.input}={_slot(atom.slot)}")
            ranked.append((cost, others, sorted(shown), assignment))
        ranked.sort(key=lambda r: (r[0], r[1], r[2]))
        for *_, assignment in ranked:  # the cheapest that the whole analysis allows
            if space.satisfiable(space.bdd.cube(assignment)):
                return self._named(assignment)
        return {}

    def _named(self, assignment: dict[str, bool]) -> dict[str, str]:
        space = self.model.space
        chosen: list[tuple[Input | str, str]] = []
        for name, value in assignment.items():
            atom = space.atom_of(name)
            if value and isinstance(atom, SlotAtom):
                chosen.append((atom.input, _slot(atom.slot)))
            elif value and isinstance(atom, FileAtom):
                chosen.append((self.tree.file_id(atom.file), "selected"))
        counts: dict[str, int] = {}
        for key, _ in chosen:
            counts[str(key)] = counts.get(str(key), 0) + 1
        named: dict[str, str] = {}
        for key, text in chosen:
            label = str(key)
            if isinstance(key, ArgInput) and counts[label] > 1:
                label = f"{self.tree.file_id(key.file)}:{key.name}"
            named[label] = text
        return dict(sorted(named.items()))


def _slot(slot: Slot) -> str:
    return slot if isinstance(slot, str) else repr(slot)


def _predicate_inputs(atom: PredicateAtom) -> set[Input]:
    """The inputs whose typed-in strings a predicate tests."""
    found: set[Input] = set()
    pending: list[Operand] = [atom.term]
    while pending:
        operand = pending.pop()
        if isinstance(operand, Hole):
            found.add(operand.input)
        elif isinstance(operand, Apply):
            pending.extend(operand.operands)
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
