"""ROS 1's ``resolve``: one configuration of several entry files."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest

from rosvar.ros1.resolve import resolve

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

BASE = """
  <arg name="ns" default=""/>
  <node pkg="pkg" type="t" name="driver" ns="$(arg ns)" if="$(eval ns != '')"/>
  <node pkg="pkg" type="t" name="driver" unless="$(eval ns != '')"/>
  <param name="shared" value="base"/>
"""
EXTRA = """
  <node pkg="pkg" type="t" name="driver"/>
  <param name="shared" value="extra"/>
"""


def test_several_files_share_one_configuration(ws: LaunchWorkspace) -> None:
    base, extra = ws.launch("base.launch", BASE), ws.launch("extra.launch", EXTRA)
    analysis = ws.analysis()
    moved = resolve(analysis, [base, extra], {"ns": "robot"})
    assert moved.ok
    assert sorted(n.name for n in moved.nodes) == ["/driver", "/robot/driver"]
    assert moved.params == {"/shared": "extra"}  # the later file wins
    clash = resolve(analysis, [base, extra], {})
    [conflict] = clash.conflicts
    assert conflict.name == "/driver"
    assert [loc.file for loc in conflict.locations] == [base, extra]


@pytest.mark.oracle
def test_several_files_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    base, extra = ws.launch("base.launch", BASE), ws.launch("extra.launch", EXTRA)
    jobs = [
        {"id": i, "roots": [str(ws.root)], "files": [base, extra], "args": args, "env": {}}
        for i, args in enumerate([{"ns": "robot"}, {}])
    ]
    from oracle.client import shared_oracle

    moved, clash = shared_oracle().run(jobs)
    ours = resolve(ws.analysis(), [base, extra], {"ns": "robot"})
    assert moved["ok"] and ours.ok
    assert moved["params"] == ours.params
    assert [n["name"] for n in moved["nodes"]] == [n.name for n in ours.sorted_nodes()]
    assert not clash["ok"] and "multiple nodes named [/driver]" in clash["error"]


def test_an_error_stops_at_its_file(ws: LaunchWorkspace) -> None:
    broken = ws.launch("broken.launch", '  <param name="p" value="$(arg missing)"/>')
    extra = ws.launch("extra.launch", EXTRA)
    result = resolve(ws.analysis(), [broken, extra])
    assert not result.ok
    assert [e.code for e in result.errors] == ["arg-undefined"]
    assert result.nodes == [] and result.params == {}
