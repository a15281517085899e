"""``<include>`` (``IncludeLaunchDescription``): no scope of its own; its ``<arg>`` children are
set in the current context before the included file runs, under the include's condition."""

from __future__ import annotations

from pathlib import Path

import pytest

from ros2.tags.launches import launch
from rosvar.logic.inputs import UNSET

INNER = """<launch>
  <arg name="x" default="dflt"/>
  <node pkg="pkg" exec="b" name="in_$(var x)"/>
</launch>"""


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{}, {"x": "cli"}, {"use": "false"}])
def test_arguments_of_an_include_agree_with_ros2_launch(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    it = launch(
        tmp_path,
        """<launch><arg name="use" default="true"/>
          <include file="$(dirname)/inner.launch.xml" if="$(var use)">
            <arg name="x" value="given"/></include>
          <include file="$(dirname)/inner.launch.xml"/>
          <node pkg="pkg" exec="a" name="after_$(var x dflt2)"/>
        </launch>""",
        files={"inner.launch.xml": INNER},
    )
    it.matches_oracle(arguments)


def test_an_included_files_nodes_carry_the_include_condition(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """<launch><arg name="use" default="true"/>
          <include file="$(dirname)/inner.launch.xml" if="$(var use)"/></launch>""",
        files={"inner.launch.xml": INNER},
    )
    (node,) = it.model.nodes
    assert it.implies(it.given("use", "true"), node.condition)
    assert it.never(node.condition & it.given("use", "false"))
    assert str(it.main.parent / "inner.launch.xml") in it.model.files


@pytest.mark.oracle
def test_a_missing_file_fails_only_where_it_is_included(tmp_path: Path) -> None:
    it = launch(
        tmp_path,
        """<launch><arg name="use" default="false"/>
          <include file="$(dirname)/missing.launch.xml" if="$(var use)"/>
          <node pkg="pkg" exec="a" name="a"/></launch>""",
    )
    assert it.implies(it.given("use", "true"), ~it.model.loads)
    assert it.implies(it.given("use", "false") | it.given("use", UNSET), it.model.loads)
    it.matches_oracle({})
    it.matches_oracle({"use": "true"})
