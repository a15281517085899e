"""The launch service's event loop after the description is visited: pending timers fire in
time order, and the shutdowns emitted since the previous round cancel those that allow it
(:mod:`rosvar.ros2.tags.timer` records both)."""

from __future__ import annotations

from rosvar.interpreter.interpretation import Interpretation
from rosvar.logic.bdd import BDD
from rosvar.ros2.api.event_handlers import EVENT_HANDLERS
from rosvar.ros2.context import Context, Handler

MAX_ROUNDS = 16
"""Rounds of process-start handlers starting processes that start handlers (a chain)."""


def fire(it: Interpretation[Context], context: Context) -> None:
    """Run the pending timers in time order (ties in creation order), as the event loop,
    handling the process starts and the shutdowns of each round of visits before the next
    timer fires; then the handlers whose events come later (exits, output, transitions,
    the shutdown), whose actions are marked so."""
    fired: dict[int, BDD] = {}
    _started(it, context, fired)
    _shut_down(it, context)
    while context.timers:
        first = min(context.timers, key=lambda t: (t.time, t.sequence))
        context.timers.remove(first)
        saved, context.now = context.now, first.time
        context.trigger = f"timer@{first.time:g}s"
        with it.under(first.condition) as live:
            if live:
                it.walk(first.actions, context)
        context.now, context.trigger = saved, "launch"
        _started(it, context, fired)
        _shut_down(it, context)
    _later(it, context)


def _when(it: Interpretation[Context], context: Context, handler: Handler) -> BDD:
    """Where ``handler``'s event comes: its target's process started (any process: no
    target; the shutdown: always)."""
    started = context.events.started
    if handler.tag == "on_shutdown":
        return handler.condition
    if handler.target is None:
        when = it.space.false
        for condition in started.values():
            when |= condition
        return handler.condition & when
    return handler.condition & started.get(handler.target, it.space.false)


def _started(it: Interpretation[Context], context: Context, fired: dict[int, BDD]) -> None:
    """Run the process-start handlers whose targets started since they last ran."""
    for _round in range(MAX_ROUNDS):
        progress = False
        for handler in list(context.events.handlers):
            if not EVENT_HANDLERS.by_name[handler.tag].at_launch:
                continue
            done = fired.get(id(handler), it.space.false)
            new = _when(it, context, handler) & ~done
            if new == it.space.false:
                continue
            fired[id(handler)] = done | new
            progress = True
            _run(it, context, handler, new)
        if not progress:
            return


def _later(it: Interpretation[Context], context: Context) -> None:
    """The handlers whose events come after the launch started: each runs once where its
    event may come, its actions marked with its trigger (nothing the launch starts)."""
    for handler in list(context.events.handlers):
        if not EVENT_HANDLERS.by_name[handler.tag].at_launch:
            _run(it, context, handler, _when(it, context, handler))


def _run(it: Interpretation[Context], context: Context, handler: Handler, when: BDD) -> None:
    saved, context.trigger = context.trigger, handler.label
    with it.under(when) as live:
        if live:
            it.walk(handler.actions, context)
    context.trigger = saved


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
