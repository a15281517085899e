"""The values a launched node's parameter takes, in every configuration at once.

A hinted interface entry may exist only for some values of the node's own parameters
(``when: "param('~use_imu')"``, docs/hints.md). The parameter server holds what the launched
files set: every ``<param>`` and ``<rosparam>`` of the configuration under its presence
condition, the last one loaded winning (roslaunch sets them in load order); where none sets
the name, the node reads the default its source gives. Each value is kept as ``rosvar
resolve`` shows it (:func:`json_value`), so that a configuration's value and the variational
one compare alike.

A value analysis cannot know is an :class:`Unknown` leaf, never a guess: a value that is a
term (an arg typed at configuration time), a ``<rosparam>`` whose names are only known per
configuration (it may set anything below its namespace), a default that is an expression,
or no value at all (nothing sets it and the node gives no default).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from rosvar.analyses.json_values import json_value
from rosvar.interpreter.model import DeferredValue, LaunchModel, ParamDecl, YamlDecl
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.terms import Term
from rosvar.ros import names
from rosvar.workspace.interfaces.model import Default, Expression


@dataclass(frozen=True)
class Unknown:
    """A parameter value analysis cannot know, and why; ``term`` when it is the text of one
    term (converted as its ``<param>`` says once a configuration types it)."""

    reason: str
    term: Term | None = None


UNSET = Unknown("no launch file sets it and the node gives no default")
ROS2_PARAMETERS = Unknown("a ROS 2 node's own parameters are not read")


@dataclass(frozen=True)
class _Setting:
    """One name set by a ``<param>`` (or anything below ``name`` by a ``<rosparam>``
    that is only known per configuration), under ``condition``."""

    condition: BDD
    name: str
    value: Choice[object]
    below: bool = False


class ParamValues:
    """Every value each parameter name can have, from the settings of launched files."""

    def __init__(self, space: ConditionSpace, launched: Iterable[tuple[BDD, LaunchModel]]) -> None:
        """``launched``: each model with the condition under which it is launched, in the
        order roslaunch loads them (iterated on the first question: most graphs ask none)."""
        self.space = space
        self._launched = launched
        self._read: list[_Setting] | None = None
        self._by_name: dict[str, list[int]] = {}  # indices into the settings, in order
        self._below: list[int] = []  # the settings that may set anything below a namespace

    def _settings(self) -> list[_Setting]:
        if self._read is not None:
            return self._read
        found: list[_Setting] = []
        self._read = found
        for condition, model in self._launched:
            for param in model.params:
                within = condition & param.condition
                if isinstance(param, ParamDecl):
                    self._add_param(found, within, param)
                elif within != self.space.false:
                    unknown = Unknown(f"a <rosparam> at {param.location} may set it")
                    value = Choice.const(self.space, unknown)
                    found.append(_Setting(within, _loaded_below(param), value, True))
        for index, setting in enumerate(found):
            if setting.below:
                self._below.append(index)
            else:
                self._by_name.setdefault(setting.name, []).append(index)
        return found

    def _add_param(self, found: list[_Setting], within: BDD, param: ParamDecl) -> None:
        """Its names known statically only (a name that is a term is not matched)."""
        value = param.value.map(_value)
        for branch, name in param.name:
            condition = within & branch
            if isinstance(name, str) and condition != self.space.false:
                found.append(_Setting(condition, _canonical(name), value))

    def names(self) -> list[str]:
        """The names the launched files set statically (canonical, global)."""
        self._settings()
        return sorted(self._by_name)

    def values(self, name: str, default: Default | None) -> Choice[object]:
        """The values of the resolved ``name``: the last setting that holds wins, else the
        node's ``default`` (else :data:`UNSET`)."""
        name = _canonical(name)
        settings = self._settings()
        below = [i for i in self._below if name.startswith(settings[i].name.rstrip("/") + "/")]
        branches: list[tuple[BDD, object]] = []
        remaining = self.space.true
        for index in sorted(self._by_name.get(name, []) + below, reverse=True):
            setting = settings[index]
            taken = remaining & setting.condition
            if taken != self.space.false:
                branches.extend((taken & c, v) for c, v in setting.value)
            remaining &= ~setting.condition
        if remaining != self.space.false:
            branches.append((remaining, param_default(default)))
        return Choice.of(branches, self.space.false)


def _loaded_below(param: YamlDecl) -> str:
    """The namespace a ``<rosparam>`` known only per configuration loads into: its scope's,
    narrowed by its ``ns`` and ``param`` where they are known."""
    scope = param.scope_ns if isinstance(param.scope_ns, str) else names.SEP
    for part in (param.ns, param.param):
        if not isinstance(part, str) or names.is_private(part) or names.is_private(scope):
            break
        scope = names.ns_join(names.make_global_ns(scope), part)
    return _canonical(scope)


def _canonical(name: str) -> str:
    return names.canonicalize_name(name if names.is_global(name) else names.SEP + name)


def _value(value: object) -> object:
    if isinstance(value, DeferredValue):
        return Unknown(f"its value is {value.raw}, known once typed", value.raw)
    return json_value(value)


def param_default(default: Default | None) -> object:
    """The value a node reads where nothing sets the parameter."""
    if default is None:
        return UNSET
    if isinstance(default, Expression):
        return Unknown(f"its default is the expression {default.text}")
    return json_value(default)
