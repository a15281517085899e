"""The abstract values a Python launch file computes, as the static reading knows them.

Python constants, lists, tuples and dicts stay themselves; launch's objects become what
their XML equivalent is made of: substitutions become :class:`Text`, actions become
:class:`Entity` elements, a condition the attribute it sets. What cannot be followed is an
:class:`Unknown` (reported once, where it arose) that spreads through whatever uses it.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass, field

from rosvar.frontends.entity import Entity
from rosvar.ros2.frontends.python.text import Text


@dataclass(frozen=True, slots=True)
class Unknown:
    """A value the static reading cannot follow; ``what`` names the construct."""

    what: str


@dataclass(frozen=True, slots=True)
class Dynamic:
    """A value known at launch time only: the Python ``source`` of an expression over
    substitutions that gives it (:mod:`~rosvar.ros2.frontends.python.launch_time`), its type
    where known, and its text where it is a string substitutions give directly."""

    source: Text
    kind: type | None
    text: Text | None = None


@dataclass(frozen=True, slots=True)
class Enumerated:
    """``enumerate(items, start)`` of a launch-time list (:class:`Dynamic`, its length known
    at launch time only): a loop over it reads each item with its index, as over the list."""

    items: Dynamic
    start: int = 0


@dataclass(frozen=True, slots=True)
class Conditional:
    """``then`` where the Python ``test`` holds at launch time, else ``otherwise``: values of
    the branches of an ``if`` on a launch-time value that are no Python expression (dicts of
    parameters, unknown values); a node's parameters hold each under its condition."""

    test: Text
    then: Value
    otherwise: Value


@dataclass(frozen=True, slots=True)
class FileHandle:
    """``open(path)`` of a file of the workspace, read where its text is used; a path known
    at launch time only is its text (the file is named by a launch configuration)."""

    path: str | Text


@dataclass(frozen=True, slots=True)
class FilePath:
    """A ``pathlib.Path``: ``head``, a text of substitutions giving a directory (a package's
    share directory), then ``tail``, literal and normalized as pathlib does (``''``: none);
    without a head, ``tail`` is the whole path."""

    head: Text | None
    tail: str


@dataclass(frozen=True, slots=True)
class Pattern:
    """``re.compile(source)`` of a literal pattern."""

    source: str


@dataclass(frozen=True, slots=True)
class Match:
    """A match of a :class:`Pattern` in a literal string: the text matched and its groups."""

    text: str
    groups: tuple[str | None, ...]


@dataclass(frozen=True, slots=True)
class XacroDocument:
    """``xacro.process_file(path, mappings=...)``: the document xacro makes of the file, which
    the command ``command`` (``xacro PATH name:=value ...``) prints; rosvar's own xacro reads
    it where a robot description is analysed, never the xacro package."""

    command: Text


@dataclass(frozen=True, slots=True)
class LaunchYaml:
    """``yaml.safe_load`` of a file named at launch time, indexed by ``keys``: its
    ``['/**']['ros__parameters']`` given as a node's parameters is that parameter file."""

    path: Text
    keys: tuple[Key, ...] = ()


@dataclass(eq=False, slots=True)
class WrittenFile:
    """A file the reading's Python writes (``tempfile.NamedTemporaryFile``): the texts
    written in order (``write``, ``yaml.dump``), never a real file; its name stands for it.
    ``deferred``, where set, are the operands of the substitution giving its text or path
    at launch time (a workspace's ``Substitution`` whose ``perform`` names it, read again per
    configuration)."""

    parts: list[Value] = field(default_factory=list)
    deferred: tuple[Text, ...] | None = None
    label: str = "a file written at launch time"


@dataclass(frozen=True, slots=True)
class Condition:
    """``IfCondition(x)`` and kin: the attribute (``if``/``unless``) and its text."""

    attribute: str
    text: Text


@dataclass(frozen=True, slots=True)
class Module:
    """An imported module or a name in it, by its qualified name (``launch_ros.actions.Node``)."""

    qualified: str


@dataclass(frozen=True, slots=True)
class Source:
    """A launch description source: the file an include names."""

    path: Text


@dataclass(frozen=True, slots=True)
class ParameterValue:
    """``ParameterValue(value, value_type=T)``: a parameter value with its declared type."""

    value: Value
    type_name: str | None


@dataclass(frozen=True, slots=True)
class ParameterFile:
    """``ParameterFile(path, allow_substs=...)``."""

    path: Value
    allow_substs: Value


@dataclass(frozen=True, slots=True)
class LaunchContext:
    """The ``context`` an ``OpaqueFunction`` passes to its function: a value read of it
    (``perform``, ``launch_configurations[...]``) is the substitution that gives it."""


@dataclass(eq=False, slots=True)
class Description:
    """A ``LaunchDescription`` under construction: its ``launch`` element."""

    root: Entity


@dataclass(eq=False, slots=True)
class SourceFile:
    """A file being read (the launch file or a module), for the places of diagnostics."""

    filename: str
    lines: list[str]


@dataclass(eq=False, slots=True)
class Function:
    """A function defined in the launch file or a module it imports, called by reading its
    body again; ``owner`` is the class whose body defines it (for ``super()``)."""

    node: ast.FunctionDef
    scope: Scope
    defaults: dict[str, Value]
    file: SourceFile
    owner: Class | None = None
    getter: bool = False
    """A ``@property``: reading the attribute calls it."""
    generator: bool = False
    """Its body yields: a call is the list of what it yields (read at once, in order)."""


@dataclass(eq=False, slots=True)
class ModuleScope:
    """A module of the workspace, read by the same interpreter: its names."""

    qualified: str
    scope: Scope


@dataclass(eq=False, slots=True)
class Class:
    """A class defined in the file or a module: its bases and its body's names; a
    ``@dataclass``'s fields in order (``__init__`` is made of them), each with its default
    or its ``default_factory`` (a factory is called for each object)."""

    name: str
    bases: list[Value]
    scope: Scope
    fields: list[DataField] | None = None


@dataclass(frozen=True, slots=True)
class DataField:
    """One field of a ``@dataclass``: its name and default (``None``: required)."""

    name: str
    default: ast.expr | None
    factory: bool


@dataclass(eq=False, slots=True)
class Instance:
    """An object of a :class:`Class`, with the attributes its methods set."""

    cls: Class
    attributes: dict[str, Value] = field(default_factory=dict)
    made: Value = None
    """What the launch class it derives from made of its constructor's arguments (the
    ``super().__init__(...)`` of a ``DeclareLaunchArgument`` subclass: that ``<arg>``)."""


@dataclass(eq=False, slots=True)
class Super:
    """``super()`` in a method of ``owner``: lookups start after it."""

    instance: Value
    owner: Class


@dataclass(frozen=True, slots=True)
class Method:
    """A method looked up on a value (``ld.add_action``), waiting for its call."""

    receiver: Value
    name: str


@dataclass(eq=False, slots=True)
class Scope:
    """Names of one function call (or the module), with the enclosing scope."""

    names: dict[str, Value] = field(default_factory=dict)
    parent: Scope | None = None

    def lookup(self, name: str) -> tuple[bool, Value]:
        scope: Scope | None = self
        while scope is not None:
            if name in scope.names:
                return True, scope.names[name]
            scope = scope.parent
        return False, None


Key = str | int | float | bool | None | Text
Value = (
    Key
    | Unknown
    | Dynamic
    | Enumerated
    | Conditional
    | FileHandle
    | FilePath
    | Pattern
    | Match
    | XacroDocument
    | LaunchYaml
    | WrittenFile
    | Condition
    | Module
    | Source
    | ParameterValue
    | ParameterFile
    | LaunchContext
    | Description
    | Function
    | ModuleScope
    | Class
    | Instance
    | Super
    | Method
    | Entity
    | list["Value"]
    | tuple["Value", ...]
    | dict[Key, "Value"]
)
