"""Restrict the variational model to one configuration: what roslaunch would load.

Nothing is interpreted again: every presence condition is evaluated under the
configuration's atom assignment, every conditional value picks its branch, and
terms are evaluated with the concrete inputs. The result has roslaunch's shape
(nodes, params, errors) plus conflicts (duplicate node names) with both
locations.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from enum import StrEnum

from rosvar.analyses.json_values import json_value
from rosvar.diagnostics import Location
from rosvar.files import Confinement
from rosvar.interpreter.model import (
    DeferredValue,
    LaunchModel,
    NodeDecl,
    ParamDecl,
    Raw,
    YamlDecl,
    anon_pattern,
)
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.inputs import ArgInput, EnvInput, Input
from rosvar.logic.terms import Apply, Hole, PackageTable, TermError, evaluate
from rosvar.ros import names
from rosvar.ros1.validation import node_values


class ResolutionError(Exception):
    """roslaunch would fail in this configuration."""

    def __init__(self, code: str, message: str, location: Location) -> None:
        super().__init__(message)
        self.code = code
        self.message = message
        self.location = location


class ConflictKind(StrEnum):
    """Why roslaunch cannot have two elements together."""

    NODE_NAME = "node-name"  # two nodes with one full name


@dataclass
class Conflict:
    """Two elements of one configuration that roslaunch cannot both have."""

    kind: ConflictKind
    name: str
    locations: list[Location]

    def to_json(self) -> dict[str, object]:
        return {
            "kind": self.kind,
            "name": self.name,
            "locations": [loc.to_json() for loc in self.locations],
        }


@dataclass
class Resolution:
    nodes: list[dict[str, object]] = field(default_factory=list)
    tests: list[dict[str, object]] = field(default_factory=list)
    params: dict[str, object] = field(default_factory=dict)
    conflicts: list[Conflict] = field(default_factory=list)
    errors: list[ResolutionError] = field(default_factory=list)
    scopes: list[Mapping[str, str]] = field(default_factory=list)
    """Per node, the texts of the args its scope sees (for a hint's ``when:``)."""

    @property
    def ok(self) -> bool:
        return not self.errors and not self.conflicts

    def to_json(self) -> dict[str, object]:
        return {
            "ok": self.ok,
            "nodes": sorted(self.nodes, key=lambda n: str(n["name"])),
            "tests": sorted(self.tests, key=lambda n: str(n["name"])),
            "params": dict(sorted(self.params.items())),
            "conflicts": [c.to_json() for c in self.conflicts],
            "errors": [
                {"code": e.code, "message": e.message, **e.location.to_json()} for e in self.errors
            ],
        }


class Restriction:
    """One model under one configuration."""

    def __init__(
        self,
        analysis: Analysis,
        model: LaunchModel,
        args: Mapping[str, str],
        env: Mapping[str, str],
    ) -> None:
        self.space = analysis.space
        self.model = model
        values: dict[Input, str | None] = {}
        for name, input_ in model.inputs.items():
            values[input_] = args.get(name, model.unset_defaults.get(name))
        for other in self.space.inputs():
            if isinstance(other, EnvInput):
                values[other] = env.get(other.name)
        self.concrete: dict[Input, str] = {k: v for k, v in values.items() if v is not None}
        self.confinement = analysis.workspace.confinement()
        self.host = PackageTable(
            {name: package.path for name, package in analysis.workspace.packages.items()}
        )
        self.assignment = self.space.assignment(values, self.host)
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
        return self.space.evaluate(condition, self.assignment)

    def evaluate(self, value: Raw, location: Location, what: str) -> str:
        """A term's string under this configuration (roslaunch's failure if it has none)."""
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

    def raw(self, choice: Choice[Raw | None], location: Location, what: str) -> str | None:
        value = self.pick(choice, location, what)
        assert value is None or isinstance(value, str)
        return value


def resolve(
    analysis: Analysis,
    files: Sequence[str],
    args: Mapping[str, str] | None = None,
    env: Mapping[str, str] | None = None,
) -> Resolution:
    """What ``roslaunch FILES name:=value...`` loads in environment ``env``."""
    result = Resolution()
    # as roslaunch reads its command line: e.g. `x:=` (empty) or `3d:=v` never reach an arg
    args = names.command_line_mappings([f"{k}:={v}" for k, v in (args or {}).items()])
    seen_nodes: dict[str, Location] = {}
    machines: set[str] = set()
    anon_offset = 0
    for file in files:
        model = analysis.model(file)
        restriction = Restriction(analysis, model, args, env or {})
        restriction.shift_anon(anon_offset)
        try:
            _restrict(restriction, model, result, seen_nodes)
            if model.anon_count is not None:
                count = restriction.pick(model.anon_count, Location(file), "$(anon) count")
                anon_offset += int(str(count))
            machines |= {
                str(restriction.pick(m.name, m.location, "machine name"))
                for m in model.machines
                if restriction.holds(m.condition)
            }
        except ResolutionError as error:
            # keep the finding, not the frames: a traceback would tie the whole
            # analysis (and its BDD manager) into a reference cycle
            error.__traceback__ = None
            error.__context__ = None
            result.errors.append(error)
            return result
    for node in result.nodes:  # roslaunch's assign_machines(), after every file is loaded
        machine = node.get("machine")
        if machine and machine not in machines:
            location = Location(
                str(node["filename"]), int(str(node["line"])), int(str(node["col"]))
            )
            result.errors.append(
                ResolutionError("machine-unknown", f"ERROR: unknown machine [{machine}]", location)
            )
            break
    return result


def _restrict(
    r: Restriction, model: LaunchModel, result: Resolution, seen: dict[str, Location]
) -> None:
    for event in model.errors:
        if r.holds(event.condition):
            raise ResolutionError(event.code, event.message, event.location)
    for include in model.includes:
        if not include.resolved and r.holds(include.condition):
            file = r.pick(include.file, include.location, "<include> file")
            raise ResolutionError(
                "include-unknown", f"cannot load included file {file}", include.location
            )
    for node in model.nodes:
        if not r.holds(node.condition):
            continue
        entry = _node(r, node)
        if node.is_test:
            result.tests.append(entry)
            continue
        full = str(entry["name"])
        if full in seen:
            result.conflicts.append(
                Conflict(ConflictKind.NODE_NAME, full, [seen[full], node.location])
            )
        else:
            seen[full] = node.location
        result.nodes.append(entry)
        result.scopes.append(_Scope(r, node))
    for param in model.params:
        if not r.holds(param.condition):
            continue
        if isinstance(param, ParamDecl):
            name = r.pick(param.name, param.location, "param name")
            value = r.pick(param.value, param.location, f"param {name}")
            if isinstance(value, DeferredValue):
                concrete = r.evaluate(value.raw, param.location, f"param {name}")
                value = deferred_value(value, concrete, param.location, r.confinement)
            result.params[str(name)] = json_value(value)
        else:
            parts = [
                None if part is None else r.evaluate(part, param.location, "<rosparam>")
                for part in (param.scope_ns, param.command, param.ns, param.file, param.param)
            ]
            body = r.evaluate(param.text, param.location, "<rosparam> body")
            scope_ns, command, ns, file, name = parts
            pairs = rosparam_pairs(
                param, (str(scope_ns), str(command), ns, file, name, body), r.confinement
            )
            for key, value in pairs:
                result.params[key] = json_value(value)


class _Scope(Mapping[str, str]):
    """The args a node's scope sees, each picked when read: a node sees every arg of its
    file, and a hint reads one or two."""

    def __init__(self, r: Restriction, node: NodeDecl) -> None:
        self._r = r
        self._node = node

    def __getitem__(self, name: str) -> str:
        choice = self._node.args[name]
        try:
            text = self._r.pick(choice, self._node.location, f"arg {name}")
        except ResolutionError:
            raise KeyError(name) from None
        if not isinstance(text, str):
            raise KeyError(name)  # undefined there
        return text

    def __iter__(self) -> Iterator[str]:
        return iter(self._node.args)

    def __len__(self) -> int:
        return len(self._node.args)


def _node(r: Restriction, node: object) -> dict[str, object]:
    assert isinstance(node, NodeDecl)
    location = node.location
    raw = {k: r.raw(v, location, f"<node> {k}") for k, v in node.fields.items()}
    typed = typed_node(raw, location)
    namespace = str(raw["namespace"])
    name = raw["name"] or ""
    remaps: dict[str, str] = {}
    for remap in node.remaps:
        if r.holds(remap.condition):
            source = r.raw(Choice.const(r.space, remap.source), location, "remap from")
            target = r.raw(Choice.const(r.space, remap.target), location, "remap to")
            check_remap(source, target, location)
            remaps.pop(str(source), None)
            remaps[str(source)] = str(target)
    env = [
        [
            r.raw(Choice.const(r.space, e.name), location, "env"),
            r.raw(Choice.const(r.space, e.value), location, "env"),
        ]
        for e in node.env
        if r.holds(e.condition)
    ]
    entry: dict[str, object] = {
        "name": names.ns_join(namespace, name),
        "namespace": namespace,
        "package": raw["pkg"],
        "type": raw["type"],
        **typed,
        "remaps": sorted([list(p) for p in remaps.items()]),
        "env": sorted(env),
        "filename": node.filename,
        "line": location.line,
        "col": location.col,
    }
    if node.is_test:
        entry.update(test_fields(raw, location))
    return entry


def evaluated(
    value: Raw, concrete: Mapping[Input, str], host: object, location: Location, what: str
) -> str:
    """A term's string with the inputs' ``concrete`` strings (roslaunch's failure if it has
    none: an unknown package, a file not read)."""
    try:
        return evaluate(value, concrete, host)
    except (TermError, LookupError, ValueError) as error:
        raise ResolutionError("value-unknown", f"{what}: {error}", location) from None


def deferred_value(
    value: DeferredValue, text: str, location: Location, confinement: Confinement
) -> object:
    """A ``<param>`` value whose string became ``text``, typed as roslaunch types it."""
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


def typed_node(raw: dict[str, str | None], location: Location) -> dict[str, object]:
    """A node's typed fields (``respawn``, ``required``...) as roslaunch's ``Node`` holds them."""
    try:
        return node_values(raw)
    except ValueError as error:
        raise ResolutionError("node-invalid", str(error), location) from None


def check_remap(source: str | None, target: str | None, location: Location) -> None:
    """roslaunch's checks of a ``<remap>``'s names."""
    for label, text in (("from", source), ("to", target)):
        if not text:
            raise ResolutionError(
                "remap-invalid", "remap from/to attributes cannot be empty", location
            )
        if not names.is_legal_name(text):
            raise ResolutionError(
                "remap-invalid", f"remap {label} [{text}] is not a valid ROS name", location
            )


def test_fields(raw: Mapping[str, str | None], location: Location) -> dict[str, object]:
    """``_test_attrs`` and the ``Test`` constructor: defaults 60 s and 0 retries, output log."""
    try:
        time_limit = float(raw.get("time-limit") or 60.0)
        retry = int(raw.get("retry") or 0)
    except ValueError as error:
        raise ResolutionError("test-invalid", str(error), location) from None
    if time_limit <= 0:
        raise ResolutionError("test-invalid", "'time-limit' must be a positive number", location)
    return {
        "test_name": raw.get("test-name"),
        "time_limit": time_limit,
        "retry": retry,
        "output": "log",
    }


__all__ = ["ArgInput", "Conflict", "Resolution", "ResolutionError", "resolve"]
