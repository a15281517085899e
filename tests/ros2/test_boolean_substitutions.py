"""launch's boolean substitutions and ``LaunchConfigurationEquals``: their texts as launch's
``perform`` computes them, and over every command line (an ``<other>`` value compared with
a foreseen text; a term evaluated once the value is given). Each against the oracle too."""

from __future__ import annotations

from pathlib import Path

import pytest

from ros2.tags.launches import launch
from rosvar.logic.inputs import OTHER, UNSET
from rosvar.ros2.boolean_substitutions import NotBoolean, equals, typed_bool


@pytest.mark.parametrize(
    ("left", "right", "same"),
    [
        ("a", "a", True),
        ("a", "A", False),
        ("TRUE", "1", True),  # booleans by value, any case
        ("false", "0", True),
        ("1.0", "1", True),  # numbers by value
        ("1e3", "1000", True),
        ("yes", "true", False),  # yes is no boolean word here
        ("", "[]", False),
    ],
)
def test_equals_compares_booleans_and_numbers_by_value(left: str, right: str, same: bool) -> None:
    assert equals(left, right) == ("true" if same else "false")


def test_a_typed_bool_reads_yaml_booleans_and_refuses_the_rest() -> None:
    assert [typed_bool(t) for t in ("1", "0", "yes", "Off", "TRUE", "true # on")] == [
        True,
        False,
        True,
        False,
        True,
        True,
    ]
    deep = "[" * 900 + "]" * 900  # within the length; PyYAML's constructor recursed on it
    for text in ("", "maybe", "2", "[true]", "x" * 5000, deep):
        with pytest.raises(NotBoolean):
            typed_bool(text)


MAIN = """<launch>
  <arg name="mode" default="a"/>
  <arg name="on" default="true"/>
  <node pkg="pkg" exec="x" name="eq" if="$(equals $(var mode) b)"/>
  <node pkg="pkg" exec="x" name="num" if="$(equals $(var mode) 1.0)"/>
  <node pkg="pkg" exec="x" name="n_$(not $(var on))"/>
</launch>"""


def test_comparisons_over_every_command_line(tmp_path: Path) -> None:
    it = launch(tmp_path, MAIN)
    model = it.model
    assert set(model.domains["mode"]) >= {"a", "b", OTHER}  # b: compared with
    assert set(model.domains["on"]) >= {"true", "false", OTHER}  # an operand of $(not)
    eq, num, negated = model.nodes
    assert it.same(eq.condition, it.given("mode", "b"))
    # an <other> value may be 1 or 1e0: known once given
    assert it.implies(it.given("mode", OTHER), ~num.condition | it.given("mode", OTHER))
    assert it.never(num.condition & (it.given("mode", "a") | it.given("mode", UNSET)))
    names = {leaf: c for c, leaf in negated.field("name") if isinstance(leaf, str)}
    assert it.same(names["n_false"], it.given("on", "true") | it.given("on", UNSET))
    assert it.same(names["n_true"], it.given("on", "false"))


@pytest.mark.oracle
@pytest.mark.parametrize(
    "arguments",
    [{}, {"mode": "b"}, {"mode": "1"}, {"mode": "1e0", "on": "no"}, {"on": "maybe"}],
)
def test_comparisons_agree_with_ros2_launch(tmp_path: Path, arguments: dict[str, str]) -> None:
    launch(tmp_path, MAIN).matches_oracle(arguments)


PYTHON = """from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, SetLaunchConfiguration
from launch.conditions import LaunchConfigurationEquals, LaunchConfigurationNotEquals
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='1'),
        Node(package='pkg', executable='x', name='text',
             condition=LaunchConfigurationEquals('mode', '1.0')),
        Node(package='pkg', executable='x', name='other',
             condition=LaunchConfigurationNotEquals('mode', '1')),
        Node(package='pkg', executable='x', name='undefined',
             condition=LaunchConfigurationEquals('nope', None)),
        Node(package='pkg', executable='x', name='empty',
             condition=LaunchConfigurationEquals('nope', '')),
    ])
"""


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{}, {"mode": "1.0"}, {"mode": "2"}])
def test_launch_configuration_equals_compares_texts(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    """Unlike ``$(equals)``, ``1.0`` is not ``1``; an undefined configuration equals only
    no value."""
    expected = launch(tmp_path, PYTHON, ".launch.py").matches_oracle(arguments)
    names = {node["name"] for node in expected["nodes"]}
    assert "undefined" in names and "empty" not in names
    assert ("text" in names) == (arguments.get("mode") == "1.0")


def test_an_unknown_python_value_in_a_condition_is_shown_readably(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """from launch import LaunchDescription
from launch.conditions import IfCondition
from launch_ros.actions import Node
import helpers


def generate_launch_description():
    return LaunchDescription([
        Node(package='pkg', executable='x', condition=IfCondition(helpers.enabled())),
    ])
""",
        ".launch.py",
    )
    (node,) = it.model.nodes
    shown = it.analysis.space.describe(node.condition)
    assert "⟨call to helpers.enabled()⟩" in shown and "rosvar-unknown" not in shown
