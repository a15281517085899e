"""``pathlib`` paths as launch helpers compute them, and what they ask of the file system.

Helper modules build paths with ``pathlib`` (moveit's ``MoveItConfigsBuilder``:
``Path(get_package_share_directory(p)) / "config" / "kinematics.yaml"``, ``.parent``,
``.exists()``, a folder's ``.iterdir()``) and read the files they name. A path is a
:class:`~rosvar.ros2.frontends.python.values.FilePath`: the substitutions that give a
directory, then a literal tail normalized as pathlib normalizes it, so that ``.name`` and
``.parent`` are known wherever the tail is. Questions to the file system (``exists``,
``is_file``, ``is_dir``, ``iterdir``, and ``os.path.exists``) are asked only of a path known
statically, only inside the workspace's confinement (a refused one is reported with the
gate's code, naming the path, and stays unknown), a folder listed up to
:data:`MAX_ENTRIES` entries in the order Python's ``iterdir`` gives them.
"""

from __future__ import annotations

import ast
import os
import posixpath
from collections.abc import Callable
from pathlib import PurePosixPath
from typing import Protocol

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.files import FileRefused
from rosvar.ros2.frontends.python import launch_time
from rosvar.ros2.frontends.python.calls import PATH_VALUED, join_path, path_text
from rosvar.ros2.frontends.python.modules import ModulePath
from rosvar.ros2.frontends.python.text import Sub, Text
from rosvar.ros2.frontends.python.values import Dynamic, FileHandle, FilePath, Unknown, Value

MAX_ENTRIES = 10_000
"""Entries of one folder listed (``iterdir``); a larger folder is not followed."""


class Interpreter(Protocol):
    """What a path needs of the interpreter (which registers these builtins)."""

    modules: ModulePath | None
    sink: DiagnosticSink

    def path_of(self, value: Value) -> str | None: ...

    def not_followed(self, what: str, node: ast.AST) -> Unknown: ...

    def location(self, node: ast.AST) -> Location: ...


def _normal(tail: str) -> str:
    """A literal path as pathlib writes it (``a//b/./c/`` is ``a/b/c``; ``''`` for ``.``)."""
    written = str(PurePosixPath(tail))
    return "" if written == "." else written


def of_text(text: Text) -> FilePath:
    """The path a text names: its literal end after the last substitution is the tail."""
    literal = text.literal()
    if literal is not None:
        return FilePath(None, _normal(literal))
    last = text.parts[-1]
    if isinstance(last, str) and last.startswith("/"):
        return FilePath(Text.of(*text.parts[:-1]), _normal(last.lstrip("/")))
    return FilePath(text, "")


def of_value(value: Value) -> FilePath | None:
    """``value`` as a path (a string, a text, a launch-time string with its text)."""
    if isinstance(value, FilePath):
        return value
    if isinstance(value, str):
        return FilePath(None, _normal(value))
    if isinstance(value, Dynamic) and value.text is not None:
        value = value.text
    return of_text(value) if isinstance(value, Text) else None


def join(left: FilePath, right: FilePath) -> FilePath:
    """``left / right``: an absolute ``right`` replaces ``left``, as pathlib's ``/``."""
    if right.head is None and right.tail.startswith("/"):
        return right
    if right.head is None:
        tail = posixpath.join(left.tail, right.tail) if left.tail else right.tail
        return FilePath(left.head, _normal(tail))
    first = right.head.parts[0]
    if isinstance(first, Sub) and first.name in PATH_VALUED:
        return right
    return of_text(join_path(path_text(left), path_text(right)))


def as_string(path: FilePath) -> Value:
    """``str(path)``: a string, known at launch time where substitutions give its head."""
    if path.head is None:
        return path.tail or "."
    return launch_time.performed(path_text(path))


def attribute(interpreter: Interpreter, path: FilePath, name: str, node: ast.AST) -> Value:
    """``path.parent``, ``.name``, ``.stem``, ``.suffix``, from the literal tail."""
    pure = PurePosixPath(path.tail or ".")
    if name == "parent":
        if path.tail and (path.head is None or "/" in path.tail):
            return FilePath(path.head, _normal(str(pure.parent)))
        if path.tail:
            return FilePath(path.head, "")
        return interpreter.not_followed("the parent of a path not known statically", node)
    if name in ("name", "stem", "suffix"):
        if path.tail:
            part: str = getattr(pure, name)
            return part
        return interpreter.not_followed(f"the {name} of a path not known statically", node)
    return interpreter.not_followed(f"attribute {name} of a path", node)


def _queried(
    interpreter: Interpreter, value: Value, node: ast.AST, question: str
) -> tuple[str, str] | Unknown:
    """The path ``value`` names (as given, and resolved) where the file system may be asked
    about it; else the reason it may not, reported."""
    path = interpreter.path_of(value)
    modules = interpreter.modules
    if path is None:
        return interpreter.not_followed(f"{question} of a path not known statically", node)
    if modules is None or modules.confinement is None:
        return interpreter.not_followed(f"{question} of {path} (no workspace)", node)
    try:
        return path, modules.confinement.check(path)
    except FileRefused as refused:
        where = interpreter.location(node)
        interpreter.sink.warning(str(refused.code), f"{path}: {refused.message}", where)
        return Unknown(f"{question} of {path}")


def _test(check: Callable[[str], bool], question: str) -> PathMethod:
    def test(interpreter: Interpreter, path: Value, args: list[Value], node: ast.AST) -> Value:
        found = _queried(interpreter, path, node, question)
        return found if isinstance(found, Unknown) else check(found[1])

    return test


def _iterdir(interpreter: Interpreter, path: Value, args: list[Value], node: ast.AST) -> Value:
    found = _queried(interpreter, path, node, "iterdir()")
    if isinstance(found, Unknown):
        return found
    folder = of_value(path)
    try:
        with os.scandir(found[1]) as entries:
            names: list[str] = []
            for entry in entries:
                if len(names) >= MAX_ENTRIES:
                    return interpreter.not_followed(f"a folder of over {MAX_ENTRIES} entries", node)
                names.append(entry.name)
    except OSError as error:
        return interpreter.not_followed(f"iterdir() that fails ({error.strerror})", node)
    assert folder is not None
    return [join(folder, FilePath(None, name)) for name in names]


def _open(interpreter: Interpreter, path: Value, args: list[Value], node: ast.AST) -> Value:
    if args and args[0] not in ("r", "rt"):
        return interpreter.not_followed(f"open() in mode {args[0]!r}", node)
    named = interpreter.path_of(path)
    if named is None:
        return interpreter.not_followed("open() of a path not known statically", node)
    return FileHandle(named)


def _joinpath(interpreter: Interpreter, path: Value, args: list[Value], node: ast.AST) -> Value:
    result = of_value(path)
    for arg in args:
        other = of_value(arg)
        if result is None or other is None:
            return interpreter.not_followed("joinpath() of a value that is no path", node)
        result = join(result, other)
    return result


PathMethod = Callable[[Interpreter, Value, list[Value], ast.AST], Value]

METHODS: dict[str, PathMethod] = {
    "exists": _test(os.path.exists, "exists()"),
    "is_file": _test(os.path.isfile, "is_file()"),
    "is_dir": _test(os.path.isdir, "is_dir()"),
    "iterdir": _iterdir,
    "open": _open,
    "joinpath": _joinpath,
}
"""The methods of a path the reading follows, by name."""

FUNCTIONS: dict[str, PathMethod] = {
    "os.path.exists": METHODS["exists"],
    "os.path.isfile": METHODS["is_file"],
    "os.path.isdir": METHODS["is_dir"],
}
"""``os.path``'s questions to the file system, the same as a path's methods."""


def construct(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``Path(*parts)`` (``PurePath``, ``PosixPath``): the parts joined."""
    result = FilePath(None, "")
    for arg in args:
        part = of_value(arg)
        if part is None:
            return interpreter.not_followed(f"Path() of a {type(arg).__name__}", node)
        result = join(result, part)
    return result


def home(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``Path.home()``: ``$HOME`` of the launching process (never rosvar's own)."""
    return FilePath(Text.of(Sub("env", (Text.of("HOME"),))), "")


def expanduser(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``os.path.expanduser('~/x')``: ``$(env HOME)/x`` (the launching process's ``HOME``,
    never rosvar's own); a path without ``~`` is itself."""
    path = args[0] if len(args) == 1 else None
    if not isinstance(path, str):
        return interpreter.not_followed("os.path.expanduser() of a value not known", node)
    if path != "~" and not path.startswith("~/"):
        return path
    return launch_time.performed(Text.of(Sub("env", (Text.of("HOME"),)), path[1:]))
