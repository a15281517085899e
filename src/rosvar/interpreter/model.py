"""The variational launch model: what one entry launch file does, for every configuration.

Every element carries a presence ``condition`` (a BDD over the entry file's inputs)
and attributes as :class:`~rosvar.logic.choice.Choice` values, so restricting the
model to one configuration (see :mod:`rosvar.ros1.resolve`) gives what
roslaunch would load, without reading the XML again.

Element classes have slots: a large workspace's models hold millions of them.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection, Mapping, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Protocol

from rosvar.diagnostics import Diagnostic, Location
from rosvar.files import Confinement
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, combine
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import ArgInput, Slot
from rosvar.logic.terms import Term
from rosvar.ros.version import RosVersion

Raw = str | Term
"""An attribute's string after substitution: concrete, or a term awaiting inputs."""


class ParamSource(StrEnum):
    """The ``<param>`` attribute that gives its value."""

    VALUE = "value"
    TEXTFILE = "textfile"
    BINFILE = "binfile"
    COMMAND = "command"  # its text is wrapped, never run


class ParamConversion(Protocol):
    """The dialect's conversion of a ``<param>``'s concrete string to its value (roslaunch's
    ``Loader.param_value``): ValueError/OSError where roslaunch fails."""

    def __call__(
        self, kind: ParamSource, raw: str, ptype: str, confinement: Confinement
    ) -> object: ...


@dataclass(frozen=True)
class DeferredValue:
    """A ``<param>`` value whose string is a term: converted with ``ptype`` once known.

    It carries its dialect's ``convert``: whoever learns the string (resolution, the
    configuration's graph) converts it as the interpreter would, without knowing the
    dialect's tags."""

    raw: Term
    ptype: str
    kind: ParamSource  # VALUE or COMMAND: a file to read must be known at once
    convert: ParamConversion


@dataclass(frozen=True)
class Binary:
    """A ``binfile`` param's content (roslaunch's ``xmlrpc.client.Binary``)."""

    data: bytes


@dataclass(slots=True)
class Remap:
    condition: BDD
    source: Raw
    target: Raw
    location: Location | None = None
    """Where a node's own ``<remap>`` is written; None for one it inherits (a group's, a
    global one) or shares with other nodes (ROS 2 Python: one list given to several), which
    renames for every node it reaches: a node that never uses its name is then no mistake."""


@dataclass(slots=True)
class EnvSetting:
    condition: BDD
    name: Raw
    value: Raw


@dataclass(frozen=True, slots=True)
class NodeField:
    """One meaning of a node declaration (its namespace, its full name...), made of the raw
    fields ``keys`` by ``compute`` (None: the one key's value as it is). A dialect defines
    each once (:class:`NodeSchema`); readers take it for one variant's values (:meth:`of`)
    or over every configuration (:meth:`over`), instead of working it out again.

    ``compute`` is total: where a part is a term, the result is a term that computes the
    same once the inputs are known."""

    keys: tuple[str, ...]
    compute: Callable[[Sequence[Raw | None]], Raw | None] | None = None

    def of(self, values: Mapping[str, Raw | None]) -> Raw | None:
        """The meaning in one variant (absent fields None)."""
        if self.compute is None:
            return values.get(self.keys[0])
        return self.compute([values.get(key) for key in self.keys])

    def text(self, values: Mapping[str, str | None]) -> str | None:
        """The meaning of known strings: a string (or None) too."""
        value = self.of(values)
        assert value is None or isinstance(value, str)
        return value

    def over(self, fields: Mapping[str, Choice[Raw | None]]) -> Choice[Raw | None]:
        """The meaning in every configuration: a field read as it is stays the same
        :class:`Choice` (shared by the declarations of one scope)."""
        if self.compute is None:
            return fields[self.keys[0]]
        if not self.keys:  # a constant (:func:`constant_field`), in the fields' space
            false = next(iter(fields.values())).false
            assert false is not None  # a field is a choice of its space
            return Choice.of([(~false, self.compute(()))], false)
        return combine([fields[key] for key in self.keys], self.compute)


def constant_field(value: Raw | None) -> NodeField:
    """A meaning a dialect's nodes never vary in (ROS 1 has no composable node's plugin)."""
    return NodeField((), lambda _values: value)


@dataclass(frozen=True)
class NodeSchema:
    """How one dialect's node declarations read: their typed accessors, one definition
    each. The node tag of the dialect stamps its declarations with it (``NodeDecl.schema``).
    """

    version: RosVersion
    package: NodeField
    executable: NodeField
    name: NodeField
    """The node's own name as the launch file gives it (ROS 2: None, its code names it)."""
    namespace: NodeField
    """The namespace it is launched in (ROS 2: the pushed one, then its own, absolute;
    None where neither is given)."""
    full_name: NodeField
    """Its namespace joined with its name (None without a name)."""
    label: NodeField
    """The name people see: the full name, or (ROS 2, where its code names the node)
    ``⟨EXEC⟩`` in its namespace."""
    args: NodeField
    plugin: NodeField
    """A ROS 2 composable node's class."""
    lifecycle: NodeField
    """ROS 2: ``"true"`` for a node launch_ros starts as a ``LifecycleNode`` (it has the
    lifecycle interface whatever its code says), None for any other."""
    launched: tuple[str, ...]
    """The raw fields the accessors read, in the order a node's variants are formed."""

    def __post_init__(self) -> None:
        accessors = (self.package, self.executable, self.name, self.namespace)
        others = (self.full_name, self.label, self.args, self.plugin, self.lifecycle)
        for accessor in (*accessors, *others):
            missing = set(accessor.keys) - set(self.launched)
            if missing:
                raise ValueError(f"{self.version.label} node fields {missing} are not launched")


@dataclass(slots=True)
class NodeDecl:
    """A ``<node>`` or ``<test>``; ``fields`` hold raw strings (or None when absent), which
    ``schema`` (the dialect's) reads."""

    condition: BDD
    location: Location
    filename: str
    is_test: bool
    fields: dict[str, Choice[Raw | None]]
    remaps: list[Remap]
    env: list[EnvSetting]
    schema: NodeSchema
    # the args its scope sees (undefined ones as a non-text leaf), for conditions written
    # outside the launch files about the node: a hinted interface entry's ``when:``
    args: Mapping[str, Choice[object]] = field(default_factory=dict)
    parameters: list[NodeParameter] = field(default_factory=list)  # ROS 2: in order
    trigger: str = "launch"
    """ROS 2: what starts it: the launch, a timer (``timer@2s``), an event handler
    (``on_process_start(FILE:LINE:COL)``, the place of the action it waits for)."""

    def field(self, key: str) -> Choice[Raw | None]:
        return self.fields[key]

    def value(self, accessor: NodeField) -> Choice[Raw | None]:
        """``accessor`` (one of ``schema``'s) over every configuration."""
        return accessor.over(self.fields)

    @property
    def ros2(self) -> bool:
        """Whether ``ros2 launch`` starts it: its name composes a pushed namespace."""
        return self.schema.version is RosVersion.ROS2


@dataclass(slots=True)
class NodeParameter:
    """A ROS 2 node's parameter (``name`` and ``value``) or parameter file (``file``), in the
    order launch_ros passes them: later ones override earlier ones."""

    condition: BDD
    name: Raw | None
    value: Raw | None
    file: Raw | None = None
    globally: bool = False
    """Set for every later node (``<set_parameter>``, ``<set_parameters_from_file>``)."""
    kind: str | None = None
    """ROS 2's ``<param type>`` (``str``, ``int``, ...): how launch coerces the value's text
    (none: by YAML rules)."""
    content: Raw | None = None
    """A parameter file given ``allow_substs``: its text with the launch's substitutions
    performed (launch_ros writes it to a file of its own), read instead of ``file``."""


@dataclass(slots=True)
class ParamDecl:
    """One parameter set on the parameter server (dicts from YAML already unrolled)."""

    condition: BDD
    location: Location
    name: Choice[Raw]
    value: Choice[object]
    textfile: Choice[Raw] | None = None
    """The file a ``textfile`` param reads, per configuration: where its text is written
    (a robot description's findings name lines of it)."""


class RosparamLoad(Protocol):
    """The dialect's ``<rosparam>`` for concrete strings (roslaunch's
    ``Loader.load_rosparam``): the params it sets, or ValueError/OSError where roslaunch
    fails."""

    def __call__(
        self,
        command: str,
        ns: str | None,
        file: str | None,
        param: str | None,
        text: str,
        scope_ns: str,
        confinement: Confinement,
    ) -> list[tuple[str, object]]: ...


@dataclass(slots=True)
class YamlDecl:
    """A ``<rosparam>`` some of whose attributes are only known per configuration.

    Whoever learns the strings (resolution, the checks, the configuration's graph) evaluates
    the terms and loads it with its dialect's ``load``, as the interpreter loads a concrete
    one, with the same checks.
    """

    condition: BDD
    location: Location
    scope_ns: Raw
    command: Raw
    ns: Raw | None
    file: Raw | None
    param: Raw | None
    text: Raw
    load: RosparamLoad


@dataclass(slots=True)
class ClearParamDecl:
    condition: BDD
    location: Location
    name: Choice[Raw]


@dataclass(slots=True)
class MachineDecl:
    condition: BDD
    location: Location
    name: Choice[Raw]
    attributes: dict[str, Choice[Raw | None]]


INCLUDE_UNREAD = "include-unread"
"""The warning at an include of a dependency's file rosvar cannot read (not followed)."""


@dataclass(slots=True)
class IncludeDecl:
    """An ``<include>`` and what became of it (``resolved`` is False for unreadable targets)."""

    condition: BDD
    location: Location
    file: Choice[Raw]
    namespace: Choice[Raw]
    resolved: bool


class Guard(StrEnum):
    """The attribute of a conditional tag."""

    IF = "if"
    UNLESS = "unless"


@dataclass(slots=True)
class Decision:
    """An ``if``/``unless`` roslaunch evaluated (on path ``condition``): true where ``outcome``."""

    condition: BDD
    location: Location
    kind: Guard
    outcome: BDD


@dataclass(frozen=True, slots=True)
class Tested:
    """A value whose test failed where it was not known yet (``what``: ``<group> attribute
    'if'``): where one configuration cannot compute it either (over the work limits, a module
    not followed), that failure is the error, not the test's (a value rosvar gave up on is
    no "not a 'bool' type")."""

    what: str
    value: Choice[Raw]


@dataclass(slots=True)
class ErrorEvent:
    """Under ``condition`` roslaunch stops here with ``message`` (unless ``tested`` fails
    first)."""

    condition: BDD
    location: Location
    code: str
    message: str
    tested: Tested | None = None


@dataclass(slots=True)
class ArgDecl:
    """An ``<arg>`` declaration of the entry file (its inputs) or of an included file."""

    name: str
    location: Location
    condition: BDD
    default: str | None
    value: str | None
    doc: str | None
    input: ArgInput | None  # set for args a user can give on the command line


@dataclass
class LaunchModel:
    """Everything one entry file loads, for all configurations at once."""

    file: str
    space: ConditionSpace
    inputs: dict[str, ArgInput]
    domains: dict[str, tuple[Slot, ...]]
    args: list[ArgDecl] = field(default_factory=list)
    nodes: list[NodeDecl] = field(default_factory=list)
    params: list[ParamDecl | YamlDecl] = field(default_factory=list)
    clear_params: list[ClearParamDecl] = field(default_factory=list)
    machines: list[MachineDecl] = field(default_factory=list)
    includes: list[IncludeDecl] = field(default_factory=list)
    errors: list[ErrorEvent] = field(default_factory=list)
    decisions: list[Decision] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    files: list[str] = field(default_factory=list)
    unset_defaults: dict[str, str] = field(default_factory=dict)
    settable: dict[str, str] = field(default_factory=dict)
    """ROS 2: launch arguments the entry file does not declare that an included file declares
    where nothing set them yet, so the command line can (name -> the declaring file)."""
    anon_ids: set[str] = field(default_factory=set)  # bases of the $(anon) names generated
    anon_count: Choice[int] | None = None  # how many, per configuration
    loads: BDD = field(kw_only=True)
    """The configurations in which the file loads without error (the walk's ``finish``)."""


def anon_pattern(bases: Collection[str]) -> re.Pattern[str] | None:
    """The ``{base}_anon{n}`` names that stand for ``$(anon base)`` (the interpreter's
    counter in place of roslaunch's random part) inside a name; None without bases."""
    if not bases:
        return None
    alternatives = "|".join(re.escape(b) for b in sorted(bases, key=len, reverse=True))
    return re.compile(rf"(?<![\w])({alternatives})_anon(\d+)(?![\w])")
