"""``xacro.process_file`` in a launch helper: the document rosvar's own xacro reads.

moveit's and launch_param_builder's helpers expand a robot description in Python
(``xacro.process_file(path, mappings={'name': ur_type}).toxml()``). The xacro package is never
read or run (a workspace's copy of it is not a module of the reading,
:data:`~rosvar.ros2.frontends.python.modules.RESERVED`): the document is the command line that
prints it, ``$(command 'xacro PATH name:=value ...')``, which rosvar's robot-description
analysis expands as it expands every xacro command, and which is never run.
"""

from __future__ import annotations

import ast
import shlex
from typing import Protocol

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.ros2.frontends.python.calls import Call
from rosvar.ros2.frontends.python.text import Sub, Text
from rosvar.ros2.frontends.python.values import Unknown, Value, XacroDocument


class Interpreter(Protocol):
    sink: DiagnosticSink

    def location(self, node: ast.AST) -> Location: ...


def _word(text: Text) -> Text:
    """A word of the command line: a literal one quoted as the shell needs."""
    literal = text.literal()
    return Text.of(shlex.quote(literal)) if literal is not None else text


def process_file(
    interpreter: Interpreter, args: list[Value], kwargs: dict[str, Value], node: ast.AST
) -> Value:
    """``xacro.process_file(input_file_name, mappings=None)``."""
    call = Call("xacro.process_file", args, kwargs, interpreter.location(node), interpreter.sink)
    path = call.arg(0, "input_file_name")
    mappings = call.arg(1, "mappings", None)
    if isinstance(path, Unknown):
        return path
    words = [Text.of("xacro "), _word(call.text(path))]
    if isinstance(mappings, dict):
        for key, value in mappings.items():
            words += [Text.of(" "), _word(Text.of(call.text(key), ":=", call.text(value)))]
    elif mappings is not None:
        return call.not_followed(f"xacro mappings given as {type(mappings).__name__}")
    return XacroDocument(Text.of(*words))


def document_text(document: XacroDocument) -> Text:
    """``document.toxml()``: what the command prints."""
    return Text.of(Sub("command", (document.command,)))
