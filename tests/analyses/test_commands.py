"""``rosvar metrics PATH --json`` and ``rosvar features PATH --format json``."""

from __future__ import annotations

import json
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pytest

from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.metrics import compute
from rosvar.outputs.documents.metrics import metrics_document

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

CORPUS = Path(__file__).resolve().parents[3] / "shared" / "corpus"
KEYS = ["LF", "LV", "LC", "LC_U", "LC_A", "A", "ACG", "AS", "AS_D", "AS_V", "IF", "IF_M"]

Main = Callable[[Sequence[str]], int]


def cli_main() -> Main:
    module = pytest.importorskip(
        "rosvar.outputs.cli",
        reason="rosvar.outputs.cli does not import (it needs rosvar.outputs.exports, "
        "which is being written)",
    )
    main: Main = module.main
    return main


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = cli_main()(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def strings(document: Any) -> Iterator[str]:
    if isinstance(document, str):
        yield document
    elif isinstance(document, dict):
        for key, value in document.items():
            yield str(key)
            yield from strings(value)
    elif isinstance(document, list):
        for item in document:
            yield from strings(item)


@pytest.fixture
def small(ws: LaunchWorkspace) -> LaunchWorkspace:
    ws.launch(
        "a.launch",
        '  <arg name="use_cam" default="false"/>\n  <arg name="robot" default="r1"/>\n'
        '  <node pkg="pkg" type="t" name="cam" if="$(arg use_cam)"/>\n'
        '  <node pkg="pkg" type="t" name="$(arg robot)"/>\n'
        '  <include file="$(find pkg)/launch/b.launch"/>',
    )
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="cam"/>')
    return ws


def test_metrics_json(small: LaunchWorkspace, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _err = run(capsys, "metrics", str(small.root), "--json")
    assert code == 0
    document = json.loads(out)
    assert list(document) == KEYS
    analysis = small.analysis()
    assert document == metrics_document(compute(analysis, extract(analysis)))
    # by hand: a-b clash on /cam when use_cam (conditional); A = ACG = 2 (use_cam, robot)
    assert (document["LF"], document["LC"], document["LC_U"], document["LC_A"]) == (2, 2, 0, 2)
    assert (document["A"], document["ACG"], document["AS"], document["IF"]) == (2, 2, 1, 1)


def test_metrics_text(small: LaunchWorkspace, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _err = run(capsys, "metrics", str(small.root))
    assert code == 0
    header, row = out.splitlines()[:2]
    assert header.split() == ["system", *KEYS]
    assert row.split() == [str(small.root), *map(str, [2, 0, 2, 0, 2, 2, 2, 1, 1, 0, 1, 1])]


def test_metrics_of_nothing(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "metrics", str(tmp_path), "--json")
    assert code == 3 and out == ""
    assert "no launch files" in err


def test_metrics_on_the_corpus(capsys: pytest.CaptureFixture[str]) -> None:
    kobuki = CORPUS / "kobuki"
    if not kobuki.is_dir():
        pytest.skip(f"no corpus at {kobuki}")
    code, out, _err = run(capsys, "metrics", str(kobuki), "--json")
    assert code == 0
    document = json.loads(out)
    assert list(document) == KEYS
    assert (document["LF"], document["A"]) == (24, 18)


def test_features_json(small: LaunchWorkspace, capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip(
        "rosvar.outputs.exports",
        reason="rosvar.outputs.exports (feature-model writers) is not written yet",
    )
    code, out, _err = run(capsys, "features", str(small.root), "--format", "json")
    assert code == 0
    document = json.loads(out)
    assert isinstance(document, dict)
    found = set(strings(document))
    model = extract(small.analysis())
    for feature in model.files:
        assert feature.id in found or feature.file in found
        for arg in feature.args:
            assert any(arg.name in text for text in found)


def test_features_to_a_file(
    small: LaunchWorkspace, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    pytest.importorskip(
        "rosvar.outputs.exports",
        reason="rosvar.outputs.exports (feature-model writers) is not written yet",
    )
    target = tmp_path / "model.json"
    code, out, _err = run(
        capsys, "features", str(small.root), "--format", "json", "-o", str(target)
    )
    assert code == 0 and out == ""
    assert isinstance(json.loads(target.read_text()), dict)


def test_features_rejects_an_unknown_format(
    small: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    pytest.importorskip(
        "rosvar.outputs.exports",
        reason="rosvar.outputs.exports (feature-model writers) is not written yet",
    )
    with pytest.raises(SystemExit) as stop:
        run(capsys, "features", str(small.root), "--format", "no-such-format")
    assert stop.value.code == 2


def test_metrics_count_the_args_of_ros2_files_in_every_format(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Each file is read by its dialect's frontend (before, the ROS 1 XML reader read them
    and counted 0 args)."""
    package = tmp_path / "ws" / "pkg"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="3"><name>pkg</name><version>0.0.0</version><description>d'
        '</description><maintainer email="a@b.c">m</maintainer><license>BSD</license>'
        "<export><build_type>ament_cmake</build_type></export></package>"
    )
    (package / "launch" / "a.launch.py").write_text(
        "from launch import LaunchDescription\n"
        "from launch.actions import DeclareLaunchArgument\n"
        "from launch.conditions import IfCondition\n"
        "from launch.substitutions import LaunchConfiguration as V\n"
        "from launch_ros.actions import Node\n"
        "def generate_launch_description():\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('use_cam', default_value='false'),\n"
        "        DeclareLaunchArgument('robot', default_value='r1'),\n"
        "        Node(package='pkg', executable='t', name='cam',\n"
        "             condition=IfCondition(V('use_cam'))),\n"
        "        Node(package='pkg', executable='t', name=V('robot')),\n"
        "    ])\n"
    )
    (package / "launch" / "b.launch.yaml").write_text(
        "launch:\n- arg: {name: mode, default: a}\n- node: {pkg: pkg, exec: t, name: $(var mode)}\n"
    )
    code, out, _ = run(capsys, "metrics", str(package.parent), "--json")
    assert code == 0
    metrics = json.loads(out)
    assert (metrics["LF"], metrics["A"], metrics["ACG"], metrics["AS"], metrics["IF"]) == (
        2,
        3,
        3,
        2,
        1,
    )
