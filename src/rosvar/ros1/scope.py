"""The variational counterpart of roslaunch's ``LoaderContext``.

A scope is the namespace, args, anon names, remaps, env settings and private
params visible at one point of a launch file. Values are
:class:`~rosvar.logic.choice.Choice` objects so one scope stands for every
configuration; the copy/share rules are roslaunch's (private params are shared
by reference across ``<include>``, copied at ``<group>``; args are copied into
children; an include starts from the args passed to it).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from rosvar.diagnostics import Location
from rosvar.interpreter.model import EnvSetting, Raw, Remap
from rosvar.interpreter.substitution_args import ArgValue
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice


@dataclass(slots=True)
class PrivateParam:
    """A ``~name`` param declared outside a node: applied to later nodes of the scope."""

    condition: BDD
    key: str
    value: Choice[object]
    location: Location


@dataclass(slots=True)  # one or two per tag: slots make them cheaper to build and read
class Scope:
    ns: Choice[Raw]
    filename: str
    parent: Scope | None = None
    remaps: list[Remap] = field(default_factory=list)
    params: list[PrivateParam] = field(default_factory=list)
    env: list[EnvSetting] = field(default_factory=list)
    args: dict[str, ArgValue] = field(default_factory=dict)
    anon: dict[str, ArgValue] = field(default_factory=dict)
    declared: dict[str, BDD] = field(default_factory=dict)
    include_args: dict[str, ArgValue] | None = None
    pass_all_args: bool = False

    def child(self, ns: Choice[Raw]) -> Scope:
        """``LoaderContext.child``: shares private params, copies the rest."""
        return Scope(  # every field given, in order: no default to make (one per tag)
            ns,
            self.filename,
            self,
            [],
            self.params,
            list(self.env),
            dict(self.args),
            dict(self.anon),
            dict(self.declared),
            self.include_args,
            False,
        )

    def include_child(self, ns: Choice[Raw], filename: str) -> Scope:
        """``LoaderContext.include_child``: arg declarations restart in the included file."""
        scope = self.child(ns)
        scope.declared = {}
        scope.filename = filename
        scope.include_args = {}
        return scope

    def remap_list(self) -> list[Remap]:
        """Inherited remaps, where a remap of this scope hides a parent's with the same source."""
        if self.parent is None:
            return list(self.remaps)
        return self.parent.remaps_with(self.remaps)

    def remaps_with(self, remaps: list[Remap]) -> list[Remap]:
        """The remaps of a child scope whose own are ``remaps`` (a node's), without making it."""
        if not remaps:
            return self.remap_list()
        inherited: list[Remap] = []
        for remap in self.remap_list():
            hidden = None
            for own in remaps:
                if own.source == remap.source:
                    hidden = own.condition if hidden is None else hidden | own.condition
            condition = remap.condition if hidden is None else remap.condition & ~hidden
            if condition != condition.bdd.false:
                inherited.append(Remap(condition, remap.source, remap.target))
        return inherited + list(remaps)
