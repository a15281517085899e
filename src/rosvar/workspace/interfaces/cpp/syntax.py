"""C++ syntax trees (tree-sitter): parsing, walking, and reading what a node spells.

No compiler is run: these helpers read declarations, calls and their arguments as written,
which is all extraction needs to follow names.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import tree_sitter_cpp
from tree_sitter import Language, Node, Parser

PARSER = Parser(Language(tree_sitter_cpp.language()))


def parse(data: bytes) -> Node:
    """The syntax tree of C++ source ``data`` (tree-sitter recovers from any error)."""
    return PARSER.parse(data).root_node


def text(node: Node) -> str:
    """The source text of ``node`` (a stray byte decoded leniently)."""
    return node.text.decode("utf-8", errors="replace") if node.text is not None else ""


def walk_all(node: Node) -> Iterator[Node]:
    """Every node below ``node`` (itself included), in source order."""
    cursor = node.walk()
    while True:
        current = cursor.node
        if current is not None:
            yield current
        if cursor.goto_first_child() or cursor.goto_next_sibling():
            continue
        while True:
            if not cursor.goto_parent() or cursor.node == node:
                return
            if cursor.goto_next_sibling():
                break


def deeper_than(root: Node, limit: int) -> Node | None:
    """The first node nested more than ``limit`` deep below ``root``, if any."""
    cursor = root.walk()
    depth = 0
    while True:
        if depth > limit:
            return cursor.node
        if cursor.goto_first_child():
            depth += 1
            continue
        while not cursor.goto_next_sibling():
            if not cursor.goto_parent():
                return None
            depth -= 1


def walk(node: Node, types: set[str] | frozenset[str]) -> Iterator[Node]:
    """Every descendant of one of ``types``, in source order (including ``node``)."""
    return (current for current in walk_all(node) if current.type in types)


def last(name: str) -> str:
    """The last component of a qualified name (``ros::NodeHandle`` → ``NodeHandle``)."""
    return name.rsplit("::", 1)[-1]


def template_arguments(node: Node) -> list[str]:
    """The template arguments written in ``node`` (``advertise<T>`` → ``[T]``)."""
    listed = next(walk(node, {"template_argument_list"}), None)
    if listed is None:
        return []
    return [text(child) for child in listed.named_children]


def arguments(call: Node) -> list[Node]:
    """The arguments of a call (or of a constructor call), comments left out."""
    listed = call.child_by_field_name("arguments")
    if listed is None:
        listed = next((c for c in call.children if c.type == "argument_list"), None)
    if listed is None:
        return []
    return [child for child in listed.named_children if child.type != "comment"]


def declarator_name(node: Node) -> str | None:
    """The variable a declarator declares (through pointers, references, arrays)."""
    while node.type not in ("identifier", "field_identifier"):
        inner = node.child_by_field_name("declarator")
        if inner is None:
            inner = next(
                (
                    c
                    for c in node.named_children
                    if c.type.endswith("declarator") or "identifier" in c.type
                ),
                None,
            )
        if inner is None:
            return None
        node = inner
    return text(node)


@dataclass
class Variable:
    """A declaration: its type as written, and what initialises it (if anything)."""

    type: str
    init: Node | None = None
    arguments: list[Node] | None = None


def function_declarator(node: Node) -> Node | None:
    declarator = node.child_by_field_name("declarator")
    while declarator is not None and declarator.type != "function_declarator":
        declarator = declarator.child_by_field_name("declarator")
    return declarator


def enclosing_function(node: Node) -> Node | None:
    parent = node.parent
    while parent is not None:
        if parent.type in ("function_definition", "lambda_expression"):
            return parent
        parent = parent.parent
    return None


def enclosing_class(node: Node) -> str | None:
    parent = node.parent
    while parent is not None:
        if parent.type in ("class_specifier", "struct_specifier"):
            name = parent.child_by_field_name("name")
            return text(name) if name is not None else None
        parent = parent.parent
    return None


def declared(node: Node) -> Iterator[tuple[str, Variable]]:
    """The variables a ``declaration`` declares, with their initialisers."""
    type_node = node.child_by_field_name("type")
    type_text = text(type_node) if type_node is not None else ""
    for declarator in node.children_by_field_name("declarator"):
        if declarator.type == "init_declarator":
            name = declarator_name(declarator.child_by_field_name("declarator") or declarator)
            value = declarator.child_by_field_name("value")
            if name is None:
                continue
            if value is not None and value.type in ("argument_list", "initializer_list"):
                yield name, Variable(type_text, arguments=list(value.named_children))
            else:
                yield name, Variable(type_text, init=value)
        elif declarator.type == "function_declarator":
            # the most vexing parse: `ImageTransport it(nh);` reads as a function declaration
            name_node = declarator.child_by_field_name("declarator")
            parameters = declarator.child_by_field_name("parameters")
            if name_node is None or parameters is None:
                continue
            arguments = [_vexing_argument(p) for p in parameters.named_children]
            yield text(name_node), Variable(type_text, arguments=arguments)
        else:
            name = declarator_name(declarator)
            if name is not None:
                yield name, Variable(type_text)


def _vexing_argument(parameter: Node) -> Node:
    """A constructor argument read as a parameter: ``nh`` (a type), or a call without
    arguments (``shared_from_this()``, a type and an abstract function declarator), re-read
    as the expression it is."""
    if len(parameter.named_children) == 1:
        return parameter.named_children[0]
    return parse((text(parameter) + ";").encode())


def parameter_type(parameter: Node) -> str:
    """A parameter declaration's type as written (what precedes its name)."""
    declarator = parameter.child_by_field_name("declarator")
    written = text(parameter)
    if declarator is None:
        return written
    return written[: declarator.start_byte - parameter.start_byte]


def template_arguments_text(type_text: str) -> list[str]:
    """The top-level template arguments of a type as written (``A<B<C>, D>`` → ``[B<C>,
    D]``); none when it has no complete argument list (a comparison read as a type)."""
    start, end = type_text.find("<"), type_text.rfind(">")
    if start < 0 or end < start:
        return []
    depth, parts, begin = 0, [], start + 1
    for index in range(start + 1, end):
        char = type_text[index]
        if char == "," and depth == 0:
            parts.append(type_text[begin:index])
            begin = index + 1
        depth += char == "<"
        depth -= char == ">"
    return [*parts, type_text[begin:end]]


def template_parameters(definition: Node) -> tuple[str, ...]:
    """The template parameters a function definition is written under: its own
    (``template <typename T> void f()``) or, for a method, its class template's."""
    names: list[str] = []
    node = definition.parent
    while node is not None:
        if node.type == "template_declaration":
            parameters = node.child_by_field_name("parameters")
            for parameter in parameters.named_children if parameters is not None else ():
                name = next(
                    (c for c in parameter.named_children if c.type == "type_identifier"), None
                )
                if name is not None:
                    names.append(text(name))
            break
        if node.type == "translation_unit":
            break
        node = node.parent
    return tuple(names)
