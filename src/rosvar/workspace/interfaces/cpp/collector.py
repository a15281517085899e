"""The recognised ROS API calls of the reached functions, turned into interface entries.

Each call, construction or member initialiser is matched against :mod:`apis`; its name
argument is evaluated (:class:`Evaluator`) within the node handle it is called on, its type
read from the template argument or the callback's parameter.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from tree_sitter import Node

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.workspace.interfaces.cpp import apis, param_defaults, syntax
from rosvar.workspace.interfaces.cpp.evaluator import Evaluator, Handle
from rosvar.workspace.interfaces.cpp.unit import Function, Unit
from rosvar.workspace.interfaces.model import Default, Entry, Expression, Role
from rosvar.workspace.interfaces.values import Text, action_type

_NULLS = frozenset({"NULL", "nullptr", "0"})


@dataclass
class Collector:
    """Turns the recognised API calls of the reached functions into entries."""

    unit: Unit
    evaluator: Evaluator
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
        name = value if isinstance(value, Text) else Text.unknown(syntax.text(name_node))
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
                    self._construction(
                        syntax.text(type_node), syntax.arguments(node), function, node
                    )
            elif node.type == "field_initializer":
                name = syntax.text(node.named_children[0])
                if syntax.last(name) in (
                    "Node",
                    "LifecycleNode",
                ):  # the base class: the node's name
                    self._node_name(syntax.arguments(node), function)
                self._construction(
                    self.unit.fields.get(name, ""), syntax.arguments(node), function, node
                )
            else:
                for _, variable in syntax.declared(node):
                    if variable.arguments is not None:
                        self._construction(variable.type, variable.arguments, function, node)

    def _construction(
        self, type_text: str, arguments: list[Node], function: Function, at: Node
    ) -> None:
        if len(arguments) == 1 and syntax.text(arguments[0]) in _NULLS:
            return  # a pointer member initialised to null constructs nothing
        compact = self.unit.unaliased(type_text).replace(" ", "")
        if apis.RCLCPP_NODE.search(compact):
            self._node_name(arguments, function)
            return
        base = syntax.last(compact.split("<")[0])
        templates = syntax.template_arguments_text(compact)
        message = self.unit.message_type(templates[0]) if templates else None
        handle, rest = self._split_handle(arguments, function)
        if base in apis.ACTION_CLASSES and "actionlib" in compact and rest:
            role = apis.ACTION_CLASSES[base]
            self.add(role, handle, rest[0], function, at, action_type(message) if message else None)
        elif base == "Subscriber" and "message_filters" in compact and handle is not None and rest:
            self.add(Role.SUBSCRIBES, handle, rest[0], function, at, message)
        elif base == "ControllerManager" and arguments:
            self._controller_manager(arguments[1:], function, at)

    def _node_name(self, arguments: list[Node], function: Function) -> None:
        if arguments:
            self.node_names.append(self.evaluator.name(arguments[0], function))

    def _controller_manager(self, arguments: list[Node], function: Function, at: Node) -> None:
        """``controller_manager::ControllerManager cm(&hw, nh)`` serves its services below
        ``controller_manager`` in ``nh``'s namespace (``ros::NodeHandle()`` by default)."""
        handle = self.evaluator.evaluate(arguments[0], function) if arguments else Handle(Text(""))
        if not isinstance(handle, Handle):
            handle = Handle(Text.unknown(syntax.text(arguments[0])))
        location = Location(function.file, at.start_point[0] + 1, at.start_point[1] + 1)
        for service, kind in apis.CONTROLLER_MANAGER_SERVICES:
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
        arguments = syntax.arguments(node)
        if callee.type != "field_expression":
            name = syntax.text(callee).replace(" ", "")
            bare = name.split("<")[0]
            if name in apis.FREE_PARAM_READS and arguments:
                self._param(None, arguments, function, node, name.endswith("param"))
            elif bare in apis.RCLCPP_FREE_CALLS:
                self._rclcpp_free(
                    bare, syntax.template_arguments(callee), arguments, function, node
                )
            elif "::" not in bare and self._rclcpp(bare, callee, arguments, function, node):
                pass  # a method of the rclcpp node the function belongs to
            elif apis.RCLCPP_NODE.search(name):
                self._node_name(arguments, function)
            elif syntax.last(bare) in ("make_shared", "make_unique"):
                templates = syntax.template_arguments(callee)
                if templates:
                    self._construction(templates[0], arguments, function, node)
            return
        receiver = callee.child_by_field_name("argument")
        method_node = callee.child_by_field_name("field")
        if receiver is None or method_node is None:
            return
        method = syntax.text(method_node).split("<")[0].strip()
        if self._rclcpp(method, method_node, arguments, function, node):
            return
        templates = syntax.template_arguments(method_node)
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
        elif method in apis.PARAM_READS:
            self._param(value, arguments, function, node, method == "param")

    def _rclcpp(
        self, method: str, callee: Node, arguments: list[Node], function: Function, at: Node
    ) -> bool:
        """An rclcpp ``Node`` method (``create_publisher<T>("name", qos)``, a parameter's
        declaration or read); whether ``method`` is one."""
        if not arguments:
            return False
        if method in apis.RCLCPP_CALLS:
            message = self._first_type(syntax.template_arguments(callee))
            self.add(apis.RCLCPP_CALLS[method], None, arguments[0], function, at, message)
        elif method == apis.RCLCPP_DECLARE:
            default = (
                param_defaults.default(arguments[1], self.evaluator, function)
                if len(arguments) > 1
                else None
            )
            self.add(Role.PARAMS, None, arguments[0], function, at, default=default)
        elif method in apis.RCLCPP_READS:
            given = arguments[2] if method == "get_parameter_or" and len(arguments) > 2 else None
            default = param_defaults.default(given, self.evaluator, function)
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
        index = 4 if arguments and "node_base" in syntax.text(arguments[0]).lower() else 1
        if index >= len(arguments):
            return
        role = apis.RCLCPP_FREE_CALLS[name]
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
            (apis.ROS2_IMAGE, apis.ROS2_CAMERA_INFO)
            if handle.rclcpp
            else (apis.IMAGE, apis.CAMERA_INFO)
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
        type_text = self.unit.fields.get(syntax.text(receiver), "")
        variable = self.evaluator.local(syntax.text(receiver), function)
        if variable is not None:
            type_text = variable.type
        handle, rest = self._split_handle(arguments, function)
        if handle is None or not rest:
            return
        compact = type_text.replace(" ", "")
        if "message_filters" in compact:
            templates = syntax.template_arguments_text(compact)
            self.add(Role.SUBSCRIBES, handle, rest[0], function, at, self._first_type(templates))
        elif "SubscriberFilter" in compact:
            self.add(Role.SUBSCRIBES, handle, rest[0], function, at, apis.IMAGE)

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
            default = param_defaults.default(
                arguments[-1] if len(arguments) >= 2 else None, self.evaluator, function
            )
        elif (test := param_defaults.result_test(at)) is not None:
            default = Expression(syntax.text(test))  # the code decides what an unset one means
        elif (guard := param_defaults.guard_of(at, arguments[0])) is not None:
            default = Expression(syntax.text(guard))  # read only when set: if (nh.hasParam(x))
        elif len(arguments) >= 2 and arguments[1].type == "identifier":
            written = syntax.text(arguments[1])
            variable = self.evaluator.local(written, function)  # bool unreliable = false;
            init = self.unit.constants.get(written) if variable is None else variable.init
            if init is not None:
                default = param_defaults.default(init, self.evaluator, function)
        self.add(Role.PARAMS, handle, arguments[0], function, at, default=default)

    def _first_type(self, templates: list[str]) -> str | None:
        return self.unit.message_type(templates[0]) if templates else None

    def _callback_type(self, arguments: list[Node]) -> str | None:
        """The message type a callback takes: the first parameter of the function named."""
        for argument in arguments:
            for node in syntax.walk(
                argument, {"qualified_identifier", "identifier", "lambda_expression"}
            ):
                if node.type == "lambda_expression":
                    declarator = node.child_by_field_name("declarator")
                    parameters = (
                        declarator.child_by_field_name("parameters") if declarator else None
                    )
                    if parameters is not None and parameters.named_children:
                        return self.unit.message_type(
                            syntax.parameter_type(parameters.named_children[0])
                        )
                    continue
                for signature in self.unit.signatures.get(syntax.last(syntax.text(node)), []):
                    if signature:
                        return self.unit.message_type(signature[0])
        return None
