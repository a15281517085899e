"""xacro's symbol and macro tables, for every configuration at once.

xacro keeps properties (and, apart, macros) in nested tables: the document's, one per macro
call, one per namespace of an include. A definition under ``<xacro:if>`` exists only where
the condition holds, so each entry is a :class:`Choice` over the configurations, with
:data:`ABSENT` where this table does not define the name (a lookup then goes on to the
parent, as xacro's does). A property is read lazily: its text is stored (:class:`Lazy`) and
evaluated, in the table that holds it, on first use; xacro keeps that first value, so the
walk does too, where the use happened (``ite`` under the path condition).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Final

from rosvar.analyses.robot_description.literals import XACRO_GLOBALS
from rosvar.diagnostics import Location
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice, ite
from rosvar.logic.conditions import ConditionSpace


class _Absent:
    def __repr__(self) -> str:
        return "<absent>"


ABSENT: Final = _Absent()
"""Leaf of an entry where its table does not define the name."""


@dataclass(frozen=True)
class Lazy:
    """A property's text, evaluated on first use (``lazy_eval``, xacro's default)."""

    text: str
    location: Location


Resolver = Callable[[Lazy, "Table"], Choice[object]]
"""Evaluates a lazy property's text in the table that holds it (the walk's ``eval_text``)."""


class Table:
    """One scope: entries by name, a parent (None: xacro's global symbols)."""

    def __init__(
        self,
        space: ConditionSpace,
        parent: Table | None,
        within: BDD,
        namespace: bool = False,
    ) -> None:
        self.space = space
        self.parent = parent
        self.within = within
        """Where the table exists (a macro call's: its path condition): a name set wherever
        it exists needs no branch for the configurations where it does not."""
        self.namespace = namespace  # an include's ``ns``: skipped by ``scope="parent"``
        self.entries: dict[str, Choice[object]] = {}

    def child(self, within: BDD, namespace: bool = False) -> Table:
        return Table(self.space, self, within, namespace)

    def top(self) -> Table:
        """The document's table (``scope="global"``)."""
        table = self
        while table.parent is not None:
            table = table.parent
        return table

    def defined(self, name: str) -> BDD:
        """Where ``name`` is in this table or a parent (``name in table``), lazy or not;
        xacro's global symbols count."""
        if name in XACRO_GLOBALS:
            return self.space.true
        result = self.space.false
        table: Table | None = self
        while table is not None:
            entry = table.entries.get(name)
            if entry is not None:
                result |= entry.where(lambda leaf: leaf is not ABSENT)
            table = table.parent
        return result

    def lookup(self, name: str, pc: BDD, resolve: Resolver) -> Choice[object]:
        """The value of ``name`` (:data:`ABSENT` where no table defines it); a lazy
        property met under ``pc`` is evaluated and kept there."""
        entry = self.entries.get(name)
        if entry is None:
            return self._up(name, pc, resolve)
        if all(leaf is not ABSENT and not isinstance(leaf, Lazy) for leaf in entry.values()):
            return entry
        branches: list[tuple[BDD, object]] = []
        for condition, leaf in entry:
            if leaf is ABSENT:
                value = self._up(name, pc, resolve)
            elif isinstance(leaf, Lazy):
                value = resolve(leaf, self).restrict(condition)
                self.entries[name] = ite(self.space, pc & condition, value, self.entries[name])
            else:
                value = Choice.const(self.space, leaf)
            branches.extend((condition & c, v) for c, v in value)
        return Choice.of(branches, self.space.false)

    def _up(self, name: str, pc: BDD, resolve: Resolver) -> Choice[object]:
        if self.parent is None:
            return Choice.const(self.space, ABSENT)
        return self.parent.lookup(name, pc, resolve)

    def set(self, name: str, value: Choice[object], pc: BDD) -> None:
        """``name`` set to ``value`` where ``pc`` holds (its old entry elsewhere)."""
        old = self.entries.get(name)
        if pc == self.within:
            self.entries[name] = value
            return
        if old is None:
            old = Choice.const(self.space, ABSENT)
        self.entries[name] = ite(self.space, pc, value, old)

    def clear(self) -> None:
        """Forget every entry, and those of the namespaces held here (an include's namespace
        table refers back to this one: a cycle would keep the BDDs alive)."""
        for entry in self.entries.values():
            for leaf in entry.values():
                if isinstance(leaf, Table):
                    leaf.clear()
        self.entries.clear()

    def remove(self, name: str, pc: BDD) -> None:
        """xacro's ``del``: gone from this table and every parent, where ``pc`` holds."""
        absent = Choice.const(self.space, ABSENT)
        table: Table | None = self
        while table is not None:
            if name in table.entries:
                table.set(name, absent, pc)
            table = table.parent
