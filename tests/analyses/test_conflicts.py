"""Name clashes are found through an index by resolved name, never by comparing every pair."""

from __future__ import annotations

import os
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, cast

from rosvar.analyses.conflicts import (
    DeclarationKind,
    Occurrence,
    clashes,
    declared_occurrences,
    index,
    node_occurrences,
)
from rosvar.analyses.feature_model.extraction import extract
from rosvar.diagnostics import Location
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.ros1.resolve import resolve
from rosvar.workspace import discover
from workspace.interfaces.ros2_packages import write_ros2_bringup

if TYPE_CHECKING:
    from conftest import LaunchWorkspace


@dataclass(frozen=True)
class Counted:
    """A condition that counts how often ``clashes`` conjoins it with another."""

    condition: Any
    calls: list[int]

    def __and__(self, other: Counted) -> Any:
        self.calls.append(1)
        return self.condition & other.condition


def occurrences(space: ConditionSpace, names: list[str], calls: list[int]) -> list[Occurrence]:
    return [
        Occurrence(
            DeclarationKind.NODE,
            name,
            f"/f{i}.launch",
            Location(f"/f{i}.launch", 1, 1),
            cast(BDD, Counted(space.true, calls)),  # a BDD that counts its conjunctions
        )
        for i, name in enumerate(names)
    ]


def test_only_declarations_in_one_bucket_are_compared() -> None:
    space = ConditionSpace()
    calls: list[int] = []
    found = occurrences(space, ["/a", "/b", "/a", "/c", "/c", "/c", "/d"], calls)
    buckets: dict[tuple[str, str], list[Occurrence]] = {}
    for occurrence in found:
        buckets.setdefault((occurrence.kind, occurrence.name), []).append(occurrence)
    result = clashes(buckets)
    # /a: 1 pair, /c: 3 pairs, /b and /d: none. Never /a against /c, etc.
    assert len(calls) == 4
    assert sorted((c.name, c.first.file, c.second.file) for c in result) == [
        ("/a", "/f0.launch", "/f2.launch"),
        ("/c", "/f3.launch", "/f4.launch"),
        ("/c", "/f3.launch", "/f5.launch"),
        ("/c", "/f4.launch", "/f5.launch"),
    ]


def test_many_distinct_names_need_no_comparison() -> None:
    space = ConditionSpace()
    calls: list[int] = []
    found = occurrences(space, [f"/node_{i}" for i in range(20000)], calls)
    buckets: dict[tuple[str, str], list[Occurrence]] = {}
    for occurrence in found:
        buckets.setdefault((occurrence.kind, occurrence.name), []).append(occurrence)
    start = time.perf_counter()
    assert clashes(buckets) == []
    assert calls == []
    assert time.perf_counter() - start < 1.0  # 20000² / 2 comparisons would take minutes


def test_a_node_and_a_param_of_one_name_do_not_clash(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", '  <node pkg="pkg" type="t" name="same"/>')
    ws.launch("b.launch", '  <param name="same" value="1"/>')
    analysis = ws.analysis()
    buckets = index(analysis.all_models())
    assert sorted(buckets) == [("node", "/same"), ("param", "/same")]
    assert clashes(buckets) == []


def test_index_keys_are_resolved_names(ws: LaunchWorkspace) -> None:
    file = ws.launch(
        "a.launch",
        '  <group ns="robot">\n'
        '    <node pkg="pkg" type="t" name="driver" ns="base"/>\n'
        '    <param name="rate" value="1"/>\n'
        '    <node pkg="pkg" type="t" name="cam"><param name="fps" value="30"/></node>\n'
        "  </group>\n",
    )
    model = ws.analysis().model(file)
    names = sorted((o.kind, o.name) for o in declared_occurrences(model))
    assert names == [
        ("node", "/robot/base/driver"),
        ("node", "/robot/cam"),
        ("param", "/robot/cam/fps"),
        ("param", "/robot/rate"),
    ]


def test_two_hundred_files_with_distinct_names(ws: LaunchWorkspace) -> None:
    for i in range(200):
        ws.launch(
            f"f{i:03}.launch",
            f'  <node pkg="pkg" type="t" name="node_{i}"/>\n'
            f'  <param name="param_{i}" value="{i}"/>',
        )
    analysis = ws.analysis()
    models = analysis.all_models()
    buckets = index(models)
    assert len(buckets) == 400
    assert all(len(b) == 1 for b in buckets.values())
    start = time.perf_counter()
    assert clashes(buckets) == []
    assert time.perf_counter() - start < 0.5
    model = extract(analysis)
    assert model.clashes == [] and model.internal == []
    assert [c for c in model.constraints if c.kind == "excludes"] == []


def test_twenty_files_one_shared_name(ws: LaunchWorkspace) -> None:
    """The counterpart: one name in every file gives every pair of files (and only those)."""
    for i in range(20):
        ws.launch(
            f"f{i:03}.launch",
            f'  <node pkg="pkg" type="t" name="node_{i}"/>\n  <param name="shared" value="{i}"/>',
        )
    model = extract(ws.analysis())
    assert len(model.clashes) == 20 * 19 // 2
    assert {c.name for c in model.clashes} == {"/shared"}
    assert len([c for c in model.constraints if c.kind == "excludes"]) == 190


def test_anonymous_names_of_two_entry_files_never_clash(ws: LaunchWorkspace) -> None:
    """roslaunch gives each top-level file a fresh ``$(anon)`` context (a random name per id
    and file): ``resolve`` of both files loads, so the feature model has no clash; two uses
    of one id in one file share the name and do clash (Husky's run_benchmark_ompl.launch)."""
    anon = '  <node pkg="p" type="t" name="$(anon bench)"><param name="x" value="1"/></node>\n'
    ws.launch("a.launch", anon)
    ws.launch("b.launch", anon)
    ws.launch("twice.launch", anon + anon)
    analysis = ws.analysis()
    model = extract(analysis)
    files = {os.path.basename(f) for c in model.clashes for f in c.files}
    assert files == {"twice.launch"}
    paths = sorted(f.file for f in model.files)
    for pair, loads in (((0, 1), True), ((2,), False)):
        assert resolve(analysis, [paths[i] for i in pair], {}).ok is loads


def test_ros2_nodes_of_one_name_are_no_conflict(tmp_path: Path) -> None:
    """``ros2 launch`` starts two nodes of one name (``rosvar check`` warns of them): no
    excludes and no internal clash, whether the nodes give a namespace or not."""
    node = '<node pkg="demo_py" exec="listener" name="ear"{}/>'
    twice = node.format("") + node.format(' namespace=""')
    write_ros2_bringup(tmp_path, f"<launch>{twice}</launch>")
    (tmp_path / "demo_bringup" / "b.launch.xml").write_text(f"<launch>{twice}</launch>")
    analysis = Analysis(discover([tmp_path]))
    model = extract(analysis)
    assert len(model.files) == 2
    assert [c for c in model.constraints if c.kind == "excludes"] == []
    assert model.internal == []
    [built] = [
        analysis.model(f) for f in analysis.workspace.launch_files if f.endswith("a.launch.xml")
    ]
    names = [o.name for n in built.nodes for o in node_occurrences(built, n)]
    assert names == ["/ear", "/ear"]  # named as ros2 launch names them, for the checks
