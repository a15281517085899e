"""``<timer period=...>`` (``TimerAction``) and ``<ros_timer>`` (launch_ros's ``ROSTimer``,
the same on ROS time, which starts with the launch): its actions run when it fires, after the
whole launch description has been visited, so in the context as it is *then* (every group
popped, later ``<let>``s applied), not where the timer stands.

``<shutdown>`` emits launch's ``Shutdown`` event, handled once the actions being visited are
done: it cancels every timer pending then whose ``cancel_on_shutdown`` holds (the default).
Processes started before or after it are launched all the same (the oracle records them; a
real launch then stops them)."""

from __future__ import annotations

import itertools

from rosvar.frontends.entity import Entity
from rosvar.interpreter.booleans import bool_value
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.logic.choice import combine
from rosvar.ros2.context import Context, Timer
from rosvar.ros2.dialect import tag

CREATED = itertools.count()
"""Creation order of timers, which breaks ties between equal times."""


@tag("timer")
@tag("ros_timer")
@processed
def timer(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    period = it.required(entity, "period", context)
    cancel = bool_value(
        it,
        it.attr(entity, "cancel_on_shutdown", context),
        True,
        f"<{entity.tag}> cancel_on_shutdown",
    )
    if period is None:
        return
    for condition, (text, cancelled) in split(it, combine([period, cancel], tuple)):
        try:
            seconds = float(text) if isinstance(text, str) else None
        except ValueError:
            seconds = None
        if seconds is None:
            it.fail(condition, "timer-period", f"<{entity.tag}> period '{text}' is not a number")
            continue
        if not isinstance(cancelled, bool):
            it.fail(condition, "value-unknown", f"<{entity.tag}> cancel_on_shutdown is unknown")
            continue
        context.timers.append(
            Timer(
                context.now + seconds,
                next(CREATED),
                it.pc & condition,
                entity.children,
                cancelled,
            )
        )


@tag("shutdown")
@processed
def shutdown(it: Interpretation[Context], entity: Entity, context: Context) -> None:
    it.attr(entity, "reason", context)  # read for the errors its substitutions raise
    context.shutdowns.append(it.pc)
