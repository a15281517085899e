"""A build target's C++ sources, parsed and indexed: functions, declarations, members,
type aliases, constants, and which functions the entry point reaches.

Headers are followed from ``#include`` (beside the including file, or in the package's
include folders). Reachability is by name, as C++'s lookup would bind it without types.
"""

from __future__ import annotations

import os
import re
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import lru_cache

from tree_sitter import Node

from rosvar.workspace.interfaces.cpp import syntax
from rosvar.workspace.interfaces.cpp.ros_types import ros_type
from rosvar.workspace.interfaces.reading import read_source


@dataclass(eq=False)
class Function:
    """A function definition: ``owner`` is its class when the source says so."""

    name: str
    owner: str | None
    parameters: list[tuple[str, str]]
    node: Node
    file: str
    required: int = 0  # the parameters without a default value
    _kinds: dict[str, list[Node]] | None = field(default=None, repr=False)

    def nodes(self, *types: str) -> list[Node]:
        """The nodes of ``types`` in the definition, in source order (one walk, kept)."""
        if self._kinds is None:
            self._kinds = {}
            for node in syntax.walk_all(self.node):
                self._kinds.setdefault(node.type, []).append(node)
        found = [node for kind in types for node in self._kinds.get(kind, ())]
        if len(types) > 1:
            found.sort(key=lambda node: node.start_byte)
        return found


@dataclass
class _Parsed:
    """A parsed file, with the nodes that declare things listed in source order."""

    path: str
    root: Node
    includes: list[str]
    declarations: list[Node]


_DECLARING = frozenset(
    {
        "function_definition",
        "field_declaration",
        "declaration",
        "preproc_def",
        "type_definition",
        "alias_declaration",
    }
)


@lru_cache(maxsize=4096)
def _parse(path: str) -> _Parsed | None:
    data = read_source(path)
    if data is None:
        return None
    root = syntax.parse(data)
    includes, declarations = [], []
    for node in syntax.walk(root, _DECLARING | {"preproc_include"}):
        if node.type != "preproc_include":
            declarations.append(node)
            continue
        target = node.child_by_field_name("path")
        if target is not None:
            includes.append(syntax.text(target).strip('"<>'))
    return _Parsed(path, root, includes, declarations)


@dataclass
class Write:
    """A member's value: an assignment or in-class initialiser (``value``), or a member
    initialiser's constructor ``arguments`` (the member's type is looked up when evaluated:
    the class may be declared in a header indexed later)."""

    function: Function | None
    value: Node | None = None
    arguments: list[Node] | None = None


@dataclass
class Unit:
    """The parsed sources of one build target, with what evaluation needs indexed."""

    files: list[str]
    functions: dict[str, list[Function]] = field(default_factory=dict)
    signatures: dict[str, list[list[str]]] = field(default_factory=dict)
    aliases: dict[str, str] = field(default_factory=dict)
    fields: dict[str, str] = field(default_factory=dict)
    writes: dict[str, list[Write]] = field(default_factory=dict)
    constants: dict[str, Node] = field(default_factory=dict)
    required: dict[tuple[str, int], int] = field(default_factory=dict)
    """Declared functions by (name, number of parameters): how many lack a default value
    (defaults are written in the declaration, not in the definition)."""

    @staticmethod
    def load(sources: Sequence[str], include_dirs: Sequence[str]) -> Unit:
        """Parse ``sources`` and the headers they include from ``include_dirs`` or beside them."""
        unit = Unit([])
        pending = [os.path.abspath(path) for path in sources]
        seen: set[str] = set()
        while pending:
            path = pending.pop(0)
            if path in seen:
                continue
            seen.add(path)
            parsed = _parse(path)
            if parsed is None:
                continue
            unit.files.append(path)
            unit._index(parsed)
            for include in parsed.includes:
                for folder in (os.path.dirname(path), *include_dirs):
                    candidate = os.path.normpath(os.path.join(folder, include))
                    if os.path.isfile(candidate):
                        pending.append(candidate)
                        break
        return unit

    def _index(self, parsed: _Parsed) -> None:
        for node in parsed.declarations:
            if node.type in ("type_definition", "alias_declaration"):
                self._alias(node)
            elif node.type == "function_definition":
                self._function(node, parsed.path)
            elif syntax.function_declarator(node) is not None:
                self._signature(node)
            elif node.type == "field_declaration":
                self._field(node)
            elif node.type == "preproc_def":
                macro, value = node.child_by_field_name("name"), node.child_by_field_name("value")
                if macro is not None and value is not None:
                    text = syntax.text(value).strip()
                    if text.startswith('"'):
                        self.constants[syntax.text(macro)] = syntax.parse((text + ";").encode())
            elif syntax.enclosing_function(node) is None:
                for name, variable in syntax.declared(node):
                    if variable.init is not None:
                        self.constants[name] = variable.init

    def _alias(self, node: Node) -> None:
        """``typedef T Name;`` or ``using Name = T;``: message types are often spelled so."""
        aliased = node.child_by_field_name("type")
        name = node.child_by_field_name("declarator" if node.type == "type_definition" else "name")
        if aliased is not None and name is not None:
            self.aliases[syntax.text(name)] = syntax.text(aliased)

    def unaliased(self, text: str) -> str:
        """C++ type ``text`` through the unit's type aliases."""
        for _ in range(8):  # an alias of an alias; a cycle stops here
            bare = re.sub(r"\b(const|typename)\b|[&*\s]", "", text)
            if bare not in self.aliases and "<" not in bare:
                bare = syntax.last(bare)  # RobotLocalization::RosEkf: namespaces are not indexed
            if bare not in self.aliases:
                break
            text = self.aliases[bare]
        return text

    def message_type(self, text: str) -> str | None:
        """The ROS type of C++ type ``text``, through the unit's type aliases."""
        return ros_type(self.unaliased(text))

    def _signature(self, node: Node) -> None:
        """A declared (not defined) function: callbacks are often only declared in a header."""
        declarator = syntax.function_declarator(node)
        target = declarator.child_by_field_name("declarator") if declarator else None
        parameters = declarator.child_by_field_name("parameters") if declarator else None
        if target is None or parameters is None:
            return
        types = [syntax.parameter_type(p) for p in parameters.named_children]
        name = syntax.last(syntax.text(target).replace(" ", ""))
        self.signatures.setdefault(name, []).append(types)
        required = sum(p.type == "parameter_declaration" for p in parameters.named_children)
        key = (name, len(types))
        self.required[key] = min(required, self.required.get(key, required))

    def _function(self, node: Node, path: str) -> None:
        declarator = syntax.function_declarator(node)
        if declarator is None:
            return
        target = declarator.child_by_field_name("declarator")
        if target is None:
            return
        qualified = syntax.text(target).replace(" ", "")
        owner: str | None = None
        if "::" in qualified:
            owner = syntax.last(qualified.rsplit("::", 1)[0].split("<")[0])
        else:
            owner = syntax.enclosing_class(node)
        parameters = []
        required = 0
        parameter_list = declarator.child_by_field_name("parameters")
        for parameter in parameter_list.named_children if parameter_list is not None else []:
            required += parameter.type == "parameter_declaration"
            type_node = parameter.child_by_field_name("type")
            name_node = parameter.child_by_field_name("declarator")
            name = syntax.declarator_name(name_node) if name_node is not None else None
            type_text = syntax.text(parameter)
            if type_node is not None and name_node is not None:
                type_text = syntax.text(parameter)[: name_node.start_byte - parameter.start_byte]
            parameters.append((type_text, name or ""))
        function = Function(
            syntax.last(qualified), owner, parameters, node, path, required=required
        )
        self.functions.setdefault(function.name, []).append(function)
        self.signatures.setdefault(function.name, []).append([t for t, _ in parameters])
        for initializer in function.nodes("field_initializer"):
            name_node = initializer.named_children[0]
            self.writes.setdefault(syntax.text(name_node), []).append(
                Write(function, arguments=syntax.arguments(initializer))
            )

    def _field(self, node: Node) -> None:
        type_node = node.child_by_field_name("type")
        type_text = syntax.text(type_node) if type_node is not None else ""
        for declarator in node.children_by_field_name("declarator"):
            name = syntax.declarator_name(declarator)
            if name is None:
                continue
            self.fields[name] = type_text
            default = node.child_by_field_name("default_value")
            if default is not None:
                self.writes.setdefault(name, []).append(Write(None, value=default))

    def reachable(self, entries: Sequence[Function]) -> list[Function]:
        """``entries`` and every function named (called, bound, constructed) from them."""
        reached: dict[int, Function] = {}
        pending = list(entries)
        while pending:
            function = pending.pop()
            if id(function) in reached:
                continue
            reached[id(function)] = function
            parts = _parts(function)
            start = min((part.start_byte for part in parts), default=function.node.end_byte)
            for node in function.nodes("identifier", "field_identifier", "type_identifier"):
                if node.start_byte < start:
                    continue  # the function's own name and parameters
                name = syntax.text(node)
                pending.extend(self._named(node, name, function.owner))
                if name in self.aliases:  # RosEkf ekf(...) runs RosFilter<Ekf>'s constructor
                    pending.extend(
                        self.functions.get(syntax.last(self.unaliased(name).split("<")[0]), ())
                    )
                if name in self.fields:  # a member's constructor runs with its owner's
                    for word in re.findall(r"\w+", self.fields[name]):
                        pending.extend(f for f in self.functions.get(word, ()) if f.owner == word)
        return list(reached.values())

    def _named(self, node: Node, name: str, owner: str | None) -> list[Function]:
        """The functions ``name`` may call, by C++'s lookup: ``Class::name`` is Class's; an
        unqualified name (or ``this->name``) inside a method is its class's own, when the
        class has one of that name (several nodelets of one library share ``connectCb``)."""
        candidates = self.functions.get(name, [])
        parent = node.parent
        scope = parent.child_by_field_name("scope") if parent is not None else None
        if parent is not None and parent.type == "qualified_identifier" and scope is not None:
            owner = syntax.last(syntax.text(scope).split("<")[0])
        elif parent is not None and parent.type == "field_expression":
            target = parent.child_by_field_name("argument")
            if target is None or target.type != "this":
                return candidates
        own = [function for function in candidates if function.owner == owner]
        return own if owner is not None and own else candidates


def _parts(function: Function) -> list[Node]:
    """What runs when ``function`` does: its member initialisers and body, not its name."""
    return [
        c
        for c in function.node.children
        if c.type in ("field_initializer_list", "compound_statement")
    ]
