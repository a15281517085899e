"""``rosvar check --format sarif`` is valid against the official SARIF 2.1.0 schema, and the
exit code follows ``--fail-on``."""

from __future__ import annotations

import json
from pathlib import Path
from typing import TYPE_CHECKING

import jsonschema
import pytest

from rosvar.outputs.cli import main
from rosvar.outputs.commands.exit_codes import EXIT_FAILS, EXIT_OK

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

SCHEMA = Path(__file__).parent / "data" / "sarif-schema-2.1.0.json"
TALKER = 'import rospy\nfrom std_msgs.msg import String\nrospy.Publisher("chatter", String)\n'
COUNTER = 'import rospy\nfrom std_msgs.msg import Int32\nrospy.Subscriber("chatter", Int32, None)\n'
LAUNCH = """
  <arg name="count" default="false"/>
  <node pkg="pkg" type="talker.py" name="talker"/>
  <node pkg="pkg" type="counter.py" name="counter" if="$(arg count)"/>
"""


def _workspace(ws: LaunchWorkspace) -> str:
    ws.write("scripts/talker.py", TALKER)
    ws.write("scripts/counter.py", COUNTER)
    ws.launch("system.launch", LAUNCH)
    return str(ws.root)


def test_sarif_is_valid(ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]) -> None:
    root = _workspace(ws)
    assert main(["check", root, "--format", "sarif"]) == EXIT_FAILS  # a type mismatch
    document = json.loads(capsys.readouterr().out)
    jsonschema.validate(document, json.loads(SCHEMA.read_text()))
    results = document["runs"][0]["results"]
    [mismatch] = [r for r in results if r["ruleId"] == "type-mismatch"]
    assert mismatch["level"] == "error"
    assert mismatch["properties"]["condition"] == "count"
    assert mismatch["properties"]["example"] == {"system.launch:count": "true"}
    region = mismatch["locations"][0]["physicalLocation"]["region"]
    assert region["startLine"] in (4, 5)  # one of the two <node>s
    assert {r["ruleId"] for r in results} == {"type-mismatch", "no-subscriber"}


def test_fail_on(ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]) -> None:
    root = _workspace(ws)
    assert main(["check", root, "--fail-on", "error"]) == EXIT_FAILS
    text = capsys.readouterr().out
    assert "error[type-mismatch]" in text and "when count; e.g. system.launch:count=true" in text
    ws.launch("system.launch", LAUNCH.replace('if="$(arg count)"', 'if="false"'))
    assert main(["check", root, "--fail-on", "warning", "--all"]) == EXIT_OK  # a note is left
    assert "note[no-subscriber]" in capsys.readouterr().out
    assert main(["check", root, "--fail-on", "note"]) == EXIT_FAILS
