"""Hints override and add entries; the catalogue fills only nodes no source defines."""

from __future__ import annotations

from pathlib import Path

from rosvar.diagnostics import Location
from rosvar.outputs.documents.interfaces import node_document
from rosvar.workspace.hints import load_hints
from rosvar.workspace.interfaces.catalogue import Catalogue
from rosvar.workspace.interfaces.model import (
    Entry,
    Interfaces,
    NodeInterface,
    NodeKind,
    Origin,
    Role,
)
from rosvar.workspace.interfaces.overrides import add_catalogue, apply_hints

HINTS = """\
nodes:
  demo/driver:
    publishes:
      - {name: scan, type: sensor_msgs/LaserScan, when: "$(arg laser)"}
      - {name: odom, type: nav_msgs/Odometry}
    params:
      - {name: ~rate, default: 20}
  demo/Camera:
    subscribes: [{name: image, type: sensor_msgs/Image, boundary: true}]
  other/new_node:
    clients: [{name: reset, type: std_srvs/Empty}]
  demo/bad:
    topics: []
    params: [{type: x}]
"""


def _source(role: Role, name: str, type_name: str | None = None) -> Entry:
    return Entry(role, name, Location("src/driver.cpp", 3), type=type_name)


def test_hints_override_and_add(tmp_path: Path) -> None:
    path = tmp_path / "hints.yaml"
    path.write_text(HINTS)
    hints = load_hints(str(path))
    assert [(d.code, d.location.line) for d in hints.diagnostics] == [
        ("hints-invalid", 13),
        ("hints-invalid", 14),
    ]
    interfaces = Interfaces(
        [
            NodeInterface(
                "demo",
                "driver",
                NodeKind.NODE,
                [_source(Role.PUBLISHES, "odom", None), _source(Role.SUBSCRIBES, "cmd_vel")],
            ),
            NodeInterface("demo", "demo/Camera", NodeKind.NODELET),
        ]
    )
    apply_hints(interfaces, hints.nodes)
    driver = interfaces.find("demo", "driver")
    assert driver is not None
    assert [(str(e.role), e.name, e.type, e.origin) for e in driver.entries] == [
        ("subscribes", "cmd_vel", None, Origin.SOURCE),
        ("publishes", "scan", "sensor_msgs/LaserScan", Origin.HINTS),
        ("publishes", "odom", "nav_msgs/Odometry", Origin.HINTS),  # replaces the source's
        ("params", "~rate", None, Origin.HINTS),
    ]
    assert driver.entries[1].when == "$(arg laser)"
    assert not driver.entries[1].boundary
    assert driver.entries[1].location == Location(str(path), 4, 1)
    assert driver.of(Role.PARAMS)[0].default == 20
    camera = interfaces.find("demo", "demo/Camera")
    assert camera is not None and [(e.name, e.boundary) for e in camera.entries] == [
        ("image", True)
    ]
    created = interfaces.find("other", "new_node")
    assert created is not None and created.kind is NodeKind.NODE
    assert node_document(created)["clients"] == [
        {
            "name": "reset",
            "type": "std_srvs/Empty",
            "file": str(path),
            "line": 11,
            "origin": "hints",
        }
    ]


def test_catalogue_fills_only_missing_nodes() -> None:
    source = NodeInterface("amcl", "amcl", NodeKind.NODE, [_source(Role.SUBSCRIBES, "scan")])
    interfaces = Interfaces([source])
    entry = Entry(Role.PUBLISHES, "map", Location("map_server.cpp", 9), Origin.CATALOGUE)
    add_catalogue(
        interfaces,
        Catalogue(
            [
                _item("amcl", []),
                _item("map_server", [{"name": "map", "type": None, "file": "m.cpp", "line": 9}]),
            ]
        ),
    )
    assert [(n.package, len(n.entries)) for n in interfaces.listed()] == [
        ("amcl", 1),
        ("map_server", 1),
    ]
    found = interfaces.find("map_server", "map_server")
    assert found is not None and found.entries[0].name == entry.name
    assert found.entries[0].location.file == "https://github.com/o/r/blob/c/m.cpp"


def _item(package: str, publishes: list[dict[str, object]]) -> dict[str, object]:
    roles: dict[str, list[dict[str, object]]] = {str(role): [] for role in Role}
    return {
        "package": package,
        "executable": package,
        "kind": "node",
        "repository": "o/r",
        "commit": "c",
        **roles,
        "publishes": publishes,
    }
