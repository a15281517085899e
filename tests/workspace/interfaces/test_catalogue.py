"""The bundled catalogue: loadable package data, every entry traceable to its source."""

from __future__ import annotations

import re

from rosvar.workspace.interfaces.catalogue import load_catalogue
from rosvar.workspace.interfaces.model import Origin, Role

SOURCE_URL = re.compile(r"^https://github\.com/[\w.-]+/[\w.-]+/blob/[0-9a-f]{40}/\S+$")


def test_every_entry_says_where_it_comes_from() -> None:
    nodes = load_catalogue()
    assert nodes
    for node in nodes:
        for entry in node.entries:
            assert entry.origin is Origin.CATALOGUE
            assert SOURCE_URL.match(entry.location.file), entry
            assert entry.location.line > 0


def test_robot_state_publisher() -> None:
    [node] = [n for n in load_catalogue() if n.executable == "robot_state_publisher"]
    assert [(e.name, e.type) for e in node.of(Role.SUBSCRIBES)] == [
        ("joint_states", "sensor_msgs/JointState")  # through the header's typedef
    ]
    assert {e.name for e in node.of(Role.PUBLISHES)} == {"/tf", "/tf_static"}  # reviewed
    params = {e.name: e.default for e in node.of(Role.PARAMS) if e.static}
    assert params["~publish_frequency"] == 50.0
    assert params["robot_description"] is None
    assert [e.name for e in node.of(Role.PARAMS) if not e.static] == ["~{tf_prefix_key}"]
