"""A ROS 2 node's typed fields (``ROS2_NODES``): the pushed namespace composed with the node's
own, as launch_ros composes them, over every configuration and per variant."""

from __future__ import annotations

from pathlib import Path

import pytest

from oracle.ros2_client import requires_ros2_oracle, run_oracle
from rosvar.interpreter.model import NodeDecl
from rosvar.interpreter.resolution import Restriction
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.terms import Apply, is_term
from rosvar.ros2.nodes import ROS2_NODES
from rosvar.workspace import discover

PACKAGE_XML = """<package format="3"><name>pkg</name>
<export><build_type>ament_cmake</build_type></export></package>"""

PUSHED = """<launch>
  <arg name="ns" default="r1"/>
  <arg name="own" default="arm"/>
  <group>
    <push_ros_namespace namespace="$(var ns)"/>
    <node pkg="pkg" exec="driver" name="driver" namespace="$(var own)"/>
    <node pkg="pkg" exec="unnamed"/>
  </group>
</launch>
"""


def model_of(tmp_path: Path) -> tuple[Analysis, Path]:
    """The model of :data:`PUSHED`; pushed namespaces ``r2`` and ``/`` are known values,
    another one and the node's own namespace outside its default are terms."""
    package = tmp_path / "ws" / "pkg"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE_XML)
    file = package / "launch" / "main.launch.xml"
    file.write_text(PUSHED)
    workspace = discover([str(tmp_path / "ws")])
    return Analysis(workspace, extra_values={"ns": ["r2", "/"]}), file


@pytest.mark.parametrize(
    ("pushed", "own", "namespace", "full"),
    [
        (None, None, None, "/n"),
        ("/r1", None, "/r1", "/r1/n"),
        ("r1", "arm", "/r1/arm", "/r1/arm/n"),
        ("/r1", "/arm", "/arm", "/arm/n"),
        (None, "arm/", "/arm", "/arm/n"),
        ("/", "", "/", "/n"),
    ],
)
def test_namespaces_compose_as_launch_ros_does(
    pushed: str | None, own: str | None, namespace: str | None, full: str
) -> None:
    values = {"ros_namespace": pushed, "namespace": own, "name": "n"}
    assert ROS2_NODES.namespace.of(values) == namespace
    assert ROS2_NODES.full_name.of(values) == full
    assert ROS2_NODES.label.of({**values, "exec": "e"}) == full
    unnamed = {**values, "name": None, "exec": "e"}
    assert ROS2_NODES.full_name.of(unnamed) is None  # its code names it
    assert ROS2_NODES.label.of(unnamed) == (namespace or "").rstrip("/") + "/⟨e⟩"


def test_unknown_parts_compose_into_a_term(tmp_path: Path) -> None:
    """An ``<other>`` value makes the composed name a term, shown with the inputs it awaits
    and evaluated with them as the known strings compose."""
    analysis, file = model_of(tmp_path)
    model = analysis.model(str(file))
    node = _named(model.nodes, "driver")
    terms = [leaf for _c, leaf in node.value(ROS2_NODES.full_name) if is_term(leaf)]
    assert terms and all(isinstance(term, Apply) for term in terms)
    assert any(str(term) == "/r1/⟨own⟩/driver" for term in terms)
    unnamed = _named(model.nodes, None)
    labels = {str(label) for _c, label in unnamed.value(ROS2_NODES.label)}
    pushed = {"/r1/⟨unnamed⟩", "/r2/⟨unnamed⟩", "/⟨unnamed⟩", "/⟨ns⟩/⟨unnamed⟩"}
    assert labels == pushed  # pushed r1, r2, / or another text
    cases = (
        ("r2", "/abs", "/abs/driver"),
        ("r2", "x/", "/r2/x/driver"),
        ("a/b/", "", "/a/b/driver"),
    )
    for ns, own, expected in cases:
        restriction = Restriction(analysis, model, {"ns": ns, "own": own}, {})
        name = restriction.pick(node.value(ROS2_NODES.full_name), node.location, "name")
        assert name == expected


@pytest.mark.parametrize(
    "arguments",
    [{}, {"ns": "r2"}, {"ns": "r2", "own": "x/y"}, {"own": "/abs"}, {"ns": "/", "own": ""}],
    ids=lambda a: ",".join(f"{k}={v}" for k, v in a.items()) or "defaults",
)
@requires_ros2_oracle[0]
@requires_ros2_oracle[1]
def test_typed_fields_in_a_configuration_are_what_ros2_launch_starts(
    tmp_path: Path, arguments: dict[str, str]
) -> None:
    """Each typed field over every configuration, restricted to one (values outside the
    arguments' defaults are terms of the shared model), is the oracle's."""
    analysis, file = model_of(tmp_path)
    model = analysis.model(str(file))
    expected = run_oracle(file, arguments, [tmp_path / "ws"], strict=False)
    assert expected["ok"]
    restriction = Restriction(analysis, model, arguments, {})
    accessors = {
        "fqn": ROS2_NODES.full_name,
        "namespace": ROS2_NODES.namespace,
        "name": ROS2_NODES.name,
        "package": ROS2_NODES.package,
        "executable": ROS2_NODES.executable,
    }
    ours = [
        {key: restriction.pick(node.value(a), node.location, key) for key, a in accessors.items()}
        for node in model.nodes
        if restriction.holds(node.condition)
    ]
    theirs = [{key: node[key] for key in accessors} for node in expected["nodes"]]
    assert sorted(ours, key=str) == sorted(theirs, key=str)


def _named(nodes: list[NodeDecl], name: str | None) -> NodeDecl:
    [node] = [n for n in nodes if name in n.fields["name"].values()]
    return node
