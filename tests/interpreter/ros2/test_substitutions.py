"""The ROS 2 substitution grammar: nesting, quoting, escapes."""

from __future__ import annotations

import pytest

from rosvar.interpreter.ros2.substitutions import Call, SubstitutionSyntaxError, parse


def test_nested_and_quoted_arguments() -> None:
    assert parse("a$(var x)b") == ("a", Call("var", (("x",),)), "b")
    assert parse("$(eval '\\'$(var r)\\' == 1')") == (
        Call("eval", (("'", Call("var", (("r",),)), "' == 1"),)),
    )
    assert parse("$(env A 'b c')") == (Call("env", (("A",), ("b c",))),)


@pytest.mark.parametrize("text", ["$(var x", "$( x)", "$(env 'a)"])
def test_malformed_text_is_refused(text: str) -> None:
    with pytest.raises(SubstitutionSyntaxError):
        parse(text)
