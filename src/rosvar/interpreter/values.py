"""Typed values from strings, exactly as roslaunch converts them."""

from __future__ import annotations

import functools
import math
import re
from typing import cast

import yaml


def convert_value(value: str, type_: str) -> object:
    """roslaunch's ``convert_value``: ``auto`` guesses int, float, bool, then str."""
    type_ = type_.lower()
    if type_ == "yaml":
        try:
            return load_yaml(value)
        except yaml.parser.ParserError as error:
            raise ValueError(str(error)) from error
    return _convert_scalar(value, type_)


@functools.lru_cache(maxsize=65536)
def _convert_scalar(value: str, type_: str) -> object:
    """The non-YAML types (cached: the same texts recur in every includer, and the
    results are immutable, unlike a YAML value, which each caller gets fresh)."""
    if type_ == "auto":
        try:
            if "." in value:
                return float(value)
            if "_" not in value:
                return int(value)
        except ValueError:
            pass
        if value.lower() in ("true", "false"):
            return _convert_scalar(value, "bool")
        return value
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


def float_attribute(value: str | None, default: float, label: str) -> float:
    if value is None:
        return default
    if not value:
        raise ValueError(f"bool value for {label} must be non-empty")
    try:
        return float(value)
    except ValueError:
        raise ValueError(f"invalid float value for {label}: {value}") from None


_SafeLoader: type[yaml.SafeLoader] = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


# ``yaml.SafeLoader`` with rosparam's additions (``!degrees``, ``!radians``, binary).
# rosparam registers these on PyYAML's global SafeLoader; a subclass keeps the behaviour
# without touching global state.
class RosparamLoader(_SafeLoader):  # type: ignore[valid-type,misc]
    """PyYAML's safe loader (the C one when built) with rosparam's tags."""


def _radians(loader: yaml.SafeLoader, node: yaml.Node) -> float:
    from rosvar.interpreter.evaluator import EvalEnvironment, evaluate

    text = str(loader.construct_scalar(node)).strip()  # type: ignore[arg-type]
    expression = text[4:-1] if text.startswith("rad(") else text
    result = evaluate(expression, EvalEnvironment(lookup_arg=_no_arg, functions={}))
    return float(result)


def _degrees(loader: yaml.SafeLoader, node: yaml.Node) -> float:
    text = str(loader.construct_scalar(node))  # type: ignore[arg-type]
    expression = text.strip()[4:-1] if text.startswith("deg(") else text
    return float(expression) * math.pi / 180.0


def _binary(loader: yaml.SafeLoader, node: yaml.Node) -> object:
    from rosvar.interpreter.model import Binary

    return Binary(loader.construct_yaml_binary(cast(yaml.ScalarNode, node)))


def _no_arg(name: str) -> str:
    raise KeyError(name)


RosparamLoader.add_constructor("!radians", _radians)
RosparamLoader.add_constructor("!degrees", _degrees)
RosparamLoader.add_constructor("tag:yaml.org,2002:binary", _binary)
RosparamLoader.add_implicit_resolver("!degrees", re.compile(r"^deg\([^\)]*\)$"), ["d"])
RosparamLoader.add_implicit_resolver("!radians", re.compile(r"^rad\([^\)]*\)$"), ["r"])


def load_yaml(text: str) -> object:
    return yaml.load(text, Loader=RosparamLoader)
