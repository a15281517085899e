"""Boolean attributes, read as roslaunch's ``_bool_attr`` reads them (only ``true`` or
``false``, in any case), which ROS 2's tags share."""

from __future__ import annotations

from typing import TypeVar

from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.model import Raw
from rosvar.logic.choice import Choice, Fail

S = TypeVar("S")


def bool_attribute(value: str | None, default: bool, label: str) -> bool:
    """``_bool_attr``: only ``true``/``false`` (any case)."""
    if value is None:
        return default
    if value.lower() == "true":
        return True
    if value.lower() == "false":
        return False
    if not value:
        raise ValueError(f"bool value for {label} must be non-empty")
    raise ValueError(f"invalid bool value for {label}: {value}")


def bool_value(
    it: Interpretation[S], value: Choice[Raw] | None, default: bool, label: str
) -> Choice[bool | Raw]:
    """``_bool_attr`` per branch; terms stay raw and are checked on resolution."""
    if value is None:
        return Choice.const(it.space, default)

    def convert(leaf: Raw) -> bool | Raw | Fail:
        if not isinstance(leaf, str):
            return leaf
        try:
            return bool_attribute(leaf, default, label)
        except ValueError as error:
            return Fail(str(error), "bool-invalid")

    return it.strip(value.map(convert), label)
