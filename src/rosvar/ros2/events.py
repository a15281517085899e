"""The launch service's event loop after the description is visited: pending timers fire in
time order, and the shutdowns emitted since the previous round cancel those that allow it
(:mod:`rosvar.ros2.tags.timer` records both)."""

from __future__ import annotations

from rosvar.interpreter.interpretation import Interpretation
from rosvar.ros2.context import Context


def fire(it: Interpretation[Context], context: Context) -> None:
    """Run the pending timers in time order (ties in creation order), as the event loop,
    handling the shutdowns of each round of visits before the next timer fires."""
    _shut_down(it, context)
    while context.timers:
        first = min(context.timers, key=lambda t: (t.time, t.sequence))
        context.timers.remove(first)
        saved, context.now = context.now, first.time
        with it.under(first.condition) as live:
            if live:
                it.walk(first.actions, context)
        context.now = saved
        _shut_down(it, context)


def _shut_down(it: Interpretation[Context], context: Context) -> None:
    """The pending timers cancelled where a ``<shutdown>`` ran since the last round."""
    if not context.shutdowns:
        return
    when = it.space.false
    for condition in context.shutdowns:
        when |= condition
    context.shutdowns.clear()
    for pending in context.timers:
        if pending.cancel_on_shutdown:
            pending.condition &= ~when
    context.timers[:] = [t for t in context.timers if t.condition != it.space.false]
