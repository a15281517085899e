"""``rosvar resolve --json``'s document: one shape for ROS 1 and ROS 2 (the schema's), values
JSON has no type for in a tagged form."""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING, Any

from outputs.schemas import schema_check
from rosvar.analyses.communication import uses_graph
from rosvar.interpreter.resolution import Resolution
from rosvar.interpreter.workspace_models import Analysis
from rosvar.outputs.documents.resolution import graph_document, resolution_document
from rosvar.workspace import discover

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

EXTRA = """
  <node pkg="pkg" type="t" name="driver"/>
  <param name="shared" value="extra"/>
"""
GRAPH = {"topics", "services", "actions"}
MANIFEST = """<package format="3"><name>p</name>
<export><build_type>ament_cmake</build_type></export></package>"""
ROS2 = """<launch>
  <arg name="ns" default="r"/>
  <node pkg="p" exec="e" name="n" namespace="$(var ns)" args="--fast">
    <param name="k" value="1"/>
    <param from="/nonexistent/params.yaml"/>
    <remap from="a" to="b"/>
    <env name="LEVEL" value="debug"/>
  </node>
  <executable cmd="/usr/bin/sleep 5"/>
</launch>
"""


def whole(result: Resolution) -> dict[str, Any]:
    """The command's document: the resolution's, and its (here empty) graph."""
    return {**resolution_document(result), **graph_document(uses_graph([]))}


def test_json_values(ws: LaunchWorkspace) -> None:
    file = ws.launch(
        "values.launch",
        '  <param name="nan" value="nan"/>\n'
        '  <param name="inf" value="-inf" type="double"/>\n'
        "  <rosparam>{a: .inf, b: !!binary AAH/, c: [1, {d: null}]}</rosparam>",
    )
    resolution = ws.resolve(file)
    assert resolution.ok
    assert resolution.params["/nan"] == "nan"  # already JSON-safe
    text = json.dumps(whole(resolution), allow_nan=False)
    document: dict[str, Any] = json.loads(text)
    assert document["params"] == {
        "/a": "inf",
        "/b": {"__binary__": "AAH/"},
        "/c": [1, {"d": None}],
        "/inf": "-inf",
        "/nan": "nan",
    }
    assert list(document["params"]) == sorted(document["params"])
    schema_check(document, "resolve.schema.json")


def test_a_ros1_document(ws: LaunchWorkspace) -> None:
    file = ws.launch("dup.launch", EXTRA + EXTRA)
    document = whole(ws.resolve(file))
    assert set(document) == {"ok", "nodes", "tests", "params", "conflicts", "errors"} | GRAPH
    assert document["ok"] is False
    [conflict] = document["conflicts"]
    assert conflict["kind"] == "node-name"
    # lines: <launch>, blank, node, param, blank, node
    assert [(loc["line"], loc["col"]) for loc in conflict["locations"]] == [(3, 3), (6, 3)]
    node = document["nodes"][0]
    assert list(node)[:4] == ["name", "namespace", "package", "type"]
    assert list(node)[-5:] == ["remaps", "env", "filename", "line", "col"]
    assert "parameters" not in node  # a ROS 1 node's are the server's
    schema_check(document, "resolve.schema.json")


def test_a_ros2_document_has_the_same_shape(tmp_path: Path) -> None:
    """A ROS 2 resolution fills the fields both ROS versions have (a node's full name, its
    namespace, package and executable as ``type``, remaps in order, env) and adds what only
    ROS 2 has after ``type``; errors and warnings are located as ROS 1's are."""
    (tmp_path / "package.xml").write_text(MANIFEST)
    launch = tmp_path / "a.launch.xml"
    launch.write_text(ROS2)
    result = Analysis(discover([str(tmp_path)])).resolve([str(launch)])
    document: dict[str, Any] = json.loads(json.dumps(whole(result)))
    assert set(document) == {"ok", "nodes", "tests", "params", "conflicts", "errors"} | {
        "warnings",
        *GRAPH,
    }
    assert (document["ok"], document["tests"], document["params"]) == (True, [], {})
    node, process = document["nodes"]  # by full name
    assert {key: node[key] for key in ("name", "namespace", "package", "type", "fqn")} == {
        "name": "/r/n",
        "namespace": "/r",
        "package": "p",
        "type": "e",
        "fqn": "/r/n",
    }
    assert (node["kind"], node["arguments"], node["parameters"]) == ("node", ["--fast"], {"k": 1})
    assert (node["remaps"], node["env"]) == ([["a", "b"]], [["LEVEL", "debug"]])
    assert (node["line"], node["col"]) == (3, 3)
    assert (process["kind"], process["cmd"], process["name"]) == (
        "process",
        ["/usr/bin/sleep", "5"],
        "/⟨sleep⟩",
    )
    [warning] = document["warnings"]
    assert warning["code"] == "parameter-file-missing" and warning["line"] == 3
    schema_check(document, "resolve.schema.json")
    launch.write_text(ROS2.replace('default="r"', ""))  # a required argument left out
    failed = Analysis(discover([str(tmp_path)])).resolve([str(launch)])
    document = whole(failed)
    assert document["ok"] is False and document["errors"]
    assert all(
        set(error) == {"code", "message", "file", "line", "col"} for error in document["errors"]
    )
    schema_check(document, "resolve.schema.json")
