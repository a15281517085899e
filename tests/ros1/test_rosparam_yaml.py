"""rosparam's YAML loader: every failure is one ``YamlInvalid`` (a ``ValueError``)."""

from __future__ import annotations

import math
import re

import pytest

from rosvar.ros1.rosparam_yaml import YamlInvalid, load_yaml


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("&a [*a]", "refers to a node that contains it"),
        ("a: b: c", "mapping values are not allowed"),
        ("a: rad(1/0)", "ZeroDivisionError"),
        ("a: !radians open('x')", "not allowed"),
        ("a: rad(1 +)", "rad(1 +)"),
        ("a: rad('x')", "could not convert"),
        ("a: !degrees nope", "deg(nope)"),
        ("a: !!python/object:os.system x", "could not determine a constructor"),
        ("[" * 200 + "]" * 200, "nested more than"),
        ("[" * 5000, "nested more than"),  # libyaml's own refusal, told as the limit
    ],
)
def test_bad_yaml_is_one_error(text: str, message: str) -> None:
    with pytest.raises(YamlInvalid, match=re.escape(message)):
        load_yaml(text)


def test_rosparam_tags_still_load() -> None:
    loaded = load_yaml("a: rad(pi/2)\nb: deg(180)\nc: &x [1, 2]\nd: *x\n")
    assert loaded == {"a": math.pi / 2, "b": math.pi, "c": [1, 2], "d": [1, 2]}
