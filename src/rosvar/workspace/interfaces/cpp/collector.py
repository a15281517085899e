"""The recognised ROS API calls of the reached functions, turned into interface entries.

Each call, construction or member initialiser is matched against :mod:`apis`; its name
argument is evaluated (:class:`Evaluator`) within the node handle it is called on, its type
read from the template argument or the callback's parameter.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from tree_sitter import Node

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.workspace.interfaces import tf
from rosvar.workspace.interfaces.cpp import apis, param_defaults, syntax
from rosvar.workspace.interfaces.cpp.evaluator import CallSite, Evaluator, Handle
from rosvar.workspace.interfaces.cpp.unit import Function, Unit
from rosvar.workspace.interfaces.model import (
    ANY_PARAMETER,
    RECONFIGURED,
    UNDECLARED_PARAMETERS,
    Default,
    Entry,
    Expression,
    NamedBy,
    Role,
)
from rosvar.workspace.interfaces.values import ParamRef, Text, action_type

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
    ros2: bool = False
    """A ROS 2 package: a node has one namespace, so whatever a call names the node by is it
    (``message_filters::Subscriber<T> sub(this, "image")``)."""
    lifecycle: Location | None = None
    """Where a lifecycle node is built (a ``LifecycleNode`` base's initializer,
    ``rclcpp_lifecycle::LifecycleNode::make_shared``): the node has the lifecycle interface."""

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
        """The entries of one use: one per value its name takes at the call sites of the
        function it is in (a wrapper's), placed at the call that gives the name."""
        if name_node is None:
            return
        namespace = handle.namespace if handle is not None else Text("")
        for value, chain in self.evaluator.alternatives(name_node, function):
            place = chain[-1].at if chain else at
            file = chain[-1].caller.file if chain else function.file
            location = Location(file, place.start_point[0] + 1, place.start_point[1] + 1)
            kind = self._instantiated(type_name, role, function, chain)
            if isinstance(value, ParamRef) and value.name.static and role is not Role.PARAMS:
                named = NamedBy(value.name.value, namespace.value)
                name = Text.unknown(value.name.value).within(namespace)
                self.entries.append(
                    Entry(
                        role,
                        name.value,
                        location,
                        type=kind,
                        default=value.default,
                        static=False,
                        named_by=named,
                    )
                )
                continue
            written = value if isinstance(value, Text) else Text.unknown(syntax.text(name_node))
            self._entry(role, written.within(namespace), location, kind, default)

    def _entry(
        self,
        role: Role,
        name: Text,
        location: Location,
        type_name: str | None = None,
        default: Default | None = None,
        boundary: bool = False,
    ) -> None:
        if not name.static:
            self.sink.warning(
                "interface-symbolic-name",
                f"{role} name not known statically: {name.value}",
                location,
            )
        if type_name is None and role is not Role.PARAMS:
            self.sink.note(
                "interface-unknown-type", f"{role} type not known: {name.value}", location
            )
        self.entries.append(
            Entry(
                role,
                name.value,
                location,
                type=type_name,
                default=default,
                static=name.static,
                boundary=boundary,
            )
        )

    def _instantiated(
        self, type_name: str | None, role: Role, function: Function, chain: tuple[CallSite, ...]
    ) -> str | None:
        """``type_name``, or, when it is a template parameter of ``function`` (or of its
        class: ``ServiceT`` of ``ServiceClient<ServiceT>``), the type the construction or
        call that gives the name instantiates it with (every one, when they agree)."""
        if type_name is None or "/" in type_name or type_name not in function.templates:
            return type_name
        index = function.templates.index(type_name)
        targets = (function.name, function.owner)
        sites = [site for site in chain if site.name in targets]
        if not sites:
            owner = self.unit.functions.get(function.owner or "", [])
            for target in (function, *(f for f in owner if f.owner == function.owner)):
                sites.extend(self.evaluator.sites(target))
        found = {
            self.unit.message_type(site.templates[index])
            for site in sites
            if index < len(site.templates)
        }
        if len(found) != 1:
            return None
        message = found.pop()
        actions = (Role.ACTION_SERVERS, Role.ACTION_CLIENTS)
        return action_type(message) if message is not None and role in actions else message

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
                    if syntax.last(name) == "LifecycleNode":
                        self._lifecycle(function, node)
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
        if apis.RCLCPP_LIFECYCLE_NODE.search(compact):
            self._node_name(arguments, function)
            self._lifecycle(function, at)
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
        elif base == "ControllerManager" and arguments and not self.ros2:
            # ROS 2's (ros2_control_node) is a node whose services its own code makes
            self._controller_manager(arguments[1:], function, at)
        elif base in tf.CLASSES and re.search(r"\btf2?(_ros)?::", compact):
            self._tf(base, Location(function.file, at.start_point[0] + 1, at.start_point[1] + 1))
        elif base == "Server" and "dynamic_reconfigure::" in compact:
            self._reconfigure(
                handle, Location(function.file, at.start_point[0] + 1, at.start_point[1] + 1)
            )

    def _reconfigure(self, handle: Handle | None, location: Location) -> None:
        """A dynamic_reconfigure server reads its config's parameters in its node handle's
        namespace (``ros::NodeHandle("~")`` by default)."""
        namespace = Text("~") if handle is None else handle.namespace
        self._entry(Role.PARAMS, namespace, location, default=RECONFIGURED)

    def _tf(self, base: str, location: Location) -> None:
        """tf's broadcasters publish ``/tf`` (the static one ``/tf_static``); a listener
        subscribes both (:mod:`rosvar.workspace.interfaces.tf`)."""
        role, topics = tf.CLASSES[base]
        message = tf.ROS2_MESSAGE if self.ros2 else tf.MESSAGE
        for topic in topics:
            self._entry(role, Text(topic), location, message, boundary=tf.is_boundary(role, topic))

    def members(self, owner: str) -> None:
        """The members a class's construction builds without arguments that make a use
        (``tf::TransformBroadcaster br_;``): those no initialiser of the unit constructs."""
        for name, (declaration, file) in self.unit.members.get(owner, {}).items():
            type_node = declaration.child_by_field_name("type")
            if type_node is None or name in self.unit.writes or "*" in syntax.text(declaration):
                continue
            compact = syntax.text(type_node).replace(" ", "")
            base = syntax.last(compact.split("<")[0])
            line, column = declaration.start_point
            if base in tf.CLASSES and re.search(r"\btf2?(_ros)?::", compact):
                self._tf(base, Location(file, line + 1, column + 1))
            elif base == "Server" and "dynamic_reconfigure::" in compact:
                self._reconfigure(None, Location(file, line + 1, column + 1))

    def _node_name(self, arguments: list[Node], function: Function) -> None:
        if arguments:
            self.node_names.append(self.evaluator.name(arguments[0], function))

    def _lifecycle(self, function: Function, at: Node) -> None:
        if self.lifecycle is None:
            self.lifecycle = Location(function.file, at.start_point[0] + 1, at.start_point[1] + 1)

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
            if self.ros2 and not isinstance(first, Text | ParamRef):
                return Handle(Text(""), rclcpp=True), arguments[1:]  # the node, however named
        return None, arguments

    def _undeclared(
        self, callee: Node, arguments: list[Node], function: Function, at: Node
    ) -> None:
        """``NodeOptions().allow_undeclared_parameters(true)`` (or
        ``automatically_declare_parameters_from_overrides(true)``): the node takes parameters
        it never declares; ``get_node_parameters_interface()``: other code may declare them
        (:data:`~.apis.RCLCPP_PARAMETERS_HANDED`)."""
        field_ = callee.child_by_field_name("field")
        called = field_ if callee.type == "field_expression" else callee
        name = None if called is None else syntax.last(syntax.text(called))
        handed = name in apis.RCLCPP_PARAMETERS_HANDED and self.ros2
        allowed = name in UNDECLARED_PARAMETERS and bool(arguments)
        if handed or (allowed and syntax.text(arguments[0]) == "true"):
            location = Location(function.file, at.start_point[0] + 1, at.start_point[1] + 1)
            self.entries.append(Entry(Role.PARAMS, ANY_PARAMETER, location, static=False))

    def _call(self, node: Node, function: Function) -> None:
        callee = node.child_by_field_name("function")
        if callee is None:
            return
        arguments = syntax.arguments(node)
        if self._own(callee, function):
            return  # the project's own function of an API's name (a wrapper): read inside
        self._undeclared(callee, arguments, function, node)
        if callee.type != "field_expression":
            name = syntax.text(callee).replace(" ", "")
            bare = name.split("<")[0]
            if callee.type == "qualified_identifier" and _node_method(bare):
                bare = syntax.last(bare)  # rclcpp::Node::create_publisher<T>(...) in a wrapper
            if bare in apis.WAIT_FOR_MESSAGE:
                self._wait_for_message(bare, callee, arguments, function, node)
            elif name in apis.FREE_PARAM_READS and arguments:
                self._param(None, arguments, function, node, name.endswith("param"))
            elif bare in apis.RCLCPP_FREE_CALLS:
                self._rclcpp_free(
                    bare, syntax.template_arguments(callee), arguments, function, node
                )
            elif "::" not in bare and self._rclcpp(bare, callee, arguments, function, node):
                pass  # a method of the rclcpp node the function belongs to
            elif apis.RCLCPP_NODE.search(name):
                self._node_name(arguments, function)
            elif apis.RCLCPP_LIFECYCLE_NODE.search(name):
                self._node_name(arguments, function)
                self._lifecycle(function, node)
            elif syntax.last(bare) in apis.MAKERS:
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

    def _own(self, callee: Node, function: Function) -> bool:
        """Whether a call of an API's name (``create_publisher``) is of a function the
        project defines: a method of the caller's class (or of the object's class) or a
        free function of the unit."""
        target = (
            callee.child_by_field_name("argument") if callee.type == "field_expression" else None
        )
        name_node = callee.child_by_field_name("field") if target is not None else callee
        if name_node is None or name_node.type not in (
            "identifier",
            "field_identifier",
            "template_function",
            "template_method",
        ):
            return False
        name = syntax.last(syntax.text(name_node).split("<")[0].strip())
        if name not in apis.API_NAMES:
            return False
        owners = {f.owner for f in self.unit.functions.get(name, ())}
        if target is None or target.type == "this":
            return function.owner in owners or (target is None and None in owners)
        declared = self.unit.receiver_type(target, function)
        return declared is not None and bool(owners & set(re.findall(r"\w+", declared)))

    def _wait_for_message(
        self, name: str, callee: Node, arguments: list[Node], function: Function, at: Node
    ) -> None:
        """``ros::topic::waitForMessage<T>("topic", nh)`` and rclcpp's
        ``wait_for_message(msg, node, "topic")``: a subscription while it waits."""
        templates = syntax.template_arguments(callee)
        if name.startswith("rclcpp") and len(arguments) >= 3:
            message = self._first_type(templates)
            if message is None and arguments[0].type == "identifier":
                variable = self.evaluator.local(syntax.text(arguments[0]), function)
                message = self.unit.message_type(variable.type) if variable is not None else None
            self.add(Role.SUBSCRIBES, None, arguments[2], function, at, message)
        elif not name.startswith("rclcpp") and arguments:
            handle = self.evaluator.evaluate(arguments[1], function) if len(arguments) > 1 else None
            within = handle if isinstance(handle, Handle) else None
            self.add(
                Role.SUBSCRIBES, within, arguments[0], function, at, self._first_type(templates)
            )

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
        if default is None and len(arguments) >= 2 and param_defaults.dropped(at):
            default = Expression(syntax.text(arguments[1]))  # it keeps the value it had
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


def _node_method(qualified: str) -> bool:
    """``rclcpp::Node::create_publisher`` (a wrapper calling its base class's method)."""
    parts = qualified.split("::")
    return (
        len(parts) >= 2
        and parts[-2] in ("Node", "LifecycleNode")
        and parts[-1] in apis.RCLCPP_CALLS
    )
