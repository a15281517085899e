"""Files a launch file's Python reads itself: ``open(path)``, ``.read()``, ``yaml.safe_load``.

Helpers load a parameter file into a dict (``yaml.safe_load(open(path))``) and pass it on as
parameters. The reading follows them where the path is known statically (a package's share
directory, the file's directory, with a literal tail): through the one gate of every read
(:func:`rosvar.files.read_file`: inside the workspace's confinement, regular files, at most
:data:`MAX_READ_BYTES`), YAML within :mod:`rosvar.bounded_yaml`'s limits. A path known at
launch time only, a refused read, or YAML that fails stays unknown, reported.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from typing import Protocol

import yaml

from rosvar.bounded_yaml import check_limits
from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.files import FileRefused, python_text, read_file
from rosvar.ros2.frontends.python import launch_time
from rosvar.ros2.frontends.python.default_files import DefaultFiles
from rosvar.ros2.frontends.python.modules import ModulePath
from rosvar.ros2.frontends.python.text import PYTHON_YAML, Sub, Text
from rosvar.ros2.frontends.python.values import (
    Dynamic,
    FileHandle,
    Key,
    LaunchYaml,
    Unknown,
    Value,
)


class Interpreter(Protocol):
    """What a read needs of the interpreter (which registers these builtins)."""

    modules: ModulePath | None
    sink: DiagnosticSink
    default_files: DefaultFiles

    rereading: Callable[[str], str] | None

    def path_of(self, value: Value) -> str | None: ...

    def not_followed(self, what: str, node: ast.AST) -> Unknown: ...

    def location(self, node: ast.AST) -> Location: ...


FILE_CONTENT = "file-content"
"""launch's ``FileContent``: the text of a file a configuration names, read when performed."""
MAX_READ_BYTES = 1024 * 1024
"""Largest file a launch file's Python reads (a parameter file, a text)."""
_READ_MODES = ("r", "rt", "tr")


def open_file(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``open(path)`` (``mode='r'``): a handle, the file read where its text is used."""
    given = args[0] if args else kwargs.get("file")
    path = interpreter.path_of(given)
    mode = args[1] if len(args) > 1 else kwargs.get("mode", "r")
    if mode not in _READ_MODES:
        return interpreter.not_followed(f"open() in mode {mode!r}", node)
    if path is None and isinstance(given, Dynamic) and given.text is not None:
        path = interpreter.default_files.opened(given.text, interpreter.path_of)
        return FileHandle(given.text if path is None else path)  # named at launch time
    if path is None:
        return interpreter.not_followed("open() of a path not known statically", node)
    return FileHandle(path)


def text(interpreter: Interpreter, handle: FileHandle, node: ast.AST) -> Value:
    """The text of ``handle``'s file, read through the one gate; of a file named at launch
    time, the string launch's ``FileContent`` gives (``$(file-content)``, read through the
    same gate once a configuration names it)."""
    if isinstance(handle.path, Text):
        return launch_time.performed(Text.of(Sub(FILE_CONTENT, (handle.path,))))
    modules = interpreter.modules
    if interpreter.rereading is not None:
        try:  # in one configuration: a file of the workspace, or one a helper wrote
            return interpreter.rereading(handle.path)
        except ValueError as error:
            return interpreter.not_followed(f"a read ({error})", node)
    if modules is None or modules.confinement is None:
        return interpreter.not_followed(f"a read of {handle.path} (no workspace)", node)
    try:
        data = read_file(handle.path, modules.confinement, MAX_READ_BYTES)
        return python_text(data, "utf-8-sig")
    except FileRefused as refused:
        interpreter.sink.warning(
            str(refused.code), f"{handle.path}: {refused.message}", interpreter.location(node)
        )
    except (OSError, UnicodeDecodeError) as error:
        interpreter.sink.warning(
            "file-unreadable", f"{handle.path}: {error}", interpreter.location(node)
        )
    return Unknown(f"the text of {handle.path}")


def load_yaml(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``yaml.safe_load(stream)`` (``yaml.load``, read safely whatever its loader) of a
    handle or a string."""
    stream = args[0] if args else kwargs.get("stream")
    if isinstance(stream, FileHandle) and isinstance(stream.path, Text):
        return LaunchYaml(stream.path)
    if isinstance(stream, FileHandle):
        stream = text(interpreter, stream, node)
    if isinstance(stream, Unknown):
        return stream
    if isinstance(stream, Dynamic) and stream.kind is str:  # a launch-time string
        return Dynamic(Text.of(Sub(PYTHON_YAML, (launch_time.as_text(stream),))), None)
    if not isinstance(stream, str):
        return interpreter.not_followed("yaml.load() of a value not known statically", node)
    try:
        check_limits(stream)
        loaded = yaml.load(stream, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader))
    except yaml.YAMLError as error:
        return interpreter.not_followed(f"yaml.load() that fails ({error})", node)
    value = _value(loaded)
    if isinstance(value, Unknown):
        return interpreter.not_followed(f"yaml.load() of {value.what}", node)
    return value


def _value(loaded: object) -> Value:
    """A loaded YAML document as the reading's values (timestamps and binary are not)."""
    if loaded is None or isinstance(loaded, str | bool | int | float):
        return loaded
    if isinstance(loaded, list):
        return [_value(item) for item in loaded]
    if isinstance(loaded, dict):
        mapping: dict[Key, Value] = {}
        for key, item in loaded.items():
            if not (key is None or isinstance(key, str | bool | int | float)):
                return Unknown(f"a YAML key of type {type(key).__name__}")
            mapping[key] = _value(item)
        return mapping
    return Unknown(f"a YAML value of type {type(loaded).__name__}")
