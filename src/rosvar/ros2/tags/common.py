"""Helpers shared by ROS 2 tag handlers."""

from __future__ import annotations

from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.model import Raw
from rosvar.logic.choice import Choice, ite
from rosvar.ros2.context import Context


def assign(
    it: Interpretation[Context], old: Choice[Raw | None] | None, new: Choice[Raw | None]
) -> Choice[Raw | None]:
    """``new`` on the current path, ``old`` (None where absent) elsewhere."""
    before = old if old is not None else Choice.const(it.space, None)
    if it.pc == it.space.true:
        return new
    return ite(it.space, it.pc, new, before)


def set_configuration(
    it: Interpretation[Context], context: Context, name: str, new: Choice[Raw | None]
) -> None:
    """Set the launch configuration ``name`` to ``new`` on the current path: its value
    before is read only where it stays somewhere (a recorded walk reads no more than it
    needs: :mod:`rosvar.ros2.include_memo`)."""
    if it.pc == it.space.true:
        context.configurations[name] = new
    else:
        context.configurations[name] = assign(it, context.get(name), new)
