"""A ``<node>``'s typed fields (``ROS1_NODES``): over every configuration, and restricted to
one, what roslaunch launches."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest

from rosvar.interpreter.resolution import Restriction
from rosvar.ros1.nodes import ROS1_NODES

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


TYPED = """
  <arg name="robot" default="r1"/>
  <arg name="sub" default="arm"/>
  <group ns="$(arg robot)">
    <node pkg="pkg" type="driver" name="driver" ns="$(arg sub)" args="--robot $(arg robot)"/>
  </group>
"""


@pytest.mark.oracle
def test_typed_fields_in_a_configuration_are_what_roslaunch_launches(
    ws: LaunchWorkspace,
) -> None:
    """Each typed field, over every configuration, restricted to one (given values that are
    ``<other>`` slots of the shared model: terms evaluated) is roslaunch's value."""
    file = ws.launch("typed.launch", TYPED)
    model = ws.model(file)
    [node] = model.nodes
    schema = node.schema
    assert schema is ROS1_NODES
    accessors = {
        "name": schema.full_name,
        "namespace": schema.namespace,
        "package": schema.package,
        "type": schema.executable,
        "args": schema.args,
    }
    configs = [{}, {"robot": "r2"}, {"robot": "r2", "sub": "x"}, {"sub": "/abs"}]
    results = ws.oracle(file, [(config, {}) for config in configs])
    for config, theirs in zip(configs, results, strict=True):
        restriction = Restriction(ws.analysis(), model, config, {})
        assert theirs["ok"] and restriction.holds(node.condition)
        ours = {
            key: restriction.pick(node.value(accessor), node.location, key)
            for key, accessor in accessors.items()
        }
        [expected] = theirs["nodes"]
        assert ours == {key: expected[key] for key in accessors}, config
    assert schema.name.of({"name": "driver"}) == "driver"
    assert schema.label is schema.full_name  # a ROS 1 node always has a name
