"""A workspace ``Substitution``'s ``perform`` read again in one configuration.

Where a helper's ``perform`` writes a file (:mod:`.written`), what it writes depends on the
launch-time values it was made of (the parameter file a launch argument names, the values
it rewrites): the reading of the launch file leaves the text to ``$(rosvar-written-file
...)``, whose arguments a configuration makes concrete. This module reads the helper's
module again, never imported nor run, makes the object of those concrete arguments and
reads its ``perform``: the text of the file it writes, or ``ValueError`` saying why not.
"""

from __future__ import annotations

import ast
import json
import os

from rosvar.diagnostics import DiagnosticSink
from rosvar.files import Confinement, FileRefused, python_text, read_file
from rosvar.memo import Memo
from rosvar.ros2.frontends.python import written as written_files
from rosvar.ros2.frontends.python.interpreter import (
    MODULE_NAME,
    Interpreter,
    OutOfBudget,
    PythonRaise,
)
from rosvar.ros2.frontends.python.modules import MAX_MODULE_BYTES, ModulePath
from rosvar.ros2.frontends.python.reads import MAX_READ_BYTES
from rosvar.ros2.frontends.python.text import WRITTEN_PATH, Text, Written
from rosvar.ros2.frontends.python.values import (
    Class,
    Condition,
    Scope,
    Unknown,
    Value,
    WrittenFile,
)

MAX_NESTED = 8
"""Files written from files written, read one in the other (nav2's ``RewrittenYaml`` of a
``ReplaceString``); deeper, the text is not computed."""


READINGS_CAPACITY = 256
"""Readings of ``perform`` kept (:data:`_readings`)."""
_readings: Memo[tuple[object, ...], tuple[WrittenFile | str, tuple[Signature, ...]]] = Memo(
    READINGS_CAPACITY
)
"""What ``perform`` gave, by the workspace and the operands, with the files its reading read:
every node an object is given to, in every configuration giving the same values, asks again
(nav2's bringup: 7 servers, each configuration, each includer); kept while those files are
unchanged."""
Signature = tuple[str, int, int]
"""A file read: its path, modification time and size (``os.stat``)."""


def written(
    packages: dict[str, str], confinement: Confinement, operands: list[str], aspect: Written
) -> str:
    """The text or path (``aspect``) of the file an object names in its ``perform``:
    ``operands`` are the file and qualified name of the class's module, the class's name and
    the Python literal of the constructor's arguments (``$(rosvar-written-file)``'s). A file
    it writes has the path :data:`WRITTEN_PATH` then the operands, whose text this function
    computes again where the path is read; a path it gives is that file, read through the
    gate. ``ValueError`` says why there is none."""
    return _Reading(packages, confinement).written(operands, aspect, 0)


class _Reading:
    def __init__(self, packages: dict[str, str], confinement: Confinement) -> None:
        self.packages = packages
        self.confinement = confinement

    def written(self, operands: list[str], aspect: Written, depth: int) -> str:
        if len(operands) != 4:
            raise ValueError("a file written is named by four operands")
        if depth > MAX_NESTED:
            raise ValueError(f"files written from files written, over {MAX_NESTED} deep")
        key = (tuple(sorted(self.packages.items())), self.confinement.roots, *operands)
        known = _readings.get(key)
        if known is not None and all(_signature(f[0]) == f for f in known[1]):
            made = known[0]
        else:
            path, qualified, name, arguments = operands
            read: list[str] = []
            made = self.performed(path, qualified, name, arguments, depth, read)
            _readings[key] = (made, tuple(_signature(file) for file in dict.fromkeys(read)))
        if isinstance(made, WrittenFile):
            if aspect is Written.PATH:
                return WRITTEN_PATH + json.dumps(operands)
            text = written_files.content(made)
            assert isinstance(text, str)  # else not made
            return text
        if aspect is Written.PATH:
            return made
        return self.read(made, depth)

    def read(self, path: str, depth: int, read: list[str] | None = None) -> str:
        """The text of ``path``: a file written, computed again, or a file of the workspace
        (its path added to ``read``)."""
        if path.startswith(WRITTEN_PATH):
            try:
                operands = json.loads(path[len(WRITTEN_PATH) :])
            except ValueError:
                raise ValueError(f"{path[:200]} names no file written") from None
            if not (isinstance(operands, list) and all(isinstance(o, str) for o in operands)):
                raise ValueError(f"{path[:200]} names no file written")
            return self.written(operands, Written.TEXT, depth + 1)
        if read is not None:
            read.append(path)
        try:
            return python_text(read_file(path, self.confinement, MAX_READ_BYTES), "utf-8-sig")
        except (FileRefused, OSError, UnicodeDecodeError) as error:
            raise ValueError(f"{path} is not read: {error}") from None

    def performed(
        self, path: str, qualified: str, name: str, arguments: str, depth: int, read: list[str]
    ) -> WrittenFile | str:
        """What ``perform`` of an object of class ``name`` made of ``arguments`` gives: the
        file it writes, or a path; the files read (modules, data) are added to ``read``."""
        given = _arguments(name, arguments)
        sink = DiagnosticSink()
        reader = Interpreter(path, "", sink, ModulePath(self.packages, self.confinement))
        reader.rereading = lambda named: self.read(named, depth, read)
        site = ast.Pass()
        try:
            scope = _module_scope(reader, path, qualified, site)
            cls = None if scope is None else scope.names.get(name)
            if not isinstance(cls, Class):
                raise ValueError(f"{qualified}.{name} is not read")
            made = reader.instantiate(cls, list(given[0]), dict(given[1]), site)
        except OutOfBudget:
            raise ValueError(f"{name}().perform() takes more than the step budget") from None
        except PythonRaise as raised:
            raise ValueError(f"{name}().perform() raises {raised.what()}") from None
        except RecursionError:
            raise ValueError(f"{name}().perform() nests too deeply") from None
        finally:
            read.append(path)
            read.extend(
                str(module.scope.names.get("__file__"))
                for module in reader.loaded.values()
                if module is not None
            )
        if isinstance(made, WrittenFile) and isinstance(written_files.content(made), str):
            return made
        if isinstance(made, Text) and made.literal() is not None:
            return str(made.literal())
        reasons = [f"{d.location}: {d.message}" for d in sink.items] or ["not known"]
        raise ValueError(f"what {name}().perform() gives is not known ({reasons[0]})")


def _signature(path: str) -> Signature:
    try:
        status = os.stat(path)
    except OSError:
        return (path, -1, -1)  # missing: kept missing
    return (path, status.st_mtime_ns, status.st_size)


def _arguments(name: str, arguments: str) -> tuple[tuple[Value, ...], dict[str, Value]]:
    """The constructor's arguments from their literal, conditions made again."""
    try:
        given = ast.literal_eval(arguments)
    except (ValueError, SyntaxError, RecursionError, MemoryError):
        raise ValueError(f"the arguments of {name}() are not known: {arguments[:200]}") from None
    if not (isinstance(given, tuple) and len(given) == 2 and isinstance(given[1], dict)):
        raise ValueError(f"the arguments of {name}() are not known: {arguments[:200]}")
    positional = _made(given[0])
    keywords = _made(given[1])
    assert isinstance(positional, tuple) and isinstance(keywords, dict)
    return positional, {str(key): value for key, value in keywords.items()}


def _made(value: object) -> Value:
    """A literal argument as the reading's value (``(CONDITION, 'if', text)``: a condition)."""
    if isinstance(value, tuple) and len(value) == 3 and value[0] == written_files.CONDITION:
        return Condition(str(value[1]), Text.of(str(value[2])))
    if isinstance(value, tuple | list):
        items = [_made(item) for item in value]
        return tuple(items) if isinstance(value, tuple) else items
    if isinstance(value, dict):
        return {key: _made(item) for key, item in value.items()}
    if value is None or isinstance(value, str | int | float | bool):
        return value
    return Unknown(f"an argument of type {type(value).__name__}")


def _module_scope(reader: Interpreter, path: str, qualified: str, site: ast.AST) -> Scope | None:
    if qualified != MODULE_NAME:
        module = reader.module(qualified, site)
        return None if module is None else module.scope
    try:  # a class of the launch file itself: its top level read again
        assert reader.modules is not None and reader.modules.confinement is not None
        reader.modules.confinement.check(path)
        text = read_file(path, limit=MAX_MODULE_BYTES).decode("utf-8-sig")
        tree = ast.parse(text, path)
    except (FileRefused, OSError, UnicodeDecodeError, SyntaxError, ValueError) as error:
        raise ValueError(f"{path} is not read: {error}") from None
    reader.file.lines = text.splitlines()
    return reader.run_module(tree)
