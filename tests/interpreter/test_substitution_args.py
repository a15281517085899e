"""Substitution args over all configurations: ``$(arg)``, ``$(find)``, ``$(eval)`` and friends."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from rosvar.interpreter import substitution_args as substitutions
from rosvar.interpreter.model import DeferredValue, LaunchModel, ParamDecl
from rosvar.logic.terms import is_term
from rosvar.ros1 import dialect

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

SUBST = """
  <arg name="robot" default="husky"/>
  <arg name="count" default="2"/>
  <param name="twice" value="$(arg robot)-$(arg robot)"/>
  <param name="path" value="$(find pkg)/config/$(arg robot).yaml"/>
  <param name="dir" value="$(dirname)"/>
  <param name="sum" value="$(eval int(count) + 1)"/>
  <param name="is_jackal" value="$(eval robot == 'jackal')"/>
  <param name="joined" value="$(eval arg('robot') + '_' + str(count))"/>
  <param name="opt" value="$(optenv ROBOT_COLOUR grey with spaces)"/>
  <param name="anon_a" value="$(anon x)"/>
  <param name="anon_b" value="$(anon x)"/>
"""


def test_substitutions_per_configuration(ws: LaunchWorkspace) -> None:
    file = ws.launch("subst.launch", SUBST)
    package = ws.root / "pkg"
    params = ws.resolve(file, {"robot": "jackal", "count": "4"}).params
    assert params == {
        "/twice": "jackal-jackal",
        "/path": f"{package}/config/jackal.yaml",
        "/dir": str(package / "launch"),
        "/sum": 5,
        "/is_jackal": True,
        "/joined": "jackal_4",
        "/opt": "grey with spaces",
        "/anon_a": params["/anon_a"],
        "/anon_b": params["/anon_a"],  # one anon name per id in a context
    }
    assert str(params["/anon_a"]).startswith("x_")
    assert ws.resolve(file, {}, {"ROBOT_COLOUR": "red"}).params["/opt"] == "red"


def test_eval_literals_become_known_values(ws: LaunchWorkspace) -> None:
    file = ws.launch("subst.launch", SUBST)
    model = ws.model(file)
    assert "jackal" in model.domains["robot"]  # compared with in an $(eval)
    params = {str(p.name.single()): p for p in model.params if isinstance(p, ParamDecl)}
    is_jackal = params["/is_jackal"].value
    assert model.space.describe(is_jackal.where(lambda v: v is True)) == "robot=jackal"
    # a value analysis did not foresee stays a term until a configuration gives it
    twice = params["/twice"].value.values()
    assert {"husky-husky", "jackal-jackal"} <= set(v for v in twice if isinstance(v, str))
    deferred = [v for v in twice if isinstance(v, DeferredValue)]
    assert len(deferred) == 1 and is_term(deferred[0].raw)


@pytest.mark.oracle
def test_substitutions_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("subst.launch", SUBST)
    ws.assert_agrees(
        file,
        [
            {},
            {"robot": "jackal", "count": "4"},
            {"count": "x"},
            ({"robot": "a b"}, {"ROBOT_COLOUR": "red"}),
            ({}, {"ROBOT_COLOUR": ""}),
        ],
    )


ERRORS = {
    "unknown_command.launch": '<param name="p" value="$(bogus x)"/>',
    "dollar_inside.launch": '<param name="p" value="$(arg $(arg a))"/>',
    "eval_not_whole.launch": '<param name="p" value="x $(eval 1 + 1)"/>',
    "arg_arity.launch": '<param name="p" value="$(arg a b)"/>',
    "undefined.launch": '<param name="p" value="$(arg nowhere)"/>',
    "env_unset.launch": '<param name="p" value="$(env ROSVAR_SURELY_UNSET_VARIABLE)"/>',
    "eval_error.launch": '<param name="p" value="$(eval 1 / 0)"/>',
    "find_arity.launch": '<param name="p" value="$(find)"/>',
}


def test_substitution_errors_are_error_events(ws: LaunchWorkspace) -> None:
    for name, body in ERRORS.items():
        model = ws.model(ws.launch(name, "  " + body))
        assert model.errors, name
        for error in model.errors:
            assert error.code and error.message
            assert (error.location.line, error.location.col) == (2, 3), name
        assert not ws.resolve(model.file).ok, name


@pytest.mark.oracle
def test_substitution_errors_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    for name, body in ERRORS.items():
        file = ws.launch(name, body)
        [result] = ws.assert_agrees(file, [{}])
        assert not result["ok"], name


def test_unknown_package_stays_symbolic(ws: LaunchWorkspace) -> None:
    file = ws.launch("unknown_pkg.launch", '  <param name="p" value="$(find not_a_pkg)/x"/>')
    model = ws.model(file)
    codes = [d.code for d in model.diagnostics]
    assert codes == ["package-unknown"]
    assert str(model.diagnostics[0].location) == f"{file}:2:3"
    assert model.errors == []  # not an error of the launch file itself
    resolution = ws.resolve(file)
    assert not resolution.ok and resolution.errors[0].code == "value-unknown"


def test_find_resolves_through_the_workspace(ws: LaunchWorkspace, tmp_path: Path) -> None:
    ws.package("other_pkg")
    file = ws.launch(
        "find.launch",
        '  <param name="p" value="$(find other_pkg)/cfg $(find other_pkg)"/>',
    )
    other = ws.root / "other_pkg"
    assert ws.resolve(file).params == {"/p": f"{other}/cfg {other}"}


def test_commands_are_registered_in_roslaunchs_order_and_only_once() -> None:
    from rosvar.interpreter.substitution_args import COMMANDS, FIRST_PASS, command

    assert COMMANDS == ("find", "env", "optenv", "dirname", "anon", "arg")
    handler = FIRST_PASS["env"]
    with pytest.raises(ValueError, match="registered twice"):
        command("env")(handler)
    assert FIRST_PASS["env"] is handler


def _codes(model: LaunchModel) -> list[str]:
    return [d.code for d in model.diagnostics]


@pytest.mark.parametrize("count", [12, 18, 40])
def test_many_varying_args_in_one_attribute_become_an_unknown_value(
    ws: LaunchWorkspace, count: int
) -> None:
    args = "".join(f'<arg name="a{i}" default="x"/>' for i in range(count))
    text = "".join(f"$(arg a{i})" for i in range(count))
    file = ws.launch("many.launch", f'{args}<param name="p" value="{text}"/>')
    model = ws.model(file)
    [param] = model.params
    assert isinstance(param, ParamDecl)
    if 2**count <= substitutions.MAX_COMBINATIONS:  # within the budget: computed exactly
        assert _codes(model) == [] and len(param.value.branches) == 2**count
        return
    assert _codes(model) == ["value-too-complex"]
    value = param.value.single()
    assert isinstance(value, DeferredValue) and is_term(value.raw)
    # one configuration computes it again, that value alone, from its operands' branches
    assert ws.resolve(file, {}).params == {"/p": "x" * count}
    given = {"a1": "y", f"a{count - 1}": "zz"}
    assert ws.resolve(file, given).params == {"/p": "xy" + "x" * (count - 3) + "zz"}


MANY = "".join(f'<arg name="a{i}" default="x"/>' for i in range(18)) + (
    '<param name="p" value="{}"/>'.format("".join(f"$(arg a{i})" for i in range(18)))
    + '<param name="e" value="$(eval {})"/>'.format("+".join(f"arg('a{i}')" for i in range(18)))
    + '<node pkg="pkg" type="n" name="$(arg a0)$(arg a1)n"'
    + ' args="{}"/>'.format(" ".join(f"$(arg a{i})" for i in range(18)))
)


@pytest.mark.oracle
def test_values_over_the_work_limits_agree_with_roslaunch_once_bound(ws: LaunchWorkspace) -> None:
    file = ws.launch("many.launch", MANY)
    assert _codes(ws.model(file)).count("value-too-complex") == 3  # p, e and the node's args
    configs = [{}, {"a1": "y", "a17": "zz"}, {"a0": "1", "a5": "2"}, {"a3": "has space"}]
    ws.assert_agrees(file, configs)


def test_a_value_over_the_bounds_in_its_configuration_stays_unknown(ws: LaunchWorkspace) -> None:
    lines = ['<arg name="a0" default="xy"/>']
    lines += [f'<arg name="a{i}" default="$(arg a{i - 1})$(arg a{i - 1})"/>' for i in range(1, 40)]
    file = ws.launch("chain.launch", "".join(lines) + '<param name="p" value="$(arg a39)"/>')
    [error] = ws.resolve(file, {"a0": "z"}).errors  # 2^39 characters even here
    assert error.code == "value-unknown" and "work limits" in str(error)


@pytest.mark.parametrize("concat", ["$(arg a{p})$(arg a{p})", "x$(arg a{p})y"])
def test_values_doubling_or_nesting_along_a_chain_are_bounded(
    ws: LaunchWorkspace, concat: str
) -> None:
    lines = ['<arg name="a0" default="xy"/>']
    lines += [f'<arg name="a{i}" default="{concat.format(p=i - 1)}"/>' for i in range(1, 160)]
    lines.append('<param name="p" value="$(arg a159)"/>')
    model = ws.model(ws.launch("chain.launch", "".join(lines)))
    assert "value-too-complex" in _codes(model)
    [param] = model.params
    assert isinstance(param, ParamDecl)
    for _condition, leaf in param.value.branches:
        shown = leaf.raw if isinstance(leaf, DeferredValue) else leaf
        assert len(str(shown)) <= substitutions.MAX_VALUE_SIZE


def test_file_budget_bounds_many_attributes_each_within_the_limit(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(substitutions, "MAX_FILE_COMBINATIONS", 100)
    args = "".join(f'<arg name="a{i}" default="x"/>' for i in range(5))
    text = "".join(f"$(arg a{i})" for i in range(5))  # 32 combinations each
    params = "".join(f'<param name="p{i}" value="{text}{i}"/>' for i in range(5))
    file = ws.launch("budget.launch", args + params)
    assert _codes(ws.model(file)).count("value-too-complex") == 2  # 3 x 32 fit in 100, not more
    resolved = ws.resolve(file, {"a2": "y"}).params
    assert resolved == {f"/p{i}": f"xxyxx{i}" for i in range(5)}


def test_eval_over_many_varying_args_is_bounded(ws: LaunchWorkspace) -> None:
    args = "".join(f'<arg name="a{i}" default="1"/>' for i in range(16))
    expression = "+".join(f"arg('a{i}')" for i in range(16))
    model = ws.model(
        ws.launch("eval.launch", f'{args}<param name="p" value="$(eval {expression})"/>')
    )
    assert _codes(model) == ["value-too-complex"]


COMMON = """
  <arg name="robot"/>
  <param name="p" value="$(arg robot)-$(find pkg)"/>
  <param name="q" value="$(find nowhere)/$(arg robot)"/>
"""
INCLUDER = (
    '<include file="$(find pkg)/launch/common.launch"><arg name="robot" value="husky"/></include>'
)


def test_walks_of_one_analysis_share_the_texts_they_resolve_alike(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    ws.launch("common.launch", COMMON)
    files = [ws.launch(f"{name}.launch", INCLUDER) for name in ("first", "second")]
    computed: list[str] = []
    resolved = substitutions.Substituter._resolved

    def spied(self: substitutions.Substituter, text: str, *rest: object) -> object:
        computed.append(text)
        return resolved(self, text, *rest)  # type: ignore[arg-type]

    monkeypatch.setattr(substitutions.Substituter, "_resolved", spied)
    with monkeypatch.context() as unshared:
        unshared.setattr(dialect, "shared_texts", lambda _files: None)
        alone = {file: ws.resolve(file).params for file in files}
    assert computed.count("$(arg robot)-$(find pkg)") == 2  # once per walk
    computed.clear()
    ws.launch("common.launch", COMMON)  # written again: a new analysis
    models = [ws.model(file) for file in files]
    # computed once for both entry files' walks; the unknown package's value, whose
    # warning belongs to each place, in each walk
    assert computed.count("$(arg robot)-$(find pkg)") == 1
    assert computed.count("$(find nowhere)/$(arg robot)") == 2
    assert all("package-unknown" in _codes(model) for model in models)
    assert {file: ws.resolve(file).params for file in files} == alone
