"""Texts with substitutions, written as the XML and YAML frontends write them.

A Python launch file builds values from strings and substitution objects
(``['/', LaunchConfiguration('ns')]``); the entity tree holds them as the text the
equivalent XML attribute holds (``/$(var ns)``), in launch's substitution grammar: literal
text escapes ``\\`` and ``$(`` with a backslash, an argument that is not a plain word is
single-quoted with ``'`` and ``\\`` escaped (``$(eval '\\'$(var r)\\' == \\'r2\\'')``).
"""

from __future__ import annotations

import posixpath
import re
from collections.abc import Callable
from dataclasses import dataclass
from enum import StrEnum

UNKNOWN = "rosvar-unknown"
"""The substitution standing for a value the static reading cannot follow; its argument
says what it was (``$(rosvar-unknown 'call read_config()')``). No launch file has it."""
PATH_JOIN = "rosvar-path-join"
"""The substitution standing for ``PathJoinSubstitution`` (``os.path.join`` of its
arguments' values) where the join is not known from the text; XML has none."""
PATH_PART = "rosvar-path-part"
"""``$(rosvar-path-part dirname|basename PATH)``: ``os.path.dirname`` or ``basename`` of a
path known at launch time only (``os.path.dirname(os.getenv('MAP'))``); XML has none."""
PATH_PARTS: dict[str, Callable[[str], str]] = {
    "dirname": posixpath.dirname,
    "basename": posixpath.basename,
}
"""The functions of :data:`PATH_PART`, by the name its first argument gives."""

PYTHON_STRING = "rosvar-python-string"
"""The substitution giving its argument's value as a Python string literal (``repr``): a
launch-time string inside a Python expression the interpreter evaluates, whatever quotes or
backslashes the value holds; XML has none."""
PYTHON_YAML = "rosvar-python-yaml"
"""The substitution giving ``yaml.safe_load`` of its argument's value as a Python literal
(``repr``): a launch-time string a Python file loads as YAML (autoware's
``yaml.load(LaunchConfiguration('camera_namespaces').perform(context))``), inside an
expression the interpreter evaluates; XML has none."""
CONFIGURATION_EQUALS = "rosvar-configuration-equals"
"""``LaunchConfigurationEquals(name, value)``: whether the launch configuration ``name`` is
the text ``value`` (plain text equality; an undefined one equals only no value), which no
frontend writes (``$(equals)`` compares booleans and numbers by value)."""
NODE_NAME = "rosvar-node-name"
"""``$(rosvar-node-name FILE:LINE:COL)``: the fully qualified name of the node declared at that
place, as launch_ros's ``node_name`` of a ``ComposableNodeContainer`` object given as a
``LoadComposableNodes`` target (XML names the target as text)."""
WRITTEN_FILE = "rosvar-written-file"
"""``$(rosvar-written-file ASPECT MODULE QUALIFIED CLASS ARGUMENTS)``: the file a workspace's
``Substitution`` subclass names in its ``perform`` (one it writes: ``tempfile``,
``yaml.dump``, ``write``), its text or its path (:class:`Written`), computed by reading that
``perform`` again once a configuration gives the constructor's ``ARGUMENTS`` (a Python
literal); no launch file has it."""
WRITTEN_PATH = "/rosvar-written-file/"
"""How the path of a file written so begins: then the JSON list of the substitution's
operands, from which a read of the path computes the text (no such file exists)."""


class Written(StrEnum):
    """What ``$(rosvar-written-file)`` gives of the file."""

    TEXT = "text"
    PATH = "path"


EMPTY = "rosvar-empty"
"""The empty text as an operand of ``$(equals)``: launch's grammar reads ``''`` there as the
text ``[]``, which the Python frontend's ``''`` is not."""

_PLAIN_ARGUMENT = re.compile(r"[^\s'\"\\$()]+")


@dataclass(frozen=True, slots=True)
class Sub:
    """One substitution: ``$(name arg...)``."""

    name: str
    args: tuple[Text, ...] = ()

    def syntax(self) -> str:
        return "$(" + self.name + "".join(" " + argument(arg) for arg in self.args) + ")"


@dataclass(frozen=True, slots=True)
class Text:
    """Literal strings and substitutions, concatenated; adjacent literals are merged."""

    parts: tuple[str | Sub, ...]

    @staticmethod
    def of(*items: str | Sub | Text) -> Text:
        parts: list[str | Sub] = []
        for item in items:
            for part in item.parts if isinstance(item, Text) else (item,):
                if isinstance(part, str) and parts and isinstance(parts[-1], str):
                    parts[-1] += part
                elif part != "":
                    parts.append(part)
        return Text(tuple(parts))

    def literal(self) -> str | None:
        """The text when it holds no substitution."""
        if all(isinstance(part, str) for part in self.parts):
            return "".join(str(part) for part in self.parts)
        return None


def unknown(what: str) -> Sub:
    return Sub(UNKNOWN, (Text.of(what),))


def render(text: Text) -> str:
    """The attribute text of ``text``."""
    return "".join(
        part.syntax() if isinstance(part, Sub) else _escape(part, "") for part in text.parts
    )


def argument(text: Text) -> str:
    """``text`` as one argument of a substitution: bare when it is a plain word."""
    if text.parts and all(
        isinstance(part, Sub) or _PLAIN_ARGUMENT.fullmatch(part) for part in text.parts
    ):
        return render(text)
    quoted = "".join(
        part.syntax() if isinstance(part, Sub) else _escape(part, "'") for part in text.parts
    )
    return f"'{quoted}'"


def _escape(literal: str, quote: str) -> str:
    escaped = literal.replace("\\", "\\\\").replace("$(", "\\$(")
    return escaped.replace(quote, "\\" + quote) if quote else escaped
