"""A launch model restricted to one configuration, and what the launch tool would then start.

Nothing is interpreted again: a dialect's resolver (``roslaunch FILE... name:=value``, ``ros2
launch FILE name:=value``; :attr:`Dialect.resolver <rosvar.interpreter.dialect.Dialect>`)
reads the model through a :class:`Restriction`: every presence condition evaluated under the
configuration's atom assignment, every conditional value picking its branch, terms evaluated
with the concrete inputs. Both dialects give one result type, :class:`Resolution`: typed nodes
(:class:`ResolvedNode`) with what only their dialect holds beside, ROS 1's tests and parameter
server, conflicts, errors and warnings.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Protocol

from rosvar.diagnostics import Diagnostic, Location
from rosvar.files import Confinement
from rosvar.interpreter.model import (
    DeferredValue,
    ErrorEvent,
    LaunchModel,
    NodeDecl,
    Raw,
    YamlDecl,
    anon_pattern,
)
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.given_up import Bindings
from rosvar.logic.inputs import EnvInput, Input
from rosvar.logic.terms import Apply, Hole, TermError, evaluate
from rosvar.ros.version import RosVersion
from rosvar.workspace import Workspace


class Models(Protocol):
    """What a resolution reads: the models of a workspace's entry files, over one space
    (:class:`~rosvar.interpreter.workspace_models.Analysis`)."""

    @property
    def space(self) -> ConditionSpace: ...

    @property
    def workspace(self) -> Workspace: ...

    def model(self, file: str) -> LaunchModel: ...


class Resolver(Protocol):
    """A dialect's resolution: what its launch tool starts for ``files`` and the command
    line's ``name:=value`` ``args``, in environment ``env`` (other variables unset)."""

    def __call__(
        self,
        models: Models,
        files: Sequence[str],
        args: Mapping[str, str],
        env: Mapping[str, str],
    ) -> Resolution: ...


class ResolutionError(Exception):
    """The launch tool would fail in this configuration."""

    def __init__(self, code: str, message: str, location: Location) -> None:
        super().__init__(message)
        self.code = code
        self.message = message
        self.location = location


class ConflictKind(StrEnum):
    """Why roslaunch cannot have two elements together."""

    NODE_NAME = "node-name"  # two nodes with one full name


@dataclass(frozen=True)
class Checks:
    """What a dialect's launch tool checks of a node's strings while loading it, as its
    resolution checks them (:class:`ResolutionError` where it stops): the configuration
    graph checks the texts a user types with them."""

    node: Callable[[Mapping[str, str | None], Location], dict[str, object]]
    """A node's typed attributes."""
    test: Callable[[Mapping[str, str | None], Location], dict[str, object]]
    """A test's own attributes."""
    remap: Callable[[str | None, str | None, Location], None]
    """A remap's two names."""
    parameter: Callable[[str, str, Location], None] = lambda _text, _kind, _where: None
    """A node's own parameter value of a declared type (ROS 2's ``<param type>``): its text
    and the type's name (a ROS 1 node has no parameters of its own)."""


NodeFields = Callable[
    [NodeDecl, Mapping[str, str | None], Sequence[tuple[str | None, str | None]], Confinement],
    dict[str, object],
]
"""What a dialect's launch tool holds of a node, beyond what every dialect has, given the
strings of one configuration: the node's fields and its parameter settings in order (``(name,
value)``, or ``(None, file)``), read inside the workspace's confinement. What is not valid
(yet: an arg still open) is left out, as the configuration graph's errors say why. The graph's
entries show a node with it."""


@dataclass
class Conflict:
    """Two elements of one configuration that roslaunch cannot both have."""

    kind: ConflictKind
    name: str
    locations: list[Location]


@dataclass
class ResolvedNode:
    """A node one configuration starts (ROS 1: or a ``<test>``; ROS 2: or a process), as its
    launch tool holds it: what both dialects have, typed; what only one has, in
    ``attributes``."""

    name: str
    """Its full name (ROS 2, where its code names it: ``⟨EXEC⟩`` in its namespace)."""
    own_name: str | None
    """The name it is given (ROS 2: None where its code names it)."""
    namespace: str | None
    """ROS 1's ends with ``/``; ROS 2's is None where neither a pushed nor its own is given."""
    package: str | None
    executable: str | None
    args: str
    """Its command-line arguments as written (``""`` without)."""
    plugin: str | None
    """A ROS 2 composable node's class."""
    remaps: list[tuple[str, str]]
    """As the node tries them: ROS 1's one per source (the last wins), sorted; ROS 2's in
    order (the first that matches wins)."""
    env: list[tuple[str, str]]
    location: Location
    filename: str
    """The launch file that declares it (roslaunch's ``Node.filename``)."""
    version: RosVersion
    attributes: dict[str, object] = field(default_factory=dict)
    """What only its dialect's launch tool holds, as JSON values: ROS 1's ``respawn``,
    ``machine``...; ROS 2's ``kind``, ``fqn``, ``plugin``, ``container``, ``arguments``,
    ``cmd``."""
    parameters: dict[str, object] | None = None
    """A ROS 2 node's own parameters, the values it starts with (ROS 1's are the server's)."""
    test: dict[str, object] | None = None
    """A ``<test>``'s own attributes (``test_name``, ``time_limit``, ``retry``)."""
    scope: Mapping[str, str] = field(default_factory=dict)
    """The texts of the args its scope sees (ROS 1; for a hinted entry's ``when:``)."""

    @property
    def ros2(self) -> bool:
        return self.version is RosVersion.ROS2


@dataclass
class Resolution:
    """What one configuration starts: nodes, ROS 1's tests and parameter server, and why it
    fails (errors, ROS 1's conflicts) or what the launch tool warns of."""

    nodes: list[ResolvedNode] = field(default_factory=list)
    tests: list[ResolvedNode] = field(default_factory=list)
    params: dict[str, object] = field(default_factory=dict)
    conflicts: list[Conflict] = field(default_factory=list)
    errors: list[ResolutionError] = field(default_factory=list)
    warnings: list[Diagnostic] = field(default_factory=list)
    on_events: list[ResolvedNode] = field(default_factory=list)
    """ROS 2: nodes that event handlers start after the launch started (a process's exit, its
    output, a lifecycle transition, the shutdown), which the launch itself does not start."""

    @property
    def ok(self) -> bool:
        return not self.errors and not self.conflicts

    def sorted_nodes(self) -> list[ResolvedNode]:
        """The nodes by full name (two ROS 2 nodes of one name keep their order)."""
        return sorted(self.nodes, key=lambda node: node.name)


class Restriction:
    """One model under one configuration."""

    def __init__(
        self,
        models: Models,
        model: LaunchModel,
        args: Mapping[str, str],
        env: Mapping[str, str],
    ) -> None:
        self.space = models.space
        self.model = model
        values: dict[Input, str | None] = {}
        for name, input_ in model.inputs.items():
            values[input_] = args.get(name, model.unset_defaults.get(name))
        for other in self.space.inputs():
            if isinstance(other, EnvInput):
                values[other] = env.get(other.name)
        self.concrete: dict[Input, str] = {k: v for k, v in values.items() if v is not None}
        self.confinement = models.workspace.confinement()
        packages = {name: package.path for name, package in models.workspace.packages.items()}
        self.assignment: dict[str, bool] = {}
        holds = functools.partial(_holds, self.space, self.assignment)
        self.host = Bindings(packages, holds, workspace=models.workspace)
        """Terms evaluate with the packages; values over the work limits are computed again
        with the conditions that hold (:mod:`~rosvar.logic.given_up`), also while the
        assignment is made: a predicate on such a value reads its operands' atoms."""
        self.space.assignment(values, self.host, into=self.assignment)
        self._shift: Callable[[str], str] | None = None

    def shift_anon(self, offset: int) -> None:
        """Number this file's ``$(anon)`` names after those of the files loaded before it.

        roslaunch draws one random name per id; the deterministic ``{id}_anon{n}``
        stand-in must keep counting across the files of one command line.
        """
        pattern = anon_pattern(self.model.anon_ids)
        if offset and pattern is not None:
            self._shift = lambda text: pattern.sub(
                lambda m: f"{m.group(1)}_anon{int(m.group(2)) + offset}", text
            )

    def holds(self, condition: BDD) -> bool:
        return self.host.holds(condition)

    def evaluate(self, value: Raw, location: Location, what: str) -> str:
        """A term's string under this configuration (the launch tool's failure if it has
        none)."""
        return evaluated(value, self.concrete, self.host, location, what)

    def pick(self, choice: Choice[object], location: Location, what: str) -> object:
        for condition, leaf in choice:
            if self.holds(condition):
                if isinstance(leaf, Hole | Apply):
                    leaf = self.evaluate(leaf, location, what)
                if isinstance(leaf, str) and self._shift is not None:
                    return self._shift(leaf)
                return leaf
        raise ResolutionError("value-undefined", f"{what} has no value here", location)

    def error(self, event: ErrorEvent) -> ResolutionError:
        """The launch tool's error of ``event`` in this configuration: the failure of the
        value it tested, where that value cannot be computed here either."""
        if event.tested is not None:
            try:
                self.pick(event.tested.value, event.location, event.tested.what)
            except ResolutionError as failure:
                # the finding, not the frames: its traceback (and that of the error it was
                # raised over) holds this frame's callers, and through them the result it
                # goes into, a reference cycle with the analysis's diagrams that the
                # collector frees in any order, the BDD manager before them
                failure.__traceback__ = None
                failure.__context__ = None
                return failure
        return ResolutionError(event.code, event.message, event.location)

    def raw(self, choice: Choice[Raw | None], location: Location, what: str) -> str | None:
        value = self.pick(choice, location, what)
        assert value is None or isinstance(value, str)
        return value


def _holds(space: ConditionSpace, assignment: Mapping[str, bool], condition: BDD) -> bool:
    """:meth:`Restriction.holds` without the restriction (which holds its bindings)."""
    return space.evaluate(condition, assignment)


def evaluated(
    value: Raw, concrete: Mapping[Input, str], host: object, location: Location, what: str
) -> str:
    """A term's string with the inputs' ``concrete`` strings (the launch tool's failure if it
    has none: an unknown package, a file not read)."""
    try:
        return evaluate(value, concrete, host)
    except TermError as error:
        raise ResolutionError(error.code, f"{what}: {error}", location) from None
    except (LookupError, ValueError) as error:
        raise ResolutionError("value-unknown", f"{what}: {error}", location) from None


def deferred_value(
    value: DeferredValue, text: str, location: Location, confinement: Confinement
) -> object:
    """A ``<param>`` value whose string became ``text``, typed as its launch tool types it."""
    try:
        return value.convert(value.kind, text, value.ptype, confinement)
    except ValueError as error:
        raise ResolutionError("param-invalid", str(error), location) from None


RosparamTexts = tuple[str, str, str | None, str | None, str | None, str]
"""A ``<rosparam>``'s strings: its scope's namespace, command, ns, file, param and body."""


def rosparam_pairs(
    param: YamlDecl, texts: RosparamTexts, confinement: Confinement
) -> list[tuple[str, object]]:
    """The params ``param`` sets with these strings, as roslaunch loads them."""
    scope_ns, command, ns, file, name, body = texts
    try:
        return param.load(command, ns, file, name, body, scope_ns, confinement)
    except ValueError as error:
        raise ResolutionError(
            "rosparam-invalid", f"error loading <rosparam> tag: {error}", param.location
        ) from None
