"""``<timer period=...>`` (``TimerAction``): its actions run when it fires, after the whole
launch description has been visited, so in the context as it is *then* (every group popped,
later ``<let>``s applied), not where the timer stands."""

from __future__ import annotations

import itertools

from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation, processed, split
from rosvar.interpreter.ros2.context import Context, Timer
from rosvar.interpreter.ros2.dialect import tag

CREATED = itertools.count()
"""Creation order of timers, which breaks ties between equal times."""


@tag("timer")
@processed
def timer(it: Interpretation, entity: Entity, context: Context) -> None:
    period = it.required(entity, "period", context)
    if period is None:
        return
    for condition, text in split(it, period):
        try:
            seconds = float(text) if isinstance(text, str) else None
        except ValueError:
            seconds = None
        if seconds is None:
            it.fail(condition, "timer-period", f"<timer> period '{text}' is not a number")
            continue
        context.timers.append(
            Timer(context.now + seconds, next(CREATED), it.pc & condition, entity.children)
        )


def fire(it: Interpretation, context: Context) -> None:
    """Run the pending timers in time order (ties in creation order), as the event loop."""
    while context.timers:
        first = min(context.timers, key=lambda t: (t.time, t.sequence))
        context.timers.remove(first)
        saved, context.now = context.now, first.time
        with it.under(first.condition) as live:
            if live:
                it.walk(first.actions, context)
        context.now = saved
