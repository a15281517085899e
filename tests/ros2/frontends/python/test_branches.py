"""Values changed in the branches of an ``if`` on a launch-time value (``branches.py`` and
the interpreter's merge): each branch changes its own copy, and after the ``if`` each
changed value is the choice of the branches' values, down to the actions built from it.
(``os.environ[...]`` is a launch-time value at a module's top level too.)"""

from __future__ import annotations

import ast

import pytest

from rosvar.diagnostics import Diagnostic, DiagnosticSink
from rosvar.frontends.entity import Entity
from rosvar.ros2 import substitutions
from rosvar.ros2.frontends.python import interpreter as module
from rosvar.ros2.frontends.python.interpreter import Interpreter, OutOfBudget, entry_point
from rosvar.ros2.frontends.python.text import render
from rosvar.ros2.frontends.python.values import Conditional, Dynamic, Unknown, Value

FLAG = "import os\nflag = os.environ['FLAG'] == 'on'\n"


def run(text: str) -> tuple[dict[str, Value], list[Diagnostic]]:
    """The module-level names after reading ``text`` (each resolved), and the diagnostics."""
    sink = DiagnosticSink()
    reader = Interpreter("t.launch.py", text, sink)
    scope = reader.run_module(ast.parse(text))
    return {name: reader.settled(value) for name, value in scope.names.items()}, sink.items


def followed(text: str) -> dict[str, Value]:
    """The names after reading ``text``, which must be followed without a diagnostic."""
    names, diagnostics = run(text)
    assert not diagnostics
    return names


def branches(value: Value) -> tuple[Value, Value]:
    assert isinstance(value, Conditional), value
    return value.then, value.otherwise


@pytest.mark.parametrize(
    ("statements", "then", "otherwise"),
    [
        ("a.append(3)", [1, 2, 3], [1, 2]),
        ("a.extend([3, 4])", [1, 2, 3, 4], [1, 2]),
        ("a += [3]", [1, 2, 3], [1, 2]),
        ("a.insert(0, 0)", [0, 1, 2], [1, 2]),
        ("a.remove(1)", [2], [1, 2]),
        ("a.pop()", [1], [1, 2]),
        ("del a[0]", [2], [1, 2]),
        ("a.clear()", [], [1, 2]),
    ],
)
def test_a_list_changed_in_one_branch_is_the_choice_of_both(
    statements: str, then: list[int], otherwise: list[int]
) -> None:
    names = followed(FLAG + f"a = [1, 2]\nb = a\nif flag:\n    {statements}\n")
    assert branches(names["a"]) == (then, otherwise)
    assert names["b"] is names["a"]  # aliasing kept


def test_an_item_changed_keeps_the_list_and_chooses_the_item() -> None:
    names, _ = run(FLAG + "a = ['x', 'y']\nif flag:\n    a[1] = 'z'\nelse:\n    a[0] = 'w'\n")
    chosen = names["a"]
    assert isinstance(chosen, list) and len(chosen) == 2
    assert all(isinstance(item, Dynamic) for item in chosen)


def test_dicts_and_attributes_changed_in_branches() -> None:
    text = FLAG + (
        "class O:\n    def __init__(self):\n        self.mode = 'a'\n"
        "o = O()\nd = {'rate': 1}\nsame = {'k': 1}\n"
        "if flag:\n    d.update({'burst': True})\n    o.mode = 'b'\n    same['k'] = 2\n"
        "else:\n    d.setdefault('slow', 1)\n    del d['rate']\n"
    )
    names = followed(text)
    assert branches(names["d"]) == ({"rate": 1, "burst": True}, {"slow": 1})
    assert isinstance(names["same"], dict) and isinstance(names["same"]["k"], Dynamic)
    assert isinstance(names["o"].attributes["mode"], Dynamic)  # type: ignore[union-attr]


def test_nested_ifs_and_a_conditional_expression_each_keep_their_copy() -> None:
    text = FLAG + (
        "import os\nother = os.environ['OTHER'] == 'on'\na = [1]\n"
        "if flag:\n    a.append(2)\n    if other:\n        a.append(3)\n"
        "a.append(4) if other else a.append(5)\n"
    )
    names = followed(text)

    def leaves(value: Value) -> list[Value]:
        if isinstance(value, Conditional):
            return leaves(value.then) + leaves(value.otherwise)
        return [value]

    found = leaves(names["a"])
    assert [leaf[:-1] for leaf in found] == [[1, 2, 3], [1, 2], [1]]  # type: ignore[index]
    assert all(isinstance(leaf[-1], Dynamic) for leaf in found)  # type: ignore[index]


def test_a_launch_time_value_removed_is_chosen_item_by_item() -> None:
    names = followed("import os\nv = os.environ['V']\na = ['x', 'y']\na.remove(v)\nn = len(a)\n")
    without_x, rest = branches(names["a"])
    without_y, missing = branches(rest)
    assert (without_x, without_y) == (["y"], ["x"])
    assert isinstance(missing, list) and isinstance(missing[0], Unknown)  # launch fails
    assert names["n"] == 1  # one item left in every branch


def test_operations_on_a_chosen_list_are_made_in_each_branch() -> None:
    text = FLAG + (
        "a = ['x']\nif flag:\n    a.append('y')\n"
        "joined = ' '.join(a)\nlonger = a + ['z']\nfirst = a[-1]\nhas = 'y' in a\n"
        "upper = [s.upper() for s in a]\nlooped = []\nfor s in a:\n    looped.append(s * 2)\n"
    )
    names = followed(text)
    for name in ("joined", "first", "has"):
        assert isinstance(names[name], Dynamic), name
    assert branches(names["longer"]) == (["x", "y", "z"], ["x", "z"])
    assert branches(names["upper"]) == (["X", "Y"], ["X"])
    assert branches(names["looped"]) == (["xx", "yy"], ["xx"])


def test_a_node_given_a_chosen_list_is_made_in_each_branch() -> None:
    text = """from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

def setup(context):
    controllers = ['a']
    if LaunchConfiguration('more').perform(context) == 'true':
        controllers.append('b')
    return [Node(package='p', executable='spawner', arguments=['-x'] + controllers)]

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=setup)])
"""
    sink = DiagnosticSink()
    root = entry_point(Interpreter("t.launch.py", text, sink), ast.parse(text))
    assert root is not None and not sink.items

    def nodes(entity: Entity, tests: tuple[str, ...]) -> list[tuple[tuple[str, ...], str]]:
        found = []
        if entity.tag == "node":
            found.append((tests, entity.attributes["args"]))
        inner = (*tests, entity.attributes["if"]) if "if" in entity.attributes else tests
        for child in entity.children:
            found += nodes(child, inner)
        return found

    made = nodes(root, ())
    assert [args for _, args in made] == ["-x a b", "-x a"]
    assert [len(tests) for tests, _ in made] == [1, 1] and made[0][0] != made[1][0]


def test_the_copies_count_against_the_budget(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(module, "MAX_STEPS", 5_000)
    text = FLAG + "a = list(range(1000))\nfor i in range(20):\n    if flag:\n        a.append(i)\n"
    with pytest.raises(OutOfBudget):
        run(text)


def test_a_loop_over_a_launch_time_list_reads_each_item_under_its_length() -> None:
    """``yaml.load`` of a launch configuration is a launch-time list: a loop over it reads
    its first items, each as ``if len(x) > i``; one beyond them is unknown."""
    text = (
        "import os, yaml\ncams = yaml.load(os.environ['CAMS'], Loader=yaml.FullLoader)\n"
        "seen = []\nfor cam in cams:\n    seen.append('/' + cam)\n"
        "upper = [cam.upper() for cam in os.environ['W'].split(',')]\n"
    )
    names = followed(text)
    assert isinstance(names["cams"], Dynamic)
    assert "rosvar-python-yaml" in render(names["cams"].source)
    lengths: list[int] = []

    def walk(value: Value) -> None:
        if isinstance(value, Conditional):
            walk(value.then)
            walk(value.otherwise)
        else:
            assert isinstance(value, list)
            lengths.append(len(value))
            assert all(isinstance(item, Dynamic | Unknown) for item in value)

    walk(names["seen"])
    assert sorted(set(lengths)) == list(range(module.MAX_UNROLLED + 2))
    walk(names["upper"])


def test_the_yaml_substitution_gives_the_loaded_value_as_python() -> None:
    assert substitutions._yaml_literal("[camera6, camera7]") == "['camera6', 'camera7']"
    assert substitutions._yaml_literal("{a: 1}") == "{'a': 1}"
    failed = substitutions._yaml_literal("[unclosed")
    assert not isinstance(failed, str) and failed.code == "eval-failed"
    assert not isinstance(substitutions._yaml_literal("2001-01-01"), str)  # a date


def test_choices_of_choices_are_charged_as_large_as_they_grow(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Twenty ``if``s each adding to a list double the branches to follow: the budget, not
    memory, runs out."""
    monkeypatch.setattr(module, "MAX_STEPS", 20_000)
    tests = "".join(f"t{i} = os.environ['T{i}'] == 'on'\n" for i in range(20))
    ifs = "".join(f"if t{i}:\n    a.append({i})\nb = a + []\n" for i in range(20))
    with pytest.raises(OutOfBudget):
        run("import os\n" + tests + "a = []\n" + ifs)
