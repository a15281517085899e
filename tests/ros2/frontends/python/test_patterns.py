"""``re`` in launch helpers: literal patterns matched as Python matches them, and only
patterns whose work is bounded."""

from __future__ import annotations

import ast
import re

import pytest

from rosvar.diagnostics import DiagnosticSink
from rosvar.ros2.frontends.python.interpreter import Interpreter
from rosvar.ros2.frontends.python.values import Unknown, Value


def value(expression: str) -> tuple[Value, list[str]]:
    text = f"import re\nv = {expression}\n"
    sink = DiagnosticSink()
    names = Interpreter("t.launch.py", text, sink).run_module(ast.parse(text)).names
    return names["v"], [d.message for d in sink.items]


@pytest.mark.parametrize(
    "expression",
    [
        "re.compile('^(.*)_planning.yaml$').search('ompl_planning.yaml').groups()",
        "re.compile('^(.*)_planning.yaml$').search('ompl.yaml')",
        "re.match('a(b)?', 'ac').group(0)",
        "re.fullmatch('[a-z]+_(x|y)', 'ab_y').group(1)",
        "re.search('x', 'abc')",
    ],
)
def test_literal_patterns_match_as_python(expression: str) -> None:
    got, messages = value(expression)
    assert got == eval(expression, {"re": re})
    assert messages == []


@pytest.mark.parametrize(
    "expression", ["re.compile('(a+)+$')", "re.compile('a*b*c*d*')", "re.search('a*', 'a' * 300)"]
)
def test_patterns_of_unbounded_work_are_not_followed(expression: str) -> None:
    got, messages = value(expression)
    assert isinstance(got, Unknown)
    assert len(messages) == 1 and "not followed" in messages[0]
