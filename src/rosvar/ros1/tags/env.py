"""``<env>``: an environment variable for the nodes of the scope."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.model import EnvSetting
from rosvar.ros1.dialect import tag
from rosvar.ros1.scope import Scope

ATTRIBUTES = ("name", "value")


@tag("env")
@processed
def handle_env(it: Interpretation[Scope], entity: Entity, scope: Scope) -> None:
    it.check_attributes(entity, ATTRIBUTES)
    name = it.required(entity, "name", scope)
    value = it.required(entity, "value", scope)
    if name is None or value is None:
        return
    it.fail(name.where(lambda v: v == ""), "env-invalid", "'name' attribute must be non-empty")
    for n_condition, n in split(it, name.restrict(name.where(lambda v: v != ""))):
        for v_condition, v in split(it, value):
            scope.env.append(EnvSetting(it.pc & n_condition & v_condition, n, v))
