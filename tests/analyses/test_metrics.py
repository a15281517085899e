"""The paper's Table I/II metrics on fixtures small enough to count by hand."""

from __future__ import annotations

from dataclasses import asdict
from pathlib import Path
from typing import TYPE_CHECKING

from rosvar.analyses.feature_model.extraction import extract
from rosvar.analyses.metrics import Metrics, command_line_args, compute
from rosvar.frontends.xml import load_launch_file

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

KEYS = ["LF", "LV", "LC", "LC_U", "LC_A", "A", "ACG", "AS", "AS_D", "AS_V", "IF", "IF_M"]


def metrics_of(ws: LaunchWorkspace) -> Metrics:
    analysis = ws.analysis()
    return compute(analysis, extract(analysis))


def settable(tmp_path: Path, body: str) -> set[str]:
    path = tmp_path / "x.launch"
    path.write_text(f"<launch>\n{body}\n</launch>\n")
    root = load_launch_file(str(path)).root
    assert root is not None
    return command_line_args(root)


def test_command_line_args_follow_the_manifest_rules(tmp_path: Path) -> None:
    assert settable(
        tmp_path,
        '  <arg name="plain" default="1"/>\n'
        '  <arg name="required"/>\n'
        '  <arg name="fixed" value="1"/>\n'  # value= : not settable
        '  <arg name="on" default="1" if="true"/>\n'
        '  <arg name="on1" default="1" if=" 1 "/>\n'
        '  <arg name="off" default="1" if="false"/>\n'
        '  <arg name="kept" default="1" unless="0"/>\n'
        '  <arg name="dropped" default="1" unless="True"/>\n'
        '  <arg name="dynamic" default="1" if="$(arg plain)"/>\n'  # non-literal: not counted
        '  <group ns="g">\n'
        '    <arg name="grouped" default="1"/>\n'
        '    <group><arg name="nested"/></group>\n'
        "  </group>\n"
        '  <group if="false"><arg name="in_dead_group"/></group>\n'
        '  <group if="$(arg plain)"><arg name="in_dynamic_group"/></group>\n'
        '  <include file="x.launch"><arg name="passed" value="1"/></include>\n'
        '  <node pkg="p" type="t" name="n"><param name="param" value="1"/></node>\n'
        '  <arg name="plain" default="2"/>',  # counted once
    ) == {"plain", "required", "on", "on1", "kept", "grouped", "nested"}


def test_argument_metrics_by_hand(ws: LaunchWorkspace) -> None:
    ws.launch(
        "m.launch",
        '  <arg name="use_cam" default="true"/>\n'  # A, ACG (if), Boolean
        '  <arg name="robot" default="r1"/>\n'  # A, ACG, AS, AS_D, AS_V (r2 from the eval)
        '  <arg name="frame"/>\n'  # A, ACG, AS; no default, no literal value
        '  <arg name="notes" default="n" doc="$(arg robot)"/>\n'  # A only
        '  <arg name="derived" value="$(arg robot)_link"/>\n'  # not A
        '  <arg name="on" default="1" unless="0"/>\n'  # A only
        '  <group ns="g"><arg name="grouped" default="v"/></group>\n'  # A only
        '  <node pkg="pkg" type="t" name="cam" if="$(arg use_cam)"/>\n'
        '  <node pkg="pkg" type="t" name="$(arg robot)"/>\n'
        '  <node pkg="pkg" type="t" name="extra" if="$(eval robot == \'r2\')"/>\n'
        '  <node pkg="pkg" type="t" name="tf" ns="$(arg frame)"/>\n'
        '  <include file="$(find pkg)/launch/b.launch">\n'
        '    <arg name="enable" value="$(arg use_cam)"/>\n'
        "  </include>\n",
    )
    ws.launch(
        "b.launch",
        '  <arg name="enable" default="false"/>\n'  # A, ACG, Boolean
        '  <node pkg="pkg" type="t" name="b_node" if="$(arg enable)"/>\n',
    )
    metrics = metrics_of(ws)
    # A: m has use_cam, robot, frame, notes, on, grouped (6); b has enable (1).
    # ACG: use_cam, robot, frame in m; enable in b.        AS: robot, frame (not Boolean).
    # AS_D: robot (frame has no default).                   AS_V: robot (r2 besides r1).
    # IF: in m, use_cam decides cam's if and, passed on, b_node's if (2); robot decides
    #     extra's if (1); in b, enable decides b_node's if (1): 4. IF_M: use_cam in m, 2.
    assert asdict(metrics) == {
        "LF": 2,
        "LV": 2,
        "LC": 0,
        "LC_U": 0,
        "LC_A": 0,
        "A": 7,
        "ACG": 4,
        "AS": 2,
        "AS_D": 1,
        "AS_V": 1,
        "IF": 4,
        "IF_M": 2,
    }


def test_launch_file_metrics_by_hand(ws: LaunchWorkspace) -> None:
    ws.launch("p.launch", '  <node pkg="pkg" type="t" name="a"/>')
    ws.launch("q.launch", '  <node pkg="pkg" type="t" name="a"/>')  # p, q: unconditional
    ws.launch(
        "r.launch",
        '  <arg name="x" default="false"/>\n  <node pkg="pkg" type="t" name="b" if="$(arg x)"/>',
    )
    ws.launch("s.launch", '  <param name="b" value="1"/>\n  <node pkg="pkg" type="t" name="b"/>')
    ws.launch("t.launch", '  <node pkg="pkg" type="t" name="c"/>')  # no conflict
    ws.launch(
        "u.launch",
        '  <arg name="y" default="false"/>\n'
        '  <node pkg="pkg" type="t" name="c" ns="u" if="$(arg y)"/>\n'
        '  <node pkg="pkg" type="t" name="c" ns="u"/>',  # only an internal clash
    )
    metrics = metrics_of(ws)
    # LF 6. Conflicts between files: p-q (unconditional), r-s (only when r's x is true).
    # LC = {p, q, r, s} = 4, LV = {t, u} = 2, LC_U = {p, q}, LC_A = {r, s}.
    assert (metrics.LF, metrics.LV, metrics.LC, metrics.LC_U, metrics.LC_A) == (6, 2, 4, 2, 2)
    # A: x and y; both decide an if (ACG, Boolean). IF: 1 each.
    assert (metrics.A, metrics.ACG, metrics.AS, metrics.IF, metrics.IF_M) == (2, 2, 0, 2, 1)


def test_a_file_in_both_kinds_of_conflict_is_unconditional(ws: LaunchWorkspace) -> None:
    ws.launch(
        "a.launch",
        '  <arg name="x" default="false"/>\n'
        '  <node pkg="pkg" type="t" name="n"/>\n'
        '  <node pkg="pkg" type="t" name="m" if="$(arg x)"/>',
    )
    ws.launch("b.launch", '  <node pkg="pkg" type="t" name="n"/>')
    ws.launch("c.launch", '  <node pkg="pkg" type="t" name="m"/>')
    metrics = metrics_of(ws)
    # a-b unconditional, a-c conditional: a and b count as LC_U, c as LC_A.
    assert (metrics.LC, metrics.LC_U, metrics.LC_A, metrics.LV) == (3, 2, 1, 0)


def test_metric_keys_and_invariants(ws: LaunchWorkspace) -> None:
    ws.launch("a.launch", '  <arg name="x" default="1"/>\n  <param name="x" value="$(arg x)"/>')
    metrics = asdict(metrics_of(ws))
    assert list(metrics) == KEYS
    assert metrics["LV"] + metrics["LC"] == metrics["LF"] == 1
    assert (metrics["A"], metrics["ACG"], metrics["AS"], metrics["AS_D"]) == (1, 1, 1, 1)
    assert metrics["AS_V"] == 0  # only the default is known
