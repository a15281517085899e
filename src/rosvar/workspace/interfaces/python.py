"""Python extraction: the ``rospy`` and ``actionlib`` calls of a script, and the ``rclpy``
calls of a ROS 2 module, read with ``ast``.

Calls are recognised through the script's imports (``import rospy as r``,
``from rospy import Publisher``), names through string constants assigned once in the
module, the function or ``self``; message types through ``from pkg.msg import T``.
rclpy's ``Node`` methods (``self.create_publisher(T, "name", qos)``) are recognised by name
on any receiver: a ROS 2 node has one namespace. Everything a script calls is its interface:
Python nodes are single files, so no reachability is needed.
"""

from __future__ import annotations

import ast
from collections.abc import Sequence
from dataclasses import dataclass, field

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.workspace.interfaces import python2, python_modules, tf
from rosvar.workspace.interfaces.lifecycle import with_lifecycle
from rosvar.workspace.interfaces.model import (
    ANY_PARAMETER,
    RECONFIGURED,
    UNDECLARED_PARAMETERS,
    Default,
    Entry,
    Expression,
    Extracted,
    NamedBy,
    Role,
)
from rosvar.workspace.interfaces.reading import SourceReader
from rosvar.workspace.interfaces.values import ParamRef, Text, action_type

_CALLS: dict[str, tuple[Role, str]] = {
    # callee → role, and the keyword naming the type argument (the second positional one)
    "rospy.Publisher": (Role.PUBLISHES, "data_class"),
    "rospy.Subscriber": (Role.SUBSCRIBES, "data_class"),
    "rospy.Service": (Role.SERVICES, "service_class"),
    "rospy.ServiceProxy": (Role.CLIENTS, "service_class"),
    "actionlib.SimpleActionServer": (Role.ACTION_SERVERS, "ActionSpec"),
    "actionlib.SimpleActionClient": (Role.ACTION_CLIENTS, "action_spec"),
    "actionlib.ActionServer": (Role.ACTION_SERVERS, "ActionSpec"),
    "actionlib.ActionClient": (Role.ACTION_CLIENTS, "ActionSpec"),
    "rospy.get_param": (Role.PARAMS, "default"),
    "rospy.wait_for_message": (Role.SUBSCRIBES, "topic_type"),
}
_RCLPY_METHODS: dict[str, tuple[Role, int]] = {
    # Node method → role, and the position of the name (the type comes first)
    "create_publisher": (Role.PUBLISHES, 1),
    "create_lifecycle_publisher": (Role.PUBLISHES, 1),  # rclpy.lifecycle.Node's
    "create_subscription": (Role.SUBSCRIBES, 1),
    "create_service": (Role.SERVICES, 1),
    "create_client": (Role.CLIENTS, 1),
    "declare_parameter": (Role.PARAMS, 0),
}
_RCLPY_ACTIONS = {  # constructor → role; (node, type, name, ...)
    "rclpy.action.ActionServer": Role.ACTION_SERVERS,
    "rclpy.action.ActionClient": Role.ACTION_CLIENTS,
    "rclpy.action.server.ActionServer": Role.ACTION_SERVERS,
    "rclpy.action.client.ActionClient": Role.ACTION_CLIENTS,
}
_RCLPY_WAIT = "rclpy.wait_for_message.wait_for_message"
"""``wait_for_message(msg_type, node, topic)``: a subscription while it waits."""
_RCLPY_LIFECYCLE_NODES = frozenset(
    {"rclpy.lifecycle.Node", "rclpy.lifecycle.LifecycleNode", "rclpy.lifecycle.node.LifecycleNode"}
)
"""rclpy's lifecycle node class: built, or derived from, it has the lifecycle interface."""
_RCLPY_NODES = frozenset({"rclpy.node.Node", "rclpy.create_node", *_RCLPY_LIFECYCLE_NODES})
"""Calls that build an rclpy node: the first argument is its name."""
_VALUE_ATTRIBUTES = frozenset(
    {"value", "string_value", "get_parameter_value", "integer_value", "double_value"}
)
"""What rclpy's parameter objects give their value through."""
MAX_DEPTH = 64
"""Nested ``+`` and f-string parts of a name evaluated before it is given up as unknown."""
_MODULE_ALIASES = {
    "actionlib.simple_action_server": "actionlib",
    "actionlib.simple_action_client": "actionlib",
}


@dataclass
class _Program:
    """The calls of every module read for one node, by the name called (a function's, or a
    class's for its constructor): where a parameter's value comes from."""

    calls: dict[str, list[tuple[_Reader, ast.Call]]] = field(default_factory=dict)


@dataclass
class _Scope:
    """Names a script binds: imports (to dotted paths) and single string assignments."""

    imports: dict[str, str] = field(default_factory=dict)
    strings: dict[str, list[ast.expr]] = field(default_factory=dict)


def _dotted(node: ast.expr) -> str | None:
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        base = _dotted(node.value)
        return f"{base}.{node.attr}" if base is not None else None
    return None


def _binding_name(target: ast.expr) -> str | None:
    if isinstance(target, ast.Name):
        return target.id
    if (
        isinstance(target, ast.Attribute)
        and isinstance(target.value, ast.Name)
        and target.value.id == "self"
    ):
        return "self." + target.attr
    return None


def _scope(tree: ast.Module) -> _Scope:
    scope = _Scope()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                scope.imports[alias.asname or alias.name.split(".")[0]] = (
                    alias.name if alias.asname else alias.name.split(".")[0]
                )
        elif isinstance(node, ast.ImportFrom) and node.module:
            for alias in node.names:
                scope.imports[alias.asname or alias.name] = f"{node.module}.{alias.name}"
        elif isinstance(node, ast.Assign):
            for target in node.targets:
                name = _binding_name(target)
                if name is not None:
                    scope.strings.setdefault(name, []).append(node.value)
    return scope


class _Reader:
    def __init__(
        self, path: str, tree: ast.Module, sink: DiagnosticSink, program: _Program | None = None
    ) -> None:
        self.path = path
        self.scope = _scope(tree)
        self.sink = sink
        self.active: set[str] = set()
        self.program = program or _Program()
        self.parents = {
            id(child): node for node in ast.walk(tree) for child in ast.iter_child_nodes(node)
        }

    def enclosing(self, node: ast.AST) -> tuple[ast.FunctionDef | None, ast.ClassDef | None]:
        """The function ``node`` is in, and that function's class."""
        function: ast.FunctionDef | None = None
        current = self.parents.get(id(node))
        while current is not None:
            if isinstance(current, ast.FunctionDef) and function is None:
                function = current
            elif isinstance(current, ast.ClassDef):
                return function, current if function is not None else None
            current = self.parents.get(id(current))
        return function, None

    def argument(self, node: ast.Name, depth: int) -> Text | ParamRef | None:
        """The value every call gives the function parameter ``node`` names (a class's
        constructor is called by the class's name), when the calls of the read modules
        agree: ``MotionWander("/cmd_vel")`` for ``def __init__(self, cmd_vel_topic)``."""
        function, owner = self.enclosing(node)
        if function is None:
            return None
        names = [a.arg for a in function.args.args]
        if node.id not in names:
            return None
        index = names.index(node.id)
        callee = function.name
        if owner is not None:
            index -= 1  # self
            if function.name == "__init__":
                callee = owner.name
        values = set()
        for reader, call in self.program.calls.get(callee, []):
            given = call.args[index] if 0 <= index < len(call.args) else None
            given = next((k.value for k in call.keywords if k.arg == node.id), given)
            values.add(None if given is None else reader.value(given, depth + 1))
        values.discard(None)
        return values.pop() if len(values) == 1 else None

    def qualified(self, node: ast.expr) -> str | None:
        dotted = _dotted(node)
        if dotted is None:
            return None
        head, _, rest = dotted.partition(".")
        full = self.scope.imports.get(head, head)
        full = f"{full}.{rest}" if rest else full
        for module, alias in _MODULE_ALIASES.items():
            if full.startswith(module + "."):
                full = alias + full[len(module) :]
        return full

    def text(self, node: ast.expr, depth: int = 0) -> Text:
        """The name ``node`` spells, its unknown parts symbolic."""
        value = self.value(node, depth)
        return value if isinstance(value, Text) else Text.unknown(_unparse(node))

    def value(self, node: ast.expr, depth: int = 0) -> Text | ParamRef:
        """A name, or the value of a parameter the script reads (``rospy.get_param("~topic",
        "scan")``, rclpy's ``declare_parameter("topic", "scan").value``)."""
        if depth > MAX_DEPTH:
            return Text.unknown(_unparse(node))
        if isinstance(node, ast.Constant) and isinstance(node.value, str):
            return Text(node.value)
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            return self.text(node.left, depth + 1) + self.text(node.right, depth + 1)
        if isinstance(node, ast.JoinedStr):
            result = Text("")
            for part in node.values:
                if isinstance(part, ast.FormattedValue):
                    result = result + self.text(part.value, depth + 1)
                else:
                    result = result + self.text(part, depth + 1)
            return result
        read = self.param_read(node, depth)
        if read is not None:
            return read
        if isinstance(node, ast.Call) and not node.args and self._node_name_call(node.func):
            return Text("~")  # the node's own name: its private namespace itself
        name = _binding_name(node)
        if name is not None and name not in self.active:
            values = self.scope.strings.get(name, [])
            self.active.add(name)
            try:
                if len(values) == 1:
                    return self.value(values[0], depth + 1)
                if isinstance(node, ast.Name) and (given := self.argument(node, depth)):
                    return given
            finally:
                self.active.discard(name)
        return Text.unknown(_unparse(node))

    def _node_name_call(self, callee: ast.expr) -> bool:
        """``rospy.get_name()`` or an rclpy node's ``self.get_name()``."""
        if self.qualified(callee) == "rospy.get_name":
            return True
        return (
            isinstance(callee, ast.Attribute)
            and callee.attr == "get_name"
            and isinstance(callee.value, ast.Name)
            and callee.value.id == "self"
        )

    def param_read(self, node: ast.expr, depth: int) -> ParamRef | None:
        """``rospy.get_param(name[, default])``; rclpy's ``declare_parameter(name[,
        value])`` and ``get_parameter(name)``, through ``.value`` or
        ``.get_parameter_value().string_value``."""
        while isinstance(node, ast.Attribute) and node.attr in _VALUE_ATTRIBUTES:
            node = node.value
            getter = node.func if isinstance(node, ast.Call) else None
            if isinstance(getter, ast.Attribute) and getter.attr == "get_parameter_value":
                node = getter.value
        if not isinstance(node, ast.Call) or not node.args:
            return None
        callee = self.qualified(node.func)
        method = node.func.attr if isinstance(node.func, ast.Attribute) else None
        if callee != "rospy.get_param" and method not in ("declare_parameter", "get_parameter"):
            return None
        name = self.text(node.args[0], depth + 1)
        given = node.args[1] if len(node.args) > 1 and method != "get_parameter" else None
        if given is None:
            given = next((k.value for k in node.keywords if k.arg in ("default", "value")), None)
        default = self.text(given, depth + 1) if given is not None else None
        return ParamRef(name, default.value if default is not None and default.static else None)

    def type_name(self, node: ast.expr | None, role: Role, ros2: bool = False) -> str | None:
        """The ROS type a class names (ROS 2's with its ``msg``/``srv``/``action`` part)."""
        if node is None:
            return None
        full = self.qualified(node)
        if full is None:
            return None
        parts = full.split(".")
        if len(parts) >= 3 and parts[-2] in ("msg", "srv", "action"):
            name = "/".join(parts[-3:] if ros2 else [parts[-3], parts[-1]])
        else:
            name = parts[-1]
        is_action = role in (Role.ACTION_SERVERS, Role.ACTION_CLIENTS)
        return action_type(name) if is_action else name

    def node_name(self, call: ast.Call) -> Text | None:
        """The name an rclpy node is built with: ``Node("talker")``,
        ``super().__init__("talker")`` in a class derived from it, ``rclpy.create_node``."""
        callee = self.qualified(call.func)
        is_super = (
            isinstance(call.func, ast.Attribute)
            and call.func.attr == "__init__"
            and isinstance(call.func.value, ast.Call)
            and _dotted(call.func.value.func) == "super"
        )
        if callee not in _RCLPY_NODES and not is_super:
            return None
        keywords = {k.arg: k.value for k in call.keywords if k.arg}
        name = call.args[0] if call.args else keywords.get("node_name")
        return None if name is None else self.text(name)

    def entry(self, call: ast.Call) -> Entry | None:
        callee = self.qualified(call.func)
        known = _CALLS.get(callee or "")
        keywords = {k.arg: k.value for k in call.keywords if k.arg}
        if known is None:
            return self.rclpy_entry(call, callee, keywords)
        role, keyword = known
        name_node = (
            call.args[0] if call.args else keywords.get("name") or keywords.get("param_name")
        )
        second = call.args[1] if len(call.args) > 1 else keywords.get(keyword)
        return self.make(call, role, name_node, second)

    def undeclared_entry(self, call: ast.Call) -> Entry | None:
        """rclpy's ``Node(..., allow_undeclared_parameters=True)`` (or
        ``automatically_declare_parameters_from_overrides=True``), a subclass's ``super()``
        call included: the node takes parameters it never declares."""
        for keyword in call.keywords:
            value = keyword.value
            if (
                keyword.arg in UNDECLARED_PARAMETERS
                and isinstance(value, ast.Constant)
                and value.value
            ):
                location = Location(self.path, call.lineno, call.col_offset + 1)
                return Entry(Role.PARAMS, ANY_PARAMETER, location, static=False)
        return None

    def lifecycle_at(self, nodes: list[ast.AST]) -> Location | None:
        """Where the code builds an rclpy lifecycle node, or a class deriving from one."""
        for part in nodes:
            for node in ast.walk(part):
                classes = node.bases if isinstance(node, ast.ClassDef) else []
                built = [node.func] if isinstance(node, ast.Call) else []
                if any(self.qualified(c) in _RCLPY_LIFECYCLE_NODES for c in (*classes, *built)):
                    assert isinstance(node, ast.ClassDef | ast.Call)
                    return Location(self.path, node.lineno, node.col_offset + 1)
        return None

    def reconfigure_entry(self, call: ast.Call) -> Entry | None:
        """``dynamic_reconfigure.server.Server(Config, callback, namespace="~")`` reads its
        config's parameters in that namespace."""
        if self.qualified(call.func) != "dynamic_reconfigure.server.Server":
            return None
        given = {k.arg: k.value for k in call.keywords if k.arg}.get("namespace")
        if given is None and len(call.args) > 2:
            given = call.args[2]
        name = Text("~") if given is None else self.text(given)
        location = Location(self.path, call.lineno, call.col_offset + 1)
        return Entry(Role.PARAMS, name.value, location, default=RECONFIGURED, static=name.static)

    def tf_entries(self, call: ast.Call) -> list[Entry]:
        """The ``/tf`` (``/tf_static``) uses of a tf broadcaster's or listener's construction."""
        callee = self.qualified(call.func) or ""
        head, _, last = callee.rpartition(".")
        if last not in tf.CLASSES or head.split(".")[0] not in ("tf", "tf2_ros"):
            return []
        role, topics = tf.CLASSES[last]
        rclpy = any(module.startswith("rclpy") for module in self.scope.imports.values())
        message = tf.ROS2_MESSAGE if rclpy else tf.MESSAGE
        location = Location(self.path, call.lineno, call.col_offset + 1)
        return [
            Entry(role, t, location, type=message, boundary=tf.is_boundary(role, t)) for t in topics
        ]

    def rclpy_entry(
        self, call: ast.Call, callee: str | None, keywords: dict[str, ast.expr]
    ) -> Entry | None:
        """``node.create_publisher(T, "name", qos)`` and the like, ``ActionServer(node, T,
        "name", ...)``, ``node.declare_parameter("name", default)``,
        ``wait_for_message(T, node, "name")``."""
        arguments = call.args
        if callee == _RCLPY_WAIT:
            name = arguments[2] if len(arguments) > 2 else keywords.get("topic")
            kind = arguments[0] if arguments else keywords.get("msg_type")
            return self.make(call, Role.SUBSCRIBES, name, kind, ros2=True)
        if callee in _RCLPY_ACTIONS:
            role = _RCLPY_ACTIONS[callee]
            name = arguments[2] if len(arguments) > 2 else keywords.get("action_name")
            kind = arguments[1] if len(arguments) > 1 else keywords.get("action_type")
            return self.make(call, role, name, kind, ros2=True)
        if not isinstance(call.func, ast.Attribute) or call.func.attr not in _RCLPY_METHODS:
            return None
        role, position = _RCLPY_METHODS[call.func.attr]
        if role is Role.PARAMS:
            name = arguments[0] if arguments else keywords.get("name")
            value = arguments[1] if len(arguments) > 1 else keywords.get("value")
            return self.make(call, role, name, value, ros2=True)
        name_keyword = "topic" if role in (Role.PUBLISHES, Role.SUBSCRIBES) else "srv_name"
        type_keyword = "msg_type" if role in (Role.PUBLISHES, Role.SUBSCRIBES) else "srv_type"
        name = arguments[position] if len(arguments) > position else keywords.get(name_keyword)
        kind = arguments[0] if arguments else keywords.get(type_keyword)
        return self.make(call, role, name, kind, ros2=True)

    def make(
        self,
        call: ast.Call,
        role: Role,
        name_node: ast.expr | None,
        second: ast.expr | None,
        ros2: bool = False,
    ) -> Entry | None:
        """The entry of ``call``: ``second`` is the type, or a parameter's default."""
        if name_node is None:
            return None
        location = Location(self.path, call.lineno, call.col_offset + 1)
        value = self.value(name_node)
        if isinstance(value, ParamRef) and value.name.static and role is not Role.PARAMS:
            return Entry(
                role,
                Text.unknown(value.name.value).value,
                location,
                type=self.type_name(second, role, ros2),
                default=value.default,
                static=False,
                named_by=NamedBy(value.name.value),
            )
        name = value if isinstance(value, Text) else Text.unknown(_unparse(name_node))
        if not name.static:
            self.sink.warning(
                "interface-symbolic-name",
                f"{role} name not known statically: {name.value}",
                location,
            )
        if role is Role.PARAMS:
            return Entry(role, name.value, location, default=_default(second), static=name.static)
        type_name = self.type_name(second, role, ros2)
        if type_name is None:
            self.sink.note(
                "interface-unknown-type", f"{role} type not known: {name.value}", location
            )
        return Entry(role, name.value, location, type=type_name, static=name.static)


def _unparse(node: ast.expr) -> str:
    """``node`` as written (``ast.unparse`` recurses: a deeper one is elided)."""
    try:
        return ast.unparse(node)
    except RecursionError:
        return "…"


def _default(node: ast.expr | None) -> Default | None:
    if node is None:
        return None
    try:
        value = ast.literal_eval(node)
    except (ValueError, SyntaxError, TypeError, RecursionError):
        return Expression(_unparse(node))
    if isinstance(value, bool | int | float | str):
        return value
    return Expression(_unparse(node))


def extract(path: str, sink: DiagnosticSink, files: SourceReader | None = None) -> list[Entry]:
    """The interface of the Python script at ``path`` (empty when it cannot be parsed)."""
    return extract_node(path, sink, files).entries


def extract_node(
    path: str,
    sink: DiagnosticSink,
    files: SourceReader | None = None,
    roots: Sequence[str] = (),
) -> Extracted:
    """:func:`extract`, with the name an rclpy node gives itself (ROS 2); with the modules
    of the package below ``roots`` that the script imports
    (:mod:`~rosvar.workspace.interfaces.python_modules`)."""
    reader = files or SourceReader(sink=sink)

    def parse(file: str) -> ast.Module | None:
        return _parse(file, sink, reader)

    tree = parse(path)
    if tree is None:
        return Extracted([])
    parts: list[tuple[str, ast.Module, list[ast.AST]]] = [(path, tree, [tree])]
    if roots:
        for module in python_modules.followed(tree, path, roots, parse):
            parts.append((module.path, module.tree, module.parts))
    entries: list[Entry] = []
    names: set[str] = set()
    program = _Program()
    read: list[tuple[_Reader, list[ast.Call]]] = []
    for file, module_tree, nodes in parts:
        module_reader = _Reader(file, module_tree, sink, program)
        calls = sorted(
            {id(c): c for n in nodes for c in ast.walk(n) if isinstance(c, ast.Call)}.values(),
            key=lambda node: (node.lineno, node.col_offset),
        )
        read.append((module_reader, calls))
        for call in calls:
            callee = call.func.id if isinstance(call.func, ast.Name) else None
            if isinstance(call.func, ast.Attribute):
                callee = call.func.attr
            if callee is not None:
                program.calls.setdefault(callee, []).append((module_reader, call))
    for module_reader, calls in read:
        for call in calls:
            name = module_reader.node_name(call)
            if name is not None and name.static:
                names.add(name.value)
        for call in calls:
            entries.extend(module_reader.tf_entries(call))
            if (server := module_reader.reconfigure_entry(call)) is not None:
                entries.append(server)
            if (undeclared := module_reader.undeclared_entry(call)) is not None:
                entries.append(undeclared)
            if (entry := module_reader.entry(call)) is not None:
                entries.append(entry)
    for (_file, _tree, nodes), (module_reader, _calls) in zip(parts, read, strict=True):
        if (lifecycle := module_reader.lifecycle_at(nodes)) is not None:
            entries = with_lifecycle(entries, lifecycle)
            break
    return Extracted(entries, names.pop() if len(names) == 1 else None)


def _parse(path: str, sink: DiagnosticSink, files: SourceReader) -> ast.Module | None:
    """The module at ``path``, Python 2 rewritten where needed; None with a diagnostic when
    it cannot be read or parsed."""
    source = files.text(path)
    if source is None:
        return None
    try:
        tree, rewritten = python2.parse(source, path)
    except (SyntaxError, ValueError, RecursionError, MemoryError) as error:
        line = getattr(error, "lineno", None) or 1
        sink.warning(
            "interface-unparsable", f"cannot parse the script: {error}", Location(path, line)
        )
        return None
    if rewritten:
        sink.note(
            "interface-python2",
            f"read as Python 2: {rewritten} lines rewritten to parse",
            Location(path),
        )
    return tree
