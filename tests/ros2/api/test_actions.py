"""The registry of launch actions: one entry per action, a handler for each walked one, and
names the real launch code exposes (read from its sources in ``../shared/ros2-oracle``)."""

from __future__ import annotations

import pytest

from ros2.api.upstream import UPSTREAM, exported_by_upstream, exposed_by_upstream
from rosvar.interpreter.dialect import dialect_of
from rosvar.ros.version import RosVersion
from rosvar.ros2.api.actions import ACTIONS, Action, attributes
from rosvar.ros2.api.registry import Registry
from rosvar.ros2.dialect import ROS2, tag


def test_every_walked_action_has_a_handler_and_no_other_tag_has() -> None:
    dialect_of(RosVersion.ROS2)  # its handlers registered
    walked = {name for action in ACTIONS if action.walked for name in action.names}
    assert set(ROS2.tags) == walked


def test_a_handler_needs_a_registered_action() -> None:
    with pytest.raises(ValueError, match="<nodes> is no action"):
        tag("nodes")
    with pytest.raises(ValueError, match="<param> is no action"):  # read by its parent
        tag("param")


def test_a_name_is_exposed_once() -> None:
    registry: Registry[Action] = Registry("action")
    registry.expose(Action(("a", "b"), ("launch.A",)))
    with pytest.raises(ValueError, match="action <b> is exposed twice"):
        registry.expose(Action(("b",)))
    with pytest.raises(ValueError, match=r"action launch\.A is exposed twice"):
        registry.expose(Action(("c",), ("launch.actions.a.A",)))
    assert list(registry) == [registry.by_name["a"]]  # a refusal registers nothing


def test_aliases_and_tags_find_one_entry() -> None:
    timer = ACTIONS.by_name["ros_timer"]
    assert ACTIONS.by_python["launch_ros", "RosTimer"] is timer
    assert ACTIONS.by_python["launch_ros", "ROSTimer"] is timer
    push = ACTIONS.by_name["push-ros-namespace"]
    assert ACTIONS.by_name["push_ros_namespace"] is push and push.tag == "push-ros-namespace"
    assert ACTIONS.by_python["launch_ros", "PushROSNamespace"] is push
    assert ACTIONS.by_python["launch_ros", "PushRosNamespace"] is push


def test_attributes_are_the_arguments_and_the_xml_only_ones() -> None:
    action = Action(("x",), params=attributes("a", "b_c:b-c"), xml_only=("d",))
    assert action.attributes == {"a", "b-c", "d"}
    assert ACTIONS.by_name["node"].attributes >= {"pkg", "exec", "param", "remap", "on_exit"}
    assert "composable_node" in ACTIONS.by_name["node_container"].attributes


@pytest.mark.skipif(not UPSTREAM.is_dir(), reason="no ROS 2 oracle")
def test_the_real_launch_exposes_every_tag_and_class() -> None:
    exposed = exposed_by_upstream("action")
    walked = {n for a in ACTIONS if a.walked and not a.python_only for n in a.names}
    assert walked <= exposed, walked - exposed
    classes = exported_by_upstream("actions", "launch", "launch_ros")
    unknown = {k for k, a in ACTIONS.by_python.items() if a.walked} - classes
    assert unknown == set()
