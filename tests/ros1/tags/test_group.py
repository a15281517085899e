"""``<group>``: a condition conjoined into everything inside, a namespace, a param scope."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest

from rosvar.interpreter.model import LaunchModel, NodeDecl

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

NESTED = """
  <arg name="arm" default="true"/>
  <arg name="robot" default="r1"/>
  <group ns="$(arg robot)">
    <node pkg="pkg" type="base" name="base"/>
    <group if="$(arg arm)" ns="arm">
      <node pkg="pkg" type="arm" name="controller"/>
      <group ns="/global">
        <node pkg="pkg" type="t" name="tf"/>
      </group>
    </group>
    <group unless="$(arg arm)">
      <node pkg="pkg" type="t" name="no_arm"/>
    </group>
  </group>
"""


def nodes_by_name(model: LaunchModel) -> dict[str, NodeDecl]:
    return {str(n.fields["name"].single()): n for n in model.nodes}


def test_group_condition_is_conjoined_into_its_content(ws: LaunchWorkspace) -> None:
    model = ws.model(ws.launch("nested.launch", NESTED))
    space = model.space
    nodes = nodes_by_name(model)
    base, controller = nodes["base"].condition, nodes["controller"].condition
    tf, no_arm = nodes["tf"].condition, nodes["no_arm"].condition
    assert base == space.true
    assert controller == tf  # the nested group adds no condition of its own
    assert space.describe(controller) == "arm"
    assert (controller & no_arm & space.valid) == space.false
    assert space.valid_implies(~model.loads | controller | no_arm)


def test_group_namespaces(ws: LaunchWorkspace) -> None:
    file = ws.launch("nested.launch", NESTED)
    model = ws.model(file)
    namespaces = nodes_by_name(model)["controller"].fields["namespace"]
    assert "/r1/arm/" in namespaces.values()
    resolution = ws.resolve(file, {"robot": "r2"})
    assert sorted(n.name for n in resolution.nodes) == [
        "/global/tf",
        "/r2/arm/controller",
        "/r2/base",
    ]
    no_arm = ws.resolve(file, {"arm": "false"})
    assert sorted(n.name for n in no_arm.nodes) == ["/r1/base", "/r1/no_arm"]


@pytest.mark.oracle
def test_groups_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("nested.launch", NESTED)
    ws.assert_agrees(
        file,
        [{}, {"arm": "false"}, {"robot": "r2"}, {"robot": "/abs"}, {"robot": "a//b/"}],
    )


PRIVATE = """
  <arg name="fast" default="false"/>
  <group>
    <param name="~rate" value="50" if="$(arg fast)"/>
    <param name="~rate" value="5" unless="$(arg fast)"/>
    <node pkg="pkg" type="t" name="inside"/>
  </group>
  <node pkg="pkg" type="t" name="outside"/>
"""


def test_private_params_are_copied_into_groups(ws: LaunchWorkspace) -> None:
    """A ``~param`` of a group applies to the group's later nodes, not to nodes after it."""
    file = ws.launch("private.launch", PRIVATE)
    assert ws.resolve(file, {}).params == {"/inside/rate": 5}
    assert ws.resolve(file, {"fast": "true"}).params == {"/inside/rate": 50}


@pytest.mark.oracle
def test_private_params_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    ws.assert_agrees(ws.launch("private.launch", PRIVATE), [{}, {"fast": "true"}])


CLEAR = """
  <arg name="clear" default="true"/>
  <group ns="ns" clear_params="$(arg clear)">
    <param name="p" value="1"/>
  </group>
"""


def test_clear_params_is_conditional(ws: LaunchWorkspace) -> None:
    model = ws.model(ws.launch("clear.launch", CLEAR))
    space = model.space
    [clear] = model.clear_params
    # a typed value counts too when it is 'true' in another case (roslaunch lowercases it)
    assert space.describe(clear.condition, known_only=False) == "clear ∨ ⟨clear⟩ is 'true'"
    assert clear.name.single() == "/ns/"
    given = model.inputs["clear"]
    assert not space.evaluate(clear.condition, space.assignment({given: "false"}))


def test_clear_params_from_other_values(ws: LaunchWorkspace) -> None:
    model = ws.model(ws.launch("clear.launch", CLEAR))
    space = model.space
    given = model.inputs["clear"]
    assert any(
        space.evaluate(c.condition, space.assignment({given: "True"})) for c in model.clear_params
    )


def test_empty_ns_is_an_error(ws: LaunchWorkspace) -> None:
    model = ws.model(
        ws.launch("emptyns.launch", '<group ns=""><node pkg="pkg" type="t" name="n"/></group>')
    )
    assert [e.code for e in model.errors] == ["ns-empty"]


def test_empty_clear_params_is_ignored(ws: LaunchWorkspace) -> None:
    file = ws.launch(
        "emptyclear.launch",
        '<group ns="a" clear_params=""><node pkg="pkg" type="t" name="n"/></group>',
    )
    model = ws.model(file)
    assert model.clear_params == [] and model.errors == []
    assert [n.name for n in ws.resolve(file).nodes] == ["/a/n"]


@pytest.mark.oracle
def test_empty_clear_params_is_ignored_by_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch(
        "emptyclear.launch",
        '<group ns="a" clear_params=""><node pkg="pkg" type="t" name="n"/></group>',
    )
    [result] = ws.oracle(file, [({}, {})])
    assert result["ok"] and [n["name"] for n in result["nodes"]] == ["/a/n"]
