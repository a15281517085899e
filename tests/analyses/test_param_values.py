"""The values of a parameter in every configuration: the last setting loaded wins."""

from __future__ import annotations

from typing import TYPE_CHECKING

from rosvar.analyses.param_values import UNSET, ParamValues, Unknown
from rosvar.logic.inputs import OTHER

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

LAUNCH = """\
  <arg name="a" default="true"/>
  <arg name="f" default="one"/>
  <param name="x" value="1"/>
  <group ns="g">
    <param name="/x" value="2" if="$(arg a)"/>
    <param name="y" value="on" unless="$(arg a)"/>
  </group>
  <rosparam file="$(find pkg)/config/$(arg f).yaml" ns="cfg"/>"""


def test_the_last_setting_wins_else_the_default(ws: LaunchWorkspace) -> None:
    ws.write("config/one.yaml", "z: 3\n")
    file = ws.launch("a.launch", LAUNCH)
    analysis = ws.analysis()
    model = analysis.model(file)
    space = analysis.space
    values = ParamValues(space, [(space.true, model)])

    def found(name: str, default: int | None = None) -> dict[object, str]:
        """Value → condition, of the values some configuration has."""
        pairs = values.values(name, default)
        return {v: space.describe(c) for c, v in pairs if space.satisfiable(c)}

    assert found("/x") == {2: "a", 1: "¬a"}  # the later one where it holds
    assert found("/g/y", 5) == {"on": "¬a", 5: "a"}  # elsewhere the node's default
    assert found("/w") == {UNSET: "true"}  # nobody sets it, no default
    z = found("/cfg/z")
    assert z.pop(3) == "f=one"
    [(other, condition)] = z.items()  # another file: it may set anything below /cfg
    assert isinstance(other, Unknown) and "<rosparam>" in other.reason
    assert condition == space.describe(space.slot(model.inputs["f"], OTHER))
    assert found("/elsewhere") == {UNSET: "true"}  # not below /cfg
