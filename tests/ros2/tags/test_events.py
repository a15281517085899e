"""Event handlers: their actions run when their event comes, marked with their trigger, as the
oracle records it (``launch``, ``timer@2s``, ``on_process_start(...)``); those of later events
(a process's exit) are listed apart."""

from __future__ import annotations

from pathlib import Path

import pytest

from differential.ros2.names_cases import CASES
from ros2.tags.launches import launch
from rosvar.interpreter.workspace_models import Analysis

MAIN = CASES["event-handlers"][0]["main.launch.py"]


def _kind(trigger: str) -> str:
    return trigger.partition("(")[0]


@pytest.mark.oracle
@pytest.mark.parametrize("arguments", [{}, {"go": "false"}])
def test_triggers_are_the_oracles(tmp_path: Path, arguments: dict[str, str]) -> None:
    it = launch(tmp_path, MAIN, ".launch.py")
    expected = it.matches_oracle(arguments)
    known = Analysis(it.analysis.workspace, extra_values={k: [v] for k, v in arguments.items()})
    result = known.resolve([str(it.main)], arguments)
    ours = sorted((str(n.own_name), _kind(str(n.attributes["trigger"]))) for n in result.nodes)
    assert ours == sorted((n["name"], _kind(n["trigger"])) for n in expected["nodes"])
    later = [(n.own_name, _kind(str(n.attributes["trigger"]))) for n in result.on_events]
    assert later == ([] if arguments else [("on_exit", "on_process_exit")])


def test_a_handler_runs_where_its_target_started(tmp_path: Path) -> None:
    it = launch(tmp_path, MAIN, ".launch.py")
    by_name = {
        leaf: (node.condition, node.trigger)
        for node in it.model.nodes
        for _c, leaf in node.field("name")
        if isinstance(leaf, str)
    }
    first, _ = by_name["first"]
    after, trigger = by_name["after_first"]
    assert it.same(after, first) and trigger.startswith("on_process_start(")
    assert by_name["late"][1] == "timer@2s"
    assert it.same(by_name["on_exit"][0], first)
