"""The cells of an arg in ``$(eval)`` expressions: whatever value the arg takes, the
expressions come out together as they do at one of the witnesses (the facts that make two
``if``s over one arg exclude each other rest on this)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from oracle.client import requires_oracle
from rosvar.analyses.checks import Check, check_models
from rosvar.interpreter.safe_eval import EvalEnvironment, EvalFailed, EvalRefused, evaluate
from rosvar.interpreter.safe_eval.cells import compared_constants, witnesses
from rosvar.outputs.documents.findings import finding_document
from rosvar.workspace.interfaces.model import Interfaces

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

GROUPS = [
    ("arg('dof') == 6", "arg('dof') == 7", "dof != 6.5"),
    ("dof > 6", "dof < 7", "dof >= 6.5"),
    ("dof in (1, 'a', True)", "dof not in [2, 'b']", "dof == 'a' or dof == 2"),
    ("3 < dof <= 7.5", "dof == -2", "not dof == 'x'"),
    ("dof == 'LDS-01'", "dof == 'LDS-02'", "'yes' if dof == 'LDS-02' else 'no'"),
]
VALUES = st.one_of(
    st.sampled_from(["6", "6.0", "06", " 7 ", "7.", "6.5", "true", "1", "0", "a", "x", "-2"]),
    st.from_regex(r"-?[0-9]{1,2}(\.[0-9]{1,2})?", fullmatch=True),
    st.text(max_size=4),
)


def _truth(expression: str, value: str) -> str | None:
    environment = EvalEnvironment(lookup_arg={"dof": value}.__getitem__, functions={})
    try:
        return evaluate(expression, environment)
    except (EvalFailed, EvalRefused):
        return None


@pytest.mark.parametrize("group", GROUPS)
@settings(max_examples=150, deadline=None)
@given(value=VALUES)
def test_every_value_comes_out_as_a_witness(group: tuple[str, ...], value: str) -> None:
    constants = frozenset().union(*(compared_constants(e, "dof") or () for e in group))
    seen = {tuple(_truth(e, w) for e in group) for w in witnesses(constants)}
    assert tuple(_truth(e, value) for e in group) in seen


@pytest.mark.parametrize(
    "expression",
    ["dof + 1 == 2", "int(dof) == 2", "dof is True", "'a' in dof", "dof < 'b'", "arg(x) == 1",
     "[dof for dof in 'ab'] == ['a']", "dof.lower() == 'a'", "dof == other",
     "dof == 6 and find('pkg') == ''", "dof == 1 or env('X') == '1'"],
)  # fmt: skip
def test_other_uses_of_the_arg_have_no_cells(expression: str) -> None:
    assert compared_constants(expression, "dof") is None


def _clashes(ws: LaunchWorkspace, first: str, second: str) -> list[str]:
    file = ws.launch(
        "spawn.launch",
        f"""<arg name="dof" default="6"/>
        <node if="$(eval {first})" name="spawner" pkg="gazebo_ros" type="spawn_model"/>
        <node if="$(eval {second})" name="spawner" pkg="gazebo_ros" type="spawn_model"/>""",
    )
    analysis = ws.analysis()
    models = analysis.all_models()
    findings = check_models(analysis.space, models, Interfaces(), analysis.workspace.confinement())
    clashes = [f for f in findings if f.check is Check.NODE_NAME_CLASH]
    assert all(f.file == file for f in clashes)
    return [analysis.space.describe(f.condition) for f in clashes]


def test_ifs_over_one_arg_exclude_each_other(ws: LaunchWorkspace) -> None:
    assert _clashes(ws, "arg('dof') == 6", "arg('dof') == 7") == []


def test_values_between_the_literals_still_clash(ws: LaunchWorkspace) -> None:
    (condition,) = _clashes(ws, "dof > 6", "dof &lt; 7")  # 6.5 is neither literal
    assert "other" in condition


def _if_and_eval(ws: LaunchWorkspace, expression: str) -> tuple[str, list[dict[str, object]]]:
    """A node under ``if="$(arg c)"`` (a predicate on the arg's own text) and one of the same
    name under an ``$(eval)`` of it: the file and its clashes as ``check`` writes them."""
    file = ws.launch(
        "spawn.launch",
        f"""<arg name="c" default="false"/>
        <node if="$(arg c)" name="spawner" pkg="gazebo_ros" type="spawn_model"/>
        <node if="$(eval {expression})" name="spawner" pkg="gazebo_ros" type="spawn_model"/>""",
    )
    analysis = ws.analysis()
    findings = check_models(
        analysis.space, analysis.all_models(), Interfaces(), analysis.workspace.confinement()
    )
    clashes = [f for f in findings if f.check is Check.NODE_NAME_CLASH]
    return file, [finding_document(f, analysis.space) for f in clashes]


def test_an_if_over_the_arg_and_an_eval_of_it_are_related(ws: LaunchWorkspace) -> None:
    """``yes`` is no boolean to roslaunch's ``if``: no text of ``c`` makes both true (they
    were two unrelated predicates of an unforeseen value)."""
    assert _if_and_eval(ws, "arg('c') == 'yes'")[1] == []


@requires_oracle[0]
@requires_oracle[1]
def test_a_clash_of_an_unforeseen_value_shows_a_text_roslaunch_refuses(
    ws: LaunchWorkspace,
) -> None:
    """``c`` compared with 1: ``1``, ``True``... make both true; the example gives such a
    text and roslaunch, given it, refuses the two nodes of one name."""
    file, [clash] = _if_and_eval(ws, "arg('c') == 1")
    example = clash["example"]
    assert isinstance(example, dict)
    [text] = [value for key, value in example.items() if key.endswith(":c")]
    assert text not in ("<other>", "false")
    [result] = ws.oracle(file, [({"c": text}, {})])
    assert "multiple nodes named" in str(result.get("error")), (text, result)
