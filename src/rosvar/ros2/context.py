"""The variational counterpart of ros2/launch's ``LaunchContext``.

Unlike roslaunch's scopes, launch configurations are global: an ``<include>`` does
not scope them (an ``<arg>`` or ``<let>`` of an included file leaks to the includer);
only a scoped ``<group>`` pushes a copy and pops it. The pushed namespace, global
remaps and global params live in launch configurations too, so they follow the
same rule (with a twist, see :meth:`Context.scoped`).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum, auto

from rosvar.frontends.entity import Entity
from rosvar.interpreter.model import Raw
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import UNSET, ArgInput

Configuration = Choice[Raw | None]
"""A launch configuration's value per configuration; None where it is not set."""


@dataclass(slots=True)
class GlobalParam:
    """A ``<set_parameter>`` (``name``, ``value``) or ``<set_parameters_from_file>``
    (``file``): prepended to the parameters of later nodes."""

    condition: BDD
    name: Raw | None
    value: Raw | None
    file: Raw | None = None


@dataclass(slots=True)
class GlobalRemap:
    """A ``<set_remap>``: prepended to the remappings of later nodes."""

    condition: BDD
    source: Raw
    target: Raw


@dataclass(slots=True)
class Timer:
    """A ``<timer>``'s actions, run at ``time`` in the context as it is then."""

    time: float
    sequence: int
    condition: BDD
    actions: list[Entity]
    cancel_on_shutdown: bool  # a shutdown cancels it while pending (the default)


@dataclass(slots=True)
class Handler:
    """A registered event handler (``RegisterEventHandler``): its actions run when its event
    comes, in the context as it is then, as a timer's."""

    tag: str
    target: str | None  # where the action it waits for was written; None: any
    condition: BDD
    actions: list[Entity]
    label: str  # the trigger its actions are marked with: on_process_start(...)


@dataclass(slots=True)
class Events:
    """The event handlers registered and the processes started, shared by every copy of a
    context: launch's handlers are global."""

    handlers: list[Handler] = field(default_factory=list)
    started: dict[str, BDD] = field(default_factory=dict)
    """Where each process action (by where it was written) started, and on what trigger."""


class Probe(Enum):
    """What a walk reads of the state before it, besides its context's fixed parts (the
    include memo's keys: :mod:`rosvar.ros2.include_memo`)."""

    CONFIGURATION = auto()  # a launch configuration's value
    INPUT = auto()  # whether the entry file's model has the name as an input
    LISTED = auto()  # whether an included file's declaration of it is listed in the model
    NAMES = auto()  # the names of every launch configuration set (``<reset>`` reads them)


@dataclass(slots=True)
class Recording:
    """What the included files' walks being recorded (:mod:`rosvar.ros2.include_memo`) read
    and met, shared by every copy of a context: each walk takes the part of the logs from
    its start."""

    walks: int = 0  # walks being recorded (nested ones included): the logs are kept
    reads: list[tuple[Probe, str, object]] = field(default_factory=list)
    """Each read, with what it saw (a configuration's value, or the probe's answer)."""
    included: list[str] = field(default_factory=list)
    """The real path of each file an include named, as the cycle check saw it."""
    loaded: list[str] = field(default_factory=list)
    """Each launch file an include loaded, as the model lists it."""
    entered: list[tuple[int, str, str | None]] = field(default_factory=list)
    """Each name a walk made an input of the entry model (with the file declaring it) or
    listed among its args (None), after how many reads: its later reads of that name's
    standing follow from the walk itself."""
    deepest_check: int = -1
    """The longest include stack an include's depth limit was checked at (-1: none)."""


@dataclass(slots=True)
class Forgetting:
    """Whether a ``<reset>`` or a group that does not forward them forgot the launch
    configurations, on some path: shared by every copy of a context. From then on an
    included file's arg unset at its declaration may be one the command line gave and a
    later interpretation, knowing it from the start, sees forgotten."""

    happened: bool = False


@dataclass(slots=True)
class Context:
    """Launch configurations and the ROS-specific state kept beside them."""

    filename: str
    configurations: dict[str, Configuration] = field(default_factory=dict)
    namespace: Choice[Raw | None] | None = None
    remaps: list[GlobalRemap] | None = None
    params: list[GlobalParam] | None = None
    env: dict[str, Choice[Raw | None]] = field(default_factory=dict)
    timers: list[Timer] = field(default_factory=list)  # pending, shared by every copy
    shutdowns: list[BDD] = field(default_factory=list)  # shared by every copy
    """Conditions of the ``<shutdown>``s met since the event loop last ran."""
    now: float = 0.0  # the virtual time of the actions being visited
    open_command_line: bool = False
    """Over every command line (the variational model): any ``name:=value`` may be given."""
    unset_reads: set[str] = field(default_factory=set)  # shared by every copy
    """Launch configurations ``$(var)`` read where they were not set."""
    events: Events = field(default_factory=Events)  # shared by every copy
    trigger: str = "launch"
    """What runs the actions being visited: the launch, a timer, an event (as the oracle's
    ``trigger``)."""
    recording: Recording = field(default_factory=Recording)  # shared by every copy
    forgetting: Forgetting = field(default_factory=Forgetting)  # shared by every copy

    def get(self, name: str) -> Configuration | None:
        """The launch configuration ``name`` (None where never set): the one door through
        which walks read them, so that a walk being recorded knows what it read."""
        value = self.configurations.get(name)
        recording = self.recording
        if recording.walks:
            recording.reads.append((Probe.CONFIGURATION, name, value))
        return value

    def scoped(self) -> Context:
        """A copy for a scoped group (``PushLaunchConfigurations``).

        The copy is shallow, as launch's: ``<set_remap>`` and ``<set_parameter>`` append
        to the lists in place, so inside a group they reach past it when the list existed
        before the group (and not when the group made it).
        """
        return Context(
            self.filename,
            dict(self.configurations),
            self.namespace,
            self.remaps,
            self.params,
            dict(self.env),
            self.timers,
            self.shutdowns,
            self.now,
            self.open_command_line,
            self.unset_reads,
            self.events,
            self.trigger,
            self.recording,
            self.forgetting,
        )

    def reset(self) -> None:
        """``<reset>``: no launch configuration left, nor what launch_ros keeps in them."""
        self.configurations = {}
        self.namespace = None
        self.remaps = None
        self.params = None

    def restore(self, saved: Context) -> None:
        """``PopLaunchConfigurations``: back to ``saved``'s state."""
        self.configurations = saved.configurations
        self.namespace = saved.namespace
        self.remaps = saved.remaps
        self.params = saved.params
        self.env = saved.env


def optional(value: Choice[Raw]) -> Choice[Raw | None]:
    """A value as a possibly-unset one (a configuration's or the namespace's type): the
    same choice, whose type only widens (no copy: every ``<arg>`` and ``<let>`` takes one)."""
    return value


def unset_as_given(space: ConditionSpace, entry: str, name: str, unset: BDD) -> bool:
    """Whether launch configuration ``name`` is unset (``unset``) only where the command line
    does not give it: where ``entry``'s input ``name`` (declared) is ``<unset>``.

    An included file's arg that no interpretation of ``entry`` knew from the start has the
    unset value under the writes before its declaration where a later one knowing it has the
    command line's (``Analysis._interpret``). Both build their values by the same writes,
    the command line's innermost, so where nothing but the command line's ``<unset>`` is
    left unset the two values are the same choice: reading it needs no other
    interpretation."""
    return unset & ~space.slot(ArgInput(entry, name), UNSET) == space.false
