"""``roslaunch FILE... name:=value``: what ROS 1 would load, read off the files' models.

Each file's variational model is restricted to the configuration
(:class:`~rosvar.interpreter.resolution.Restriction`), in command-line order: the first
error stops it, as roslaunch stops; nodes (and tests) are typed as roslaunch's ``Node``
holds them, parameters set on the server, and two nodes of one full name are a conflict
with both locations.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from contextlib import suppress

from rosvar.analyses.json_values import json_value
from rosvar.diagnostics import Location
from rosvar.files import Confinement
from rosvar.interpreter.model import DeferredValue, LaunchModel, NodeDecl, ParamDecl, Raw
from rosvar.interpreter.resolution import (
    Checks,
    Conflict,
    ConflictKind,
    Models,
    Resolution,
    ResolutionError,
    ResolvedNode,
    Restriction,
    deferred_value,
    rosparam_pairs,
)
from rosvar.logic.choice import Choice
from rosvar.ros import names
from rosvar.ros1.validation import node_values


def resolve(
    models: Models,
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
        model = models.model(file)
        restriction = Restriction(models, model, args, env or {})
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
        machine = node.attributes.get("machine")
        if machine and machine not in machines:
            location = Location(node.filename, node.location.line, node.location.col)
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
            raise r.error(event)
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
        full = entry.name
        if full in seen:
            result.conflicts.append(
                Conflict(ConflictKind.NODE_NAME, full, [seen[full], node.location])
            )
        else:
            seen[full] = node.location
        result.nodes.append(entry)
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


def _node(r: Restriction, node: NodeDecl) -> ResolvedNode:
    """The node (or test) as roslaunch's ``Node`` holds it: its typed attributes checked,
    its remaps one per source (the last wins)."""
    location = node.location
    raw = {k: r.raw(v, location, f"<node> {k}") for k, v in node.fields.items()}
    typed = typed_node(raw, location)
    remaps: dict[str, str] = {}
    for remap in node.remaps:
        if r.holds(remap.condition):
            source = _text(r, remap.source, location, "remap from")
            target = _text(r, remap.target, location, "remap to")
            check_remap(source, target, location)
            remaps.pop(source, None)
            remaps[source] = target
    env = [
        (_text(r, e.name, location, "env"), _text(r, e.value, location, "env"))
        for e in node.env
        if r.holds(e.condition)
    ]
    schema = node.schema
    return ResolvedNode(
        name=schema.full_name.text(raw) or "",
        own_name=schema.name.text(raw),
        namespace=schema.namespace.text(raw),
        package=schema.package.text(raw),
        executable=schema.executable.text(raw),
        args=str(typed["args"]),
        plugin=schema.plugin.text(raw),
        remaps=sorted(remaps.items()),
        env=sorted(env),
        location=location,
        filename=node.filename,
        version=schema.version,
        attributes=typed,
        test=test_fields(raw, location) if node.is_test else None,
        scope=_Scope(r, node),
    )


def _text(r: Restriction, raw: Raw, location: Location, what: str) -> str:
    """A remap's or an ``<env>``'s string in the configuration."""
    text = r.raw(Choice.const(r.space, raw), location, what)
    assert text is not None  # a raw string is never absent
    return text


def typed_node(raw: Mapping[str, str | None], location: Location) -> dict[str, object]:
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


def node_fields(
    node: NodeDecl,
    raw: Mapping[str, str | None],
    _parameters: Sequence[tuple[str | None, str | None]],
    _confinement: Confinement,
) -> dict[str, object]:
    """A node's (a test's) typed fields as roslaunch's ``Node`` (``Test``) holds them, those
    that are valid; its parameters are the graph's own elements in ROS 1."""
    try:
        fields = node_values(raw)
    except ValueError:
        fields = {}
    if node.is_test:
        with suppress(ResolutionError):
            fields.update(test_fields(raw, node.location))
    return fields


ROS1_CHECKS = Checks(node=typed_node, test=test_fields, remap=check_remap)
"""roslaunch's checks of a node's strings, for the typed texts of the configuration graph."""
