"""The ROS 2 substitution grammar: nesting, quoting, escapes."""

from __future__ import annotations

from pathlib import Path

import pytest

from rosvar.interpreter.workspace_models import Analysis
from rosvar.ros2.substitutions import Call, SubstitutionSyntaxError, parse
from rosvar.workspace import discover

MANIFEST = """<package format="3"><name>p</name>
<export><build_type>ament_cmake</build_type></export></package>"""


def test_nested_and_quoted_arguments() -> None:
    assert parse("a$(var x)b") == ("a", Call("var", (("x",),)), "b")
    assert parse("$(eval '\\'$(var r)\\' == 1')") == (
        Call("eval", (("'", Call("var", (("r",),)), "' == 1"),)),
    )
    assert parse("$(env A 'b c')") == (Call("env", (("A",), ("b c",))),)


@pytest.mark.parametrize("text", ["$(var x", "$( x)", "$(env 'a)"])
def test_malformed_text_is_refused(text: str) -> None:
    with pytest.raises(SubstitutionSyntaxError):
        parse(text)


def test_anon_names_are_kept_per_id_and_scoped_by_groups(tmp_path: Path) -> None:
    (tmp_path / "package.xml").write_text(MANIFEST)
    file = tmp_path / "a.launch.xml"
    file.write_text(
        """<launch>
          <node pkg="p" exec="e" name="$(anon n)"/>
          <node pkg="p" exec="e" name="$(anon n)" namespace="x"/>
          <group><node pkg="p" exec="e" name="$(anon m)" namespace="y"/></group>
          <node pkg="p" exec="e" name="$(anon m)" namespace="z"/>
        </launch>"""
    )
    result = Analysis(discover([str(tmp_path)])).resolve([str(file)])
    names = [node.own_name for node in result.nodes]
    assert names[0] == names[1] and names[2] != names[3]
    assert all(str(name).startswith(("n_", "m_")) for name in names)


def test_find_exec_is_kept_as_its_text_with_a_warning(tmp_path: Path) -> None:
    """The PATH that ``$(find-exec)`` searches is the launching machine's: the value stays
    the substitution's text, inside a ``$(command)`` too, and the launch goes on."""
    (tmp_path / "package.xml").write_text(MANIFEST)
    file = tmp_path / "a.launch.xml"
    file.write_text(
        """<launch><arg name="tool" default="xacro"/>
          <node pkg="p" exec="e" name="n">
            <param name="d" value="$(command '$(find-exec $(var tool)) f.xacro')"/>
          </node>
          <node pkg="p" exec="e" name="m" args="$(find-exec)"/>
        </launch>"""
    )
    analysis = Analysis(discover([str(tmp_path)]), extra_values={"tool": ["ros2"]})
    result = analysis.resolve([str(file)], {"tool": "ros2"})
    assert result.nodes[0].parameters == {"d": "$(command $(find-exec ros2) f.xacro)"}
    assert [error.code for error in result.errors] == ["substitution-invalid"]
