"""``<rosparam>``: YAML unrolled into parameters, per configuration."""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

import pytest

from rosvar.interpreter.model import ParamDecl, YamlDecl
from rosvar.ros1.tags import rosparam

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

INLINE = """
  <arg name="gain" default="2.0"/>
  <arg name="controller" default="pid"/>
  <rosparam ns="ctrl">
    kind: fixed
    limits: {min: -1, max: 1}
    angle: !degrees 180
  </rosparam>
  <rosparam subst_value="true" ns="$(arg controller)">
    gain: $(arg gain)
    name: $(arg controller)
  </rosparam>
  <rosparam param="list" if="$(eval controller == 'pid')">[1, 2, 3]</rosparam>
"""


def test_inline_yaml_is_unrolled(ws: LaunchWorkspace) -> None:
    file = ws.launch("inline.launch", INLINE)
    model = ws.model(file)
    fixed = {
        str(p.name.single()): p.value.single()
        for p in model.params
        if isinstance(p, ParamDecl) and p.condition == model.space.true
    }
    assert fixed["/ctrl/kind"] == "fixed"
    assert fixed["/ctrl/limits/min"] == -1 and fixed["/ctrl/limits/max"] == 1
    assert fixed["/ctrl/angle"] == pytest.approx(3.141592653589793)
    # the substituted block depends on the args: known values unrolled, others deferred
    assert any(isinstance(p, YamlDecl) for p in model.params)
    resolution = ws.resolve_fresh(file, {"gain": "0.5", "controller": "pd"})
    assert resolution.ok, resolution.errors
    assert resolution.params["/pd/gain"] == 0.5
    assert resolution.params["/pd/name"] == "pd"
    assert "/list" not in resolution.params
    assert ws.resolve(file, {}).params["/list"] == [1, 2, 3]


def test_inline_yaml_with_other_namespace(ws: LaunchWorkspace) -> None:
    file = ws.launch("inline.launch", INLINE)
    resolution = ws.resolve(file, {"gain": "0.5", "controller": "pd"})
    assert resolution.params.get("/pd/gain") == 0.5


INLINE_CONFIGS = [{}, {"gain": "0.5", "controller": "pd"}, {"gain": "[1"}, {"controller": "a b"}]


@pytest.mark.oracle
def test_inline_yaml_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.assert_agrees(ws.launch("inline.launch", INLINE), INLINE_CONFIGS, modes=["fresh"])


@pytest.mark.oracle
def test_inline_yaml_shared_model_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.assert_agrees(ws.launch("inline.launch", INLINE), INLINE_CONFIGS, modes=["shared"])


FROM_FILE = """
  <arg name="config" default="default"/>
  <rosparam command="load" file="$(find pkg)/config/$(arg config).yaml" ns="cfg"/>
  <rosparam command="delete" param="nothing"/>
"""


def test_yaml_file_chosen_by_arg(ws: LaunchWorkspace) -> None:
    ws.write("config/default.yaml", "a: 1\nb: {c: two}\n")
    ws.write("config/fast.yaml", "a: 10\n")
    ws.write("config/broken.yaml", "a: [1\n")
    file = ws.launch("file.launch", FROM_FILE)
    fresh = ws.analysis(extra_values={"config": ["fast", "broken"]})
    model = fresh.model(file)
    space = model.space
    by_value = {
        (str(p.name.single()), p.value.single()): p.condition
        for p in model.params
        if isinstance(p, ParamDecl)
    }
    assert space.describe(by_value[("/cfg/a", 1)]) == "config=default"
    assert space.describe(by_value[("/cfg/a", 10)]) == "config=fast"
    [error] = [e for e in model.errors if e.code == "rosparam-invalid"]
    assert space.describe(error.condition) == "config=broken"
    assert ws.resolve(file, {}).params == {"/cfg/a": 1, "/cfg/b/c": "two"}
    assert ws.resolve_fresh(file, {"config": "fast"}).params == {"/cfg/a": 10}
    assert not ws.resolve_fresh(file, {"config": "absent"}).ok


def test_yaml_file_with_other_value(ws: LaunchWorkspace) -> None:
    ws.write("config/fast.yaml", "a: 10\n")
    file = ws.launch("file.launch", FROM_FILE)
    assert ws.resolve(file, {"config": "fast"}).params == {"/cfg/a": 10}
    assert not ws.resolve(file, {"config": "absent"}).ok


FILE_CONFIGS = [{}, {"config": "fast"}, {"config": "broken"}, {"config": "absent"}]


def _config_files(ws: LaunchWorkspace) -> None:
    ws.write("config/default.yaml", "a: 1\nb: {c: two}\n")
    ws.write("config/fast.yaml", "a: 10\n")
    ws.write("config/broken.yaml", "a: [1\n")


@pytest.mark.oracle
def test_yaml_file_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    _config_files(ws)
    ws.assert_agrees(ws.launch("file.launch", FROM_FILE), FILE_CONFIGS, modes=["fresh"])


@pytest.mark.oracle
def test_yaml_file_shared_model_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    _config_files(ws)
    ws.assert_agrees(ws.launch("file.launch", FROM_FILE), FILE_CONFIGS, modes=["shared"])


def test_rosparam_errors(ws: LaunchWorkspace) -> None:
    cases = {
        "scalar.launch": ("<rosparam>42</rosparam>", "rosparam-invalid"),
        "command.launch": ('<rosparam command="explode">a: 1</rosparam>', "rosparam-invalid"),
        "yaml.launch": ("<rosparam>a: [</rosparam>", "rosparam-invalid"),
        "missing.launch": ('<rosparam file="$(find pkg)/nonexistent.yaml"/>', "file-missing"),
    }
    for name, (body, code) in cases.items():
        model = ws.model(ws.launch(name, body))
        assert [e.code for e in model.errors] == [code], name
        assert not ws.resolve(model.file).ok


@pytest.mark.oracle
def test_rosparam_errors_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    for name, body in {
        "scalar.launch": "<rosparam>42</rosparam>",
        "param.launch": '<rosparam param="answer">42</rosparam>',
        "command.launch": '<rosparam command="explode">a: 1</rosparam>',
        "yaml.launch": "<rosparam>a: [</rosparam>",
        "empty.launch": "<rosparam></rosparam>",
        "global.launch": '<rosparam param="/">5</rosparam>',
    }.items():
        ws.assert_agrees(ws.launch(name, body), [{}])


@pytest.mark.parametrize(
    "body",
    ["&amp;a {b: *a}", "a: rad(1/0)", "a: b: c", "&amp;a [*a]"],
)
def test_hostile_yaml_is_an_error_event(ws: LaunchWorkspace, body: str) -> None:
    file = ws.launch("hostile.launch", f"<rosparam>{body}</rosparam>")
    model = ws.model(file)
    assert [e.code for e in model.errors] == ["rosparam-invalid"]
    assert not ws.resolve(file, {}).ok


def test_alias_bomb_in_a_parameter_file_is_refused(ws: LaunchWorkspace) -> None:
    lines = ["a0: &a0 [x, x, x, x, x, x, x, x, x, x]"]
    lines += [f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 10)}]" for i in range(1, 9)]
    ws.write("config/bomb.yaml", "\n".join(lines) + "\n")
    file = ws.launch("bomb.launch", '<rosparam file="$(find pkg)/config/bomb.yaml"/>')
    model = ws.model(file)
    assert [e.code for e in model.errors] == ["rosparam-invalid"]
    assert "expands to more than" in model.errors[0].message


def test_a_parameter_file_is_loaded_once_for_all_its_includers(
    ws: LaunchWorkspace, monkeypatch: pytest.MonkeyPatch
) -> None:
    ws.write("config/gains.yaml", "kp: 1.5\nki: [1, 2]\n")
    ws.launch(
        "common.launch",
        '<rosparam file="$(find pkg)/config/gains.yaml" ns="ctrl"/>'
        '<rosparam file="$(find pkg)/config/missing.yaml"/>',
    )
    include = '<include file="$(find pkg)/launch/common.launch"/>'
    files = [ws.launch(f"{name}.launch", include) for name in ("first", "second")]
    loaded: list[str | None] = []
    load = rosparam.load_rosparam

    def spied(command: str, ns: str | None, file: str | None, *rest: Any) -> object:
        loaded.append(file)
        return load(command, ns, file, *rest)

    monkeypatch.setattr(rosparam, "load_rosparam", spied)
    for file in files:
        model = ws.model(file)
        params = {
            str(p.name.single()): p.value.single() for p in model.params if isinstance(p, ParamDecl)
        }
        assert params == {"/ctrl/kp": 1.5, "/ctrl/ki": [1, 2]}
        assert [e.code for e in model.errors] == ["file-missing"]  # at each place
    assert [os.path.basename(str(f)) for f in loaded] == [
        "gains.yaml",
        "missing.yaml",
        "missing.yaml",
    ]
