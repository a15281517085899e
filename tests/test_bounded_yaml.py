"""Limits on untrusted YAML: self-reference, alias bombs and deep nesting are refused."""

from __future__ import annotations

import pytest
import yaml

from rosvar.bounded_yaml import MAX_DEPTH, MAX_NODES, YamlLimitError, check_limits


def _bomb(levels: int, fanout: int) -> str:
    lines = ["a0: &a0 x"]
    for level in range(1, levels + 1):
        items = ", ".join([f"*a{level - 1}"] * fanout)
        lines.append(f"a{level}: &a{level} [{items}]")
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize(
    "text",
    ["&a [*a]", "&a {b: *a}", "&a {b: [1, {c: *a}]}", "x: &a\n  y: &b [*a]\n", "&a [[*a]]"],
)
def test_self_reference_is_refused(text: str) -> None:
    with pytest.raises(YamlLimitError, match="refers to a node that contains it"):
        check_limits(text)


def test_alias_bombs_are_refused_but_sharing_within_the_limit_is_not() -> None:
    with pytest.raises(YamlLimitError, match="expands to more than"):
        check_limits(_bomb(9, 10))
    small = _bomb(3, 10)  # 1000 leaves: fine, and PyYAML loads it the same way
    check_limits(small)
    assert len(yaml.safe_load(small)["a3"]) == 10


def test_expansion_is_counted_at_the_top_level_too() -> None:
    text = (
        "a: &a ["
        + ", ".join(["1"] * 1000)
        + "]\n"
        + "".join(f"b{i}: *a\n" for i in range(MAX_NODES // 1000 + 1))
    )
    with pytest.raises(YamlLimitError):
        check_limits(text)


def test_nesting_depth_is_bounded() -> None:
    check_limits("[" * MAX_DEPTH + "]" * MAX_DEPTH)
    with pytest.raises(YamlLimitError, match="nested more than"):
        check_limits("[" * (MAX_DEPTH + 1) + "]" * (MAX_DEPTH + 1))
    # libyaml's scanner refuses it first (over 1,000 flow levels): told as this limit
    with pytest.raises(YamlLimitError, match=f"^YAML nested more than {MAX_DEPTH} levels deep$"):
        check_limits("[" * 100_000)


def test_syntax_errors_stay_the_parsers() -> None:
    with pytest.raises(yaml.YAMLError) as raised:
        check_limits("a: b: c")
    assert not isinstance(raised.value, YamlLimitError)
