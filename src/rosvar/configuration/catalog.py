"""The feature tree as the user names it: ids spelled with the user's file paths.

The feature model names files relative to their package roots; a user names them as typed
on the command line. The catalogue re-spells every id (``FILE``, ``FILE:ARG``,
``FILE:ARG=VALUE``) and ties each feature to its solver variable.
"""

from __future__ import annotations

import difflib
import os
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass

from rosvar.analyses.feature_model.features import (
    ArgFeature,
    FeatureKind,
    FileFeature,
    ValueFeature,
)
from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.configuration.choices import ChoiceError

NEAREST = 3
"""Ids an unknown feature id is answered with, at most."""


@dataclass(frozen=True)
class Feature:
    """One feature; ``variable`` is its solver variable (an arg shares its file's)."""

    id: str
    kind: FeatureKind
    file: str
    arg: str | None
    value: str | None
    parent: str | None
    variable: str


@dataclass(frozen=True)
class FileEntry:
    """A launch file of the model with its spelled id and its feature-model parts."""

    id: str
    path: str
    feature: FileFeature
    variable: str


class Catalog:
    """Every feature by id and by solver variable, in tree order."""

    def __init__(
        self,
        model: FeatureModel,
        spelling: Mapping[str, str] | None = None,
    ) -> None:
        solver = model.solver
        self.model = model
        spell = _speller(spelling)
        self.files: list[FileEntry] = []
        self.features: dict[str, Feature] = {}
        self.by_variable: dict[str, Feature] = {}
        self.args: dict[str, tuple[ArgFeature, list[tuple[Feature, ValueFeature]]]] = {}
        self._by_path: dict[str, str] = {}
        for file in model.files:
            file_id = spell(file.file)
            variable = str(solver.var(file.variable).var)
            self.files.append(FileEntry(file_id, file.file, file, variable))
            self._by_path[os.path.realpath(file.file)] = file_id
            self._by_path[file.id] = file_id  # as ``rosvar features`` prints it
            self._add(Feature(file_id, FeatureKind.FILE, file_id, None, None, None, variable))
            for arg in file.args:
                arg_id = f"{file_id}:{arg.name}"
                self._add(
                    Feature(arg_id, FeatureKind.ARG, file_id, arg.name, None, file_id, variable)
                )
                values = []
                for value in arg.values:
                    entry = Feature(
                        f"{arg_id}={value.value}",
                        FeatureKind.VALUE,
                        file_id,
                        arg.name,
                        value.value,
                        arg_id,
                        str(solver.var(value.variable).var),
                    )
                    self._add(entry)
                    values.append((entry, value))
                self.args[arg_id] = (arg, values)

    def _add(self, feature: Feature) -> None:
        self.features[feature.id] = feature
        if feature.kind != FeatureKind.ARG:
            self.by_variable[feature.variable] = feature

    def __iter__(self) -> Iterator[Feature]:
        return iter(self.features.values())

    def file_id(self, path: str) -> str:
        return self._by_path[os.path.realpath(path)]

    def lookup(self, text: str) -> Feature:
        """The feature named ``text``; the file part may be any path to the file (from the
        current directory, absolute) or its id in the feature model (from the workspace root,
        as ``rosvar features`` prints it). An unknown id is refused with the nearest ones."""
        found = self.features.get(text)
        if found is not None:
            return found
        file, sep, rest = text.partition(":")
        while True:
            spelled = self._by_path.get(file) or self._by_path.get(os.path.realpath(file))
            if spelled is not None:
                found = self.features.get(spelled + sep + rest)
                if found is not None:
                    return found
            head, sep2, tail = rest.partition(":")
            if not sep2:
                break
            file, rest = f"{file}:{head}", tail
        near = self._nearest(text)
        hint = f"; did you mean {' or '.join(repr(n) for n in near)}?" if near else ""
        raise ChoiceError(f"no feature {text!r}{hint}")

    def _nearest(self, text: str) -> list[str]:
        """Up to ``NEAREST`` ids near ``text``. People name a file by its name alone
        (``control.launch``), or misspell it: its files are those of that name, else of that
        name without its suffix (``control.xml``), else of a close name; with what ``text``
        says after the file (``:ARG=VALUE``), or the features of the file closest to it.
        Else ids close to ``text`` as a whole."""
        file, sep, rest = text.partition(":")
        name = os.path.basename(file)
        names = {entry.id: os.path.basename(entry.id) for entry in self.files}
        found = [i for i, n in names.items() if n == name]
        if not found:
            stem = name.split(".")[0]
            found = [i for i, n in names.items() if n.split(".")[0] == stem]
        if not found:
            close = set(difflib.get_close_matches(name, set(names.values()), n=NEAREST))
            found = [i for i, n in names.items() if n in close]
        spelled: list[str] = []
        for file_id in found:
            whole = f"{file_id}{sep}{rest}"
            if whole in self.features:
                spelled.append(whole)
                continue
            own = [k for k in self.features if k.startswith(f"{file_id}:")]  # its args, values
            spelled += difflib.get_close_matches(whole, own, NEAREST, 0.6) or [file_id]
        return spelled[:NEAREST] or difflib.get_close_matches(text, self.features, NEAREST, 0.6)

    def values_of(self, arg_id: str) -> list[tuple[Feature, ValueFeature]]:
        return self.args[arg_id][1]

    def chosen(self, arg_id: str, decided: Mapping[str, bool]) -> ValueFeature | None:
        """The value the arg takes once ``decided`` (variable → value) selects one."""
        for feature, value in self.values_of(arg_id):
            if decided.get(feature.variable):
                return value
        return None


def _speller(spelling: Mapping[str, str] | None) -> Callable[[str], str]:
    def spell(path: str) -> str:
        real = os.path.realpath(path)
        if spelling is not None and real in spelling:
            return spelling[real]
        return os.path.relpath(path)

    return spell
