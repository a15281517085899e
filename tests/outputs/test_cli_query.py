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
    assert out.splitlines()[-1] == "0 results"
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


def test_a_topic_lists_its_publishers_and_subscribers(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    header = "import rospy\nfrom geometry_msgs.msg import Twist\n"
    ws.write("scripts/teleop.py", header + 'rospy.Publisher("cmd_vel", Twist)\n')
    ws.write("scripts/base.py", header + 'rospy.Subscriber("cmd_vel", Twist, None)\n')
    ws.launch(
        "robot.launch",
        """<arg name="joy" default="true"/>
        <node pkg="pkg" type="teleop.py" name="teleop" if="$(arg joy)"/>
        <node pkg="pkg" type="base.py" name="base"/>
        <node pkg="elsewhere" type="planner" name="planner"/>""",
    )
    query = "topics[self.name == '/cmd_vel']"
    code, out, _err = run(capsys, "query", str(ws.root), query)
    assert code == EXIT_OK
    assert "  publishers: /teleop (when joy)" in out.splitlines()
    assert "  subscribers: /base" in out.splitlines()
    assert "1 launched nodes have no known interfaces" in out
    code, out, _err = run(capsys, "query", str(ws.root), query, "--json")
    document = json.loads(out)
    schema_check(document, "query.schema.json")
    (result,) = document["results"]
    assert result["publishers"] == [{"node": "/teleop", "condition": "joy"}]
    assert result["subscribers"] == [{"node": "/base", "condition": "true"}]
    assert [u["names"] for u in document["uninterfaced"]] == [["/planner"]]
    _code, out, _err = run(capsys, "query", str(ws.root), query, "joy:=false")
    assert "  publishers: none" in out.splitlines()  # where joy is false nobody publishes
