"""Tests of the ROS 2 YAML launch frontend: the trees of equivalent XML, typed values,
locations, and every refusal as a diagnostic."""

from __future__ import annotations

import random
from pathlib import Path

from ros2.frontends.trees import demo_launch, shape, xml_shape
from rosvar.diagnostics import Location
from rosvar.ros2.frontends.yaml.parser import parse_yaml_launch_bytes, parse_yaml_launch_file


def parse(source: str) -> tuple[object, list[str]]:
    result = parse_yaml_launch_bytes(source.encode(), "t.launch.yaml")
    codes = [diagnostic.code for diagnostic in result.diagnostics]
    return (shape(result.root) if result.root else None), codes


def test_entities_attributes_and_nested_lists_as_in_xml() -> None:
    tree, codes = parse(
        """
launch:
- arg: {name: robot, default: r1, description: "the robot"}
- let: {name: x, value: $(var robot)_x}
- group:
    scoped: "false"
    children:
    - push_ros_namespace: {namespace: ns}
    - node:
        pkg: demo
        exec: talker
        param:
        - {from: $(find-pkg-share demo)/p.yaml}
        - name: outer
          param:
          - {name: inner, value: "$(var x)"}
        remap:
        - {from: a, to: b}
        env:
        - {name: E, value: v}
- include:
    file: f.launch.yaml
    arg:
    - {name: robot, value: r2}
"""
    )
    assert codes == []
    assert tree == xml_shape(
        """<launch>
  <arg name="robot" default="r1" description="the robot"/>
  <let name="x" value="$(var robot)_x"/>
  <group scoped="false">
    <push_ros_namespace namespace="ns"/>
    <node pkg="demo" exec="talker">
      <param from="$(find-pkg-share demo)/p.yaml"/>
      <param name="outer"><param name="inner" value="$(var x)"/></param>
      <remap from="a" to="b"/>
      <env name="E" value="v"/>
    </node>
  </group>
  <include file="f.launch.yaml"><arg name="robot" value="r2"/></include>
</launch>"""
    )


def test_typed_values_are_canonical_yaml_text_and_marked() -> None:
    result = parse_yaml_launch_bytes(
        b"""launch:
- node:
    pkg: p
    exec: e
    respawn: yes
    param:
    - {name: rate, value: 10}
    - {name: ratio, value: 0.5}
    - {name: flag, value: true}
    - {name: quoted, value: "10"}
    - {name: list, value: [1, 2]}
    - {name: words, value: [a, "1"]}
    - {name: empty, value: }
""",
        "t.yaml",
    )
    assert result.diagnostics == []
    assert result.root is not None
    node = result.root.children[0]
    assert node.attributes["respawn"] == "true" and node.typed == {"respawn"}
    values = [(p.attributes["value"], p.typed, p.get("type")) for p in node.children]
    assert values == [
        ("10", {"value"}, None),
        ("0.5", {"value"}, None),
        ("true", {"value"}, None),
        ("10", frozenset(), "str"),  # a string, as XML says with type="str"
        ("[1, 2]", {"value"}, None),
        ("[a, '1']", {"value"}, None),
        ("null", {"value"}, None),
    ]


def test_locations_are_those_of_the_keys() -> None:
    result = parse_yaml_launch_bytes(
        b"launch:\n- node:\n    pkg: p\n    param:\n    - {name: a, value: 1}\n", "t.yaml"
    )
    assert result.root is not None
    node = result.root.children[0]
    assert result.root.location == Location("t.yaml", 1, 1)
    assert node.location == Location("t.yaml", 2, 3)
    assert node.children[0].location == Location("t.yaml", 5, 8)


def test_repeated_keys_and_merge_keys_read_as_a_dict() -> None:
    tree, codes = parse(
        "launch:\n- node: {pkg: a, exec: e, pkg: b}\n"
        "- arg: &base {name: x, default: d}\n- arg: {<<: *base, name: y}\n"
    )
    assert codes == []
    assert tree == xml_shape(
        '<launch><node pkg="b" exec="e"/><arg name="x" default="d"/>'
        '<arg name="y" default="d"/></launch>'
    )


def test_structure_errors_are_diagnostics_and_the_rest_is_kept() -> None:
    tree, codes = parse(
        "launch:\n- node: just-a-string\n- {a: 1, b: 2}\n- 7\n- group:\n"
        "- node: {pkg: p, param: {name: x}}\n- node: {pkg: q, when: 2024-01-01}\n"
        "- arg: {name: kept}\n"
    )
    assert codes == ["yaml-launch-structure"] * 6
    assert tree == xml_shape(
        '<launch><node/><group/><node pkg="p"/><node pkg="q"/><arg name="kept"/></launch>'
    )


def test_malformed_documents_are_refused() -> None:
    for source, code in [
        ("launch: [\n", "yaml-malformed"),
        ("- a\n- b\n", "yaml-launch-structure"),
        ("a: 1\nb: 2\n", "yaml-launch-structure"),
        ("", "yaml-launch-structure"),
        ("a: 1\n---\nb: 2\n", "yaml-malformed"),
    ]:
        tree, codes = parse(source)
        assert (tree, codes) == (None, [code]), source
    result = parse_yaml_launch_bytes(b"launch: \xff", "t.yaml")
    assert [d.code for d in result.diagnostics] == ["yaml-encoding"]


def test_alias_bombs_and_deep_nesting_are_refused_before_construction() -> None:
    bomb = "a: &a [x, x, x, x, x, x, x, x, x, x]\n" + "".join(
        f"{chr(98 + i)}: &{chr(98 + i)} [{', '.join(['*' + chr(97 + i)] * 10)}]\n" for i in range(6)
    )
    assert parse("launch:\n- arg: {name: x}\n" + bomb) == (None, ["yaml-limit"])
    assert parse("launch: " + "[" * 200 + "]" * 200) == (None, ["yaml-limit"])
    assert parse("launch: &a [*a]\n") == (None, ["yaml-limit"])


def test_files_are_read_through_the_confined_reader(tmp_path: Path) -> None:
    missing = parse_yaml_launch_file(tmp_path / "none.launch.yaml")
    assert missing.root is None and missing.diagnostics[0].code == "file-unreadable"


def test_demo_package_yaml_equals_its_xml() -> None:
    for name in ("top", "sub"):
        yaml_tree = parse_yaml_launch_file(demo_launch(f"{name}.launch.yaml")).root
        assert yaml_tree is not None
        expected = xml_shape(demo_launch(f"{name}.launch.xml").read_text())
        # the two files differ only where their authors wrote the same thing differently:
        # the included file's suffix, and the quotes of the $(eval) argument.
        rewrite = (
            (".launch.yaml", ".launch.xml"),
            ("\"'$(var robot)' == 'robot2'\"", "'\\'$(var robot)\\' == \\'robot2\\''"),
        )
        assert shape(yaml_tree, rewrite) == expected


def test_mutants_of_a_launch_file_never_raise() -> None:
    """Seeded mutations (lines dropped, duplicated, cut, re-indented) read without an
    exception."""
    source = demo_launch("sub.launch.yaml").read_text().splitlines()
    rng = random.Random(19)
    for _ in range(300):
        lines = list(source)
        for _ in range(rng.randint(1, 4)):
            at = rng.randrange(len(lines))
            mutation = rng.choice(("drop", "duplicate", "cut", "indent"))
            if mutation == "drop":
                del lines[at]
            elif mutation == "duplicate":
                lines.insert(at, lines[rng.randrange(len(lines))])
            elif mutation == "cut":
                lines[at] = lines[at][: rng.randrange(len(lines[at]) + 1)]
            else:
                lines[at] = " " * rng.randrange(8) + lines[at].lstrip()
        result = parse_yaml_launch_bytes("\n".join(lines).encode(), "m.yaml")
        assert result.root is not None or result.diagnostics
