"""``<env>`` and the environment as an input (``$(env)``, ``$(optenv)``)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest

from rosvar.logic.inputs import EnvInput

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

ENV = """
  <env name="LOG_LEVEL" value="$(optenv ROBOT_LOG info)"/>
  <group ns="$(optenv ROBOT_NS /)">
    <env name="ROBOT" value="$(env ROBOT_NAME)" if="$(optenv WITH_NAME false)"/>
    <node pkg="pkg" type="t" name="n">
      <env name="OWN" value="1"/>
    </node>
  </group>
  <node pkg="pkg" type="t" name="after"/>
"""


def test_environment_variables_are_inputs(ws: LaunchWorkspace) -> None:
    file = ws.launch("env.launch", ENV)
    analysis = ws.analysis(env_values={"ROBOT_NS": ["/r1"]})
    model = analysis.model(file)
    space = model.space
    inputs = {i for i in space.inputs() if isinstance(i, EnvInput)}
    assert {i.name for i in inputs} == {"ROBOT_LOG", "ROBOT_NS", "WITH_NAME", "ROBOT_NAME"}
    [node] = [n for n in model.nodes if n.fields["name"].single() == "n"]
    namespaces = node.fields["namespace"]
    r1 = namespaces.where(lambda v: v == "/r1/")
    assert space.describe(r1) == "$ROBOT_NS=/r1"
    # $(env ROBOT_NAME) fails only where the <env> is processed and the variable is unset
    [error] = [e for e in model.errors if e.code == "env-unset"]
    text = space.describe(error.condition)
    assert "$ROBOT_NAME=<unset>" in text


def test_env_settings_per_configuration(ws: LaunchWorkspace) -> None:
    file = ws.launch("env.launch", ENV)
    plain = ws.resolve(file, {}, {})
    assert plain.ok, plain.errors
    nodes = {n.name: n for n in plain.nodes}
    assert nodes["/n"].env == [("LOG_LEVEL", "info"), ("OWN", "1")]
    assert nodes["/after"].env == [("LOG_LEVEL", "info")]
    named = ws.resolve(
        file, {}, {"WITH_NAME": "true", "ROBOT_NAME": "rob", "ROBOT_NS": "r2", "ROBOT_LOG": "dbg"}
    )
    nodes = {n.name: n for n in named.nodes}
    assert nodes["/r2/n"].env == [("LOG_LEVEL", "dbg"), ("OWN", "1"), ("ROBOT", "rob")]
    unset = ws.resolve(file, {}, {"WITH_NAME": "true"})
    assert not unset.ok and unset.errors[0].code == "env-unset"


@pytest.mark.oracle
def test_env_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("env.launch", ENV)
    ws.assert_agrees(
        file,
        [
            ({}, {}),
            ({}, {"WITH_NAME": "true", "ROBOT_NAME": "rob", "ROBOT_NS": "r2"}),
            ({}, {"WITH_NAME": "true"}),
            ({}, {"WITH_NAME": "maybe"}),
            ({}, {"ROBOT_LOG": ""}),
        ],
    )


def test_empty_namespace_from_environment_fails(ws: LaunchWorkspace) -> None:
    file = ws.launch("env.launch", ENV)
    assert not ws.resolve_fresh(file, {}, {"ROBOT_NS": ""}).ok  # a known slot: checked
    resolution = ws.resolve(file, {}, {"ROBOT_NS": ""})
    assert not resolution.ok and resolution.errors[0].code == "ns-empty"


@pytest.mark.oracle
def test_empty_namespace_from_environment_agrees_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.assert_agrees(ws.launch("env.launch", ENV), [({}, {"ROBOT_NS": ""})], modes=["shared"])


def test_env_requires_a_name(ws: LaunchWorkspace) -> None:
    model = ws.model(ws.launch("noname.launch", '  <env value="x"/>'))
    assert [e.code for e in model.errors] == ["attribute-missing"]
    empty = ws.model(ws.launch("emptyname.launch", '  <env name="" value="x"/>'))
    assert [e.code for e in empty.errors] == ["env-invalid"]
