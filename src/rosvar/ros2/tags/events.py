"""Event handlers (``RegisterEventHandler(OnProcessStart(...))``, as the Python frontend
writes them: ``<on_process_start target=...>`` holding the actions): registered where they
stand, their actions run when their event comes (:mod:`rosvar.ros2.events`), in the context
as it is then, marked with the trigger (``on_process_start(FILE:LINE:COL)``, the place of the
action whose process it waits for)."""

from __future__ import annotations

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed
from rosvar.ros2.api.event_handlers import EVENT_HANDLERS
from rosvar.ros2.context import Context, Handler
from rosvar.ros2.dialect import tag


@processed
def register(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    target = entity.get("target")
    label = f"{entity.tag}({target or ''})"
    context.events.handlers.append(Handler(entity.tag, target, it.pc, entity.children, label))


for _handler in EVENT_HANDLERS:
    tag(_handler.tag)(register)
