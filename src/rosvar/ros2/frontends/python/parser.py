"""ROS 2 Python launch files to :class:`Entity` trees, read statically.

The file's ``generate_launch_description()`` is read by an abstract interpreter
(:mod:`~rosvar.ros2.frontends.python.interpreter`), never executed or compiled: the
result is the element tree of the equivalent XML launch file, with what could not be
followed as ``$(rosvar-unknown ...)`` texts or left out, each with a diagnostic.
"""

from __future__ import annotations

import ast
import itertools
import os
import re

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.frontends.entity import ParseResult
from rosvar.frontends.xml import read_bytes
from rosvar.ros2.frontends.python.interpreter import (
    MAX_STEPS,
    Interpreter,
    OutOfBudget,
    entry_point,
)
from rosvar.ros2.frontends.python.modules import ModulePath

MAX_PYTHON_BYTES = 1024 * 1024
"""Largest Python launch file read (real ones are below 50 KB): ``ast.parse`` of a few
megabytes takes seconds and gigabytes before any step is counted."""
MAX_PYTHON_TOKENS = 100_000
"""Words and symbols of a Python launch file (real ones have fewer than 10,000), counted
before parsing: what ``ast.parse`` builds grows with them."""
_TOKEN = re.compile(r"\w+|[^\w\s]")


def parse_python_launch_bytes(
    data: bytes, filename: str, modules: ModulePath | None = None
) -> ParseResult:
    """Read a ROS 2 Python launch file held in memory; never raises."""
    sink = DiagnosticSink()
    start = Location(filename, 1, 1)
    if len(data) > MAX_PYTHON_BYTES:
        message = f"file is {len(data)} bytes, over the limit of {MAX_PYTHON_BYTES} bytes"
        sink.error("file-too-large", message, start)
        return ParseResult(None, sink.items)
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        sink.error("python-syntax", f"invalid UTF-8 byte at offset {error.start}", start)
        return ParseResult(None, sink.items)
    if (
        len(list(itertools.islice(_TOKEN.finditer(text), MAX_PYTHON_TOKENS + 1)))
        > MAX_PYTHON_TOKENS
    ):
        message = f"more than {MAX_PYTHON_TOKENS} tokens: not parsed"
        sink.error("python-budget", message, start)
        return ParseResult(None, sink.items)
    try:
        tree = ast.parse(text, filename)
    except SyntaxError as error:
        where = Location(filename, error.lineno or 1, error.offset or 1)
        sink.error("python-syntax", f"invalid Python: {error.msg}", where)
        return ParseResult(None, sink.items)
    except (ValueError, RecursionError, MemoryError) as error:
        reason = str(error) or "nested too deeply"
        sink.error("python-syntax", f"invalid Python: {reason}", start)
        return ParseResult(None, sink.items)
    interpreter = Interpreter(filename, text, sink, modules)
    try:
        root = entry_point(interpreter, tree)
    except OutOfBudget:
        statement = interpreter.statement
        where = start if statement is None else interpreter.location(statement)
        sink.error("python-budget", f"reading the file takes more than {MAX_STEPS} steps", where)
        return ParseResult(None, sink.items)
    except RecursionError:
        sink.error("python-budget", "expressions nested too deeply to read", start)
        return ParseResult(None, sink.items)
    return ParseResult(root, sink.items)


def parse_python_launch_file(
    path: str | os.PathLike[str], modules: ModulePath | None = None
) -> ParseResult:
    """Read a ROS 2 Python launch file; Locations use ``path`` as given; ``modules``: where
    its imports find the workspace's modules (none: every import stays symbolic). Never
    raises."""
    data = read_bytes(path, MAX_PYTHON_BYTES)
    if isinstance(data, ParseResult):
        return data
    return parse_python_launch_bytes(data, os.fspath(path), modules)
