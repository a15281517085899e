"""``roslaunch FILE name:=value``: the entry file's args are the command line's, in a scope at
``/``."""

from __future__ import annotations

from collections.abc import Mapping

from rosvar.frontends.entity import Entity
from rosvar.interpreter.domains import entry_declarations
from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.substitution_args import MISSING
from rosvar.logic.choice import Choice
from rosvar.ros.names import settable
from rosvar.ros1.scope import Scope


def walk_entry(
    it: Interpretation[Scope], file: str, root: Entity, _undeclared: Mapping[str, str]
) -> set[str]:
    """Walk the entry file over every command line (roslaunch reads every arg where it is
    declared: none is read before)."""
    deprecated = root.get("deprecated")
    if deprecated:
        it.sink.note("launch-deprecated", f"DEPRECATED: {deprecated}", root.location)
    names = list(
        dict.fromkeys(
            d.get("name") or "" for d in entry_declarations(root) if settable(d.get("name") or "")
        )
    )
    args = it.entry_args(file, names, MISSING)
    scope = Scope(ns=Choice.const(it.space, "/"), filename=file, args=args)
    with it.at(root):
        it.walk(root.children, scope)
    return set()
