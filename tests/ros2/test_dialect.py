"""The ROS 2 dialect keeps its tag registry apart from ROS 1's, and its walks free what they
made."""

from __future__ import annotations

import gc
from pathlib import Path

import pytest

from rosvar.interpreter.dialect import dialect_of
from rosvar.logic.conditions import ConditionSpace
from rosvar.outputs.cli import main
from rosvar.ros.version import RosVersion
from rosvar.ros1.dialect import ROS1
from rosvar.ros2.dialect import ROS2


def test_each_dialect_has_its_own_tags() -> None:
    assert dialect_of(RosVersion.ROS2) is ROS2 and dialect_of(RosVersion.ROS1) is ROS1
    assert "let" in ROS2.tags and "let" not in ROS1.tags
    assert len({ROS1.tags["node"], ROS2.tags["node"]}) == 2  # two handlers


def test_a_tag_is_registered_once() -> None:
    dialect_of(RosVersion.ROS2)
    with pytest.raises(ValueError, match="registered twice"):
        ROS2.tag("let")(ROS2.tags["let"])


MANIFEST = """<package format="3"><name>r2</name><version>0.0.0</version>
<description>d</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend>ament_cmake</buildtool_depend>
<export><build_type>ament_cmake</build_type></export></package>
"""


def test_an_analysis_leaves_no_cycle_holding_its_conditions(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A reference cycle holding the condition space is freed by a collection in any order,
    its BDD manager before the conditions (CUDD then asserts "nodes still referenced"): the
    walk's objects (the substituter and its value budget) make none."""
    (tmp_path / "r2" / "launch").mkdir(parents=True)
    (tmp_path / "r2" / "package.xml").write_text(MANIFEST)
    (tmp_path / "r2" / "launch" / "a.launch.xml").write_text(
        '<launch><arg name="a" default="x"/><node pkg="p" exec="e" name="n_$(var a)"/></launch>'
    )
    gc.collect()
    gc.set_debug(gc.DEBUG_SAVEALL)
    try:
        main(["check", str(tmp_path), "--format", "json"])
        gc.collect()
        spaces = [o for o in gc.garbage if isinstance(o, ConditionSpace)]
    finally:
        gc.set_debug(0)
        gc.garbage.clear()
    capsys.readouterr()
    assert spaces == []
