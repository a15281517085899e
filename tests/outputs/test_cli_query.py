"""``rosvar query``: text and JSON output, name:=value words, refusals as usage errors."""

from __future__ import annotations

import json
from typing import TYPE_CHECKING

import pytest

from rosvar.outputs.cli import main
from rosvar.outputs.commands.exit_codes import EXIT_OK, EXIT_USAGE

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

from outputs.schemas import schema_check

LAUNCH = """
  <arg name="robot" default="kobuki"/>
  <node pkg="$(arg robot)_node" type="driver" name="base"/>
  <node pkg="tools" type="teleop" name="teleop" if="$(eval robot == 'husky')"/>
"""


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_json_validates_and_examples_select(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    ws.launch("robot.launch", LAUNCH)
    code, out, _err = run(
        capsys, "query", str(ws.root), "nodes[self.package == 'husky_node']", "--json"
    )
    assert code == EXIT_OK
    document = json.loads(out)
    schema_check(document, "query.schema.json")
    (result,) = document["results"]
    assert (result["kind"], result["name"]) == ("node", "/base")
    assert result["example"] == {"robot.launch:robot": "husky"}


def test_mappings_restrict_and_text_output(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    ws.launch("robot.launch", LAUNCH)
    query = "for n in nodes where n.type == 'teleop' return n"
    code, out, _err = run(capsys, "query", str(ws.root), query)
    assert code == EXIT_OK
    assert out.splitlines()[0].startswith("node /teleop")
    assert out.splitlines()[-1] == "1 result"
    code, out, _err = run(capsys, "query", str(ws.root), query, "robot:=kobuki")
    assert out.splitlines() == ["0 results"]
    code, out, _err = run(capsys, "query", str(ws.root), "robot:=husky", query)
    assert "robot.launch:robot:=husky" in out


def test_refused_query_is_a_usage_error(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    ws.launch("robot.launch", LAUNCH)
    code, _out, err = run(capsys, "query", str(ws.root), "nodes[__import__('os')]")
    assert code == EXIT_USAGE
    assert "double underscores" in err and "^" in err
    code, _out, err = run(capsys, "query", "nodes")
    assert code == EXIT_USAGE
