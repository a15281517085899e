"""ROS 2 parameter merging: node-name wildcards and the order of sources."""

from __future__ import annotations

import pytest

from rosvar.ros2.conventions.parameters import (
    Source,
    coerce,
    effective,
    file_entries,
    matches,
    typed,
)


def test_wildcards() -> None:
    assert matches("/**", "/a/b/n") and matches("/*/n", "/a/n") and matches("n", "/n")
    assert not matches("/*/n", "/a/b/n") and not matches("/a/n", "/b/n")


def test_later_sources_override_and_patterns_keep_first_appearance() -> None:
    entries = file_entries(
        {"/n": {"ros__parameters": {"p": 1, "g": {"x": 2}}}, "/**": {"ros__parameters": {"p": 0}}}
    )
    assert entries == [("/n", {"p": 1, "g.x": 2}), ("/**", {"p": 0})]
    # /n comes first in the table, so /** (applied after it) wins for p
    assert effective("/n", [Source(entries=tuple(entries))]) == {"p": 0, "g.x": 2}
    assert effective(None, [Source(entries=tuple(entries))]) == {"p": 0}


def test_typed_values() -> None:
    assert [typed(t) for t in ("7", "1.5", "true", "[1, 2]", "", "a b")] == [
        7, 1.5, True, [1, 2], "", "a b"]  # fmt: skip


@pytest.mark.parametrize("text", ["~", "a: b", "[a, 1]"])
def test_values_no_parameter_holds(text: str) -> None:
    with pytest.raises(ValueError):
        typed(text)


DEEP = "[" * 900 + "1" + "]" * 900
"""Within the length of a typed value; PyYAML's constructor ran out of Python's recursion."""


@pytest.mark.parametrize("type_name", ["list_of_int", "bool"])
def test_a_value_nested_deeper_than_the_yaml_limit_is_refused(type_name: str) -> None:
    with pytest.raises(ValueError, match="nested more than 100 levels"):
        coerce(DEEP, type_name)


def test_an_untyped_value_nested_deeper_than_the_yaml_limit_stays_text() -> None:
    assert typed(DEEP) == coerce(DEEP, "yaml") == DEEP
