"""ROS 2 parameter semantics: typed values of ``-p``-style strings and the merging of
parameter files (rcl's one structure keyed by node pattern, then rclcpp's matching)."""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import yaml

from rosvar import bounded_yaml

ALL_NODES = "/**"


def typed(text: str) -> object:
    """A parameter value string as ROS 2 reads it: YAML scalars and lists, else the text.

    Raises ``ValueError`` for what a parameter cannot hold: a null, a map, a list mixing types.
    """
    if not text:
        return text
    try:
        value = bounded_yaml.safe_load(text)
    except yaml.YAMLError:
        return text
    if value is None or isinstance(value, dict):
        raise ValueError(f"'{text}' can not be converted to a parameter value")
    if isinstance(value, list) and len({type(item) for item in value}) > 1:
        raise ValueError("The result is a non-uniform list")
    return value


MAX_TYPED_TEXT = 1 << 16
"""Longer texts are not coerced to a type (YAML reads them unbounded)."""

PARAMETER_TYPES = (
    "str",
    "bool",
    "float",
    "int",
    "list_of_str",
    "list_of_bool",
    "list_of_float",
    "list_of_int",
    "yaml",
)
"""launch's type identifiers of a parameter (``<param type>``)."""
_SCALARS: dict[str, type] = {"str": str, "bool": bool, "float": float, "int": int}


def _yaml(text: str) -> object:
    if len(text) > MAX_TYPED_TEXT:
        raise ValueError(f"a value over {MAX_TYPED_TEXT} characters is not converted")
    try:
        return bounded_yaml.safe_load(text)
    except bounded_yaml.YamlLimitError as refused:
        raise ValueError(f"a value is not converted: {refused}") from None
    except yaml.YAMLError:
        raise ValueError(f"Failed to convert '{text}' using yaml rules") from None


def coerce(text: str, type_name: str) -> object:
    """launch's ``coerce_to_type(text, type)`` for a type identifier: ``str`` keeps the
    text, ``int``/``float`` convert as Python does, ``bool`` reads ``1``/``0`` and YAML's
    booleans, ``list_of_X`` a YAML list of ``X``s, ``yaml`` what YAML reads. Raises
    ``ValueError`` where launch does."""
    if type_name not in PARAMETER_TYPES:
        raise ValueError(f"Got invalid type identifier '{type_name}'")
    if type_name == "yaml":
        return typed(text)
    item_name = type_name.removeprefix("list_of_")
    wanted = _SCALARS[item_name]
    if item_name != type_name:
        value = _yaml(text) if text else text
        if not isinstance(value, list) or not all(isinstance(v, wanted) for v in value):
            raise ValueError(f"Cannot convert value '{text}' to a list of '{wanted}'")
        return value
    if wanted is str:
        return text
    if wanted is not bool:
        return wanted(text)
    value = _yaml({"1": "true", "0": "false"}.get(text, text)) if text else text
    if not isinstance(value, bool):
        raise ValueError(f"Cannot convert value '{text}' to '{wanted}'")
    return value


def flatten(values: Mapping[object, object], prefix: str = "") -> dict[str, object]:
    """Nested parameter maps as dotted names."""
    out: dict[str, object] = {}
    for key, value in values.items():
        name = f"{prefix}{key}"
        if isinstance(value, Mapping):
            out.update(flatten(value, name + "."))
        else:
            out[name] = value
    return out


def file_entries(document: object) -> list[tuple[str, dict[str, object]]]:
    """The (node pattern, parameters) entries of a parameter file, in document order."""
    entries: list[tuple[str, dict[str, object]]] = []

    def visit(node: object, keys: list[str]) -> None:
        if not isinstance(node, Mapping):
            return
        for key, value in node.items():
            if key == "ros__parameters":
                params = flatten(value) if isinstance(value, Mapping) else {}
                entries.append(("/".join(keys), params))
            elif isinstance(value, Mapping):
                visit(value, [*keys, str(key)])

    visit(document, [])
    return entries


def matches(pattern: str, fqn: str) -> bool:
    """rclcpp's node-name wildcards: ``/*`` one token, ``/**`` any number."""
    key = pattern if pattern.startswith("/") else "/" + pattern
    parts = re.split(r"(/\*\*|/\*)", key)
    regex = "".join(
        r"(/\w+)*" if p == "/**" else r"(/\w+)" if p == "/*" else re.escape(p) for p in parts
    )
    return re.fullmatch(regex, fqn) is not None


@dataclass(frozen=True)
class Source:
    """One ``-p name:=value`` (``name`` set) or one parameter file's entries."""

    name: str | None = None
    value: object = None
    entries: tuple[tuple[str, dict[str, object]], ...] = ()


def effective(fqn: str | None, sources: Iterable[Source]) -> dict[str, object]:
    """The parameters a node named ``fqn`` starts with (None: name unknown, ``/**`` only)."""
    table: dict[str, dict[str, object]] = {}
    for source in sources:
        if source.name is not None:
            table.setdefault(ALL_NODES, {})[source.name] = source.value
        for pattern, params in source.entries:
            table.setdefault(pattern, {}).update(params)
    result: dict[str, object] = {}
    for pattern, params in table.items():
        applies = pattern.lstrip("/") == "**" if fqn is None else matches(pattern, fqn)
        if applies:
            result.update(params)
    return result
