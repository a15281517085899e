"""Launch actions of Python launch files as the elements of their XML equivalents.

Each action class is described once, in the registry of actions
(:data:`rosvar.ros2.api.actions.ACTIONS`): the XML tag it is exposed as, and for each
constructor argument the attribute or children it becomes and how (a :class:`Slot`, with one
writer per slot here). ``Node(package='p', parameters=[{'rate': 10}],
remappings=[('a', 'b')])`` becomes ``<node pkg="p"><param name="rate" value="10"/>
<remap from="a" to="b"/></node>``, children in the order the arguments are written.
"""

from __future__ import annotations

import shlex
from collections.abc import Callable
from dataclasses import replace

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.frontends.entity import Entity
from rosvar.ros2.api.actions import ACTIONS, Action, Param, Slot
from rosvar.ros2.api.event_handlers import EVENT_HANDLERS, EventHandler
from rosvar.ros2.frontends.python import launch_time, written
from rosvar.ros2.frontends.python.calls import CALLS, Call
from rosvar.ros2.frontends.python.text import Text, Written, render, unknown
from rosvar.ros2.frontends.python.values import (
    Condition,
    Conditional,
    Description,
    Dynamic,
    Key,
    LaunchYaml,
    ParameterFile,
    ParameterValue,
    Unknown,
    Value,
    WrittenFile,
)
from rosvar.ros2.frontends.typed_text import Scalar, reads_as_other_value, typed_text


def set_attribute(call: Call, entity: Entity, name: str, value: Value) -> None:
    """A typed scalar as typed text (:mod:`rosvar.ros2.frontends.typed_text`), anything else as
    the text of its substitutions."""
    if value is None or isinstance(value, bool | int | float):
        entity.attributes[name] = typed_text(value)
        entity.typed = entity.typed | {name}
    else:
        entity.attributes[name] = render(call.text(value))


def _items(call: Call, value: Value, what: str) -> list[Value]:
    """The items of a list argument; anything else is reported and read as empty."""
    if isinstance(value, list | tuple):
        return list(value)
    if isinstance(value, dict):
        return [(name, item) for name, item in value.items()]
    if not isinstance(value, Unknown):
        call.not_followed(f"{what} given as {type(value).__name__}")
    return []


def _child(call: Call, parent: Entity, tag: str) -> Entity:
    child = Entity(tag, {}, call.location)
    parent.children.append(child)
    return child


def _write_attribute(call: Call, entity: Entity, param: Param, value: Value) -> None:
    set_attribute(call, entity, param.xml, value)


def _write_command_line(call: Call, entity: Entity, param: Param, value: Value) -> None:
    """Each item one word, as launch keeps it whatever its value: literal text quoted for
    the shell, also between substitutions (``[V('a'), ' tail']`` is one word)."""
    words = []
    for item in _items(call, value, param.python):
        text = call.text(item)
        literal = text.literal()
        quoted = (shlex.quote(p) if isinstance(p, str) else p for p in text.parts)
        words.append(shlex.quote(literal) if literal is not None else render(Text(tuple(quoted))))
    entity.attributes[param.xml] = " ".join(words)


def _write_parameters(call: Call, entity: Entity, param: Param, value: Value) -> None:
    for item in _items(call, value, param.python):
        if isinstance(item, Conditional):
            _conditional_parameters(call, entity, param, item)
        elif isinstance(item, LaunchYaml) and item.keys == ("/**", "ros__parameters"):
            set_attribute(call, _child(call, entity, param.xml), "from", item.path)
        elif isinstance(item, LaunchYaml):
            call.not_followed("parameters of a YAML file named at launch time (not its '/**')")
        elif isinstance(item, dict):
            _named_parameters(call, entity, param.xml, item)
        elif isinstance(item, WrittenFile) or (
            isinstance(item, ParameterFile) and isinstance(item.path, WrittenFile)
        ):
            _written_parameters(call, _child(call, entity, param.xml), item)
        elif isinstance(item, ParameterFile):
            child = _child(call, entity, param.xml)
            set_attribute(call, child, "from", item.path)
            if item.allow_substs is not None:
                set_attribute(call, child, "allow_substs", item.allow_substs)
        else:
            set_attribute(call, _child(call, entity, param.xml), "from", item)


def _written_parameters(call: Call, child: Entity, item: WrittenFile | ParameterFile) -> None:
    """A parameter file the launch file's Python writes: ``content``, its text (a tag of
    this frontend only), ``from``, what wrote it (:mod:`.written`)."""
    file = item if isinstance(item, WrittenFile) else item.path
    assert isinstance(file, WrittenFile)
    child.attributes["from"] = render(Text.of(file.label))
    child.attributes["content"] = render(written.text_of(file, Written.TEXT))
    if isinstance(item, ParameterFile) and item.allow_substs is not None:
        set_attribute(call, child, "allow_substs", item.allow_substs)


def _conditional_parameters(call: Call, entity: Entity, param: Param, item: Conditional) -> None:
    """The parameters of each branch, each under its test (``{} if c else read(f)``)."""
    tests = (launch_time.truth(item.test), launch_time.negated(item.test))
    for branch, test in zip((item.then, item.otherwise), tests, strict=True):
        start = len(entity.children)
        _write_parameters(call, entity, param, branch if isinstance(branch, list) else [branch])
        for child in entity.children[start:]:
            if "if" in child.attributes or "unless" in child.attributes:
                call.not_followed("parameters under nested 'if's on launch-time values")
                child.attributes.pop("unless", None)
                child.attributes["if"] = render(Text.of(unknown("nested condition")))
            else:
                child.attributes["if"] = render(launch_time.condition(test))


def _named_parameters(call: Call, parent: Entity, tag: str, values: dict[Key, Value]) -> None:
    """``{'a': {'b': 1}}`` as ``<param name="a"><param name="b" value="1"/></param>``."""
    for name, value in values.items():
        child = _child(call, parent, tag)
        set_attribute(call, child, "name", name)
        if isinstance(value, dict):
            _named_parameters(call, child, tag, value)
        elif isinstance(value, ParameterValue) and value.type_name is not None:
            set_attribute(call, child, "value", value.value)
            child.attributes["type"] = value.type_name
        else:  # launch keeps a ParameterValue's Python value as launch_ros keeps a dict's
            _parameter_value(
                call, child, value.value if isinstance(value, ParameterValue) else value
            )


def _parameter_value(call: Call, child: Entity, value: Value) -> None:
    """A parameter's value as launch_ros normalizes a dict's: a Python string, whatever it
    holds (a file's text over lines), stays that string (launch_ros dumps it as YAML and
    reads it back); only the text of substitutions is read by YAML rules. A list of ints
    and floats is a list of floats."""
    if isinstance(value, list | tuple) and all(
        isinstance(item, bool | int | float | str) for item in value
    ):
        items: list[Scalar] = [item for item in value if isinstance(item, Scalar)]
        numbers = [n for n in items if isinstance(n, int | float) and not isinstance(n, bool)]
        if len(numbers) == len(items) and any(isinstance(n, float) for n in numbers):
            items = [float(n) for n in numbers]
        child.attributes["value"] = typed_text(items)
        child.typed = child.typed | {"value"}
        return
    if isinstance(value, Conditional):  # a list chosen at launch time: its Python
        chosen = launch_time.source(value)  # expression, as a parameter's value
        value = value if chosen is None else Dynamic(chosen, None)
    set_attribute(call, child, "value", value)
    if isinstance(value, str) and reads_as_other_value(value, substitutions=False):
        child.attributes["type"] = "str"  # a literal stays a string, unlike XML's
    elif isinstance(value, Dynamic) and value.kind is str:
        # a launch-time Python string (`.perform(context)`, `str(x)`) too: launch_ros
        # reads by YAML rules only the substitutions it performs itself
        child.attributes["type"] = "str"


def _write_pairs(call: Call, entity: Entity, param: Param, value: Value) -> None:
    for item in _items(call, value, param.python):
        if isinstance(item, list | tuple) and len(item) == 2:
            child = _child(call, entity, param.xml)
            set_attribute(call, child, "from", item[0])
            set_attribute(call, child, "to", item[1])
            if call.remaps is not None:
                call.remaps.give(item, entity, child)
        else:
            call.not_followed(f"an item of {param.python} that is not a pair")


def _write_named_values(call: Call, entity: Entity, param: Param, value: Value) -> None:
    for item in _items(call, value, param.python):
        if isinstance(item, list | tuple) and len(item) == 2:
            child = _child(call, entity, param.xml)
            set_attribute(call, child, "name", item[0])
            set_attribute(call, child, "value", item[1])
        else:
            call.not_followed(f"an item of {param.python} that is not a (name, value) pair")


def _write_values(call: Call, entity: Entity, param: Param, value: Value) -> None:
    for item in _items(call, value, param.python):
        set_attribute(call, _child(call, entity, param.xml), "value", item)


def _write_actions(call: Call, entity: Entity, param: Param, value: Value) -> None:
    add_actions(call, entity, value)


def _write_descriptions(call: Call, entity: Entity, param: Param, value: Value) -> None:
    """Composable node descriptions as children. A description the reading put under an
    ``if`` on a launch-time value carries it as its own ``if`` (launch_ros evaluates each
    description's condition); the unconditioned group that gathers the branches' values is
    their descriptions in order, since a container holds no group."""
    holder = Entity(entity.tag, {}, call.location)
    add_actions(call, holder, value)
    pending = list(reversed(holder.children))
    while pending:
        child = pending.pop()
        if child.tag != "group":
            entity.children.append(child)
        elif set(child.attributes) <= {"scoped"}:
            pending.extend(reversed(child.children))
        else:
            call.not_followed("a group of composable node descriptions")


WRITERS: dict[Slot, Callable[[Call, Entity, Param, Value], None]] = {
    Slot.ATTRIBUTE: _write_attribute,
    Slot.COMMAND_LINE: _write_command_line,
    Slot.PARAMETERS: _write_parameters,
    Slot.PAIRS: _write_pairs,
    Slot.NAMED_VALUES: _write_named_values,
    Slot.VALUES: _write_values,
    Slot.ACTIONS: _write_actions,
    Slot.DESCRIPTIONS: _write_descriptions,
}


def add_actions(call: Call, parent: Entity, actions: Value) -> None:
    """Actions as children of ``parent``; a nested LaunchDescription adds its own."""
    for action in _items(call, actions, "actions"):
        if isinstance(action, Entity):
            parent.children.append(action)
        elif isinstance(action, Description):
            parent.children.extend(action.root.children)
        elif isinstance(action, list | tuple):
            add_actions(call, parent, action)
        elif not isinstance(action, Unknown):  # an Unknown was reported where it arose
            call.not_followed(f"a {type(action).__name__} used as an action")


def _set_condition(call: Call, entity: Entity, condition: Value) -> None:
    if isinstance(condition, Condition):
        entity.attributes[condition.attribute] = render(condition.text)
    elif isinstance(condition, Unknown):
        set_attribute(call, entity, "if", condition)
    elif condition is not None:
        call.not_followed(f"condition={type(condition).__name__}")


def _action(spec: Action) -> Callable[[Call], Value]:
    def build(call: Call) -> Value:
        branching = _branching(spec, call)
        if branching is not None:
            return _branches(build, *branching)
        entity = Entity(spec.tag, {}, call.location)
        given: list[tuple[Param, Value]] = []
        by_name = {param.python: param for param in spec.params}
        renamed = {param.before: param for param in spec.params if param.before}
        for param, value in zip(spec.params, call.args, strict=False):
            given.append((param, value))
        for name, value in call.kwargs.items():
            if name == "condition":
                _set_condition(call, entity, value)
            elif name in by_name:
                given.append((by_name[name], value))
            elif name in renamed:
                param = renamed[name]
                call.sink.warning(
                    "python-launch-renamed",
                    f"{call.name}() argument '{name}' is launch_ros' name before Galactic, "
                    f"which later releases refuse: read as '{param.python}'",
                    call.location,
                )
                given.append((param, value))
            else:
                call.sink.note(
                    "python-launch-argument",
                    f"{call.name}() argument '{name}' has no XML equivalent; not analysed",
                    call.location,
                )
        if len(call.args) > len(spec.params):
            call.not_followed(f"extra positional arguments of {call.name}()")
        for param, value in given:
            if param.xml == "output" and isinstance(value, dict):  # launch's output per stream
                call.sink.note(
                    "python-launch-argument",
                    f"{call.name}() argument 'output' as a dict (one per stream) has no XML "
                    "equivalent; not analysed",
                    call.location,
                )
            elif value is not None:  # None is each argument's default: nothing to write
                WRITERS[param.slot](call, entity, param, value)
        return entity

    return build


def _branching(spec: Action, call: Call) -> tuple[Call, Conditional, Call, Call] | None:
    """An argument given a value that differs by the branches of an ``if`` on a launch-time
    value (an attribute, a whole list of arguments or parameters): the value, and the call
    as each branch makes it."""
    for index, value in enumerate(call.args[: len(spec.params)]):
        if isinstance(value, Conditional):
            args = (list(call.args), list(call.args))
            args[0][index], args[1][index] = value.then, value.otherwise
            return call, value, replace(call, args=args[0]), replace(call, args=args[1])
    names = {param.python for param in spec.params}
    for name, value in call.kwargs.items():
        if name in names and isinstance(value, Conditional):
            then = replace(call, kwargs={**call.kwargs, name: value.then})
            return call, value, then, replace(call, kwargs={**call.kwargs, name: value.otherwise})
    return None


def _branches(
    build: Callable[[Call], Value], call: Call, value: Conditional, then: Call, otherwise: Call
) -> Value:
    """The action each branch makes, each under its test (as if the action were written in
    both branches): a value chosen at launch time is only computed where it is chosen (a
    container's name where it is launched)."""
    groups: list[Value] = []
    tests = (launch_time.truth(value.test), launch_time.negated(value.test))
    for branch, test in zip((then, otherwise), tests, strict=True):
        condition = Condition("if", launch_time.condition(test))
        kwargs: dict[str, Value] = {"actions": [build(branch)], "scoped": False}
        groups.append(
            _group(Call("GroupAction", [], kwargs | {"condition": condition}, *_at(call)))
        )
    return _group(Call("GroupAction", [], {"actions": groups, "scoped": False}, *_at(call)))


def _at(call: Call) -> tuple[Location, DiagnosticSink]:
    return call.location, call.sink


def _group(call: Call) -> Value:
    return CALLS["launch", "GroupAction"](call)


def _launch_description(call: Call) -> Value:
    description = Description(Entity("launch", {}, call.location))
    add_actions(call, description.root, call.arg(0, "initial_entities", []))
    return description


def _emit_event(call: Call) -> Value:
    """``EmitEvent(event=Shutdown(...))`` is the ``<shutdown>`` action (the event's class
    shares the action's name, so it is built as that action), under the ``condition`` given;
    other events are read only by event handlers and the launch service."""
    event = call.arg(0, "event")
    if not isinstance(event, Entity) or event.tag != "shutdown":
        return call.not_followed(f"EmitEvent of a {type(event).__name__} (only Shutdown is)")
    event.location = call.location
    _set_condition(call, event, call.kwargs.get("condition"))
    return event


def _register_event_handler(call: Call) -> Value:
    """``RegisterEventHandler(handler)``: the handler's element (its tag and actions), under
    the ``condition`` given."""
    handler = call.arg(0, "event_handler")
    if not isinstance(handler, Entity) or handler.tag not in EVENT_HANDLERS.by_name:
        return call.not_followed(f"RegisterEventHandler of a {type(handler).__name__}")
    _set_condition(call, handler, call.kwargs.get("condition"))
    return handler


def _event_handler(spec: EventHandler) -> Callable[[Call], Value]:
    """An event handler as ``<tag target=...>`` holding its actions; ``target`` is where the
    action it waits for was written (the walk finds its processes by it)."""

    def build(call: Call) -> Value:
        entity = Entity(spec.tag, {}, call.location)
        if spec.target is not None:
            target = call.kwargs.get(spec.target)
            if isinstance(target, Entity):
                entity.attributes["target"] = str(target.location)
            elif target is not None:
                call.not_followed(f"{spec.target} of a {type(target).__name__}")
        for name in spec.actions:
            actions = call.kwargs.get(name)
            if actions is None:
                continue
            if isinstance(actions, Entity | Description | list | tuple):
                add_actions(call, entity, [actions])
            else:  # a function of the event: run by launch, never by rosvar
                call.not_followed(f"{name} given as a {type(actions).__name__}")
        return entity

    return build


for _key, _spec in ACTIONS.by_python.items():
    CALLS[_key] = _action(_spec)
CALLS["launch", "LaunchDescription"] = _launch_description
CALLS["launch", "EmitEvent"] = _emit_event
CALLS["launch", "RegisterEventHandler"] = _register_event_handler
for _key, _handler_spec in EVENT_HANDLERS.by_python.items():
    CALLS[_key] = _event_handler(_handler_spec)
