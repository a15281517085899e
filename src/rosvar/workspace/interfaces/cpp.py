"""C++ extraction: the ROS API calls of one executable or nodelet class, read with tree-sitter.

No compiler is run, so types are not known: a value is followed only as far as the source
says it statically. Node handles are followed through their constructors
(``NodeHandle nh("~")``, ``NodeHandle(parent, "ns")``, ``getPrivateNodeHandle()``), members
(assigned anywhere in the unit), function parameters (bound from every call site of a function
of that name) and string constants. Only functions reachable by name from the entry point
(``main``, or the nodelet class's ``onInit``) count, so that a library holding several nodelets
gives each its own interface. What cannot be decided is kept symbolic with a diagnostic.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from functools import lru_cache

import tree_sitter_cpp
from tree_sitter import Language, Node, Parser

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.workspace.interfaces.model import Default, Entry, Expression, Extracted, Role
from rosvar.workspace.interfaces.reading import read_source
from rosvar.workspace.interfaces.values import Text, action_type

_PARSER = Parser(Language(tree_sitter_cpp.language()))
MAX_DEPTH = 64
"""Nested evaluations allowed before a value is given up as unknown (cycles end earlier)."""

_PRIVATE_HANDLES = frozenset({"getPrivateNodeHandle", "getMTPrivateNodeHandle"})
_PUBLIC_HANDLES = frozenset({"getNodeHandle", "getMTNodeHandle"})
_PARAM_READS = frozenset({"param", "getParam", "getParamCached"})
_FREE_PARAM_READS = frozenset({"ros::param::get", "ros::param::param", "ros::param::getCached"})
_ACTION_CLASSES = {
    "SimpleActionServer": Role.ACTION_SERVERS,
    "ActionServer": Role.ACTION_SERVERS,
    "SimpleActionClient": Role.ACTION_CLIENTS,
    "ActionClient": Role.ACTION_CLIENTS,
}
_SMART_POINTERS = re.compile(
    r"^(?:boost::|std::)?(?:shared_ptr|scoped_ptr|unique_ptr)<(.*)>$|^ros::MessageEvent<(.*)>$"
)
_IMAGE = "sensor_msgs/Image"
_CAMERA_INFO = "sensor_msgs/CameraInfo"
_RCLCPP_CALLS = {
    "create_publisher": Role.PUBLISHES,
    "create_subscription": Role.SUBSCRIBES,
    "create_service": Role.SERVICES,
    "create_client": Role.CLIENTS,
}
"""rclcpp's ``Node`` methods: called on the node (``this->``, ``node->``, a member pointer,
``shared_from_this()``) or unqualified in a class derived from it. A ROS 2 node has one
namespace, so the receiver need not be followed."""
_RCLCPP_FREE_CALLS = {
    # free function → role and the index of the name argument (the node comes first)
    "rclcpp_action::create_server": Role.ACTION_SERVERS,
    "rclcpp_action::create_client": Role.ACTION_CLIENTS,
    "image_transport::create_publisher": Role.PUBLISHES,
    "image_transport::create_subscription": Role.SUBSCRIBES,
    "image_transport::create_camera_publisher": Role.PUBLISHES,
    "image_transport::create_camera_subscription": Role.SUBSCRIBES,
}
_RCLCPP_DECLARE = "declare_parameter"
_RCLCPP_READS = frozenset({"get_parameter", "get_parameter_or"})
_RCLCPP_NODE = re.compile(r"^rclcpp::Node(?:::make_shared)?$|make_shared<rclcpp::Node>$")
"""An rclcpp node built here (``rclcpp::Node::make_shared("name")``): its first argument
is the node's name."""
_ROS2_IMAGE = "sensor_msgs/msg/Image"
_ROS2_CAMERA_INFO = "sensor_msgs/msg/CameraInfo"
_NULLS = frozenset({"NULL", "nullptr", "0"})
_CONTROLLER_MANAGER_SERVICES = tuple(
    (service, "controller_manager_msgs/" + service.title().replace("_", ""))
    for service in (
        "list_controllers",
        "list_controller_types",
        "load_controller",
        "unload_controller",
        "switch_controller",
        "reload_controller_libraries",
    )
)
"""What ros_control's ControllerManager serves (its constructor, controller_manager.cpp)."""
_TESTING = frozenset({"unary_expression", "parenthesized_expression", "binary_expression"})
_FAILING = ("ROS_ERROR", "ROS_FATAL", "exit", "abort", "ros::shutdown")


@dataclass(frozen=True)
class Handle:
    """A ``NodeHandle`` (or an ``ImageTransport`` built on one, when ``images``); an rclcpp
    node (``rclcpp``) has no namespace of its own."""

    namespace: Text
    images: bool = False
    rclcpp: bool = False


Value = Text | Handle | None


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
            for node in _walk_all(self.node):
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
    root = _PARSER.parse(data).root_node
    includes, declarations = [], []
    for node in _walk(root, _DECLARING | {"preproc_include"}):
        if node.type != "preproc_include":
            declarations.append(node)
            continue
        target = node.child_by_field_name("path")
        if target is not None:
            includes.append(_text(target).strip('"<>'))
    return _Parsed(path, root, includes, declarations)


def _text(node: Node) -> str:
    return node.text.decode("utf-8", errors="replace") if node.text is not None else ""


def _walk_all(node: Node) -> Iterator[Node]:
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


def _walk(node: Node, types: set[str] | frozenset[str]) -> Iterator[Node]:
    """Every descendant of one of ``types``, in source order (including ``node``)."""
    return (current for current in _walk_all(node) if current.type in types)


def _last(name: str) -> str:
    return name.rsplit("::", 1)[-1]


def ros_type(text: str) -> str | None:
    """A C++ message, service or action type as ROS names it (``pkg::Msg`` → ``pkg/Msg``)."""
    text = re.sub(r"\b(const|typename|volatile)\b|[&*]", "", text)
    text = "".join(text.split())
    smart = _SMART_POINTERS.match(text)
    while smart:
        text = smart.group(1) or smart.group(2)
        smart = _SMART_POINTERS.match(text)
    text = re.sub(
        r"::(ConstPtr|Ptr|ConstSharedPtr|SharedPtr|UniquePtr|Request|Response)$", "", text
    )
    text = re.sub(r"(?<=\w)(ConstPtr|Ptr)$", "", text)
    text = text.lstrip(":")
    if not text or not re.fullmatch(r"[A-Za-z_][\w:]*", text):
        return None
    parts = text.split("::")
    if len(parts) >= 3 and parts[-2] in ("msg", "srv", "action"):
        return "/".join(parts[-3:])  # ROS 2: std_msgs::msg::String is std_msgs/msg/String
    return "/".join(parts[-2:])


def _template_arguments(node: Node) -> list[str]:
    arguments = next(_walk(node, {"template_argument_list"}), None)
    if arguments is None:
        return []
    return [_text(child) for child in arguments.named_children]


def _arguments(call: Node) -> list[Node]:
    arguments = call.child_by_field_name("arguments")
    if arguments is None:
        arguments = next((c for c in call.children if c.type == "argument_list"), None)
    if arguments is None:
        return []
    return [child for child in arguments.named_children if child.type != "comment"]


def _declarator_name(node: Node) -> str | None:
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
    return _text(node)


@dataclass
class _Variable:
    """A declaration: its type as written, and what initialises it (if anything)."""

    type: str
    init: Node | None = None
    arguments: list[Node] | None = None


@dataclass
class _Write:
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
    writes: dict[str, list[_Write]] = field(default_factory=dict)
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
            elif _function_declarator(node) is not None:
                self._signature(node)
            elif node.type == "field_declaration":
                self._field(node)
            elif node.type == "preproc_def":
                macro, value = node.child_by_field_name("name"), node.child_by_field_name("value")
                if macro is not None and value is not None:
                    text = _text(value).strip()
                    if text.startswith('"'):
                        self.constants[_text(macro)] = _PARSER.parse(
                            (text + ";").encode()
                        ).root_node
            elif _enclosing_function(node) is None:
                for name, variable in _declared(node):
                    if variable.init is not None:
                        self.constants[name] = variable.init

    def _alias(self, node: Node) -> None:
        """``typedef T Name;`` or ``using Name = T;``: message types are often spelled so."""
        aliased = node.child_by_field_name("type")
        name = node.child_by_field_name("declarator" if node.type == "type_definition" else "name")
        if aliased is not None and name is not None:
            self.aliases[_text(name)] = _text(aliased)

    def unaliased(self, text: str) -> str:
        """C++ type ``text`` through the unit's type aliases."""
        for _ in range(8):  # an alias of an alias; a cycle stops here
            bare = re.sub(r"\b(const|typename)\b|[&*\s]", "", text)
            if bare not in self.aliases and "<" not in bare:
                bare = _last(bare)  # RobotLocalization::RosEkf: namespaces are not indexed
            if bare not in self.aliases:
                break
            text = self.aliases[bare]
        return text

    def message_type(self, text: str) -> str | None:
        """The ROS type of C++ type ``text``, through the unit's type aliases."""
        return ros_type(self.unaliased(text))

    def _signature(self, node: Node) -> None:
        """A declared (not defined) function: callbacks are often only declared in a header."""
        declarator = _function_declarator(node)
        target = declarator.child_by_field_name("declarator") if declarator else None
        parameters = declarator.child_by_field_name("parameters") if declarator else None
        if target is None or parameters is None:
            return
        types = [_parameter_type(p) for p in parameters.named_children]
        name = _last(_text(target).replace(" ", ""))
        self.signatures.setdefault(name, []).append(types)
        required = sum(p.type == "parameter_declaration" for p in parameters.named_children)
        key = (name, len(types))
        self.required[key] = min(required, self.required.get(key, required))

    def _function(self, node: Node, path: str) -> None:
        declarator = _function_declarator(node)
        if declarator is None:
            return
        target = declarator.child_by_field_name("declarator")
        if target is None:
            return
        qualified = _text(target).replace(" ", "")
        owner: str | None = None
        if "::" in qualified:
            owner = _last(qualified.rsplit("::", 1)[0].split("<")[0])
        else:
            owner = _enclosing_class(node)
        parameters = []
        required = 0
        parameter_list = declarator.child_by_field_name("parameters")
        for parameter in parameter_list.named_children if parameter_list is not None else []:
            required += parameter.type == "parameter_declaration"
            type_node = parameter.child_by_field_name("type")
            name_node = parameter.child_by_field_name("declarator")
            name = _declarator_name(name_node) if name_node is not None else None
            type_text = _text(parameter)
            if type_node is not None and name_node is not None:
                type_text = _text(parameter)[: name_node.start_byte - parameter.start_byte]
            parameters.append((type_text, name or ""))
        function = Function(_last(qualified), owner, parameters, node, path, required=required)
        self.functions.setdefault(function.name, []).append(function)
        self.signatures.setdefault(function.name, []).append([t for t, _ in parameters])
        for initializer in function.nodes("field_initializer"):
            name_node = initializer.named_children[0]
            self.writes.setdefault(_text(name_node), []).append(
                _Write(function, arguments=_arguments(initializer))
            )

    def _field(self, node: Node) -> None:
        type_node = node.child_by_field_name("type")
        type_text = _text(type_node) if type_node is not None else ""
        for declarator in node.children_by_field_name("declarator"):
            name = _declarator_name(declarator)
            if name is None:
                continue
            self.fields[name] = type_text
            default = node.child_by_field_name("default_value")
            if default is not None:
                self.writes.setdefault(name, []).append(_Write(None, value=default))

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
                name = _text(node)
                pending.extend(self._named(node, name, function.owner))
                if name in self.aliases:  # RosEkf ekf(...) runs RosFilter<Ekf>'s constructor
                    pending.extend(
                        self.functions.get(_last(self.unaliased(name).split("<")[0]), ())
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
            owner = _last(_text(scope).split("<")[0])
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


def _function_declarator(node: Node) -> Node | None:
    declarator = node.child_by_field_name("declarator")
    while declarator is not None and declarator.type != "function_declarator":
        declarator = declarator.child_by_field_name("declarator")
    return declarator


def _enclosing_function(node: Node) -> Node | None:
    parent = node.parent
    while parent is not None:
        if parent.type in ("function_definition", "lambda_expression"):
            return parent
        parent = parent.parent
    return None


def _enclosing_class(node: Node) -> str | None:
    parent = node.parent
    while parent is not None:
        if parent.type in ("class_specifier", "struct_specifier"):
            name = parent.child_by_field_name("name")
            return _text(name) if name is not None else None
        parent = parent.parent
    return None


def _declared(node: Node) -> Iterator[tuple[str, _Variable]]:
    """The variables a ``declaration`` declares, with their initialisers."""
    type_node = node.child_by_field_name("type")
    type_text = _text(type_node) if type_node is not None else ""
    for declarator in node.children_by_field_name("declarator"):
        if declarator.type == "init_declarator":
            name = _declarator_name(declarator.child_by_field_name("declarator") or declarator)
            value = declarator.child_by_field_name("value")
            if name is None:
                continue
            if value is not None and value.type in ("argument_list", "initializer_list"):
                yield name, _Variable(type_text, arguments=list(value.named_children))
            else:
                yield name, _Variable(type_text, init=value)
        elif declarator.type == "function_declarator":
            # the most vexing parse: `ImageTransport it(nh);` reads as a function declaration
            name_node = declarator.child_by_field_name("declarator")
            parameters = declarator.child_by_field_name("parameters")
            if name_node is None or parameters is None:
                continue
            arguments = [_vexing_argument(p) for p in parameters.named_children]
            yield _text(name_node), _Variable(type_text, arguments=arguments)
        else:
            name = _declarator_name(declarator)
            if name is not None:
                yield name, _Variable(type_text)


def _vexing_argument(parameter: Node) -> Node:
    """A constructor argument read as a parameter: ``nh`` (a type), or a call without
    arguments (``shared_from_this()``, a type and an abstract function declarator), re-read
    as the expression it is."""
    if len(parameter.named_children) == 1:
        return parameter.named_children[0]
    return _PARSER.parse((_text(parameter) + ";").encode()).root_node


@dataclass
class _CallSite:
    """A call of a function ``name``; ``receiver`` is the type it is called on, when known."""

    name: str
    caller: Function
    arguments: list[Node]
    receiver: str | None


class _Evaluator:
    """Values of expressions in the context of a function of a :class:`Unit`."""

    def __init__(self, unit: Unit, reached: list[Function]) -> None:
        self.unit = unit
        self.reached = reached
        self.locals: dict[int, dict[str, _Variable]] = {}
        self.assignments: dict[int, dict[str, list[Node]]] = {}
        self.calls: dict[str, list[_CallSite]] = {}
        self.active: set[tuple[int, int]] = set()
        self._writes: dict[str, list[tuple[Function, Node]]] | None = None
        self._fields: dict[str, Value] = {}
        for function in reached:
            kinds = ("call_expression", "new_expression", "declaration", "field_initializer")
            for call in function.nodes(*kinds):
                for site in self._call_sites(call, function):
                    self.calls.setdefault(site.name, []).append(site)

    def _call_sites(self, node: Node, caller: Function) -> Iterator[_CallSite]:
        if node.type == "call_expression":
            callee = node.child_by_field_name("function")
            if callee is None:
                return
            receiver: str | None = caller.owner
            if callee.type == "field_expression":
                target = callee.child_by_field_name("argument")
                receiver = self._type_of(target, caller) if target is not None else None
                callee = callee.child_by_field_name("field")
            name = _last(_text(callee).split("<")[0]) if callee is not None else ""
            yield _CallSite(name, caller, _arguments(node), receiver)
        elif node.type == "new_expression":
            type_node = node.child_by_field_name("type")
            if type_node is not None:
                name = _last(self.unit.unaliased(_text(type_node)).split("<")[0])
                yield _CallSite(name, caller, _arguments(node), name)
        elif node.type == "field_initializer":
            # a member's constructor, or a base class's or a delegated one (RosFilter(...))
            written = _text(node.named_children[0])
            name = _last(self.unit.fields.get(written, written).split("<")[0])
            yield _CallSite(name, caller, _arguments(node), name)
        else:
            for _, variable in _declared(node):
                if variable.arguments is not None or variable.init is None:
                    name = _last(self.unit.unaliased(variable.type).split("<")[0])
                    yield _CallSite(name, caller, variable.arguments or [], name)

    def _type_of(self, node: Node, function: Function) -> str | None:
        """The declared type of a receiver variable, when the unit declares it."""
        if node.type == "this":
            return function.owner
        if node.type in ("subscript_expression", "pointer_expression"):
            inner = node.child_by_field_name("argument")
            return self._type_of(inner, function) if inner is not None else None
        if node.type == "field_expression":
            member = node.child_by_field_name("field")
            return self.unit.fields.get(_text(member)) if member is not None else None
        if node.type != "identifier":
            return None
        variable = self._scope(function).get(_text(node))
        if variable is not None:
            return variable.type
        return self.unit.fields.get(_text(node))

    def _scope(self, function: Function) -> dict[str, _Variable]:
        key = id(function)
        if key not in self.locals:
            scope: dict[str, _Variable] = {}
            assignments: dict[str, list[Node]] = {}
            for node in function.nodes("declaration", "assignment_expression", "call_expression"):
                if node.type == "declaration":
                    scope.update(_declared(node))
                elif node.type == "call_expression":
                    reset = _reset(node)
                    if reset is not None:
                        assignments.setdefault(reset[0], []).append(reset[1])
                    for written in _out_arguments(node):  # a value no evaluation knows
                        assignments.setdefault(written, []).append(node)
                else:
                    left, right = (
                        node.child_by_field_name("left"),
                        node.child_by_field_name("right"),
                    )
                    if left is None or right is None:
                        continue
                    if left.type == "identifier":
                        assignments.setdefault(_text(left), []).append(right)
                    elif left.type == "field_expression":
                        argument = left.child_by_field_name("argument")
                        member = left.child_by_field_name("field")
                        if argument is not None and argument.type == "this" and member is not None:
                            assignments.setdefault("this->" + _text(member), []).append(right)
            self.locals[key] = scope
            self.assignments[key] = assignments
        return self.locals[key]

    def _member_writes(self) -> dict[str, list[tuple[Function, Node]]]:
        """Assignments to members (a name no local declares, or ``this->name``) by member."""
        if self._writes is None:
            self._writes = {}
            for function in self.reached:
                scope = self._scope(function)
                for name, nodes in self.assignments[id(function)].items():
                    member = name.removeprefix("this->")
                    if member == name and name in scope:
                        continue
                    self._writes.setdefault(member, []).extend((function, n) for n in nodes)
        return self._writes

    def evaluate(self, node: Node, function: Function | None) -> Value:
        key = (id(node), id(function))
        if key in self.active or len(self.active) > MAX_DEPTH:
            return None
        self.active.add(key)
        try:
            return self._evaluate(node, function)
        finally:
            self.active.discard(key)

    def _evaluate(self, node: Node, function: Function | None) -> Value:
        kind = node.type
        if kind in ("translation_unit", "expression_statement") and node.named_child_count == 1:
            return self.evaluate(node.named_children[0], function)
        if kind == "string_literal":
            return Text(
                "".join(_text(c) for c in node.named_children if c.type == "string_content")
            )
        if kind == "raw_string_literal":
            content = node.child_by_field_name("delimiter")
            raw = _text(node)
            return Text(raw[raw.index("(") + 1 : raw.rindex(")")]) if content is None else None
        if kind == "concatenated_string":
            return self._concatenate(node.named_children, function)
        if kind == "parenthesized_expression" and node.named_child_count == 1:
            return self.evaluate(node.named_children[0], function)
        if (
            kind == "binary_expression"
            and _text(node.child_by_field_name("operator") or node) == "+"
        ):
            left, right = node.child_by_field_name("left"), node.child_by_field_name("right")
            if left is not None and right is not None:
                return self._concatenate([left, right], function)
        if kind in ("identifier", "type_identifier"):  # the latter in a most vexing parse
            return self._variable(_text(node), function)
        if kind == "qualified_identifier":
            return self._constant(_last(_text(node)))
        if kind == "field_expression":
            argument = node.child_by_field_name("argument")
            member = node.child_by_field_name("field")
            if argument is not None and argument.type == "this" and member is not None:
                return self._field(_text(member))
        if kind == "call_expression":
            return self._call_value(node, function)
        if kind == "pointer_expression":  # &nh, *nh: the same handle
            argument = node.child_by_field_name("argument")
            return self.evaluate(argument, function) if argument is not None else None
        if kind == "new_expression":
            type_node = node.child_by_field_name("type")
            if type_node is not None:
                return self.construct(_text(type_node), _arguments(node), function)
        return None

    def _concatenate(self, parts: list[Node], function: Function | None) -> Value:
        result = Text("")
        for part in parts:
            value = self.evaluate(part, function)
            result = result + (value if isinstance(value, Text) else Text.unknown(_text(part)))
        return result

    def _call_value(self, node: Node, function: Function | None) -> Value:
        callee = node.child_by_field_name("function")
        if callee is None:
            return None
        arguments = _arguments(node)
        if callee.type == "field_expression":
            method = callee.child_by_field_name("field")
            receiver = callee.child_by_field_name("argument")
            name = _text(method) if method is not None else ""
            if name == "c_str" and receiver is not None:
                return self.evaluate(receiver, function)
            if receiver is not None and receiver.type == "this":
                return self._handle_getter(name)
            if name == "resolveName" and receiver is not None and len(arguments) == 1:
                handle, value = (
                    self.evaluate(receiver, function),
                    self._name(arguments[0], function),
                )
                return value.within(handle.namespace) if isinstance(handle, Handle) else None
            return None
        name = _text(callee).replace(" ", "")
        getter = self._handle_getter(_last(name))
        if getter is not None:
            return getter
        if name == "ros::names::resolve" and len(arguments) == 1:
            return self._name(arguments[0], function)  # resolved like a relative use
        if _last(name) == "string" and len(arguments) == 1:
            return self.evaluate(arguments[0], function)
        return self.construct(name, arguments, function)

    def _name(self, node: Node, function: Function | None) -> Text:
        value = self.evaluate(node, function)
        return value if isinstance(value, Text) else Text.unknown(_text(node))

    @staticmethod
    def _handle_getter(name: str) -> Value:
        if name in _PRIVATE_HANDLES:
            return Handle(Text("~"))
        if name in _PUBLIC_HANDLES:
            return Handle(Text(""))
        if name == "shared_from_this":  # an rclcpp node's pointer to itself
            return Handle(Text(""), rclcpp=True)
        return None

    def construct(self, type_text: str, arguments: list[Node], function: Function | None) -> Value:
        """The value of a ``NodeHandle``, rclcpp node or ``ImageTransport`` built from
        ``arguments``."""
        if _RCLCPP_NODE.search(type_text.replace(" ", "")):
            return Handle(Text(""), rclcpp=True)
        type_name = _last(type_text.replace(" ", "").split("<")[0])
        if type_name == "NodeHandle":
            values = [self.evaluate(argument, function) for argument in arguments]
            parent = values[0] if values and isinstance(values[0], Handle) else None
            rest = values[1:] if parent is not None else values
            rest_nodes = arguments[1:] if parent is not None else arguments
            namespace = parent.namespace if parent is not None else Text("")
            if arguments and parent is None and not isinstance(values[0], Text):
                return Handle(Text.unknown(_text(arguments[0])))
            if rest and rest_nodes:
                child = rest[0] if isinstance(rest[0], Text) else Text.unknown(_text(rest_nodes[0]))
                return Handle(child.within(namespace) if namespace.value else child)
            return Handle(namespace)
        if type_name == "ImageTransport" and arguments:
            base = self.evaluate(arguments[0], function)
            if isinstance(base, Handle):
                return Handle(base.namespace, images=True, rclcpp=base.rclcpp)
            return Handle(Text.unknown(_text(arguments[0])), images=True)
        return None

    def _variable(self, name: str, function: Function | None) -> Value:
        if function is not None:
            scope = self._scope(function)
            variable = scope.get(name)
            if variable is not None:
                return self._local(name, variable, function)
            for index, (type_text, parameter) in enumerate(function.parameters):
                if parameter == name:
                    return self._parameter(function, index, type_text)
        if name in self.unit.fields or name in self.unit.writes:
            return self._field(name)
        return self._constant(name)

    def local(self, name: str, function: Function) -> _Variable | None:
        """The declaration of local variable ``name`` of ``function``."""
        return self._scope(function).get(name)

    def _local(self, name: str, variable: _Variable, function: Function) -> Value:
        if variable.arguments is not None:
            return self.construct(variable.type, variable.arguments, function)
        written = self.assignments[id(function)].get(name, [])
        if variable.init is not None:
            written = [variable.init, *written]  # a later write wins or disagrees
        values = {self.evaluate(node, function) for node in written}
        if len(values) == 1:
            return values.pop()
        if "NodeHandle" in variable.type and not values:
            return Handle(Text(""))
        return None

    def _parameter(self, function: Function, index: int, type_text: str) -> Value:
        values: set[Value] = set()
        for site in self.calls.get(function.name, []):
            if (
                site.receiver is not None
                and function.owner is not None
                and function.owner not in re.findall(r"\w+", site.receiver)
            ):
                continue  # a method of that name of another class
            if index < len(site.arguments) and len(site.arguments) <= len(function.parameters):
                values.add(self.evaluate(site.arguments[index], site.caller))
        name = function.parameters[index][1]
        if len(values) == 1 and None not in values:
            return values.pop()
        if "NodeHandle" in type_text or any(isinstance(v, Handle) for v in values):
            return Handle(Text.unknown(name))
        return Text.unknown(name)

    def _field(self, name: str) -> Value:
        if name not in self._fields:
            self._fields[name] = self._field_value(name)
        return self._fields[name]

    def _field_value(self, name: str) -> Value:
        values: set[Value] = set()
        type_text = self.unit.fields.get(name, "")
        for write in self.unit.writes.get(name, []):
            if not self._constructed(write.function):
                continue
            if write.arguments is not None:
                values.add(self.construct(type_text, write.arguments, write.function))
            elif write.value is not None:
                values.add(self.evaluate(write.value, write.function))
        for function, node in self._member_writes().get(name, []):
            if self._constructed(function):
                values.add(self.evaluate(node, function))
        values.discard(None)
        if len(values) == 1:
            return values.pop()
        if not values and "NodeHandle" in type_text:
            return Handle(Text(""))
        if values or "NodeHandle" in type_text:
            return (
                Handle(Text.unknown(name)) if any(isinstance(v, Handle) for v in values) else None
            )
        return None

    def _constructed(self, function: Function | None) -> bool:
        """Whether a member write in ``function`` happens: not in a constructor overload that
        the reached code never calls with its number of arguments (``SlamGMapping gn;`` runs
        the default constructor, not the nodelet's ``SlamGMapping(nh, pnh)``). A class no
        reached code constructs (the nodelet's own) keeps every constructor."""
        if function is None or function.name != function.owner:
            return True
        sites = self.calls.get(function.name, [])
        count = len(function.parameters)
        required = min(function.required, self.unit.required.get((function.name, count), count))
        arities = range(required, count + 1)
        return not sites or any(len(s.arguments) in arities for s in sites)

    def _constant(self, name: str) -> Value:
        node = self.unit.constants.get(name)
        return self.evaluate(node, None) if node is not None else None


@dataclass
class _Collector:
    """Turns the recognised API calls of the reached functions into entries."""

    unit: Unit
    evaluator: _Evaluator
    sink: DiagnosticSink
    entries: list[Entry] = field(default_factory=list)
    reads: list[Entry] = field(default_factory=list)
    """rclcpp's parameter reads: kept where no declaration names the parameter."""
    node_names: list[Text] = field(default_factory=list)
    """The names rclcpp nodes are built with (``Node("talker")``)."""

    def add(
        self,
        role: Role,
        handle: Handle | None,
        name_node: Node | None,
        function: Function,
        at: Node,
        type_name: str | None = None,
        default: Default | None = None,
    ) -> None:
        location = Location(function.file, at.start_point[0] + 1, at.start_point[1] + 1)
        if name_node is None:
            return
        value = self.evaluator.evaluate(name_node, function)
        name = value if isinstance(value, Text) else Text.unknown(_text(name_node))
        namespace = handle.namespace if handle is not None else Text("")
        resolved = name.within(namespace)
        if not resolved.static:
            self.sink.warning(
                "interface-symbolic-name",
                f"{role} name not known statically: {resolved.value}",
                location,
            )
        if type_name is None and role is not Role.PARAMS:
            self.sink.note(
                "interface-unknown-type", f"{role} type not known: {resolved.value}", location
            )
        self.entries.append(
            Entry(
                role,
                resolved.value,
                location,
                type=type_name,
                default=default,
                static=resolved.static,
            )
        )

    def scan(self, function: Function) -> None:
        for node in function.nodes(
            "call_expression", "new_expression", "declaration", "field_initializer"
        ):
            if node.type == "call_expression":
                self._call(node, function)
            elif node.type == "new_expression":
                type_node = node.child_by_field_name("type")
                if type_node is not None:
                    self._construction(_text(type_node), _arguments(node), function, node)
            elif node.type == "field_initializer":
                name = _text(node.named_children[0])
                if _last(name) in ("Node", "LifecycleNode"):  # the base class: the node's name
                    self._node_name(_arguments(node), function)
                self._construction(self.unit.fields.get(name, ""), _arguments(node), function, node)
            else:
                for _, variable in _declared(node):
                    if variable.arguments is not None:
                        self._construction(variable.type, variable.arguments, function, node)

    def _construction(
        self, type_text: str, arguments: list[Node], function: Function, at: Node
    ) -> None:
        if len(arguments) == 1 and _text(arguments[0]) in _NULLS:
            return  # a pointer member initialised to null constructs nothing
        compact = self.unit.unaliased(type_text).replace(" ", "")
        if _RCLCPP_NODE.search(compact):
            self._node_name(arguments, function)
            return
        base = _last(compact.split("<")[0])
        templates = _template_arguments_text(compact)
        message = self.unit.message_type(templates[0]) if templates else None
        handle, rest = self._split_handle(arguments, function)
        if base in _ACTION_CLASSES and "actionlib" in compact and rest:
            role = _ACTION_CLASSES[base]
            self.add(role, handle, rest[0], function, at, action_type(message) if message else None)
        elif base == "Subscriber" and "message_filters" in compact and handle is not None and rest:
            self.add(Role.SUBSCRIBES, handle, rest[0], function, at, message)
        elif base == "ControllerManager" and arguments:
            self._controller_manager(arguments[1:], function, at)

    def _node_name(self, arguments: list[Node], function: Function) -> None:
        if arguments:
            self.node_names.append(self.evaluator._name(arguments[0], function))

    def _controller_manager(self, arguments: list[Node], function: Function, at: Node) -> None:
        """``controller_manager::ControllerManager cm(&hw, nh)`` serves its services below
        ``controller_manager`` in ``nh``'s namespace (``ros::NodeHandle()`` by default)."""
        handle = self.evaluator.evaluate(arguments[0], function) if arguments else Handle(Text(""))
        if not isinstance(handle, Handle):
            handle = Handle(Text.unknown(_text(arguments[0])))
        location = Location(function.file, at.start_point[0] + 1, at.start_point[1] + 1)
        for service, kind in _CONTROLLER_MANAGER_SERVICES:
            name = Text("controller_manager/" + service).within(handle.namespace)
            self.entries.append(
                Entry(Role.SERVICES, name.value, location, type=kind, static=name.static)
            )

    def _split_handle(
        self, arguments: list[Node], function: Function
    ) -> tuple[Handle | None, list[Node]]:
        if arguments:
            first = self.evaluator.evaluate(arguments[0], function)
            if isinstance(first, Handle):
                return first, arguments[1:]
        return None, arguments

    def _call(self, node: Node, function: Function) -> None:
        callee = node.child_by_field_name("function")
        if callee is None:
            return
        arguments = _arguments(node)
        if callee.type != "field_expression":
            name = _text(callee).replace(" ", "")
            bare = name.split("<")[0]
            if name in _FREE_PARAM_READS and arguments:
                self._param(None, arguments, function, node, name.endswith("param"))
            elif bare in _RCLCPP_FREE_CALLS:
                self._rclcpp_free(bare, _template_arguments(callee), arguments, function, node)
            elif "::" not in bare and self._rclcpp(bare, callee, arguments, function, node):
                pass  # a method of the rclcpp node the function belongs to
            elif _RCLCPP_NODE.search(name):
                self._node_name(arguments, function)
            elif _last(bare) in ("make_shared", "make_unique"):
                templates = _template_arguments(callee)
                if templates:
                    self._construction(templates[0], arguments, function, node)
            return
        receiver = callee.child_by_field_name("argument")
        method_node = callee.child_by_field_name("field")
        if receiver is None or method_node is None:
            return
        method = _text(method_node).split("<")[0].strip()
        if self._rclcpp(method, method_node, arguments, function, node):
            return
        templates = _template_arguments(method_node)
        value = self.evaluator.evaluate(receiver, function)
        if not isinstance(value, Handle):
            self._filter_subscribe(receiver, method, arguments, function, node)
            return
        if not arguments:
            return
        topic = arguments[0]
        if value.images:
            self._image(value, method, topic, function, node)
        elif method == "advertise":
            self.add(Role.PUBLISHES, value, topic, function, node, self._first_type(templates))
        elif method == "subscribe":
            type_name = self._first_type(templates) or self._callback_type(arguments[1:])
            self.add(Role.SUBSCRIBES, value, topic, function, node, type_name)
        elif method == "advertiseService":
            type_name = self._first_type(templates) or self._callback_type(arguments[1:])
            if type_name is not None:  # a callback takes Srv::Request& or SrvRequest&
                type_name = type_name.removesuffix("Request")
            self.add(Role.SERVICES, value, topic, function, node, type_name)
        elif method == "serviceClient":
            self.add(Role.CLIENTS, value, topic, function, node, self._first_type(templates))
        elif method in _PARAM_READS:
            self._param(value, arguments, function, node, method == "param")

    def _rclcpp(
        self, method: str, callee: Node, arguments: list[Node], function: Function, at: Node
    ) -> bool:
        """An rclcpp ``Node`` method (``create_publisher<T>("name", qos)``, a parameter's
        declaration or read); whether ``method`` is one."""
        if not arguments:
            return False
        if method in _RCLCPP_CALLS:
            message = self._first_type(_template_arguments(callee))
            self.add(_RCLCPP_CALLS[method], None, arguments[0], function, at, message)
        elif method == _RCLCPP_DECLARE:
            default = (
                _default(arguments[1], self.evaluator, function) if len(arguments) > 1 else None
            )
            self.add(Role.PARAMS, None, arguments[0], function, at, default=default)
        elif method in _RCLCPP_READS:
            given = arguments[2] if method == "get_parameter_or" and len(arguments) > 2 else None
            default = _default(given, self.evaluator, function)
            self.add(Role.PARAMS, None, arguments[0], function, at, default=default)
            self.reads.append(self.entries.pop())
        else:
            return False
        return True

    def _rclcpp_free(
        self, name: str, templates: list[str], arguments: list[Node], function: Function, at: Node
    ) -> None:
        """``rclcpp_action::create_server<A>(node, "name", ...)`` and image_transport's
        functions: the node comes first (or, in the older form, its four interfaces)."""
        index = 4 if arguments and "node_base" in _text(arguments[0]).lower() else 1
        if index >= len(arguments):
            return
        role = _RCLCPP_FREE_CALLS[name]
        if name.startswith("image_transport::"):
            camera = "camera" in name
            self._images(
                role, Handle(Text(""), rclcpp=True), arguments[index], function, at, camera
            )
        else:
            message = self._first_type(templates)
            self.add(role, None, arguments[index], function, at, message and action_type(message))

    def _image(self, handle: Handle, method: str, name: Node, function: Function, at: Node) -> None:
        role = Role.PUBLISHES if method.startswith("advertise") else Role.SUBSCRIBES
        if method not in ("advertise", "subscribe", "advertiseCamera", "subscribeCamera"):
            return
        self._images(role, handle, name, function, at, method.endswith("Camera"))

    def _images(
        self, role: Role, handle: Handle, name: Node, function: Function, at: Node, camera: bool
    ) -> None:
        """An image topic, and with a ``camera`` the camera info beside it."""
        image_type, info_type = (
            (_ROS2_IMAGE, _ROS2_CAMERA_INFO) if handle.rclcpp else (_IMAGE, _CAMERA_INFO)
        )
        self.add(role, handle, name, function, at, image_type)
        image = self.entries[-1].name
        if camera:
            value = self.evaluator.evaluate(name, function)
            if isinstance(value, Text) and value.static:
                # image_transport: the camera info lives beside the image topic
                info = (
                    value.value.rsplit("/", 1)[0] + "/camera_info"
                    if "/" in value.value
                    else "camera_info"
                )
                location = Location(function.file, at.start_point[0] + 1, at.start_point[1] + 1)
                resolved = Text(info).within(handle.namespace)
                self.entries.append(
                    Entry(
                        role,
                        resolved.value,
                        location,
                        type=info_type,
                        static=resolved.static,
                        beside=image,
                    )
                )

    def _filter_subscribe(
        self, receiver: Node, method: str, arguments: list[Node], function: Function, at: Node
    ) -> None:
        """``sub.subscribe(nh, "topic", 1)`` on a ``message_filters::Subscriber`` member."""
        if method != "subscribe" or len(arguments) < 2:
            return
        type_text = self.unit.fields.get(_text(receiver), "")
        variable = self.evaluator._scope(function).get(_text(receiver))
        if variable is not None:
            type_text = variable.type
        handle, rest = self._split_handle(arguments, function)
        if handle is None or not rest:
            return
        compact = type_text.replace(" ", "")
        if "message_filters" in compact:
            templates = _template_arguments_text(compact)
            self.add(Role.SUBSCRIBES, handle, rest[0], function, at, self._first_type(templates))
        elif "SubscriberFilter" in compact:
            self.add(Role.SUBSCRIBES, handle, rest[0], function, at, _IMAGE)

    def _param(
        self,
        handle: Handle | None,
        arguments: list[Node],
        function: Function,
        at: Node,
        has_default: bool,
    ) -> None:
        default: Default | None = None
        if has_default:
            default = _default(
                arguments[-1] if len(arguments) >= 2 else None, self.evaluator, function
            )
        elif (test := _test_of(at)) is not None:
            default = Expression(_text(test))  # the code decides what an unset one means
        elif (guard := _guard_of(at, arguments[0])) is not None:
            default = Expression(_text(guard))  # read only when set: if (nh.hasParam(x))
        elif len(arguments) >= 2 and arguments[1].type == "identifier":
            written = _text(arguments[1])
            variable = self.evaluator.local(written, function)  # bool unreliable = false;
            init = self.unit.constants.get(written) if variable is None else variable.init
            if init is not None:
                default = _default(init, self.evaluator, function)
        self.add(Role.PARAMS, handle, arguments[0], function, at, default=default)

    def _first_type(self, templates: list[str]) -> str | None:
        return self.unit.message_type(templates[0]) if templates else None

    def _callback_type(self, arguments: list[Node]) -> str | None:
        """The message type a callback takes: the first parameter of the function named."""
        for argument in arguments:
            for node in _walk(
                argument, {"qualified_identifier", "identifier", "lambda_expression"}
            ):
                if node.type == "lambda_expression":
                    declarator = node.child_by_field_name("declarator")
                    parameters = (
                        declarator.child_by_field_name("parameters") if declarator else None
                    )
                    if parameters is not None and parameters.named_children:
                        return self.unit.message_type(_parameter_type(parameters.named_children[0]))
                    continue
                for signature in self.unit.signatures.get(_last(_text(node)), []):
                    if signature:
                        return self.unit.message_type(signature[0])
        return None


def _out_arguments(call: Node) -> list[str]:
    """The local variables a ROS call writes through a reference: ``searchParam(key, out)``,
    ``getParam(name, out)``, ``param(name, out, default)`` (a value read from a parameter)."""
    callee = call.child_by_field_name("function")
    method = callee.child_by_field_name("field") if callee is not None else None
    arguments = _arguments(call)
    if method is None or len(arguments) < 2 or arguments[1].type != "identifier":
        return []
    name = _text(method).split("<")[0]
    if name in ("searchParam", "getParam", "getParamCached") or len(arguments) == 3:
        return [_text(arguments[1])] if name in ("searchParam", *_PARAM_READS) else []
    return []  # param(name, default) returns the value


def _reset(call: Node) -> tuple[str, Node] | None:
    """``x.reset(value)`` or ``this->x.reset(value)`` (a smart pointer): an assignment of
    ``value`` to ``x`` (``this->x``), as the evaluator's assignments are keyed."""
    callee = call.child_by_field_name("function")
    arguments = _arguments(call)
    if callee is None or callee.type != "field_expression" or len(arguments) != 1:
        return None
    method, target = callee.child_by_field_name("field"), callee.child_by_field_name("argument")
    if method is None or target is None or _text(method) != "reset":
        return None
    if target.type == "identifier":
        return _text(target), arguments[0]
    if target.type == "field_expression":
        inner, member = target.child_by_field_name("argument"), target.child_by_field_name("field")
        if inner is not None and inner.type == "this" and member is not None:
            return "this->" + _text(member), arguments[0]
    return None


def _parameter_type(parameter: Node) -> str:
    declarator = parameter.child_by_field_name("declarator")
    text = _text(parameter)
    return text[: declarator.start_byte - parameter.start_byte] if declarator is not None else text


def _template_arguments_text(type_text: str) -> list[str]:
    if "<" not in type_text:
        return []
    inner = type_text[type_text.index("<") + 1 : type_text.rindex(">")]
    depth, parts, current = 0, [], ""
    for char in inner:
        if char == "," and depth == 0:
            parts.append(current)
            current = ""
            continue
        depth += char == "<"
        depth -= char == ">"
        current += char
    return [*parts, current]


def _test_of(call: Node) -> Node | None:
    """The expression that tests ``call``'s result (``!nh.getParam(...)`` in an ``if``): the
    code handles an unset parameter. None when the result is dropped (the variable silently
    keeps its value) or when the branch taken when unset fails (returns, throws, logs an
    error): the parameter is required."""
    node, negated = call, False
    while node.parent is not None and node.parent.type in _TESTING:
        node = node.parent
        negated ^= node.type == "unary_expression" and _text(node).startswith("!")
    parent = node.parent
    if parent is None or parent.type in ("expression_statement", "compound_statement"):
        return None
    statement = parent.parent if parent.type == "condition_clause" else None
    if statement is not None and statement.type == "if_statement":
        unset = statement.child_by_field_name("consequence" if negated else "alternative")
        if unset is not None and any(_fails(n) for n in _walk_all(unset)):
            return None
    return node


def _guard_of(call: Node, name: Node) -> Node | None:
    """The condition of an enclosing ``if`` that asks whether parameter ``name`` is set
    (``if (nh.hasParam("x")) nh.getParam("x", v);``)."""
    node = call.parent
    while node is not None and node.type != "function_definition":
        if node.type == "if_statement":
            condition = node.child_by_field_name("condition")
            text = _text(condition) if condition is not None else ""
            if "hasParam(" + _text(name) in text.replace(" ", ""):
                return condition
        node = node.parent
    return None


def _fails(node: Node) -> bool:
    if node.type in ("return_statement", "throw_statement"):
        return True
    callee = node.child_by_field_name("function") if node.type == "call_expression" else None
    return callee is not None and _text(callee).startswith(_FAILING)


def _default(node: Node | None, evaluator: _Evaluator, function: Function) -> Default | None:
    if node is None:
        return None
    text = _text(node)
    if node.type in ("true", "false"):
        return node.type == "true"
    if node.type == "number_literal":
        number = text.rstrip("fFlLuU")
        try:
            return int(number, 0)
        except ValueError:
            try:
                return float(number)
            except ValueError:
                return Expression(text)
    value = evaluator.evaluate(node, function)
    if isinstance(value, Text) and value.static:
        return value.value
    return Expression(text)


def extract(
    unit: Unit, entry: str, owner: str | None, sink: DiagnosticSink, where: Location
) -> list[Entry]:
    """The interface of the code reachable from function ``entry`` (of class ``owner``)."""
    return extract_node(unit, entry, owner, sink, where).entries


def extract_node(
    unit: Unit, entry: str, owner: str | None, sink: DiagnosticSink, where: Location
) -> Extracted:
    """:func:`extract`, with the node's own name (ROS 2)."""
    starts = [f for f in unit.functions.get(entry, []) if owner is None or f.owner == owner]
    if owner is not None:
        starts += unit.functions.get(owner, [])  # the nodelet's constructor runs first
    if not starts:
        what = f"{owner}::{entry}" if owner else entry
        sink.warning(
            "interface-no-entry",
            f"no definition of {what} in the sources; every function of them is read",
            where,
        )
        starts = [f for functions in unit.functions.values() for f in functions]
    reached = unit.reachable(starts)
    evaluator = _Evaluator(unit, reached)
    collector = _Collector(unit, evaluator, sink)
    for function in sorted(reached, key=lambda f: (f.file, f.node.start_byte)):
        collector.scan(function)
    declared = {e.name for e in collector.entries if e.role is Role.PARAMS}
    reads = [read for read in collector.reads if read.name not in declared]
    names = {name.value for name in collector.node_names if name.static}
    node_name = names.pop() if len(names) == 1 else None
    return Extracted(collector.entries + reads, node_name)
