"""``rosvar check``: notes hidden unless ``--all``, nodes without interfaces said, stable
fingerprints, and the baselines (``--baseline`` FILE, ``--baseline-rev`` of a git repository)."""

from __future__ import annotations

import json
import shutil
import subprocess
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from outputs.schemas import schema_check
from rosvar.outputs.cli import main
from rosvar.outputs.commands.exit_codes import EXIT_FAILS, EXIT_OK, EXIT_USAGE

if TYPE_CHECKING:
    from conftest import LaunchWorkspace

SOURCES = {
    "talker.py": "import rospy\nfrom std_msgs.msg import String\n"
    'rospy.Publisher("chatter", String)\n',
    "listener.py": "import rospy\nfrom std_msgs.msg import String\n"
    'rospy.Subscriber("heard", String, None)\n',
}
LAUNCH = """
  <node pkg="pkg" type="talker.py" name="talker"/>
  <node pkg="pkg" type="listener.py" name="listener"/>
  <node pkg="mystery" type="box" name="box" ns="tools"/>
"""
CLASH = '  <node pkg="pkg" type="talker.py" name="listener"/>\n'


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def _workspace(ws: LaunchWorkspace, extra: str = "") -> str:
    for name, text in SOURCES.items():
        ws.write(f"scripts/{name}", text)
    ws.launch("system.launch", LAUNCH + extra)
    return str(ws.root)


def test_notes_are_hidden_unless_all(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    root = _workspace(ws)
    code, out, _err = run(capsys, "check", root)
    assert code == EXIT_OK
    assert "warning[no-provider]: /listener subscribes to /heard" in out
    assert "note[" not in out
    assert "1 notes not shown (--all shows them)" in out  # /chatter has no subscriber
    assert "1 launched nodes have no known interfaces" in out
    assert "/tools/box" not in out
    code, out, _err = run(capsys, "check", root, "--all")
    assert "note[no-subscriber]: /talker publishes /chatter" in out
    assert "/tools/box (mystery/box) at " in out
    assert out.splitlines()[-1] == "2 findings in 1 launch files: 0 errors, 1 warnings, 1 notes"


def test_json_lists_fingerprints_and_nodes_without_interfaces(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    root = _workspace(ws)
    _code, out, _err = run(capsys, "check", root, "--format", "json")
    document = json.loads(out)
    schema_check(document, "check.schema.json")
    assert [u["names"] for u in document["uninterfaced"]] == [["/tools/box"]]
    prints = {f["fingerprint"] for f in document["findings"]}
    assert len(prints) == 2
    moved = tmp_path / "elsewhere"  # another checkout, another line: the same fingerprints
    shutil.copytree(root, moved)
    launch = next(moved.rglob("system.launch"))
    launch.write_text(launch.read_text().replace("<launch>", "<launch>\n\n<!-- moved -->\n"))
    _code, out, _err = run(capsys, "check", str(moved), "--format", "json")
    assert {f["fingerprint"] for f in json.loads(out)["findings"]} == prints
    _code, out, _err = run(capsys, "check", root, "--format", "sarif")
    results = json.loads(out)["runs"][0]["results"]
    assert {r["partialFingerprints"]["rosvar/v1"] for r in results} == prints


@pytest.mark.parametrize("form", ["json", "sarif"])
def test_a_baseline_file_leaves_the_new_findings(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str], tmp_path: Path, form: str
) -> None:
    root = _workspace(ws)
    _code, out, _err = run(capsys, "check", root, "--format", form)
    baseline = tmp_path / f"baseline.{form}"
    baseline.write_text(out)
    code, out, _err = run(capsys, "check", root, "--baseline", str(baseline), "--fail-on", "note")
    assert code == EXIT_OK
    assert out.splitlines()[-1] == "0 new findings in 1 launch files: 0 errors, 0 warnings, 0 notes"
    _workspace(ws, CLASH)  # a second node named /listener: an error the baseline lacks
    code, out, _err = run(capsys, "check", root, "--baseline", str(baseline))
    assert code == EXIT_FAILS
    assert "error[node-name-clash]: two nodes are named /listener" in out
    assert "/heard" not in out  # the warning the baseline holds
    assert "new findings in 1 launch files: 1 errors, 0 warnings" in out.splitlines()[-1]


def test_a_baseline_that_is_no_check_output_is_refused(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    root = _workspace(ws)
    other = tmp_path / "other.json"
    other.write_text('{"results": []}')
    code, _out, err = run(capsys, "check", root, "--baseline", str(other))
    assert code == EXIT_USAGE
    assert "no output of rosvar check" in err


def _git(where: Path, *words: str) -> None:
    subprocess.run(
        ["git", "-C", str(where), "-c", "user.name=t", "-c", "user.email=t@t", *words],
        check=True,
        capture_output=True,
    )


def test_baseline_rev_reports_what_a_change_brings(
    ws: LaunchWorkspace,
    capsys: pytest.CaptureFixture[str],
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    if shutil.which("git") is None:
        pytest.skip("no git")
    temporary = tmp_path / "temporary"
    temporary.mkdir()
    monkeypatch.setattr(tempfile, "tempdir", str(temporary))
    root = _workspace(ws)
    _git(ws.root, "init", "-q")
    _git(ws.root, "add", "-A")
    _git(ws.root, "commit", "-qm", "first")
    _workspace(ws, CLASH)
    code, out, _err = run(capsys, "check", root, "--baseline-rev", "HEAD")
    assert code == EXIT_FAILS
    assert out.count("error[node-name-clash]") == 1
    assert "/heard" not in out
    assert "new findings in 1 launch files: 1 errors, 0 warnings" in out.splitlines()[-1]
    _git(ws.root, "commit", "-qam", "second")
    code, out, _err = run(capsys, "check", root, "--baseline-rev", "HEAD")
    assert code == EXIT_OK
    assert out.splitlines()[-1].startswith("0 new findings")
    code, _out, err = run(capsys, "check", root, "--baseline-rev", "no-such-rev")
    assert code == EXIT_USAGE
    assert "has no revision no-such-rev" in err
    assert list(temporary.iterdir()) == []  # the revision's tree is removed


def test_baseline_rev_outside_git_is_an_error(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    root = _workspace(ws)
    code, _out, err = run(capsys, "check", root, "--baseline-rev", "HEAD")
    assert code == EXIT_USAGE
    assert "is not inside a git repository" in err


def test_interfaces_missing_lists_launched_nodes_without_interface(
    ws: LaunchWorkspace, capsys: pytest.CaptureFixture[str]
) -> None:
    root = _workspace(
        ws,
        '  <node pkg="mystery" type="box" name="box2"/>\n'
        '  <node pkg="robot_state_publisher" type="robot_state_publisher" name="rsp"/>\n'
        '  <node pkg="pkg" type="absent" name="absent"/>\n',
    )
    code, out, _err = run(capsys, "interfaces", root, "--missing")
    assert code == EXIT_OK
    assert out.splitlines() == ["   2  mystery/box  (third-party)", "   1  pkg/absent  (workspace)"]
    code, out, _err = run(capsys, "interfaces", root, "--missing", "--json")
    rows = json.loads(out)["missing"]
    assert [(r["executable"], r["launches"], r["third_party"]) for r in rows] == [
        ("mystery/box", 2, True),
        ("pkg/absent", 1, False),
    ]
    assert sorted(site.rsplit(":", 1)[1] for site in rows[0]["launched_at"]) == ["5", "6"]


def test_interfaces_missing_in_a_ros2_workspace(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """ROS 2's catalogue describes rviz2 and the component containers (their loading
    services); a process that names no package executable (``gzserver``) is no node."""
    package = tmp_path / "p"
    package.mkdir()
    (package / "package.xml").write_text(
        "<package format='3'><name>p</name>"
        "<export><build_type>ament_cmake</build_type></export></package>"
    )
    (package / "a.launch.xml").write_text(
        "<launch>\n"
        '  <node pkg="rviz2" exec="rviz2"/>\n'
        '  <node pkg="rclcpp_components" exec="component_container" name="c"/>\n'
        '  <executable cmd="gzserver -s libgazebo_ros_factory.so"/>\n'
        '  <node pkg="mystery" exec="box"/>\n'
        "</launch>\n"
    )
    code, out, _err = run(capsys, "interfaces", str(tmp_path), "--missing")
    assert code == EXIT_OK
    assert out.splitlines() == ["   1  mystery/box  (third-party)"]
