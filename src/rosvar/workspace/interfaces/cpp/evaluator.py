"""The values of C++ expressions where extraction needs them: names and node handles.

Values are followed as far as the source says them statically: string literals and
constants, ``+`` and ``.c_str()``, locals and their later writes, members (every write in
the reached code whose constructor runs), function parameters (bound from every call site
of that name and arity), node handles through their constructors and getters. Anything else
is unknown (None), or a :class:`Text` with unknown parts; the checks reuse this evaluator.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass

from tree_sitter import Node

from rosvar.workspace.interfaces.cpp import apis, syntax
from rosvar.workspace.interfaces.cpp.unit import Function, Unit
from rosvar.workspace.interfaces.values import ParamRef, Text

MAX_DEPTH = 64
"""Nested evaluations allowed before a value is given up as unknown (cycles end earlier)."""


@dataclass(frozen=True)
class Handle:
    """A ``NodeHandle`` (or an ``ImageTransport`` built on one, when ``images``); an rclcpp
    node (``rclcpp``) has no namespace of its own."""

    namespace: Text
    images: bool = False
    rclcpp: bool = False


Value = Text | Handle | ParamRef | None
MAX_ALTERNATIVES = 64
"""Call sites a name is evaluated at, one by one, when they disagree (a wrapper given a
different name at each call)."""
MAX_PINNED = 4
"""Callers followed outwards when a wrapper's argument is itself a parameter."""


@dataclass(eq=False)
class CallSite:
    """A call of a function ``name`` (a construction of class ``name``) at ``at``;
    ``receiver`` is the type it is called on, when known; ``templates`` the template
    arguments written there (``make_shared<Wrapper<T>>``: ``[T]``)."""

    name: str
    caller: Function
    arguments: list[Node]
    receiver: str | None
    at: Node
    templates: tuple[str, ...] = ()


class Evaluator:
    """Values of expressions in the context of a function of a :class:`Unit`."""

    def __init__(self, unit: Unit, reached: list[Function]) -> None:
        self.unit = unit
        self.reached = reached
        self.locals: dict[int, dict[str, syntax.Variable]] = {}
        self.assignments: dict[int, dict[str, list[Node]]] = {}
        self.calls: dict[str, list[CallSite]] = {}
        self.active: set[tuple[int, int, tuple[int, ...]]] = set()
        self.pinned: dict[int, CallSite] = {}
        """Functions whose parameters are taken from one call site only (by id)."""
        self._writes: dict[str, list[tuple[Function, Node]]] | None = None
        self._fields: dict[tuple[str, tuple[int, ...]], Value] = {}
        self._parameters: dict[tuple[int, int, tuple[int, ...]], Value] = {}
        for function in reached:
            kinds = ("call_expression", "new_expression", "declaration", "field_initializer")
            for call in function.nodes(*kinds):
                for site in self._call_sites(call, function):
                    self.calls.setdefault(site.name, []).append(site)

    def _call_sites(self, node: Node, caller: Function) -> Iterator[CallSite]:
        if node.type == "call_expression":
            callee = node.child_by_field_name("function")
            if callee is None:
                return
            receiver: str | None = caller.owner
            if callee.type == "field_expression":
                target = callee.child_by_field_name("argument")
                receiver = self._type_of(target, caller) if target is not None else None
                callee = callee.child_by_field_name("field")
            written = syntax.text(callee) if callee is not None else ""
            name = syntax.last(written.split("<")[0])
            templates = tuple(syntax.template_arguments_text(written))
            arguments = syntax.arguments(node)
            yield CallSite(name, caller, arguments, receiver, node, templates)
            if name in apis.MAKERS and templates:  # make_shared<T>(...) constructs a T
                yield self._construction(templates[0], caller, arguments, node)
        elif node.type == "new_expression":
            type_node = node.child_by_field_name("type")
            if type_node is not None:
                yield self._construction(
                    syntax.text(type_node), caller, syntax.arguments(node), node
                )
        elif node.type == "field_initializer":
            # a member's constructor, or a base class's or a delegated one (RosFilter(...))
            written = syntax.text(node.named_children[0])
            type_text = self.unit.fields.get(written, written)
            yield self._construction(type_text, caller, syntax.arguments(node), node)
        else:
            for _, variable in syntax.declared(node):
                if variable.arguments is not None or variable.init is None:
                    yield self._construction(variable.type, caller, variable.arguments or [], node)

    def _construction(
        self, type_text: str, caller: Function, arguments: list[Node], at: Node
    ) -> CallSite:
        written = self.unit.unaliased(type_text).replace(" ", "")
        name = syntax.last(written.split("<")[0])
        templates = tuple(syntax.template_arguments_text(written))
        return CallSite(name, caller, arguments, name, at, templates)

    def _type_of(self, node: Node, function: Function) -> str | None:
        """The declared type of a receiver variable, when the unit declares it."""
        if node.type == "this":
            return function.owner
        if node.type in ("subscript_expression", "pointer_expression"):
            inner = node.child_by_field_name("argument")
            return self._type_of(inner, function) if inner is not None else None
        if node.type == "field_expression":
            member = node.child_by_field_name("field")
            return self.unit.fields.get(syntax.text(member)) if member is not None else None
        if node.type != "identifier":
            return None
        variable = self._scope(function).get(syntax.text(node))
        if variable is not None:
            return variable.type
        return self.unit.fields.get(syntax.text(node))

    def _scope(self, function: Function) -> dict[str, syntax.Variable]:
        key = id(function)
        if key not in self.locals:
            scope: dict[str, syntax.Variable] = {}
            assignments: dict[str, list[Node]] = {}
            for node in function.nodes("declaration", "assignment_expression", "call_expression"):
                if node.type == "declaration":
                    scope.update(syntax.declared(node))
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
                        assignments.setdefault(syntax.text(left), []).append(right)
                    elif left.type == "field_expression":
                        argument = left.child_by_field_name("argument")
                        member = left.child_by_field_name("field")
                        if argument is not None and argument.type == "this" and member is not None:
                            assignments.setdefault("this->" + syntax.text(member), []).append(right)
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

    def alternatives(
        self, node: Node, function: Function
    ) -> list[tuple[Value, tuple[CallSite, ...]]]:
        """The values of ``node`` at each call site of ``function`` (or construction of its
        class) that gives it another one, each with the sites that give it, outermost last:
        a wrapper (``create_pub(node, "a")``, ``TwistSubscriber(node, "cmd_vel")``) called
        with several names has one value per call. One value when all agree."""
        merged = self.evaluate(node, function)
        if not _open(merged):
            return [(merged, ())]
        found: list[tuple[Value, tuple[CallSite, ...]]] = []
        self._pin(node, function, function, (), found)
        closed = [(value, chain) for value, chain in found if not _open(value)]
        if not closed:
            return [(merged, ())]
        if len(closed) < len(found):  # the sites that still say nothing: one unknown use
            closed.append((merged, ()))
        return closed

    def _pin(
        self,
        node: Node,
        function: Function,
        outer: Function,
        chain: tuple[CallSite, ...],
        found: list[tuple[Value, tuple[CallSite, ...]]],
    ) -> None:
        """Pin ``outer`` (or its class's constructor) to each of its call sites in turn."""
        candidates = [outer]
        if outer.owner is not None:
            candidates += [
                f for f in self.unit.functions.get(outer.owner, ()) if f.owner == outer.owner
            ]
        for target in candidates:
            sites = [] if id(target) in self.pinned else self.sites(target)
            if len(sites) < 2 and not (chain and sites):
                continue
            for site in sites:
                if len(found) >= MAX_ALTERNATIVES:
                    return
                self.pinned[id(target)] = site
                try:
                    value = self.evaluate(node, function)
                    if _open(value) and len(chain) + 1 < MAX_PINNED:
                        before = len(found)
                        self._pin(node, function, site.caller, (*chain, site), found)
                        if len(found) > before:
                            continue
                    found.append((value, (*chain, site)))
                finally:
                    del self.pinned[id(target)]
            return

    def _pins(self) -> tuple[int, ...]:
        return tuple(sorted(id(site) for site in self.pinned.values()))

    def evaluate(self, node: Node, function: Function | None) -> Value:
        key = (id(node), id(function), self._pins())
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
                "".join(syntax.text(c) for c in node.named_children if c.type == "string_content")
            )
        if kind == "raw_string_literal":
            content = node.child_by_field_name("delimiter")
            raw = syntax.text(node)
            return Text(raw[raw.index("(") + 1 : raw.rindex(")")]) if content is None else None
        if kind == "concatenated_string":
            return self._concatenate(node.named_children, function)
        if kind in ("parenthesized_expression", "initializer_list") and node.named_child_count == 1:
            return self.evaluate(node.named_children[0], function)
        if (
            kind == "binary_expression"
            and syntax.text(node.child_by_field_name("operator") or node) == "+"
        ):
            left, right = node.child_by_field_name("left"), node.child_by_field_name("right")
            if left is not None and right is not None:
                return self._concatenate([left, right], function)
        if kind in ("identifier", "type_identifier"):  # the latter in a most vexing parse
            return self._variable(syntax.text(node), function)
        if kind == "qualified_identifier":
            return self._constant(syntax.last(syntax.text(node)))
        if kind == "field_expression":
            argument = node.child_by_field_name("argument")
            member = node.child_by_field_name("field")
            if argument is not None and argument.type == "this" and member is not None:
                return self._field(syntax.text(member))
        if kind == "call_expression":
            return self._call_value(node, function)
        if kind == "pointer_expression":  # &nh, *nh: the same handle
            argument = node.child_by_field_name("argument")
            return self.evaluate(argument, function) if argument is not None else None
        if kind == "new_expression":
            type_node = node.child_by_field_name("type")
            if type_node is not None:
                return self.construct(syntax.text(type_node), syntax.arguments(node), function)
        return None

    def _concatenate(self, parts: list[Node], function: Function | None) -> Value:
        result = Text("")
        for part in parts:
            value = self.evaluate(part, function)
            result = result + (
                value if isinstance(value, Text) else Text.unknown(syntax.text(part))
            )
        return result

    def _call_value(self, node: Node, function: Function | None) -> Value:
        callee = node.child_by_field_name("function")
        if callee is None:
            return None
        arguments = syntax.arguments(node)
        if callee.type == "field_expression":
            method = callee.child_by_field_name("field")
            receiver = callee.child_by_field_name("argument")
            name = syntax.text(method) if method is not None else ""
            bare = name.split("<")[0].strip()
            if bare in apis.VALUE_GETTERS and receiver is not None:
                return self.evaluate(receiver, function)  # .c_str(), .as_string()
            if receiver is not None and receiver.type == "this":
                return self._handle_getter(name) or self._ros2_value(bare, arguments, function)
            if name == "resolveName" and receiver is not None and len(arguments) == 1:
                handle, value = (
                    self.evaluate(receiver, function),
                    self.name(arguments[0], function),
                )
                if not isinstance(handle, Handle):
                    return None
                resolved = value.within(handle.namespace)  # resolved: no namespace again
                return Text(resolved.value, resolved.static, resolved=True)
            if bare in apis.PARAM_READS and receiver is not None:
                handle = self.evaluate(receiver, function)
                if isinstance(handle, Handle) and arguments:
                    return self._param_read(handle.namespace, bare, arguments, function)
            if receiver is not None:
                return self._ros2_value(bare, arguments, function)
            return None
        name = syntax.text(callee).replace(" ", "")
        getter = self._handle_getter(syntax.last(name))
        if getter is not None:
            return getter
        bare = name.split("<")[0]
        if bare in apis.FREE_PARAM_READS and arguments:
            return self._param_read(Text(""), syntax.last(bare), arguments, function)
        if "::" not in bare and (ros2 := self._ros2_value(bare, arguments, function)):
            return ros2
        if name == "ros::names::resolve" and len(arguments) == 1:
            return self.name(arguments[0], function)  # resolved like a relative use
        if syntax.last(name) == "string" and len(arguments) == 1:
            return self.evaluate(arguments[0], function)
        return self.construct(name, arguments, function)

    def _param_read(
        self, namespace: Text, method: str, arguments: list[Node], function: Function | None
    ) -> ParamRef:
        """``nh.param("topic", t, "scan")``, ``nh.param<std::string>("topic", "scan")``,
        ``nh.getParam("topic", t)``: the parameter's value (its default, where written)."""
        given = arguments[2] if len(arguments) == 3 else None
        if method == "param" and len(arguments) == 2:
            given = arguments[1]  # the form that returns the value
        return ParamRef(
            self.name(arguments[0], function).within(namespace), self._text(given, function)
        )

    def _ros2_value(self, method: str, arguments: list[Node], function: Function | None) -> Value:
        """rclcpp's values: ``declare_parameter("topic", "scan")`` and
        ``get_parameter("topic")`` (a parameter's value), ``get_name()`` (the node's name,
        so that ``get_name() + "/map"`` is the private ``~/map``)."""
        if method == "get_name" and not arguments:
            return Text("~")
        if method == apis.RCLCPP_DECLARE and arguments:
            default = self._text(arguments[1], function) if len(arguments) > 1 else None
            return ParamRef(self.name(arguments[0], function), default)
        if method == "get_parameter" and len(arguments) in (1, 2):  # (name[, out])
            return ParamRef(self.name(arguments[0], function))
        if method == "get_parameter_or" and len(arguments) == 3:  # (name, out, alternative)
            return ParamRef(self.name(arguments[0], function), self._text(arguments[2], function))
        return None

    def _text(self, node: Node | None, function: Function | None) -> str | None:
        value = self.evaluate(node, function) if node is not None else None
        return value.value if isinstance(value, Text) and value.static else None

    def name(self, node: Node, function: Function | None) -> Text:
        value = self.evaluate(node, function)
        return value if isinstance(value, Text) else Text.unknown(syntax.text(node))

    @staticmethod
    def _handle_getter(name: str) -> Value:
        if name in apis.PRIVATE_HANDLES:
            return Handle(Text("~"))
        if name in apis.PUBLIC_HANDLES:
            return Handle(Text(""))
        if name == "shared_from_this":  # an rclcpp node's pointer to itself
            return Handle(Text(""), rclcpp=True)
        return None

    def construct(self, type_text: str, arguments: list[Node], function: Function | None) -> Value:
        """The value of a ``NodeHandle``, rclcpp node or ``ImageTransport`` built from
        ``arguments``."""
        if apis.RCLCPP_NODE.search(type_text.replace(" ", "")):
            return Handle(Text(""), rclcpp=True)
        bare = re.sub(r"\b(const|volatile)\b|[&*\s]", "", type_text)
        type_name = syntax.last(bare.split("<")[0])
        if type_name == "NodeHandle":
            values = [self.evaluate(argument, function) for argument in arguments]
            parent = values[0] if values and isinstance(values[0], Handle) else None
            rest = values[1:] if parent is not None else values
            rest_nodes = arguments[1:] if parent is not None else arguments
            namespace = parent.namespace if parent is not None else Text("")
            if arguments and parent is None and not isinstance(values[0], Text):
                return Handle(Text.unknown(syntax.text(arguments[0])))
            if rest and rest_nodes:
                child = (
                    rest[0]
                    if isinstance(rest[0], Text)
                    else Text.unknown(syntax.text(rest_nodes[0]))
                )
                return Handle(child.within(namespace) if namespace.value else child)
            return Handle(namespace)
        if type_name == "ImageTransport" and arguments:
            base = self.evaluate(arguments[0], function)
            if isinstance(base, Handle):
                return Handle(base.namespace, images=True, rclcpp=base.rclcpp)
            return Handle(Text.unknown(syntax.text(arguments[0])), images=True)
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

    def local(self, name: str, function: Function) -> syntax.Variable | None:
        """The declaration of local variable ``name`` of ``function``."""
        return self._scope(function).get(name)

    def _local(self, name: str, variable: syntax.Variable, function: Function) -> Value:
        if variable.arguments is not None:
            return self.construct(variable.type, variable.arguments, function)
        written = self.assignments[id(function)].get(name, [])
        if variable.init is not None:
            written = [variable.init, *written]  # a later write wins or disagrees
        values = {self.evaluate(node, function) for node in written}
        if len(values) == 1:
            return values.pop()
        if (read := _read_over(values)) is not None:
            return read
        if "NodeHandle" in variable.type and not values:
            return Handle(Text(""))
        return None

    def _parameter(self, function: Function, index: int, type_text: str) -> Value:
        """The value every call site gives parameter ``index`` of ``function``, kept: a
        chain of helpers each calling the next twice is evaluated once per helper."""
        key = (id(function), index, self._pins())
        if key not in self._parameters:
            self._parameters[key] = self._parameter_value(function, index, type_text)
        return self._parameters[key]

    def sites(self, function: Function) -> list[CallSite]:
        """The reached calls of ``function`` (the constructions of its class, for a
        constructor) that may bind its parameters; only the pinned one when it is pinned.
        Without types, a call that several overloads accept by its number of arguments is
        taken as the one with the fewest parameters (the others usually forward to it with
        more, as a delegating constructor does)."""
        pinned = self.pinned.get(id(function))
        if pinned is not None:
            return [pinned]
        shorter = [
            f
            for f in self.unit.functions.get(function.name, ())
            if f.owner == function.owner and len(f.parameters) < len(function.parameters)
        ]
        return [
            site
            for site in self.calls.get(function.name, [])
            if (
                site.receiver is None
                or function.owner is None
                or function.owner in re.findall(r"\w+", site.receiver)
            )  # not a method of that name of another class
            and self._accepts(function, site)
            and not any(self._accepts(other, site) for other in shorter)
            and self.constructed(site.caller)  # not from an overload nothing calls
        ]

    def _accepts(self, function: Function, site: CallSite) -> bool:
        """Whether ``site`` may call ``function``: its number of arguments, and no string
        literal given for a parameter that is no string (nor a template's) or the reverse
        (an overload taking the node's interfaces against one taking a name)."""
        if len(site.arguments) not in self._arities(function):
            return False
        for argument, (type_text, _) in zip(site.arguments, function.parameters, strict=False):
            literal = argument.type in ("string_literal", "concatenated_string")
            textual = re.search(r"string|char|\bauto\b|&&", type_text) is not None or (
                syntax.last(re.sub(r"\b(const|volatile)\b|[&*\s]", "", type_text))
                in function.templates
            )
            if literal and not textual:
                return False
            if not literal and "string" in type_text and "interface" in syntax.text(argument):
                return False
        return True

    def _arities(self, function: Function) -> range:
        """How many arguments a call of ``function`` gives: at least those without a default
        (in its definition or a declaration), at most all."""
        count = len(function.parameters)
        required = min(function.required, self.unit.required.get((function.name, count), count))
        return range(required, count + 1)

    def _parameter_value(self, function: Function, index: int, type_text: str) -> Value:
        values: set[Value] = set()
        for site in self.sites(function):
            if index < len(site.arguments):
                values.add(self.evaluate(site.arguments[index], site.caller))
            elif (default := function.defaults.get(index)) is not None:  # = {"~"}
                braces = next(syntax.walk(default, {"initializer_list"}), None)
                built = None
                if braces is not None:
                    built = self.construct(type_text, list(braces.named_children), function)
                values.add(built if built is not None else self.evaluate(default, function))
        name = function.parameters[index][1]
        if len(values) == 1 and None not in values:
            return values.pop()
        if "NodeHandle" in type_text or any(isinstance(v, Handle) for v in values):
            return Handle(Text.unknown(name))
        return Text.unknown(name)

    def _field(self, name: str) -> Value:
        key = (name, self._pins())
        if key not in self._fields:
            self._fields[key] = self._field_value(name)
        return self._fields[key]

    def _field_value(self, name: str) -> Value:
        values: set[Value] = set()
        type_text = self.unit.fields.get(name, "")
        for write in self.unit.writes.get(name, []):
            if not self.constructed(write.function):
                continue
            if write.arguments is not None:
                built = self.construct(type_text, write.arguments, write.function)
                if built is None and len(write.arguments) == 1:  # topic_(topic): a copy
                    built = self.evaluate(write.arguments[0], write.function)
                values.add(built)
            elif write.value is not None:
                values.add(self.evaluate(write.value, write.function))
        for function, node in self._member_writes().get(name, []):
            if self.constructed(function):
                values.add(self.evaluate(node, function))
        values.discard(None)
        if len(values) == 1:
            return values.pop()
        if (read := _read_over(values)) is not None:
            return read
        if not values and "NodeHandle" in type_text:
            return Handle(Text(""))
        if values or "NodeHandle" in type_text:
            return (
                Handle(Text.unknown(name)) if any(isinstance(v, Handle) for v in values) else None
            )
        return None

    def constructed(self, function: Function | None) -> bool:
        """Whether a member write in ``function`` happens: not in a constructor overload that
        the reached code never calls with its number of arguments (``SlamGMapping gn;`` runs
        the default constructor, not the nodelet's ``SlamGMapping(nh, pnh)``). A class no
        reached code constructs (the nodelet's own) keeps every constructor."""
        if function is None or function.name != function.owner:
            return True
        sites = self.calls.get(function.name, [])
        return not sites or any(self._accepts(function, s) for s in sites)

    def _constant(self, name: str) -> Value:
        node = self.unit.constants.get(name)
        return self.evaluate(node, None) if node is not None else None


def _read_over(values: set[Value]) -> ParamRef | None:
    """A variable given a literal, then a parameter's value (``std::string t = "scan";
    nh.getParam("topic", t)``): the parameter, with the literal as its default (a read
    leaves the variable as it was when the parameter is unset)."""
    reads = [v for v in values if isinstance(v, ParamRef) and v.default is None]
    texts = [v for v in values if isinstance(v, Text) and v.static]
    if len(reads) == 1 and len(texts) == 1 and len(values) == 2:
        return ParamRef(reads[0].name, texts[0].value)
    return None


def _open(value: Value) -> bool:
    """Whether a call site could tell more: a name with unknown parts, or no value."""
    return value is None or (isinstance(value, Text) and not value.static)


def _out_arguments(call: Node) -> list[str]:
    """The variables a ROS call writes through a reference: ``searchParam(key, out)``,
    ``getParam(name, out)``, ``param(name, out, default)``, rclcpp's ``get_parameter(name,
    out)`` and ``get_parameter_or(name, out, alternative)`` (a value read from a parameter)."""
    callee = call.child_by_field_name("function")
    if callee is not None and callee.type == "field_expression":
        callee = callee.child_by_field_name("field")
    arguments = syntax.arguments(call)
    if callee is None or len(arguments) < 2 or arguments[1].type not in _WRITABLE:
        return []
    name = syntax.last(syntax.text(callee).split("<")[0])
    if name in apis.OUT_ARGUMENT_READS or (name == "param" and len(arguments) == 3):
        return [syntax.text(arguments[1])]
    return []  # param(name, default) returns the value


_WRITABLE = frozenset({"identifier", "field_expression"})


def _reset(call: Node) -> tuple[str, Node] | None:
    """``x.reset(value)`` or ``this->x.reset(value)`` (a smart pointer): an assignment of
    ``value`` to ``x`` (``this->x``), as the evaluator's assignments are keyed."""
    callee = call.child_by_field_name("function")
    arguments = syntax.arguments(call)
    if callee is None or callee.type != "field_expression" or len(arguments) != 1:
        return None
    method, target = callee.child_by_field_name("field"), callee.child_by_field_name("argument")
    if method is None or target is None or syntax.text(method) != "reset":
        return None
    if target.type == "identifier":
        return syntax.text(target), arguments[0]
    if target.type == "field_expression":
        inner, member = target.child_by_field_name("argument"), target.child_by_field_name("field")
        if inner is not None and inner.type == "this" and member is not None:
            return "this->" + syntax.text(member), arguments[0]
    return None
