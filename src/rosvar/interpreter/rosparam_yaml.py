"""rosparam's YAML: PyYAML's safe loader with the tags rosparam adds."""

from __future__ import annotations

import math
import re
from typing import cast

import yaml

from rosvar.interpreter.model import Binary
from rosvar.interpreter.safe_eval import EvalEnvironment, evaluate

_SafeLoader: type[yaml.SafeLoader] = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


# ``yaml.SafeLoader`` with rosparam's additions (``!degrees``, ``!radians``, binary).
# rosparam registers these on PyYAML's global SafeLoader; a subclass keeps the behaviour
# without touching global state.
class RosparamLoader(_SafeLoader):  # type: ignore[valid-type,misc]
    """PyYAML's safe loader (the C one when built) with rosparam's tags."""


def _radians(loader: yaml.SafeLoader, node: yaml.Node) -> float:
    text = str(loader.construct_scalar(node)).strip()  # type: ignore[arg-type]
    expression = text[4:-1] if text.startswith("rad(") else text
    result = evaluate(expression, EvalEnvironment(lookup_arg=_no_arg, functions={}))
    return float(result)


def _degrees(loader: yaml.SafeLoader, node: yaml.Node) -> float:
    text = str(loader.construct_scalar(node))  # type: ignore[arg-type]
    expression = text.strip()[4:-1] if text.startswith("deg(") else text
    return float(expression) * math.pi / 180.0


def _binary(loader: yaml.SafeLoader, node: yaml.Node) -> object:
    return Binary(loader.construct_yaml_binary(cast(yaml.ScalarNode, node)))


def _no_arg(name: str) -> str:
    raise KeyError(name)


RosparamLoader.add_constructor("!radians", _radians)
RosparamLoader.add_constructor("!degrees", _degrees)
RosparamLoader.add_constructor("tag:yaml.org,2002:binary", _binary)
RosparamLoader.add_implicit_resolver("!degrees", re.compile(r"^deg\([^\)]*\)$"), ["d"])
RosparamLoader.add_implicit_resolver("!radians", re.compile(r"^rad\([^\)]*\)$"), ["r"])


def load_yaml(text: str) -> object:
    """A YAML text as rosparam loads it."""
    return yaml.load(text, Loader=RosparamLoader)
