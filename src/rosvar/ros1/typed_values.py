"""Typed values from strings, exactly as roslaunch converts them (but YAML, whose loader
with rosparam's tags is ``rosparam_yaml``: its ``!radians`` needs the ``$(eval)`` evaluator;
``auto`` is the evaluator's own conversion of args)."""

from __future__ import annotations

import functools

from rosvar.interpreter.safe_eval import convert_auto


@functools.lru_cache(maxsize=65536)
def convert_scalar(value: str, type_: str) -> object:
    """The non-YAML types (cached: the same texts recur in every includer, and the
    results are immutable, unlike a YAML value, which each caller gets fresh)."""
    if type_ == "auto":
        return convert_auto(value)
    if type_ in ("str", "string"):
        return value
    if type_ == "int":
        return int(value)
    if type_ == "double":
        return float(value)
    if type_ in ("bool", "boolean"):
        word = value.lower().strip()
        if word in ("true", "1"):
            return True
        if word in ("false", "0"):
            return False
        raise ValueError(f"{word} is not a '{type_}' type")
    raise ValueError(f"Unknown type '{type_}'")


def float_attribute(value: str | None, default: float, label: str) -> float:
    if value is None:
        return default
    if not value:
        raise ValueError(f"bool value for {label} must be non-empty")
    try:
        return float(value)
    except ValueError:
        raise ValueError(f"invalid float value for {label}: {value}") from None
