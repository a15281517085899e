"""``<group>``: a child scope with its own namespace, args and params."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed
from rosvar.ros1.dialect import tag
from rosvar.ros1.scope import Scope
from rosvar.ros1.tags.common import namespace_scope

ATTRIBUTES = ("ns", "clear_params")


@tag("group")
@processed
def handle_group(it: Interpretation[Scope], entity: Entity, scope: Scope) -> None:
    it.check_attributes(entity, ATTRIBUTES)
    child = namespace_scope(it, "group", entity, scope)
    child.params = list(child.params)
    it.walk(entity.children, child)
