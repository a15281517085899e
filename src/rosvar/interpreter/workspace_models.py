"""Entry point of the interpreter: one condition space, every launch file interpreted once."""

from __future__ import annotations

import gc
import os
from collections.abc import Callable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from typing import TypeVar

from rosvar.forked import forked_map
from rosvar.frontends.xml import Snapshot
from rosvar.interpreter.dialect import dialect_of
from rosvar.interpreter.domains import DomainTable
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.resolution import Resolution
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.terms import PackageTable
from rosvar.workspace import Workspace

Progress = Callable[[int, int, str], None]
Result = TypeVar("Result")
Value = TypeVar("Value")
MAX_PASSES = 4
"""ROS 2: interpretations of one entry file at most, each knowing more undeclared args from
the start (one, unless an included file's arg is read before it is declared)."""


class Analysis:
    """The variational models of a workspace's launch files, sharing one BDD manager."""

    def __init__(
        self,
        workspace: Workspace,
        extra_values: Mapping[str, Sequence[str]] | None = None,
        env_values: Mapping[str, Sequence[str]] | None = None,
        extra_executables: Mapping[str, Sequence[str]] | None = None,
    ) -> None:
        self.workspace = workspace
        self.space = ConditionSpace(len(workspace.launch_files))
        self.dialect = dialect_of(workspace.ros_version)
        self.files = Snapshot(self.dialect.loader_for(workspace))
        self.domains = DomainTable(
            workspace, extra_values, env_values, extra_executables, files=self.files
        )
        self._given = frozenset(extra_values or ())
        """The args a command line gives values (``rosvar resolve``'s)."""
        self._models: dict[str, LaunchModel] = {}
        self._labels: dict[str, str] | None = None

    def package_table(self) -> PackageTable:
        """The workspace's packages, as terms' ``$(find)`` reads them when evaluated."""
        packages = {name: p.path for name, p in self.workspace.packages.items()}
        return PackageTable(packages, workspace=self.workspace)

    def model(self, file: str) -> LaunchModel:
        """The model of ``file`` as an entry point (interpreted once, then cached)."""
        if file not in self._models:
            self._models[file] = self._interpret(file)
        return self._models[file]

    def resolve(
        self,
        files: Sequence[str],
        args: Mapping[str, str] | None = None,
        env: Mapping[str, str] | None = None,
    ) -> Resolution:
        """What the workspace's launch tool starts for ``files`` and the command line's
        ``name:=value`` ``args``, in environment ``env`` (other variables unset): its
        dialect's resolution, restricting the models."""
        resolver = dialect_of(self.workspace.ros_version).resolver
        return resolver(self, files, args or {}, env or {})

    def all_models(self, progress: Progress | None = None) -> list[LaunchModel]:
        """Every launch file's model, in this process (the callers keep working on them)."""
        return self.map_models(_itself, progress=progress)

    def map_models(
        self,
        work: Callable[[LaunchModel], Result],
        jobs: int = 1,
        progress: Progress | None = None,
    ) -> list[Result]:
        """What ``work`` makes of each launch file's model, in the files' order, computed by
        ``jobs`` processes (``rosvar.forked``), for outputs that need only data derived from
        each model: the models stay in the process that built them. Every file is read and
        the include index built first, so that the processes share them; each process
        builds all its models before ``work`` runs on one (the readable form of conditions
        is computed once the facts stop growing)."""
        files = self.workspace.launch_files

        def worked(file: str) -> Result:
            return work(self.model(file))

        def shown(index: int) -> None:
            if progress is not None:
                progress(index, len(files), files[index])

        with collector_paused():  # the parsed trees are long-lived too
            self.domains.read_all()
            return forked_map(files, worked, jobs, shown, prepare=self.model)

    def label(self, file: str) -> str:
        """The file as people name it: relative to the root it was found under, or its
        absolute path when a file found before it already has that name (two roots holding
        the same relative path): labels name feature variables, so they must be unique."""
        if self._labels is None:
            self._labels = {}
            taken: set[str] = set()
            for found in self.workspace.launch_files:
                relative = self._relative(found)
                self._labels[found] = found if relative in taken else relative
                taken.add(relative)
        return self._labels.get(file) or self._relative(file)

    def _relative(self, file: str) -> str:
        for root in self.workspace.roots:
            relative = os.path.relpath(file, root)
            if not relative.startswith(".."):
                return relative
        return file

    def _interpret(self, file: str) -> LaunchModel:
        # The file's feature variable goes first so that it sits next to its args in
        # the BDD variable order (the feature model pairs them).
        self.space.file_atom(file, self.label(file))
        undeclared: dict[str, str] = {}
        first: list[str] | None = None  # the first interpretation's names, in order
        declared: dict[str, str] = {}  # the file declaring each included file's arg first
        for _ in range(MAX_PASSES):
            model, late = self._interpret_with(file, undeclared)
            if first is None:
                first = [*model.inputs, *model.settable]
            for name, declaring in model.settable.items():
                declared.setdefault(name, declaring)
            # ROS 2: a given name:=value that no file declares is set all the same
            # (ros2 launch sets every one before loading): the entry file's, from the start
            unknown = self._given - model.inputs.keys() - model.settable.keys() - undeclared.keys()
            if not late and not unknown:
                break
            # ROS 2: args included files declare are inputs from their declaration; one read
            # before it needs them from the start, as the command line sets them
            # sorted: a set's order follows the hash seed
            undeclared |= {name: declared[name] for name in sorted(late)}
            undeclared |= dict.fromkeys(sorted(unknown), file)
        return _settled(model, first, declared, self.space) if undeclared and first else model

    def _interpret_with(
        self, file: str, undeclared: Mapping[str, str]
    ) -> tuple[LaunchModel, set[str]]:
        """The model, and the args to know from the start in another interpretation."""
        model, late = self.dialect.interpret(
            self.workspace,
            self.space,
            self.domains.arg_domain,
            self.domains.env_domain,
            file,
            self.files,
            undeclared,
        )
        for name in model.inputs:  # what leaving each arg out amounts to, if one literal
            default = self.domains.unset_default(file, name)
            if default is not None:
                model.unset_defaults[name] = default
        return model, late


def _settled(
    model: LaunchModel, names: list[str], declared: Mapping[str, str], space: ConditionSpace
) -> LaunchModel:
    """``model`` as if interpreted once: which interpretation found a name late, or which
    include declared an arg first in it, must not show. Its inputs, domains and settable
    names in the order of ``names`` (the first interpretation's: the order of declaration;
    one knowing late names from the start enters them first), those it did not have after;
    each included file's arg declared by the file that declared it first (``declared``),
    whose values are its input's slots in the condition space."""

    def ordered(table: dict[str, Value]) -> dict[str, Value]:
        return {name: table[name] for name in names if name in table} | table

    model.settable = {name: declared.get(name, file) for name, file in model.settable.items()}
    for name in model.settable:
        model.domains[name] = space.domain(model.inputs[name])
    model.inputs = ordered(model.inputs)
    model.domains = ordered(model.domains)
    model.settable = ordered(model.settable)
    model.unset_defaults = ordered(model.unset_defaults)
    return model


def _itself(model: LaunchModel) -> LaunchModel:
    return model


@contextmanager
def collector_paused() -> Iterator[None]:
    """Pause CPython's cyclic garbage collector while models (or what is derived from
    them, such as the feature model) are built.

    Models are a large heap of long-lived objects that form no cycles: the collector
    rescanned all of it each time it grew by a quarter (a large share of the time on big
    workspaces) and found nothing to free. Reference counting still frees everything else.
    Afterwards what was built goes straight to the oldest generation (freezing and
    unfreezing moves it there unscanned): left in the youngest, the collector's next run
    scanned all of it, at a cost in analysis time, and two more runs followed as it
    aged. The rare cycles (an exception's frames) are still collected by a full run.
    """
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.freeze()
            gc.unfreeze()
            gc.enable()
