"""The C++ evaluator on its own: values of names and node handles, as the checks reuse it."""

from __future__ import annotations

from pathlib import Path

from tree_sitter import Node

from rosvar.workspace.interfaces.cpp import syntax
from rosvar.workspace.interfaces.cpp.evaluator import Evaluator, Handle
from rosvar.workspace.interfaces.cpp.unit import Function, Unit
from rosvar.workspace.interfaces.values import Text

SOURCE = """\
const std::string BASE = "robot";
#define SUFFIX "scan"

void use(ros::NodeHandle& nh, const std::string& topic) {
  std::string local = BASE + "/" + SUFFIX;
  ros::NodeHandle child(nh, "sensors");
  sink(local, child, topic, std::string("x").c_str(), nh.resolveName("y"));
}

int main() {
  ros::NodeHandle pnh("~");
  use(pnh, "given");
}
"""


def _setup(tmp_path: Path) -> tuple[Evaluator, Function, list[Node]]:
    path = tmp_path / "node.cpp"
    path.write_text(SOURCE)
    unit = Unit.load([str(path)], [])
    evaluator = Evaluator(unit, unit.reachable(unit.functions["main"]))
    (use,) = unit.functions["use"]
    sink = next(c for c in use.nodes("call_expression") if syntax.text(c).startswith("sink"))
    return evaluator, use, syntax.arguments(sink)


def test_constants_concatenation_and_locals(tmp_path: Path) -> None:
    evaluator, use, arguments = _setup(tmp_path)
    assert evaluator.evaluate(arguments[0], use) == Text("robot/scan")
    assert evaluator.evaluate(arguments[3], use) == Text("x")


def test_handles_through_constructors_and_call_sites(tmp_path: Path) -> None:
    evaluator, use, arguments = _setup(tmp_path)
    assert evaluator.evaluate(arguments[1], use) == Handle(Text("~sensors"))
    assert evaluator.evaluate(arguments[4], use) == Text("~y", resolved=True)  # in pnh


def test_parameters_bound_from_the_one_call_site(tmp_path: Path) -> None:
    evaluator, use, arguments = _setup(tmp_path)
    assert evaluator.evaluate(arguments[2], use) == Text("given")
    assert evaluator.name(arguments[2], use) == Text("given")


def test_an_unknown_value_is_named_by_its_expression(tmp_path: Path) -> None:
    evaluator, use, _ = _setup(tmp_path)
    node = next(syntax.walk(syntax.parse(b"argv[1];"), {"subscript_expression"}))
    assert evaluator.evaluate(node, use) is None
    assert evaluator.name(node, use) == Text("{argv[1]}", static=False)
