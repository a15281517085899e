"""``$(eval)`` of comparisons computed as a condition: the same values, conditions, order,
budget and diagnostics as crossing the values it is made of (random expressions)."""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.describe import describe_model
from rosvar.ros2 import substitutions
from rosvar.ros2.boolean_eval import boolean_expression
from rosvar.ros2.substitutions import parse
from rosvar.workspace import discover

MANIFEST = """<package format="3"><name>p</name>
<export><build_type>ament_cmake</build_type></export></package>"""

_VALUES = ("", "a", "b", "ab", "true", "a_", "_b", "b a", "é")
"""Values of the compared configurations: some make ``__`` beside the text around them."""
_LEAVING = ("a&apos;b", "x\\\\y")
"""Values that leave their literal (a quote, a backslash): sometimes, as they are crossed."""
_OPS = ("==", "!=", "&lt;", "&gt;=", "in", "not in")


def _literal(rng: random.Random, names: int) -> str:
    if rng.random() < 0.25:
        return repr(rng.choice(("a", "ab", "", "true", "b a")))
    var = f"$(var x{rng.randrange(names)})"
    return "'" + rng.choice(("", "_", "p")) + var + rng.choice(("", "_", "s")) + "'"


def _expression(rng: random.Random, names: int, depth: int = 0) -> str:
    kind = rng.randrange(6 if depth < 3 else 3) if depth or rng.random() > 0.1 else 6
    if kind == 0 and depth:
        return rng.choice(("True", "False"))
    if kind <= 2:
        chain = [_literal(rng, names)]
        for _ in range(rng.choice((1, 1, 1, 2))):
            chain += [rng.choice(_OPS), _literal(rng, names)]
        return " ".join(chain)
    if kind == 3:
        return f"not ({_expression(rng, names, depth + 1)})"
    if kind == 6:  # not a boolean: crossed
        return f"{_literal(rng, names)} + 'z'"
    joint = " and " if kind == 4 else " or "
    operands = [_expression(rng, names, depth + 1) for _ in range(rng.randint(2, 3))]
    return joint.join(f"({operand})" for operand in operands)


def _value(rng: random.Random) -> str:
    return rng.choice(_LEAVING if rng.random() < 0.05 else _VALUES)


def _random_file(rng: random.Random) -> str:
    """Bool args, configurations set to string values under conditions on them, and
    ``$(eval)``s of those configurations in ``<let>``s, names and ``if``s."""
    flags = 3
    lines = [f'<arg name="b{i}" default="{rng.choice(("true", "false"))}"/>' for i in range(flags)]
    names = rng.randint(1, 4)
    for index in range(names):
        lines.append(f'<let name="x{index}" value="{_value(rng)}"/>')
        for _ in range(rng.randint(1, 3)):
            guard = rng.choice(("if", "unless"))
            let = f'<let name="x{index}" value="{_value(rng)}"/>'
            flag = f"$(var b{rng.randrange(flags)})"
            lines.append(f'<group {guard}="{flag}" scoped="false">{let}</group>')
        if rng.random() < 0.15:  # set only under a condition
            let = f'<let name="x{index}" value="c"/>'
            lines.append(f'<group if="$(var b0)" scoped="false">{let}</group>')
    for index in range(8):
        evaluated = f"$(eval &quot;{_expression(rng, names)}&quot;)"
        if index % 3 == 0:
            lines.append(f'<let name="r{index}" value="{evaluated}"/>')
            lines.append(f'<node pkg="p" exec="e" name="n{index}_$(var r{index})"/>')
        elif index % 3 == 1:
            lines.append(f'<node pkg="p" exec="e" name="m{index}" if="{evaluated}"/>')
        else:
            lines.append(f'<node pkg="p" exec="e" name="k{index}_{evaluated}"/>')
    return "<launch>" + "\n".join(lines) + "</launch>"


def _compared(tmp_path: Path, text: str, monkeypatch: pytest.MonkeyPatch) -> list[object]:
    """The models of ``text`` with ``$(eval)``s computed as conditions, checked equal to
    those with every one crossed; the values computed as conditions."""
    package = tmp_path / "pkg"
    package.mkdir()
    (package / "package.xml").write_text(MANIFEST)
    (package / "main.launch.xml").write_text(text)
    workspace = discover([str(package)])
    computed: list[object] = []
    condition = substitutions.Ros2Substituter._condition

    def counted(*args: object) -> object:
        value = condition(*args)  # type: ignore[arg-type]
        if value is not None:
            computed.append(value)
        return value

    def described() -> list[object]:
        return [
            (
                describe_model(m),
                [(e.code, e.message, e.location, m.space.describe(e.condition)) for e in m.errors],
                [str(d) for d in m.diagnostics],
                [(m.space.describe(d.condition), m.space.describe(d.outcome)) for d in m.decisions],
            )
            for m in Analysis(workspace).all_models()
        ]

    monkeypatch.setattr(substitutions.Ros2Substituter, "_condition", counted)
    as_conditions = described()
    with monkeypatch.context() as patched:
        patched.setattr(substitutions, "boolean_expression", lambda *_args: None)
        assert described() == as_conditions
    return computed


@pytest.mark.parametrize("seed", [f"boolean-eval-{n}" for n in range(40)])
def test_an_expression_computed_as_a_condition_is_the_crossed_one(
    tmp_path: Path, seed: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    _compared(tmp_path, _random_file(random.Random(seed)), monkeypatch)


def test_comparisons_of_varying_values_are_computed_as_conditions(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Values that vary with two args, compared in a ``<let>`` and an ``if``: computed as a
    condition (once: the ``if`` reuses the resolved text), true and false each somewhere,
    as crossing them gives."""
    lets = (
        '<let name="x" value="a"/><group if="$(var b0)" scoped="false"><let name="x" value="b"/>'
        '</group><let name="y" value="c"/><group unless="$(var b1)" scoped="false">'
        '<let name="y" value="d_"/></group>'
    )
    test = "$(eval &quot;'$(var x)' == 'b' or not '_$(var y)' in 'x_d_'&quot;)"
    text = (
        f'<launch><arg name="b0" default="true"/><arg name="b1" default="false"/>{lets}'
        f'<let name="r" value="{test}"/><node pkg="p" exec="e" name="n_$(var r)" if="{test}"/>'
        "</launch>"
    )
    computed = _compared(tmp_path, text, monkeypatch)
    assert [value.values() for value in computed] == [["True", "False"]]  # type: ignore[attr-defined]


def test_a_value_that_leaves_its_literal_is_crossed() -> None:
    """The shape is read with the values' places held open; a value is accepted only where
    it stays its literal's text, and an expression that is no boolean of comparisons, or
    that the evaluator refuses, is never computed as a condition."""
    shape = boolean_expression(parse("'$(var a)' == 'x' and not 'p_$(var b)' in 'y'"), frozenset())
    assert shape is not None
    assert [literal.prefix for literal in shape.literals] == ["", "p_"]
    first, second = shape.literals
    assert first.keeps("a b") and first.keeps("é")
    assert not first.keeps("a'b") and not first.keeps("a\\b") and not first.keeps("a\nb")
    assert not second.keeps("_x") and second.keeps("x_")  # p__x would be refused
    for text in (
        "'$(var a)' + 'x'",  # a string, not a boolean
        "'$(var a)$(var b)' == 'x'",  # two values in one literal: texts may coincide
        "'$(var a)\\\\n' == 'x'",  # an escape: a value's text is not its literal's content
        "$(var a) == 'x'",  # outside a literal
        "'$(var a)' is 'x'",  # identity
        "'__$(var a)' == 'x'",  # refused by the evaluator whatever the value
    ):
        assert boolean_expression(parse(text), frozenset()) is None, text
