"""``<arg>``: inputs of the entry file, defaults that are not fixed, values that are."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest

from rosvar.interpreter.model import LaunchModel, ParamDecl
from rosvar.logic.inputs import OTHER, UNSET

if TYPE_CHECKING:
    from conftest import Config, LaunchWorkspace


def param_values(model: LaunchModel) -> dict[str, list[object]]:
    out: dict[str, list[object]] = {}
    for param in model.params:
        assert isinstance(param, ParamDecl)
        out[str(param.name.single())] = param.value.values()
    return out


def test_default_is_not_fixed(ws: LaunchWorkspace) -> None:
    file = ws.launch(
        "default.launch",
        '  <arg name="rate" default="10" doc="publishing rate"/>\n'
        '  <param name="rate" value="$(arg rate)"/>',
    )
    model = ws.model(file)
    assert set(model.inputs) == {"rate"}
    assert model.domains["rate"] == ("10", OTHER)  # no UNSET: leaving it out means "10"
    assert model.unset_defaults == {"rate": "10"}
    [values] = param_values(model).values()
    assert 10 in values and len(values) == 2  # the default AND a value only known later
    [decl] = model.args
    assert (decl.name, decl.default, decl.value, decl.doc) == (
        "rate",
        "10",
        None,
        "publishing rate",
    )
    assert decl.input is model.inputs["rate"]
    assert ws.resolve(file, {}).params == {"/rate": 10}
    assert ws.resolve(file, {"rate": "2.5"}).params == {"/rate": 2.5}
    assert ws.resolve(file, {"rate": "fast"}).params == {"/rate": "fast"}


def test_arg_without_default_has_an_unset_slot(ws: LaunchWorkspace) -> None:
    file = ws.launch(
        "required.launch",
        '  <arg name="robot"/>\n  <node pkg="pkg" type="t" name="$(arg robot)_driver"/>',
    )
    model = ws.model(file)
    assert UNSET in model.domains["robot"]
    [error] = model.errors
    assert error.code == "arg-undefined" and "robot" in error.message
    assert model.space.describe(error.condition, known_only=False) == "robot=<unset>"
    missing = ws.resolve(file, {})
    assert not missing.ok and missing.errors[0].code == "arg-undefined"
    given = ws.resolve(file, {"robot": "husky"})
    assert given.ok and [n.name for n in given.nodes] == ["/husky_driver"]


def test_value_arg_cannot_be_overridden(ws: LaunchWorkspace) -> None:
    file = ws.launch(
        "value.launch",
        '  <arg name="mode" value="fixed"/>\n  <param name="mode" value="$(arg mode)"/>',
    )
    assert ws.resolve(file, {}).params == {"/mode": "fixed"}
    overridden = ws.resolve(file, {"mode": "other"})
    assert not overridden.ok and overridden.errors[0].code == "arg-override"


CONDITIONAL_DEFAULTS = """
  <arg name="sim" default="false"/>
  <arg name="world" default="empty" if="$(arg sim)"/>
  <arg name="world" default="lab" unless="$(arg sim)"/>
  <param name="world" value="$(arg world)"/>
"""


def test_conditional_declarations_give_conditional_defaults(ws: LaunchWorkspace) -> None:
    file = ws.launch("cond.launch", CONDITIONAL_DEFAULTS)
    model = ws.model(file)
    # two defaults: not giving world is not the same as any one literal
    assert "world" not in model.unset_defaults
    assert UNSET in model.domains["world"]
    assert {"empty", "lab"} <= set(model.domains["world"])
    [param] = model.params
    assert isinstance(param, ParamDecl)
    lab = param.value.where(lambda v: v == "lab")
    assert model.space.describe(lab) == "world=lab ∨ (¬sim ∧ world=<unset>)"
    assert ws.resolve(file, {}).params == {"/world": "lab"}
    assert ws.resolve(file, {"sim": "true"}).params == {"/world": "empty"}
    assert ws.resolve(file, {"sim": "true", "world": "moon"}).params == {"/world": "moon"}
    assert not ws.resolve(file, {"sim": "maybe"}).ok


@pytest.mark.oracle
def test_conditional_declarations_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("cond.launch", CONDITIONAL_DEFAULTS)
    ws.assert_agrees(file, [{}, {"sim": "true"}, {"sim": "true", "world": "moon"}, {"world": "x"}])


def test_declaration_errors(ws: LaunchWorkspace) -> None:
    duplicate = ws.launch(
        "dup.launch", '  <arg name="a" default="1"/>\n  <arg name="a" default="2"/>'
    )
    both = ws.launch("both.launch", '  <arg name="a" default="1" value="2"/>')
    nameless = ws.launch("nameless.launch", '  <arg default="1"/>')
    for file, code in (
        (duplicate, "arg-duplicate"),
        (both, "arg-value-and-default"),
        (nameless, "attribute-missing"),
    ):
        model = ws.model(file)
        assert [e.code for e in model.errors] == [code], file
        assert model.errors[0].location.line == 2 + (file == duplicate)
        assert not ws.resolve(file, {}).ok


SCOPES = """
  <arg name="outer" default="o"/>
  <group ns="g">
    <arg name="inner" default="i"/>
    <param name="seen" value="$(arg outer)-$(arg inner)"/>
  </group>
  <param name="after" value="$(arg inner)"/>
"""


def test_args_declared_in_a_group_stay_in_it(ws: LaunchWorkspace) -> None:
    """roslaunch copies the args into a group's context: ``inner`` is unknown after the group."""
    file = ws.launch("scopes.launch", SCOPES)
    resolution = ws.resolve(file, {})
    assert not resolution.ok
    assert resolution.errors[0].code == "arg-undefined"
    assert resolution.errors[0].location.line == 8


@pytest.mark.oracle
def test_arg_scopes_and_errors_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    cases: dict[str, tuple[str, list[Config]]] = {
        "value.launch": (
            '<arg name="mode" value="fixed"/><param name="mode" value="$(arg mode)"/>',
            [{}, {"mode": "other"}],
        ),
        "required.launch": (
            '<arg name="robot"/><node pkg="pkg" type="t" name="$(arg robot)_driver"/>',
            [{}, {"robot": "husky"}],
        ),
        "dup.launch": ('<arg name="a" default="1"/><arg name="a" default="2"/>', [{}]),
        "unused.launch": ('<arg name="a" default="1"/>', [{}, {"b": "2"}, {"a": "3"}]),
    }
    for name, (body, configs) in cases.items():
        ws.assert_agrees(ws.launch(name, body), configs)


CONDITIONAL_ONLY = """
  <arg name="flag" default="false"/>
  <arg name="x" default="d" if="$(arg flag)"/>
  <param name="x" value="$(arg x)"/>
"""


def test_command_line_value_is_visible_outside_the_declaring_group(ws: LaunchWorkspace) -> None:
    """roslaunch puts every name:=value of the command line into the root context's args."""
    file = ws.launch("scopes.launch", SCOPES)
    resolution = ws.resolve(file, {"inner": "x"})
    assert resolution.ok, resolution.errors
    assert resolution.params == {"/g/seen": "o-x", "/after": "x"}


@pytest.mark.oracle
def test_scoped_defaults_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.assert_agrees(ws.launch("scopes.launch", SCOPES), [{}, {"inner": "x"}])
    ws.assert_agrees(
        ws.launch("conditional.launch", CONDITIONAL_ONLY), [{}, {"flag": "true"}, {"x": "e"}]
    )
