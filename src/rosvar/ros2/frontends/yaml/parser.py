"""ROS 2 YAML launch files to :class:`Entity` trees, as launch_yaml reads them.

The document is one mapping with one key, the root entity (``launch:``). An entity is a
single-key mapping ``tag: body``. A body that is a list holds the children; a mapping holds
attributes, except that ``children:`` lists the children and a list of mappings (``param:
[{...}]``, ``remap``, ``arg``, ``env``, ``choice``, ``composable_node``...) gives one child
entity tagged with the key per mapping, exactly where launch_xml finds nested elements of
that tag. Children come in document order, so the tree is the one the equivalent XML file
gives. Strings stay raw; other scalars and lists of scalars are typed values, and a
parameter's string value that XML would coerce gets ``type="str"``
(:mod:`rosvar.ros2.frontends.typed_text`). Locations are those of each entity's key (the
attributes of list items: the item's first key). The text goes through
:func:`~rosvar.bounded_yaml.check_limits` before anything is built; every problem
is a diagnostic.
"""

from __future__ import annotations

import os

import yaml
from yaml.constructor import ConstructorError, SafeConstructor
from yaml.nodes import MappingNode, Node, ScalarNode, SequenceNode

from rosvar.bounded_yaml import YamlLimitError, check_limits
from rosvar.diagnostics import Diagnostic, DiagnosticSink, Location, Severity
from rosvar.frontends.entity import Entity, ParseResult
from rosvar.frontends.xml import read_bytes
from rosvar.ros2.frontends.typed_text import reads_as_other_value, typed_text

PARAM_TAG = "param"
"""The one entity whose ``value`` XML coerces by YAML rules (see ``typed_text``)."""

CHILDREN_KEY = "children"
"""The key launch_yaml reads an entity's children from when its body is a mapping."""

_STR_TAG = "tag:yaml.org,2002:str"
_Loader: type[yaml.SafeLoader] = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def _location(node: Node, filename: str) -> Location:
    return Location(filename, node.start_mark.line + 1, node.start_mark.column + 1)


class _Reader:
    """Walks one composed document; the depth is bounded by ``check_limits``."""

    def __init__(self, filename: str) -> None:
        self.filename = filename
        self.sink = DiagnosticSink()
        self.constructor = SafeConstructor()

    def structure(self, message: str, node: Node) -> None:
        self.sink.error("yaml-launch-structure", message, _location(node, self.filename))

    def entity(self, tag: str, body: Node, at: Node) -> Entity:
        entity = Entity(tag, {}, _location(at, self.filename))
        if isinstance(body, SequenceNode):
            entity.children = self.children(tag, body)
        elif isinstance(body, MappingNode):
            self.body(entity, body)
        else:  # launch_yaml fails on any scalar body, an empty one (``- group:``) included
            self.structure(f"<{tag}> must be a mapping or a list, not a scalar", body)
        return entity

    def children(self, tag: str, body: SequenceNode) -> list[Entity]:
        children: list[Entity] = []
        for item in body.value:
            if not (isinstance(item, MappingNode) and len(item.value) == 1):
                self.structure(f"each child of <{tag}> must be a mapping with one key", item)
                continue
            key, value = item.value[0]
            name = self.key(key)
            if name is not None:
                children.append(self.entity(name, value, key))
        return children

    def key(self, node: Node) -> str | None:
        if isinstance(node, ScalarNode) and node.tag == _STR_TAG:
            return str(node.value)
        self.structure("keys must be strings", node)
        return None

    def body(self, entity: Entity, body: MappingNode) -> None:
        """Attributes and children, keys in document order; a repeated key keeps its first
        place and its last value, as the dict launch_yaml reads."""
        self.constructor.flatten_mapping(body)  # merge keys (``<<: *base``)
        fields: dict[str, Node] = {}
        for key, value in body.value:
            name = self.key(key)
            if name is not None:
                fields[name] = value
        typed: set[str] = set()
        for name, value in fields.items():
            if name == CHILDREN_KEY and isinstance(value, SequenceNode):
                entity.children.extend(self.children(entity.tag, value))
            elif (
                isinstance(value, SequenceNode)
                and value.value
                and (isinstance(value.value[0], MappingNode))
            ):
                entity.children.extend(self.nested(name, value))
            elif isinstance(value, ScalarNode) and value.tag == _STR_TAG:
                entity.attributes[name] = str(value.value)
            else:
                text = self.typed(entity.tag, name, value)
                if text is not None:
                    entity.attributes[name] = text
                    typed.add(name)
        if typed:
            entity.typed = frozenset(typed)
        value = entity.attributes.get("value")
        if (
            entity.tag == PARAM_TAG
            and value is not None
            and "value" not in typed
            and "type" not in entity.attributes
            and reads_as_other_value(value)
        ):
            entity.attributes["type"] = "str"  # a YAML string stays a string, unlike XML's

    def nested(self, tag: str, items: SequenceNode) -> list[Entity]:
        nested: list[Entity] = []
        for item in items.value:
            if isinstance(item, MappingNode):
                entity = Entity(
                    tag, {}, _location(item.value[0][0] if item.value else item, self.filename)
                )
                self.body(entity, item)
                nested.append(entity)
            else:
                self.structure(f"each <{tag}> in the list must be a mapping", item)
        return nested

    def typed(self, tag: str, name: str, node: Node) -> str | None:
        """The text of a typed scalar or list of scalars; ``None`` (reported) otherwise."""
        try:
            value = self.constructor.construct_object(node, deep=True)
        except ConstructorError as error:
            self.structure(f"<{tag}> attribute '{name}': {error.problem}", node)
            return None
        if _is_typed(value, top=True):
            return typed_text(value)
        self.structure(
            f"<{tag}> attribute '{name}' must be a string, number, boolean or list of them, "
            f"not {type(value).__name__}",
            node,
        )
        return None


def _is_typed(value: object, top: bool) -> bool:
    if isinstance(value, list):
        return top and all(_is_typed(item, top=False) for item in value)
    return value is None or isinstance(value, bool | int | float | str)


def parse_yaml_launch_bytes(data: bytes, filename: str) -> ParseResult:
    """Parse a ROS 2 YAML launch file held in memory; never raises."""
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        return _error("yaml-encoding", f"invalid UTF-8 byte at offset {exc.start}", filename)
    try:
        check_limits(text)
        document = yaml.compose(text, Loader=_Loader)
    except YamlLimitError as refused:
        return _error("yaml-limit", str(refused), filename)
    except yaml.MarkedYAMLError as malformed:
        mark = malformed.problem_mark or malformed.context_mark
        location = Location(filename, mark.line + 1, mark.column + 1) if mark else None
        return _error("yaml-malformed", f"malformed YAML: {malformed.problem}", filename, location)
    except yaml.YAMLError as malformed:
        return _error("yaml-malformed", f"malformed YAML: {malformed}", filename)
    if not (isinstance(document, MappingNode) and len(document.value) == 1):
        at = _location(document, filename) if document is not None else Location(filename, 1, 1)
        return _error(
            "yaml-launch-structure",
            "a YAML launch file is a mapping with one key, the root entity (launch:)",
            filename,
            at,
        )
    reader = _Reader(filename)
    key, body = document.value[0]
    name = reader.key(key)
    root = reader.entity(name, body, key) if name is not None else None
    return ParseResult(root, reader.sink.items)


def _error(code: str, message: str, filename: str, at: Location | None = None) -> ParseResult:
    return ParseResult(
        None, [Diagnostic(code, Severity.ERROR, message, at or Location(filename, 1, 1))]
    )


def parse_yaml_launch_file(path: str | os.PathLike[str]) -> ParseResult:
    """Read and parse a ROS 2 YAML launch file; Locations use ``path`` as given."""
    data = read_bytes(path)
    if isinstance(data, ParseResult):
        return data
    return parse_yaml_launch_bytes(data, os.fspath(path))
