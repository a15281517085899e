"""``<machine>``: declarations and the default machine of later nodes, per configuration."""

from __future__ import annotations

from typing import TYPE_CHECKING

import pytest

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

MACHINES = """
  <arg name="remote" default="false"/>
  <node pkg="pkg" type="t" name="before"/>
  <machine name="local" address="localhost"/>
  <machine name="robot" address="10.0.0.2" user="ros" default="true" if="$(arg remote)"/>
  <node pkg="pkg" type="t" name="driver"/>
  <node pkg="pkg" type="t" name="viewer" machine="local"/>
"""


def test_default_machine_is_conditional(ws: LaunchWorkspace) -> None:
    file = ws.launch("machines.launch", MACHINES)
    model = ws.model(file)
    space = model.space
    names = {str(m.name.single()): m for m in model.machines}
    assert set(names) == {"local", "robot"}
    assert space.describe(names["robot"].condition) == "remote"
    assert names["robot"].attributes["user"].single() == "ros"
    nodes = {str(n.fields["name"].single()): n for n in model.nodes}
    driver = nodes["driver"].fields["machine"]
    assert space.describe(driver.where(lambda v: v == "robot")) == "remote"
    assert nodes["before"].fields["machine"].values() == [None]  # only later nodes
    assert nodes["viewer"].fields["machine"].values() == ["local"]

    machine_of = {
        n.name: n.attributes["machine"] for n in ws.resolve(file, {"remote": "true"}).nodes
    }
    assert machine_of == {"/before": None, "/driver": "robot", "/viewer": "local"}
    machine_of = {n.name: n.attributes["machine"] for n in ws.resolve(file, {}).nodes}
    assert machine_of == {"/before": None, "/driver": None, "/viewer": "local"}


@pytest.mark.oracle
def test_machines_agree_with_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("machines.launch", MACHINES)
    results = ws.assert_agrees(file, [{}, {"remote": "true"}])
    assert set(results[1]["machines"]) == {"local", "robot"}


def test_machine_errors(ws: LaunchWorkspace) -> None:
    cases = {
        "noaddress.launch": ('<machine name="m"/>', "attribute-missing"),
        "env.launch": (
            '<machine name="m" address="h"><env name="A" value="1"/></machine>',
            "machine-env",
        ),
        "default.launch": (
            '<machine name="m" address="h" default="sometimes"/>',
            "machine-invalid",
        ),
    }
    for name, (body, code) in cases.items():
        model = ws.model(ws.launch(name, body))
        assert [e.code for e in model.errors] == [code], name
        assert not ws.resolve(model.file).ok


UNKNOWN = """
  <arg name="host" default="local"/>
  <machine name="local" address="localhost"/>
  <node pkg="pkg" type="t" name="n" machine="$(arg host)"/>
"""


def test_unknown_machine_is_an_error(ws: LaunchWorkspace) -> None:
    file = ws.launch("unknown.launch", UNKNOWN)
    assert ws.resolve(file, {}).ok
    assert not ws.resolve(file, {"host": "elsewhere"}).ok


@pytest.mark.oracle
def test_unknown_machine_fails_in_roslaunch(ws: LaunchWorkspace) -> None:
    file = ws.launch("unknown.launch", UNKNOWN)
    ok, unknown = ws.oracle(file, [({}, {}), ({"host": "elsewhere"}, {})])
    assert ok["ok"] and not unknown["ok"]
    assert "unknown machine" in unknown["error"]
