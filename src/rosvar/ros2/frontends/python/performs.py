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

from rosvar.diagnostics import DiagnosticSink
from rosvar.files import Confinement, FileRefused, read_file
from rosvar.ros2.frontends.python import written
from rosvar.ros2.frontends.python.interpreter import (
    MODULE_NAME,
    Interpreter,
    OutOfBudget,
    PythonRaise,
)
from rosvar.ros2.frontends.python.modules import MAX_MODULE_BYTES, ModulePath
from rosvar.ros2.frontends.python.values import Class, Scope, Unknown, WrittenFile


def written_text(
    packages: dict[str, str],
    confinement: Confinement,
    path: str,
    qualified: str,
    name: str,
    arguments: str,
) -> str:
    """The text an object of class ``name`` of module ``qualified`` (file ``path``) made of
    ``arguments`` (the Python literal of its positional and keyword arguments) writes."""
    try:
        given = ast.literal_eval(arguments)
    except (ValueError, SyntaxError, RecursionError, MemoryError):
        raise ValueError(f"the arguments of {name}() are not known: {arguments[:200]}") from None
    if not (isinstance(given, tuple) and len(given) == 2 and isinstance(given[1], dict)):
        raise ValueError(f"the arguments of {name}() are not known: {arguments[:200]}")
    sink = DiagnosticSink()
    reader = Interpreter(path, "", sink, ModulePath(packages, confinement))
    reader.rereading = True
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
    text = written.content(made) if isinstance(made, WrittenFile) else Unknown("no file")
    if isinstance(text, str):
        return text
    reasons = [f"{d.location}: {d.message}" for d in sink.items] or [text.what]
    raise ValueError(f"the file {name}() writes is not known ({reasons[0]})")


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
