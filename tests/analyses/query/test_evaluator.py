"""Queries over a small workspace: the elements selected and the conditions they hold under,
compared with conditions built from the space's slots; every example satisfies its condition."""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from rosvar.analyses.query.collections import ElementSet
from rosvar.analyses.query.evaluator import QueryEngine, Result
from rosvar.analyses.query.parser import QueryError
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.inputs import ArgInput, Input
from rosvar.workspace import discover

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

ROBOT = """
  <arg name="robot" default="kobuki"/>
  <arg name="sim" default="false"/>
  <node pkg="$(arg robot)_node" type="driver" name="base"/>
  <node pkg="sim" type="gazebo" name="gazebo" if="$(arg sim)"/>
  <group ns="robot">
    <node pkg="x" type="y" name="z"><remap from="cmd_vel" to="/cmd"/></node>
  </group>
  <node pkg="a" type="b" name="teleop" unless="$(arg sim)"><remap from="out" to="/cmd"/></node>
  <param name="/robot/speed" value="1.0"/>
  <param name="/other" value="x" if="$(arg sim)"/>
"""


@pytest.fixture
def robot(ws: LaunchWorkspace) -> tuple[QueryEngine, str]:
    file = ws.launch("robot.launch", ROBOT)
    analysis = Analysis(discover([ws.root], ros_package_path=""), extra_values={"robot": ["husky"]})
    return QueryEngine(analysis, [file]), file


def slot(engine: QueryEngine, file: str, arg: str, value: str) -> BDD:
    space = engine.space
    return space.slot(ArgInput(file, arg), value)


def satisfied(engine: QueryEngine, file: str, result: Result) -> bool:
    """The result's example configuration (as ``name:=value`` words) satisfies its condition."""
    values: dict[Input, str | None] = {}
    space = engine.space
    for key, value in engine.example(result.condition).items():
        _file, name = key.split(":")
        special = value.startswith("<")
        values[ArgInput(file, name)] = (
            "\0other" if value == "<other>" else None if special else value
        )
    return space.evaluate(result.condition, space.assignment(values))


def by_name(results: list[Result]) -> Mapping[str, Result]:
    return {r.element.name: r for r in results}


def test_path_predicate_on_a_conditional_attribute(robot: tuple[QueryEngine, str]) -> None:
    engine, file = robot
    found = by_name(engine.run("nodes[self.package == 'kobuki_node']"))
    assert list(found) == ["/base"]
    assert found["/base"].condition == slot(engine, file, "robot", "kobuki")
    assert satisfied(engine, file, found["/base"])
    husky = by_name(engine.run("nodes[self.package.startswith('husky')]"))["/base"]
    assert husky.condition == slot(engine, file, "robot", "husky")
    assert satisfied(engine, file, husky)


def test_presence_is_part_of_the_condition(robot: tuple[QueryEngine, str]) -> None:
    engine, file = robot
    model = engine.models[0]
    declared = {n.fields["name"].single(): n.condition for n in model.nodes}
    found = by_name(engine.run("nodes[self.type in ('gazebo', 'b')]"))
    assert {name: r.condition for name, r in found.items()} == {
        "/gazebo": declared["gazebo"],
        "/teleop": declared["teleop"],
    }
    assert found["/gazebo"].condition != engine.space.true
    assert all(satisfied(engine, file, r) for r in found.values())


def test_flwor_form_and_chained_predicates(robot: tuple[QueryEngine, str]) -> None:
    engine, _file = robot
    flwor = engine.run("for n in nodes where n.name.startswith('/robot/') return n")
    path = engine.run("nodes[self.name.startswith('/robot')][self.type == 'y']")
    assert [r.element.name for r in flwor] == [r.element.name for r in path] == ["/robot/z"]
    assert len(engine.run("for n in nodes return n")) == len(engine.run("nodes"))


def test_len_of_a_conditional_set(robot: tuple[QueryEngine, str]) -> None:
    engine, _file = robot
    teleop = by_name(engine.run("nodes[self.type == 'b']"))["/teleop"]
    shared = engine.run("topics[len(self.remapped_by) > 1]")
    assert [r.element.name for r in shared] == ["/cmd"]
    assert shared[0].condition == teleop.condition
    assert engine.run("topics[len(self.publishers) > 0]") == []
    assert [r.element.name for r in engine.run("topics[self.remapped_by]")] == ["/cmd"]


def test_subsets_of_an_element_set(robot: tuple[QueryEngine, str]) -> None:
    engine, file = robot
    space = engine.space
    a, b = slot(engine, file, "robot", "kobuki"), slot(engine, file, "sim", "true")
    first, second = (r.element for r in engine.run("nodes")[:2])
    subsets = ElementSet(((a, first), (b, second))).subsets(space, 4)
    assert subsets is not None
    assert {members: c for c, members in subsets} == {
        (first, second): a & b,
        (first,): a & ~b,
        (second,): ~a & b,
        (): ~a & ~b,
    }
    assert ElementSet(((a, first), (b, second))).subsets(space, 3) is None


def test_params_args_and_launch_files(robot: tuple[QueryEngine, str]) -> None:
    engine, file = robot
    assert [r.element.name for r in engine.run("params[self.name.startswith('/robot')]")] == [
        "/robot/speed"
    ]
    assert [r.element.name for r in engine.run("params[self.value > 0.5]")] == ["/robot/speed"]
    assert [r.element.name for r in engine.run("args[self.default == 'false']")] == ["sim"]
    (entry,) = engine.run("launch_files[len(self.nodes) >= 2]")
    assert entry.condition == engine.space.true
    assert entry.element.name.endswith(os.path.basename(file))
    assert engine.run("launch_files[len(self.nodes) > 3]") == []


def test_arg_values_restrict_the_question(robot: tuple[QueryEngine, str]) -> None:
    engine, file = robot
    kobuki = slot(engine, file, "robot", "kobuki")
    (gazebo,) = engine.run("nodes[self.type == 'gazebo']", {"robot": "kobuki"})
    assert gazebo.condition == kobuki & engine.models[0].nodes[1].condition
    assert engine.run("nodes[self.package == 'husky_node']", {"robot": "kobuki"}) == []
    assert engine.run("nodes[self.package == 'kobuki_node']", {"unknown": "1"})


@pytest.mark.parametrize(
    ("query", "message"),
    [
        ("nodes[__import__('os').system('true')]", "double underscores"),
        ("nodes[self.__class__]", "double underscores"),
        ("nodes[lambda: 1]", "lambda"),
        ("nodes[[x for x in 'a' * 9]]", "comprehensions are not allowed"),
        ("nodes[len([1 for x in self.name for y in self.name])]", "comprehensions are not"),
        ("nodes[open('/etc/passwd')]", "only these functions"),
        ("nodes[getattr(self, 'name')]", "only these functions"),
        ("nodes[self.name.format(self)]", "only these functions"),
        ("nodes[self.name * 10 ** 9]", "operator Pow"),
        ("nodes[len(self.name, key=1)]", "positional arguments only"),
        ("nodes[os]", "unknown name 'os'"),
        ("nodes[self]", "read attributes of the element"),
        ("nodes[" + "-" * 1500 + "1]", "nested more than 100 levels|cannot parse"),
        ("nodes[" + "not " * 300 + "True]", "nested more than 100 levels"),
        ("nodes[(1).real]", "attributes are read from self only"),
        ("nodes[self.pkg == 'x']", "no attribute 'pkg'"),
        ("robots[True]", "unknown collection 'robots'"),
        ("nodes[", "invalid Python expression"),
        ("for n in nodes where n.name return m", "return must name"),
        ("nodes[self.name * 100000000 == 'a']", "longer than"),
        # issue 30.5: a million references to a list of a million, built at once in C, and
        # compared element by element for minutes: what a sequence holds counts
        ("nodes[[[0] * 999999] * 999999 == [[1] * 999999] * 999999]", "longer than"),
        ("nodes[[['x' * 1000] * 1000] * 1000 == []]", "longer than"),
        ("nodes[[[0] * 1000] * 1000 + [[0] * 1000] * 1 == []]", "longer than"),
    ],
)
def test_unsafe_or_invalid_queries_are_refused(
    robot: tuple[QueryEngine, str], query: str, message: str
) -> None:
    engine, _file = robot
    with pytest.raises(QueryError, match=message):
        engine.run(query)


CORPUS = Path(__file__).resolve().parents[4] / "shared" / "corpus"


def test_kobuki_nodes_of_a_package() -> None:
    if not (CORPUS / "kobuki").is_dir():
        pytest.skip("corpus not found")
    analysis = Analysis(
        discover([str(CORPUS / "kobuki")], deps=[str(CORPUS / "_external")], ros_package_path="")
    )
    engine = QueryEngine(analysis)
    results = engine.run("nodes[self.package == 'kobuki_node']")
    expected: dict[tuple[str, int], BDD] = {}
    for model in engine.models:
        for node in model.nodes:
            where = node.condition & node.fields["pkg"].where(lambda p: p == "kobuki_node")
            if where != analysis.space.false:
                key = (model.file, node.location.line)
                expected[key] = expected.get(key, analysis.space.false) | where
    found: dict[tuple[str, int], BDD] = {}
    for result in results:
        assert result.element.location is not None
        model = next(m for m in engine.models if analysis.label(m.file) == result.element.file)
        key = (model.file, result.element.location.line)
        found[key] = found.get(key, analysis.space.false) | result.condition
    assert found == expected
    assert found
