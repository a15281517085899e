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

from rosvar.diagnostics import Location
from rosvar.workspace.interfaces.cpp import syntax
from rosvar.workspace.interfaces.cpp.apis import FRAMEWORK_CALLBACKS, MAKERS
from rosvar.workspace.interfaces.cpp.ros_types import ros_type
from rosvar.workspace.interfaces.reading import SourceReader


@dataclass(eq=False)
class Function:
    """A function definition: ``owner`` is its class when the source says so."""

    name: str
    owner: str | None
    parameters: list[tuple[str, str]]
    node: Node
    file: str
    required: int = 0  # the parameters without a default value
    defaults: dict[int, Node] = field(default_factory=dict)
    """The default arguments written in the definition, by parameter index."""
    templates: tuple[str, ...] = ()
    """Template parameters the construction or call names (a class template's for its
    methods, a function template's own), in order: ``ServiceT`` of ``ServiceClient<ServiceT>``."""
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


MAX_NESTING = 256
"""Syntax nested deeper than this (40,000 braces, 20,000 templates) is no hand-written node:
such a file is not read, so that every walk of its tree stays short."""
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


@dataclass(frozen=True)
class _Tree:
    """A file's tree and what indexing needs of it, or the place it nests too deep."""

    root: Node
    includes: tuple[str, ...] = ()
    declarations: tuple[Node, ...] = ()
    too_deep: Node | None = None


@lru_cache(maxsize=4096)
def _tree(data: bytes) -> _Tree:
    """Parsed once per content: a header included by every target of a package, the same
    source in several packages."""
    root = syntax.parse(data)
    deep = syntax.deeper_than(root, MAX_NESTING)
    if deep is not None:
        return _Tree(root, too_deep=deep)
    includes, declarations = [], []
    for node in syntax.walk(root, _DECLARING | {"preproc_include"}):
        if node.type != "preproc_include":
            declarations.append(node)
            continue
        target = node.child_by_field_name("path")
        if target is not None:
            includes.append(syntax.text(target).strip('"<>'))
    return _Tree(root, tuple(includes), tuple(declarations))


def _parse(path: str, reader: SourceReader) -> _Parsed | None:
    data = reader.data(path)
    if data is None:
        return None
    tree = _tree(data)
    if tree.too_deep is not None:
        if reader.sink is not None:
            line = tree.too_deep.start_point[0] + 1
            reader.sink.warning(
                "interface-too-nested",
                f"not read: C++ nested more than {MAX_NESTING} deep",
                Location(path, line),
            )
        return None
    return _Parsed(path, tree.root, list(tree.includes), list(tree.declarations))


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
    members: dict[str, dict[str, tuple[Node, str]]] = field(default_factory=dict)
    """Each class's members: name → the declaration and its file (a member is constructed
    with its class: a ``tf2_ros::TransformBroadcaster br_;`` publishes once it is built)."""
    bases: dict[str, list[str]] = field(default_factory=dict)
    """Each class's base classes, as written."""

    @staticmethod
    def load(
        sources: Sequence[str], include_dirs: Sequence[str], reader: SourceReader | None = None
    ) -> Unit:
        """Parse ``sources`` and the headers they include from ``include_dirs`` or beside them
        (read through ``reader``, the extraction's read gate)."""
        reader = reader or SourceReader()
        unit = Unit([])
        pending = [os.path.abspath(path) for path in sources]
        seen: set[str] = set()
        while pending:
            path = pending.pop(0)
            if path in seen:
                continue
            seen.add(path)
            parsed = _parse(path, reader)
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
                self._field(node, parsed.path)
            elif node.type in ("class_specifier", "struct_specifier"):
                self._class(node)
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
        parameters: list[tuple[str, str]] = []
        required = 0
        defaults: dict[int, Node] = {}
        parameter_list = declarator.child_by_field_name("parameters")
        for parameter in parameter_list.named_children if parameter_list is not None else []:
            required += parameter.type == "parameter_declaration"
            default = parameter.child_by_field_name("default_value")
            if default is not None:
                defaults[len(parameters)] = default
            type_node = parameter.child_by_field_name("type")
            name_node = parameter.child_by_field_name("declarator")
            name = syntax.declarator_name(name_node) if name_node is not None else None
            type_text = syntax.text(parameter)
            if type_node is not None and name_node is not None:
                type_text = syntax.text(parameter)[: name_node.start_byte - parameter.start_byte]
            parameters.append((type_text, name or ""))
        function = Function(
            syntax.last(qualified),
            owner,
            parameters,
            node,
            path,
            required=required,
            defaults=defaults,
            templates=syntax.template_parameters(node),
        )
        self.functions.setdefault(function.name, []).append(function)
        self.signatures.setdefault(function.name, []).append([t for t, _ in parameters])
        for initializer in function.nodes("field_initializer"):
            name_node = initializer.named_children[0]
            self.writes.setdefault(syntax.text(name_node), []).append(
                Write(function, arguments=syntax.arguments(initializer))
            )

    def _class(self, node: Node) -> None:
        name = node.child_by_field_name("name")
        clause = next((c for c in node.children if c.type == "base_class_clause"), None)
        if name is not None and clause is not None:
            self.bases[syntax.text(name)] = [
                syntax.text(c)
                for c in clause.named_children
                if c.type in ("type_identifier", "qualified_identifier", "template_type")
            ]

    def _field(self, node: Node, path: str) -> None:
        type_node = node.child_by_field_name("type")
        type_text = syntax.text(type_node) if type_node is not None else ""
        owner = syntax.enclosing_class(node)
        for declarator in node.children_by_field_name("declarator"):
            name = syntax.declarator_name(declarator)
            if name is None:
                continue
            self.fields[name] = type_text
            if owner is not None:
                self.members.setdefault(owner, {})[name] = (node, path)
            default = node.child_by_field_name("default_value")
            if default is not None:
                self.writes.setdefault(name, []).append(Write(None, value=default))

    def reachable(self, entries: Sequence[Function]) -> list[Function]:
        """``entries`` and every function named (called, bound, constructed) from them; a
        class's constructor brings its members' and bases' constructors along, and the
        callbacks the framework calls on such an object (a lifecycle node's
        ``on_configure``)."""
        reached: dict[int, Function] = {}
        pending = list(entries)
        while pending:
            function = pending.pop()
            if id(function) in reached:
                continue
            reached[id(function)] = function
            if function.owner is not None and function.name == function.owner:
                pending.extend(self._constructed_with(function.owner))
            parts = _parts(function)
            start = min((part.start_byte for part in parts), default=function.node.end_byte)
            own = self.members.get(function.owner or "", {})
            for node in function.nodes("identifier", "field_identifier", "type_identifier"):
                if node.start_byte < start:
                    continue  # the function's own name and parameters
                name = syntax.text(node)
                pending.extend(self._named(node, name, function))
                if name in self.aliases:  # RosEkf ekf(...) runs RosFilter<Ekf>'s constructor
                    pending.extend(
                        self.functions.get(syntax.last(self.unaliased(name).split("<")[0]), ())
                    )
                if name in self.fields and (function.owner not in self.members or name in own):
                    pending.extend(self.constructors(self.fields[name]))
        return list(reached.values())

    def constructors(self, type_text: str) -> list[Function]:
        """The constructors of the classes ``type_text`` names (``std::unique_ptr<A<B>>``)."""
        return [
            f
            for word in re.findall(r"\w+", type_text)
            for f in self.functions.get(word, ())
            if f.owner == word
        ]

    def _constructed_with(self, owner: str) -> list[Function]:
        """What runs when a ``owner`` is built: its members' and bases' constructors, and
        the framework's callbacks on it."""
        found = [
            f
            for name in FRAMEWORK_CALLBACKS
            for f in self.functions.get(name, ())
            if f.owner == owner
        ]
        for declaration, _ in self.members.get(owner, {}).values():
            type_node = declaration.child_by_field_name("type")
            if type_node is not None:
                found.extend(self.constructors(syntax.text(type_node)))
        for base in self.bases.get(owner, ()):
            found.extend(self.constructors(base.split("<")[0]))
        return found

    def receiver_type(self, target: Node, function: Function) -> str | None:
        """The declared type of the object a method is called on, where the unit says it:
        a local, a parameter, a member (``this`` is the function's class)."""
        if target.type == "this":
            return function.owner
        if target.type in ("pointer_expression", "parenthesized_expression"):
            inner = target.child_by_field_name("argument") or next(
                iter(target.named_children), None
            )
            return self.receiver_type(inner, function) if inner is not None else None
        if target.type == "field_expression":
            member = target.child_by_field_name("field")
            return self.fields.get(syntax.text(member)) if member is not None else None
        if target.type != "identifier":
            return None
        name = syntax.text(target)
        for declaration in function.nodes("declaration"):
            for declared, variable in syntax.declared(declaration):
                if declared == name:
                    return _inferred(variable)
        for type_text, parameter in function.parameters:
            if parameter == name:
                return type_text
        return self.fields.get(name)

    def _named(self, node: Node, name: str, caller: Function) -> list[Function]:
        """The functions ``name`` may call, by C++'s lookup: ``Class::name`` is Class's; an
        unqualified name (or ``this->name``) inside a method is its class's own, when the
        class has one of that name (several nodelets of one library share ``connectCb``);
        ``object.name()`` is the method of the object's class, when the unit declares the
        object and its class has one."""
        candidates = self.functions.get(name, [])
        if not candidates:
            return candidates
        owner = caller.owner
        parent = node.parent
        scope = parent.child_by_field_name("scope") if parent is not None else None
        if parent is not None and parent.type == "qualified_identifier" and scope is not None:
            owner = syntax.last(syntax.text(scope).split("<")[0])
        elif parent is not None and parent.type == "field_expression":
            target = parent.child_by_field_name("argument")
            if target is None:
                return candidates
            if target.type != "this":
                declared = self.receiver_type(target, caller)
                words = set(re.findall(r"\w+", self.unaliased(declared))) if declared else set()
                typed = [f for f in candidates if f.owner in words]
                return typed or candidates
        own = [function for function in candidates if function.owner == owner]
        return own if owner is not None and own else candidates


def _inferred(variable: syntax.Variable) -> str:
    """A variable's type, ``auto`` read from its initialiser where it says the type
    (``auto node = std::make_shared<MapSaver>()``, ``new MapSaver``)."""
    if variable.type.strip() != "auto" or variable.init is None:
        return variable.type
    init = variable.init
    if init.type == "new_expression":
        type_node = init.child_by_field_name("type")
        return syntax.text(type_node) if type_node is not None else variable.type
    callee = init.child_by_field_name("function") if init.type == "call_expression" else None
    written = syntax.text(callee) if callee is not None else ""
    if syntax.last(written.split("<")[0]) in MAKERS:
        return next(iter(syntax.template_arguments_text(written)), variable.type)
    return variable.type


def _parts(function: Function) -> list[Node]:
    """What runs when ``function`` does: its member initialisers and body, not its name."""
    return [
        c
        for c in function.node.children
        if c.type in ("field_initializer_list", "compound_statement")
    ]
