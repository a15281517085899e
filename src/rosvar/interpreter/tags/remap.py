"""``<remap>``: rename a topic or service for the nodes of the scope."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, split, tag
from rosvar.interpreter.model import Raw, Remap
from rosvar.interpreter.scope import Scope
from rosvar.logic.terms import Apply
from rosvar.ros import names

ATTRIBUTES = ("from", "to")


def remap_pairs(it: Interpretation, entity: Entity, scope: Scope) -> list[Remap]:
    """The remaps a ``<remap>`` adds on the current path (``_remap_tag`` + ``add_remap``)."""
    with it.under(it.condition_of(entity, scope)) as live:
        if not live:
            return []
        it.check_attributes(entity, ATTRIBUTES)
        sources = it.required(entity, "from", scope)
        targets = it.required(entity, "to", scope)
        if sources is None or targets is None:
            return []
        result = []
        for s_condition, source in split(it, sources):
            for t_condition, target in split(it, targets):
                condition = it.pc & s_condition & t_condition
                if condition == it.space.false:
                    continue
                with it.under(condition):
                    pair = _canonical_pair(it, source, target)
                if pair is not None:
                    result.append(Remap(condition, *pair))
        return result


def _canonical(value: Raw) -> Raw:
    if isinstance(value, str):
        return names.canonicalize_name(value)
    return Apply("canonicalize", (value,))


def _canonical_pair(it: Interpretation, source: Raw, target: Raw) -> tuple[Raw, Raw] | None:
    source, target = _canonical(source), _canonical(target)
    for label, value in (("from", source), ("to", target)):
        if value == "":
            it.fail(it.space.true, "remap-invalid", "remap from/to attributes cannot be empty")
            return None
        if isinstance(value, str) and not names.is_legal_name(value):
            it.fail(
                it.space.true,
                "remap-invalid",
                f"remap {label} [{value}] is not a valid ROS name",
            )
            return None
    return source, target


def add_remap(remaps: list[Remap], new: Remap) -> None:
    """A remap hides earlier ones with the same source (on its path)."""
    kept = []
    for remap in remaps:
        if remap.source == new.source:
            remap = Remap(remap.condition & ~new.condition, remap.source, remap.target)
            if remap.condition == remap.condition.bdd.false:
                continue
        kept.append(remap)
    kept.append(new)
    remaps[:] = kept


@tag("remap")
def handle_remap(it: Interpretation, entity: Entity, scope: Scope) -> None:
    for remap in remap_pairs(it, entity, scope):
        add_remap(scope.remaps, remap)
