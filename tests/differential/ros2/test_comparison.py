"""The comparison of :mod:`.repositories` on answers written here: what makes a difference,
what does not (``$(anon)`` names, errors the missing packages explain), and the repair of the
oracle's JSON when its file renaming swallows an escape."""

from __future__ import annotations

import json
from typing import Any

from oracle.ros2_client import loads_repaired

from .repositories import compare


def _node(**fields: Any) -> dict[str, Any]:
    node: dict[str, Any] = {
        "kind": "node",
        "package": "demo",
        "executable": "talker",
        "plugin": None,
        "name": "talker",
        "namespace": "/",
        "parameters": {},
        "remappings": [],
        "arguments": [],
    }
    node.update(fields)
    return node


def _answer(*nodes: dict[str, Any], **fields: Any) -> dict[str, Any]:
    return {"ok": True, "nodes": list(nodes), **fields}


def test_equal_answers_have_no_difference() -> None:
    answer = _answer(_node(parameters={"rate": 10}))
    assert compare(answer, answer) == []


def test_each_kind_of_difference_has_its_category() -> None:
    oracle = _answer(_node(parameters={"rate": 10, "frame": "map"}), _node(executable="listener"))
    rosvar = _answer(
        _node(parameters={"rate": "10", "extra": True}, namespace="/robot"),
        errors=[{"code": "substitution-unknown", "message": "unknown substitution 'not'"}],
    )
    categories = {cause.category for cause in compare(oracle, rosvar)}
    assert categories == {
        "rosvar error [substitution-unknown]: unknown substitution '…'",
        "node only in the oracle",
        "namespace differs",
        "parameter only in the oracle",
        "parameter only in rosvar",
        "parameter type: oracle int, rosvar str",
    }


def test_anonymous_names_and_explained_errors_agree() -> None:
    oracle = _answer(_node(name="talker_host_1234_5678"), missing_packages=["absent_pkg"])
    rosvar = _answer(
        _node(name="talker_anon1"),
        errors=[{"code": "package-not-found", "message": "package 'absent_pkg' not found"}],
    )
    assert compare(oracle, rosvar) == []
    assert compare(oracle, _answer(_node(name="other_anon1")))
    unread = {"code": "node-invalid", "message": "parameter file /deps/absent_pkg/a.yaml"}
    assert compare(oracle, _answer(_node(name="talker_anon1"), errors=[unread])) == []


def test_errors_inside_an_include_the_oracle_could_not_read_are_explained() -> None:
    """The oracle's index lacks a package rosvar finds (one inside another package): an
    error in the included file is not held against rosvar; one elsewhere still is."""
    include = {"location": "/deps/inner_pkg/launch/device.launch.py", "reason": "missing package"}
    oracle = _answer(missing_packages=["inner_pkg"], unresolved_includes=[include])
    inside = {"file": "/ws/outer/inner_pkg/launch/device.launch.py", "line": 3, "col": 1}
    error = {"code": "value-unknown", "message": "a container's name is not known"}
    assert compare(oracle, _answer(errors=[{**error, "location": inside}])) == []
    elsewhere = {**inside, "file": "/ws/outer/other_pkg/launch/device.launch.py"}
    assert compare(oracle, _answer(errors=[{**error, "location": elsewhere}]))


def test_remappings_differ_in_order_only_where_the_order_matters() -> None:
    rules = [["a", "x"], ["b", "y"]]
    swapped = _answer(_node(remappings=rules[::-1]))
    assert compare(_answer(_node(remappings=rules)), swapped) == []
    shared = [["a", "x"], ["a", "y"]]
    (cause,) = compare(_answer(_node(remappings=shared)), _answer(_node(remappings=shared[::-1])))
    assert cause.category == "remappings differs"


def test_the_oracles_json_is_repaired_where_a_renamed_path_ate_an_escape() -> None:
    message = 'error in "<generated:1>": bad'
    text = json.dumps({"ok": False, "error": message}).replace(
        '\\"<generated:1>\\"', '\\"<generated:1>"'
    )
    assert loads_repaired(text) == {"ok": False, "error": message}
    assert loads_repaired('{"ok": true}') == {"ok": True}
