"""``<master>``: defunct since ROS Fuerte; roslaunch ignores it with a warning."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation
from rosvar.ros1.dialect import tag
from rosvar.ros1.scope import Scope


@tag("master")
def handle_master(it: Interpretation[Scope], entity: Entity, scope: Scope) -> None:
    _ = scope
    it.sink.note("master-ignored", "ignoring defunct <master /> tag", entity.location)
