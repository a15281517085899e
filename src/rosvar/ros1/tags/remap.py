"""``<remap>``: rename a topic or service for the nodes of the scope."""

from __future__ import annotations

import functools
from dataclasses import replace

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import Raw, Remap
from rosvar.logic.terms import Apply
from rosvar.ros import names
from rosvar.ros1.dialect import tag
from rosvar.ros1.scope import Scope

ATTRIBUTES = ("from", "to")


@processed
def add_remaps(
    it: Interpretation[Scope], entity: Entity, scope: Scope, remaps: list[Remap], own: bool = False
) -> None:
    """Add to ``remaps`` what a ``<remap>`` adds on the current path (``_remap_tag`` +
    ``add_remap``): a scope's, or a node's ``own`` (located)."""
    it.check_attributes(entity, ATTRIBUTES)
    sources = it.required(entity, "from", scope)
    targets = it.required(entity, "to", scope)
    if sources is None or targets is None:
        return
    for s_condition, source in split(it, sources):
        for t_condition, target in split(it, targets):
            condition = it.pc & s_condition & t_condition
            if condition == it.space.false:
                continue
            with it.under(condition):
                pair = _canonical_pair(it, source, target)
            if pair is not None:
                add_remap(remaps, Remap(condition, *pair, it.location if own else None))


@functools.lru_cache(maxsize=65536)
def _canonical_text(text: str) -> tuple[str, bool]:
    """A remap name canonicalised, and whether that is a legal name (cached: the same
    names recur in every includer)."""
    canonical = names.canonicalize_name(text)
    return canonical, canonical == "" or names.is_legal_name(canonical)


def _canonical_pair(it: Interpretation[Scope], source: Raw, target: Raw) -> tuple[Raw, Raw] | None:
    pair: list[Raw] = []
    for label, value in (("from", source), ("to", target)):
        if not isinstance(value, str):
            pair.append(Apply("canonicalize", (value,)))
            continue
        canonical, legal = _canonical_text(value)
        if canonical == "":
            it.fail(it.space.true, "remap-invalid", "remap from/to attributes cannot be empty")
            return None
        if not legal:
            it.fail(
                it.space.true,
                "remap-invalid",
                f"remap {label} [{canonical}] is not a valid ROS name",
            )
            return None
        pair.append(canonical)
    return pair[0], pair[1]


def add_remap(remaps: list[Remap], new: Remap) -> None:
    """A remap hides earlier ones with the same source (on its path)."""
    kept = []
    for remap in remaps:
        if remap.source == new.source:
            remap = replace(remap, condition=remap.condition & ~new.condition)
            if remap.condition == remap.condition.bdd.false:
                continue
        kept.append(remap)
    kept.append(new)
    remaps[:] = kept


@tag("remap")
def handle_remap(it: Interpretation[Scope], entity: Entity, scope: Scope) -> None:
    add_remaps(it, entity, scope, scope.remaps)
