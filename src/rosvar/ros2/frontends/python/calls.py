"""The callables of the launch API the static reading knows, by qualified name.

A call is looked up by its package and its name (``launch_ros`` and ``Node`` for
``launch_ros.actions.Node`` as for ``launch_ros.actions.node.Node``), so that every import
path of a name finds it. Substitutions, conditions and description sources are built here
from the launch API's registries (:mod:`rosvar.ros2.api`), with the helpers that make text
(``PathJoinSubstitution``, ``os.path``); actions in
:mod:`~rosvar.ros2.frontends.python.actions`. A call to anything else is not followed.
"""

from __future__ import annotations

import functools
import posixpath
from collections.abc import Callable
from dataclasses import dataclass

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.frontends.entity import Entity
from rosvar.ros2.api.conditions import CONDITIONS
from rosvar.ros2.api.conditions import Condition as ConditionEntry
from rosvar.ros2.api.registry import python_name
from rosvar.ros2.api.sources import SOURCES
from rosvar.ros2.api.substitutions import SUBSTITUTIONS, Signature
from rosvar.ros2.api.unmodelled import UNMODELLED
from rosvar.ros2.frontends.python import launch_time, written
from rosvar.ros2.frontends.python.shared_remaps import SharedRemaps
from rosvar.ros2.frontends.python.text import (
    CONFIGURATION_EQUALS,
    EMPTY,
    NODE_NAME,
    PATH_JOIN,
    PATH_PART,
    PATH_PARTS,
    Sub,
    Text,
    Written,
    unknown,
)
from rosvar.ros2.frontends.python.values import (
    Condition,
    Conditional,
    Dynamic,
    FilePath,
    Module,
    ParameterFile,
    ParameterValue,
    Source,
    Unknown,
    Value,
    WrittenFile,
)
from rosvar.ros2.frontends.typed_text import typed_text

NOT_FOLLOWED = "python-not-followed"
"""Diagnostic code of every construct the static reading does not follow."""

_MISSING = Unknown("missing argument")
PATH_VALUED = frozenset(
    {"find-pkg-share", "find-pkg-prefix", "dirname", "filename", "find-exec", "exec-in-pkg"}
)
"""Substitutions whose value is an absolute path with no trailing ``/``."""


@dataclass(slots=True)
class Call:
    """One call of a known callable: its arguments as abstract values, and where it is."""

    name: str
    args: list[Value]
    kwargs: dict[str, Value]
    location: Location
    sink: DiagnosticSink
    remaps: SharedRemaps | None = None
    """The file's remaps by the pair objects they are made of (actions' calls only)."""

    def arg(self, index: int, keyword: str, default: Value = _MISSING) -> Value:
        """The argument given by position ``index`` or by ``keyword``."""
        if keyword in self.kwargs:
            return self.kwargs[keyword]
        if index < len(self.args):
            return self.args[index]
        if default is _MISSING:
            self.sink.warning(
                "python-launch-argument", f"{self.name}() without '{keyword}'", self.location
            )
        return default

    def not_followed(self, what: str) -> Unknown:
        self.sink.warning(NOT_FOLLOWED, f"{what} is not followed", self.location)
        return Unknown(what)

    def text(self, value: Value) -> Text:
        """``value`` as launch normalizes a substitution argument: texts concatenated."""
        if isinstance(value, Text):
            return value
        if isinstance(value, Dynamic):
            return launch_time.as_text(value)
        if isinstance(value, str):
            return Text.of(value)
        if isinstance(value, list | tuple):
            return Text.of(*(self.text(item) for item in value))
        if isinstance(value, Unknown):
            return Text.of(unknown(value.what))
        if isinstance(value, Source):
            return value.path
        if isinstance(value, FilePath):
            return path_text(value)
        if isinstance(value, WrittenFile):  # its name
            return written.text_of(value, Written.PATH)
        if isinstance(value, Conditional):  # the text of the branch taken
            then, otherwise = (self.text(value.then), self.text(value.otherwise))
            chosen = launch_time.chosen(
                value.test, launch_time.quoted(then), launch_time.quoted(otherwise), str
            )
            return launch_time.as_text(chosen)
        if isinstance(value, Entity) and value.tag == "group" and len(value.children) == 1:
            return self.text(value.children[0])  # an action put under an 'if': itself
        if isinstance(value, Entity) and value.tag == "node_container":  # a target's name
            return Text.of(Sub(NODE_NAME, (Text.of(str(value.location)),)))
        if value is None or isinstance(value, bool | int | float):
            return Text.of(typed_text(value))
        return Text.of(unknown(self.not_followed(f"{type(value).__name__} used as text").what))


def path_text(path: FilePath) -> Text:
    """The text of a ``pathlib`` path."""
    if path.head is None:
        return Text.of(path.tail or ".")
    return Text.of(path.head, "/", path.tail) if path.tail else path.head


Builder = Callable[[Call], Value]

CALLS: dict[tuple[str, str], Builder] = {}
"""Known callables by (package, name)."""

REASONS: dict[tuple[str, str], str] = {
    key: entry.why(key[1]) for key, entry in UNMODELLED.by_python.items()
}
"""Why a name of the launch API stays unknown, for its diagnostic."""


def _register(package: str, *names: str) -> Callable[[Builder], Builder]:
    def register(builder: Builder) -> Builder:
        for name in names:
            CALLS[package, name] = builder
        return builder

    return register


def join_path(head: Text, tail: Text) -> Text:
    """``os.path.join`` of two texts (an absolute ``tail`` replaces ``head``), as text where
    the boundary is known (a literal, or a substitution giving a path); else the join left
    to the interpreter, ``$(rosvar-path-join head tail)``: ``$(var dir)`` may end in ``/``,
    or be absolute, or empty."""
    first = tail.parts[0] if tail.parts else ""
    if not head.parts:
        return tail
    if isinstance(first, Sub):
        if first.name in PATH_VALUED:
            return tail
        return Text.of(Sub(PATH_JOIN, (head, tail)))
    if first.startswith("/"):
        return tail
    last = head.parts[-1]
    if isinstance(last, Sub) and last.name not in PATH_VALUED:
        return Text.of(Sub(PATH_JOIN, (head, tail)))
    separator = "" if isinstance(last, str) and last.endswith("/") else "/"
    return Text.of(head, separator, tail)


COMPARISONS = frozenset({"equals", "not-equals"})


def _substitution(name: str, signature: Signature) -> Builder:
    """A call of ``signature``, as ``$(name ...)`` of its arguments."""

    def build(call: Call) -> Value:
        if signature.variadic:
            return Text.of(Sub(name, tuple(call.text(arg) for arg in call.args)))
        args: list[Text] = []
        keywords = signature.arguments
        defaulted = len(keywords) - len(signature.defaults)
        for index, keyword in enumerate(keywords):
            required = index < len(keywords) - signature.optional
            default = signature.defaults[index - defaulted] if index >= defaulted else None
            value = call.arg(
                index, keyword, default if default is not None else (_MISSING if required else None)
            )
            if value is None and not required:
                break
            if keyword in signature.listed and isinstance(value, list | tuple):
                items = [call.text(item) for item in value]
                args.append(Text.of(*[part for item in items for part in (",", item)][1:]))
            else:
                args.append(call.text(value))
        if name in COMPARISONS:  # '' is the text [] there
            args = [arg if arg.parts else Text.of(Sub(EMPTY)) for arg in args]
        return Text.of(Sub(name, tuple(args)))

    return build


def _performed(builder: Builder) -> Builder:
    """A function giving the string a substitution gives (``get_package_share_directory``):
    a ``str`` at launch time, not a substitution object (``isinstance(p, str)`` holds)."""

    def build(call: Call) -> Value:
        made = builder(call)
        return launch_time.performed(made) if isinstance(made, Text) else made

    return build


for _substitution_entry in SUBSTITUTIONS:
    for _signature in _substitution_entry.signatures:
        _builder = _substitution(_substitution_entry.names[0], _signature)
        if _signature.function:
            _builder = _performed(_builder)
        CALLS[python_name(_signature.qualified)] = _builder


def _fold(operator: str, empty: str) -> Builder:
    """``AllSubstitution``/``AnySubstitution`` as nested ``$(and)``/``$(or)``, which read
    each operand as the same ``bool`` (jazzy's XML and YAML frontends fail on ``$(all)``
    and ``$(any)``: the Python class is the only way to them)."""

    def build(call: Call) -> Value:
        operands = [call.text(arg) for arg in call.args]
        if not operands:
            return Text.of(empty)
        result = Text.of(Sub(operator, (operands[-1], Text.of(empty))))
        for operand in reversed(operands[:-1]):
            result = Text.of(Sub(operator, (operand, result)))
        return result

    return build


CALLS["launch", "AllSubstitution"] = _fold("and", "true")
CALLS["launch", "AnySubstitution"] = _fold("or", "false")


@_register("launch", "PathSubstitution")
def _path(call: Call) -> Value:
    return call.text(call.arg(0, "path"))


@_register("launch", "TextSubstitution")
def _text(call: Call) -> Value:
    return call.text(call.arg(0, "text"))


@_register("launch", "PathJoinSubstitution")
def _path_join(call: Call) -> Value:
    parts = call.arg(0, "substitutions")
    result = Text.of()
    for part in parts if isinstance(parts, list | tuple) else [parts]:
        result = join_path(result, call.text(part))
    return result


@_register("os", "join")
def _os_path_join(call: Call) -> Value:
    """A Python string, whose text substitutions give where its parts are known at launch
    time only (a package's share directory)."""
    if all(isinstance(arg, str) for arg in call.args):
        return posixpath.join(*(str(arg) for arg in call.args))
    result = Text.of()
    for part in call.args:
        result = join_path(result, call.text(part))
    return launch_time.performed(result)


@_register("os", "dirname")
def _dirname(call: Call) -> Value:
    path = call.arg(0, "p")
    if isinstance(path, Dynamic) and path.text == Text.of(Sub("filename")):
        return launch_time.performed(Text.of(Sub("dirname")))
    return _path_part(call, path, "dirname")


@_register("os", "basename")
def _basename(call: Call) -> Value:
    return _path_part(call, call.arg(0, "p"), "basename")


def _path_part(call: Call, path: Value, part: str) -> Value:
    """``os.path.dirname`` (``basename``) of a path: computed where it is a Python string,
    else the part of the string it is at launch time (``$(rosvar-path-part)``)."""
    if isinstance(path, str):
        return PATH_PARTS[part](path)
    if isinstance(path, Dynamic) and path.kind is str:
        operands = (Text.of(part), launch_time.as_text(path))
        return launch_time.performed(Text.of(Sub(PATH_PART, operands)))
    return call.not_followed(f"os.path.{part}() of a {type(path).__name__}")


def _condition(condition: ConditionEntry) -> Builder:
    def build(call: Call) -> Value:
        if not condition.compares:
            return Condition(condition.attribute, call.text(call.arg(0, "predicate_expression")))
        name = call.text(call.arg(0, "launch_configuration_name"))
        expected = call.arg(1, "expected_value")
        operands = (name,) if expected is None else (name, call.text(expected))
        return Condition(condition.attribute, Text.of(Sub(CONFIGURATION_EQUALS, operands)))

    return build


def _source(call: Call) -> Value:
    return Source(call.text(call.arg(0, "launch_file_path")))


for _condition_entry in CONDITIONS:
    for _qualified in _condition_entry.python:
        CALLS[python_name(_qualified)] = _condition(_condition_entry)
for _source_entry in SOURCES:
    for _qualified in _source_entry.python:
        CALLS[python_name(_qualified)] = _source


SubstitutionMethod = Callable[[Sub, Call], Value]

SUBSTITUTION_METHODS: dict[tuple[str, str], SubstitutionMethod] = {}
"""Methods of a substitution object a launch file calls, by (``$(name)``, method): the
object is the text of that one substitution."""


def _find(substitution: Sub, call: Call) -> Value:
    """launch_ros's ``FindPackageShare(p).find(name)`` (``FindPackagePrefix``): the
    directory of package ``name``, as ``get_package_share_directory(name)`` gives it (the
    object's own package plays no part)."""
    return Text.of(Sub(substitution.name, (call.text(call.arg(0, "package_name")),)))


for _found in ("find-pkg-share", "find-pkg-prefix"):
    SUBSTITUTION_METHODS[_found, "find"] = _find


def substitution_method(receiver: Text, name: str) -> Builder | None:
    """The method ``name`` of the substitution object ``receiver`` is, if it is one."""
    substitution = receiver.parts[0] if len(receiver.parts) == 1 else None
    if not isinstance(substitution, Sub):
        return None
    method = SUBSTITUTION_METHODS.get((substitution.name, name))
    return None if method is None else functools.partial(method, substitution)


@_register("launch", "normalize_to_list_of_substitutions")
def _normalized(call: Call) -> Value:
    """launch's ``normalize_to_list_of_substitutions(subs)``: the text they give."""
    return call.text(call.arg(0, "subs"))


@_register("launch", "perform_substitutions")
def _performed_substitutions(call: Call) -> Value:
    """launch's ``perform_substitutions(context, subs)``: their string at launch time."""
    return launch_time.performed_value(call.text(call.arg(1, "subs")))


@_register("launch_ros", "ParameterValue")
def _parameter_value(call: Call) -> Value:
    kind = call.arg(1, "value_type", None)
    type_name = None
    if kind is not None:
        type_name = kind.qualified if isinstance(kind, Module) else None
        if type_name not in ("str", "int", "float", "bool"):
            call.not_followed(f"value_type={kind!r}")
            type_name = None
    return ParameterValue(call.arg(0, "value"), type_name)


@_register("launch_ros", "ParameterFile")
def _parameter_file(call: Call) -> Value:
    return ParameterFile(call.arg(0, "param_file"), call.arg(1, "allow_substs", None))
