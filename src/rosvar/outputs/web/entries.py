"""The graph's entries as the state document shows them (the page, ``configure --json``):
each element's content rendered with the strings the choices fix, one renderer per kind of
content. The engine keeps contents in raw values and conditions, and takes
:func:`render` to show them."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from functools import singledispatch
from typing import TypeVar, cast

from rosvar.analyses.communication import JSON_SIDES, SIDES
from rosvar.analyses.json_values import json_value
from rosvar.configuration.graph import (
    ChannelContent,
    Content,
    ErrorContent,
    Fields,
    NamedContent,
    NodeContent,
    ParamContent,
    PartKind,
    Setting,
    Shown,
    TopicContent,
    Values,
    YamlContent,
    topic_name,
)
from rosvar.configuration.presence import Presence
from rosvar.diagnostics import Location
from rosvar.interpreter.dialect import dialect_of
from rosvar.interpreter.model import Raw
from rosvar.interpreter.resolution import ResolutionError
from rosvar.workspace.interfaces.model import Role

C = TypeVar("C", bound=Content)
Renderer = Callable[[C, Values, Sequence[Shown]], list[Fields]]


@singledispatch
def render(content: Content, values: Values, parts: Sequence[Shown]) -> list[Fields]:
    """The entries' fields of an element showing ``content`` with ``values``, given the
    presence of each of its parts (several entries for a YAML load)."""
    raise TypeError(f"no renderer for {type(content).__name__}")


def _renders(kind: type[C]) -> Callable[[Renderer[C]], Renderer[C]]:
    """Registers the renderer of one kind of content."""

    def register(renderer: Renderer[C]) -> Renderer[C]:
        render.register(kind, renderer)
        return renderer

    return register


@_renders(ChannelContent)
def _channel(content: ChannelContent, _values: Values, parts: Sequence[Shown]) -> list[Fields]:
    """A topic (service, action) with its types and its publishers and subscribers (servers
    and clients) that are not absent, each with its presence and condition (the name's
    parts, in the order of its edges)."""
    edges = content.edges
    types = sorted({type_ for _id, _role, type_, _c, _b in edges if type_ is not None})
    roles = SIDES[content.channel]
    lists = JSON_SIDES[content.channel]
    sides: dict[Role, list[Fields]] = {role: [] for role in roles}
    for (node, role, _type, _c, _b), (presence, condition) in zip(edges, parts, strict=True):
        if presence != Presence.ABSENT:
            sides[role].append({"node": node, "presence": presence, "condition": condition})
    return [{"name": content.name, "types": types, **{lists[i]: sides[roles[i]] for i in (0, 1)}}]


@_renders(TopicContent)
def _topic(content: TopicContent, values: Values, _parts: Sequence[Shown]) -> list[Fields]:
    return [{"name": topic_name(values, *content.raws)}]


@_renders(NamedContent)
def _named(content: NamedContent, _values: Values, _parts: Sequence[Shown]) -> list[Fields]:
    return [{"name": content.name}]


@_renders(ErrorContent)
def _error(content: ErrorContent, _values: Values, _parts: Sequence[Shown]) -> list[Fields]:
    return [{"code": content.code, "message": content.message, **content.location.to_json()}]


@_renders(NodeContent)
def _node(content: NodeContent, values: Values, parts: Sequence[Shown]) -> list[Fields]:
    node, raw = content.node, content.raw
    text = {k: values.text(v) for k, v in raw.items()}
    undetermined: list[Fields] = []
    mapping: dict[str, str] = {}
    for remap in content.remaps:
        pair = _present(PartKind.REMAP, remap, values, parts, undetermined)
        if pair is not None:
            key = pair[0] or ""
            mapping.pop(key, None)
            mapping[key] = pair[1] or ""
    settings = []
    for setting in content.env:
        pair = _present(PartKind.ENV, setting, values, parts, undetermined)
        if pair is not None:
            settings.append(list(pair))
    present = [
        _present(PartKind.PARAMETER, p, values, parts, undetermined) for p in content.parameters
    ]
    schema = node.schema
    own = dialect_of(schema.version).node_fields(
        node, text, [p for p in present if p is not None], content.confinement
    )
    return [
        {
            "name": schema.full_name.text(text),
            "namespace": schema.namespace.text(text) or "/",
            "package": schema.package.text(text),
            "type": schema.executable.text(text),
            **own,
            "remaps": sorted([list(p) for p in mapping.items()]),
            "env": sorted(settings),
            **({"undetermined": undetermined} if undetermined else {}),
            "filename": node.filename,
            "line": node.location.line,
            "col": node.location.col,
        }
    ]


def _present(
    kind: PartKind,
    setting: Setting,
    values: Values,
    parts: Sequence[Shown],
    undetermined: list[Fields],
) -> tuple[str | None, str | None] | None:
    """A setting's strings where the step has it, else None; an undetermined one is added to
    ``undetermined`` with its condition."""
    first, second, part = setting
    shown = (values.text(first), values.text(second))
    presence, condition = (Presence.PRESENT, None) if part is None else parts[part]
    if presence == Presence.UNDETERMINED:
        undetermined.append({"kind": kind, "pair": list(shown), "condition": condition})
    return shown if presence == Presence.PRESENT else None


@_renders(ParamContent)
def _param(content: ParamContent, values: Values, _parts: Sequence[Shown]) -> list[Fields]:
    try:
        shown = json_value(content.loaded(values))
    except ResolutionError:  # a string not known yet, or failing (the graph's errors say)
        shown = values.text(cast(Raw, content.raw))
    name = values.text(cast(Raw, content.name))
    return [{"name": name, "value": shown, **_where(content.location)}]


@_renders(YamlContent)
def _yaml(content: YamlContent, values: Values, _parts: Sequence[Shown]) -> list[Fields]:
    where = _where(content.param.location)
    if values.knows(content.raws):
        try:
            return [
                {"name": key, "value": json_value(v), **where} for key, v in content.pairs(values)
            ]
        except ResolutionError:
            pass  # failing: the graph's errors say where
    return [{"name": f"{values.text(content.raws[0])} (YAML)", "value": "<yaml>", **where}]


def _where(location: Location) -> Fields:
    return {"filename": location.file, "line": location.line}
