"""rosparam's YAML: PyYAML's safe loader with the tags rosparam adds, within limits.

Every failure (syntax, a refused tag, a ``rad()`` expression that raises, a limit of
:mod:`rosvar.bounded_yaml`) is one :class:`YamlInvalid`: the YAML comes from
files nobody vetted, and no problem in it may stop the analysis.
"""

from __future__ import annotations

import math
import re
from typing import cast

import yaml

from rosvar.bounded_yaml import check_limits
from rosvar.interpreter.model import Binary
from rosvar.interpreter.safe_eval import EvalEnvironment, EvalFailed, EvalRefused, evaluate

_SafeLoader: type[yaml.SafeLoader] = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


# ``yaml.SafeLoader`` with rosparam's additions (``!degrees``, ``!radians``, binary).
# rosparam registers these on PyYAML's global SafeLoader; a subclass keeps the behaviour
# without touching global state.
class RosparamLoader(_SafeLoader):  # type: ignore[valid-type,misc]
    """PyYAML's safe loader (the C one when built) with rosparam's tags."""


class YamlInvalid(ValueError):
    """The YAML text cannot be loaded; the message is the loader's."""


def _radians(loader: yaml.SafeLoader, node: yaml.Node) -> float:
    text = str(loader.construct_scalar(node)).strip()  # type: ignore[arg-type]
    expression = text[4:-1] if text.startswith("rad(") else text
    try:
        result = evaluate(expression, EvalEnvironment(lookup_arg=_no_arg, functions={}))
        return float(result)
    except EvalRefused as refused:
        raise _tag_error(node, f"rad({expression}): {refused.message}") from None
    except EvalFailed as failure:
        raise _tag_error(node, f"rad({expression}): {failure.message}") from None
    except (ValueError, OverflowError) as error:
        raise _tag_error(node, f"rad({expression}): {error}") from None


def _degrees(loader: yaml.SafeLoader, node: yaml.Node) -> float:
    text = str(loader.construct_scalar(node))  # type: ignore[arg-type]
    expression = text.strip()[4:-1] if text.startswith("deg(") else text
    try:
        return float(expression) * math.pi / 180.0
    except ValueError as error:
        raise _tag_error(node, f"deg({expression}): {error}") from None


def _tag_error(node: yaml.Node, message: str) -> yaml.constructor.ConstructorError:
    return yaml.constructor.ConstructorError(None, None, message, node.start_mark)


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
    """A YAML text as rosparam loads it; raises :class:`YamlInvalid`."""
    try:
        check_limits(text)
        return yaml.load(text, Loader=RosparamLoader)
    except yaml.YAMLError as error:
        raise YamlInvalid(str(error)) from None
