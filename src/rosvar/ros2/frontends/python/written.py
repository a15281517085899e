"""Files a launch file's Python writes: ``tempfile``, ``yaml.dump``, ``write``, as their text.

Helpers such as nav2's ``RewrittenYaml`` read a parameter file in their ``perform``, change
it with launch-time values, write it to a temporary file and give its name, which a node then
reads as a parameter file. The reading never writes a file: ``tempfile.NamedTemporaryFile()``
is a :class:`~rosvar.ros2.frontends.python.values.WrittenFile` that keeps what is written to
it (``write``, ``yaml.dump``), and its ``name`` stands for it. A workspace ``Substitution``
whose ``perform`` gives such a file is, where it stands, the file whose text
``$(rosvar-written-file ...)`` gives: the same ``perform`` read again once a configuration
gives the constructor's arguments (:mod:`.performs`), every value then concrete, so that the
helper's own loops over the file's keys, conversions and ``try``/``except`` run as Python
runs them. The files it reads go through the one gate, as every read.
"""

from __future__ import annotations

import ast
from typing import Protocol

import yaml

from rosvar.ros2.frontends.python import launch_time
from rosvar.ros2.frontends.python.text import WRITTEN_FILE, Sub, Text, Written, unknown
from rosvar.ros2.frontends.python.values import (
    Class,
    Condition,
    Conditional,
    Dynamic,
    Key,
    Unknown,
    Value,
    WrittenFile,
)

CONDITION = "rosvar-condition"
"""The tag of a condition among a constructor's arguments: ``(CONDITION, 'if', text)``."""
MAX_WRITTEN = 1024 * 1024
"""Largest text a launch file's Python writes to one file (as the largest it reads)."""


class Interpreter(Protocol):
    """What writing needs of the interpreter (which registers these builtins)."""

    filename: str

    def not_followed(self, what: str, node: ast.AST) -> Unknown: ...


def temporary_file(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``tempfile.NamedTemporaryFile(mode='w', ...)``: a file to write text to."""
    mode = args[0] if args else kwargs.get("mode", "w+b")
    if not isinstance(mode, str) or "b" in mode:
        return interpreter.not_followed(f"a temporary file in mode {mode!r}", node)
    return WrittenFile()


def dump_yaml(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``yaml.dump(data, stream)`` (``safe_dump``): the YAML text of plain data, written to
    ``stream`` or given back without one."""
    data = args[0] if args else kwargs.get("data")
    stream = args[1] if len(args) > 1 else kwargs.get("stream")
    text: Value = Unknown("yaml.dump() of values known at launch time only")
    if _plain(data):
        try:
            text = yaml.safe_dump(data)
        except yaml.YAMLError as error:
            text = interpreter.not_followed(f"yaml.dump() that fails ({error})", node)
    if stream is None:
        return text
    if isinstance(stream, WrittenFile):
        return write(interpreter, stream, [text], node)
    return interpreter.not_followed("yaml.dump() to a stream other than a temporary file", node)


def write(interpreter: Interpreter, file: WrittenFile, args: list[Value], node: ast.AST) -> Value:
    """``file.write(text)``: kept, in order; the length Python returns where it is known."""
    text = args[0] if len(args) == 1 else interpreter.not_followed("write() of many values", node)
    written = sum(len(part) for part in file.parts if isinstance(part, str))
    if isinstance(text, str) and written + len(text) > MAX_WRITTEN:
        text = interpreter.not_followed(f"a file written beyond {MAX_WRITTEN} characters", node)
    file.parts.append(text)
    return len(text) if isinstance(text, str) else None


def content(file: WrittenFile) -> str | Unknown:
    """The text written to ``file``, where every part is known."""
    for part in file.parts:
        if not isinstance(part, str):
            return part if isinstance(part, Unknown) else Unknown("a text known at launch time")
    return "".join(part for part in file.parts if isinstance(part, str))


def text_of(file: WrittenFile, aspect: Written) -> Text:
    """The substitution giving ``file``'s text or path at launch time; a file written by the
    launch file's own code has its text known (no path: nothing names it)."""
    if file.deferred is not None:
        return Text.of(Sub(WRITTEN_FILE, (Text.of(aspect), *file.deferred)))
    known = content(file)
    if aspect is Written.TEXT and isinstance(known, str):
        return Text.of(known)
    what = known.what if isinstance(known, Unknown) else "the path of a file written"
    return Text.of(unknown(what))


TEMPORARY_FILES = frozenset({"NamedTemporaryFile"})
"""The ``tempfile`` makers the reading models (:func:`temporary_file`)."""


def writes_file(method: ast.FunctionDef) -> bool:
    """Whether ``method``'s own body makes a temporary file: its object is then the file it
    writes, computed per configuration, without reading it first over values not known yet
    (nav2's ``RewrittenYaml`` walks its whole parameter file, every value a choice)."""
    return any(
        (isinstance(node, ast.Attribute) and node.attr in TEMPORARY_FILES)
        or (isinstance(node, ast.Name) and node.id in TEMPORARY_FILES)
        for node in ast.walk(method)
    )


def written_in(value: Value) -> bool:
    """Whether ``value`` is a file written, or one in a branch of a launch-time ``if``."""
    if isinstance(value, Conditional):
        return written_in(value.then) or written_in(value.otherwise)
    return isinstance(value, WrittenFile)


def deferred(
    interpreter: Interpreter, cls: Class, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """The file an object of ``cls`` writes in its ``perform``, computed once a configuration
    gives the constructor's arguments (their Python source over substitutions)."""
    keywords: dict[Key, Value] = {name: item for name, item in kwargs.items()}
    arguments = _source((tuple(args), keywords))
    module = _module(cls)
    if arguments is None or module is None:
        return interpreter.not_followed(f"the file {cls.name}() writes, of launch objects", node)
    path, qualified = module
    literal = arguments.literal()
    given = Text.of(literal) if literal is not None else Text.of(Sub("eval", (arguments,)))
    operands = (Text.of(path or interpreter.filename), Text.of(qualified), Text.of(cls.name))
    return WrittenFile(deferred=(*operands, given), label=f"{cls.name}() of {qualified}")


def _module(cls: Class) -> tuple[str | None, str] | None:
    """The file (``None``: the launch file) and qualified name of the module defining ``cls``
    at its top level, if it does."""
    scope = cls.scope.parent
    if scope is None or scope.parent is not None or scope.names.get(cls.name) is not cls:
        return None
    qualified, path = scope.names.get("__name__"), scope.names.get("__file__")
    if not isinstance(qualified, str):
        return None
    return (path if isinstance(path, str) else None), qualified


def _source(value: Value) -> Text | None:
    """The Python source of a constructor's argument, launch's objects as the strings they
    give (``LaunchConfiguration('ns')``: ``$(rosvar-python-string $(var ns))``)."""
    if isinstance(value, Text):
        return launch_time.quoted(value)
    if isinstance(value, Condition):  # made again by the reading (`performs.py`)
        tag = f"({CONDITION!r}, {value.attribute!r}, "
        return Text.of(tag, launch_time.quoted(value.text), ")")
    if isinstance(value, WrittenFile):
        return launch_time.quoted(text_of(value, Written.PATH))
    if isinstance(value, dict):
        parts: list[str | Text] = ["{"]
        for index, (key, item) in enumerate(value.items()):
            pair = (_source(key), _source(item))
            if pair[0] is None or pair[1] is None:
                return None
            parts.extend([", " if index else "", pair[0], ": ", pair[1]])
        return Text.of(*parts, "}")
    if isinstance(value, list | tuple):
        items = [_source(item) for item in value]
        known = [item for item in items if item is not None]
        if len(known) < len(items):
            return None
        inner: list[str | Text] = []
        for item in known:
            inner.extend([item, ", "])
        opening, closing = ("[", "]") if isinstance(value, list) else ("(", ")")
        return Text.of(opening, *inner, closing)
    if isinstance(value, Dynamic | Conditional | str | int | float | bool) or value is None:
        return launch_time.source(value)
    return None


def _plain(value: Value) -> bool:
    """Whether ``value`` is made of what YAML writes as it is (no launch-time values)."""
    if value is None or isinstance(value, str | bool | int | float):
        return True
    if isinstance(value, list | tuple):
        return all(_plain(item) for item in value)
    if isinstance(value, dict):
        return all(_plain(key) and _plain(item) for key, item in value.items())
    return False
