"""Sanity tests of the roslaunch oracle itself, on small launch files written to tmp_path."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from conftest import LaunchWorkspace

from .client import Result, RoslaunchOracle, requires_oracle, shared_oracle

pytestmark = requires_oracle


def make_package(root: Path, name: str, files: dict[str, str]) -> Path:
    """A package directory (package.xml only, no CMakeLists.txt) holding the given files."""
    workspace = LaunchWorkspace(root)
    for relative, text in files.items():
        workspace.write(relative, text, name)
    return workspace.package(name)


def launch(body: str) -> str:
    return f"<launch>\n{body}\n</launch>\n"


def run_one(
    tmp_path: Path,
    body: str,
    *,
    args: dict[str, str] | None = None,
    env: dict[str, str] | None = None,
    job_id: Any = "job",
) -> Result:
    root = tmp_path / "ws"
    pkg = make_package(root, "pkg_a", {"launch/main.launch": launch(body)})
    return shared_oracle().run_one(
        {
            "id": job_id,
            "roots": [str(root)],
            "files": [str(pkg / "launch" / "main.launch")],
            "args": args or {},
            "env": env or {},
        }
    )


def node(result: Result, name: str) -> dict[str, Any]:
    nodes = {n["name"]: n for n in result["nodes"]}
    assert name in nodes, sorted(nodes)
    found: dict[str, Any] = nodes[name]
    return found


def test_node_with_remaps_and_private_param(tmp_path: Path) -> None:
    result = run_one(
        tmp_path,
        """
  <remap from="scan" to="base_scan"/>
  <group ns="robot">
    <node pkg="pkg_a" type="talker" name="talker" args="--fast" output="screen">
      <remap from="chatter" to="/news"/>
      <param name="rate" value="10"/>
      <env name="FOO" value="bar"/>
    </node>
  </group>
""",
    )
    assert result["ok"], result
    n = node(result, "/robot/talker")
    assert n["namespace"] == "/robot/"
    assert (n["package"], n["type"], n["args"]) == ("pkg_a", "talker", "--fast")
    assert n["output"] == "screen"
    assert n["remaps"] == [["chatter", "/news"], ["scan", "base_scan"]]
    assert n["env"] == [["FOO", "bar"]]
    assert n["machine"] is None and n["respawn"] is False and n["required"] is False
    assert n["filename"].endswith("main.launch")
    assert result["params"] == {"/robot/talker/rate": 10}
    # roscore.xml's /rosversion and /rosdistro and its /rosout node are left out
    assert [x["name"] for x in result["nodes"]] == ["/robot/talker"]


def test_command_param_is_never_run(tmp_path: Path) -> None:
    marker = tmp_path / "command_ran"
    result = run_one(
        tmp_path,
        f"""
  <arg name="word" default="hi"/>
  <param name="greeting" command="echo $(arg word)"/>
  <param name="touch" command="touch {marker}"/>
  <param name="number" type="str" command="seq 3"/>
""",
    )
    assert result["ok"], result
    assert result["params"]["/greeting"] == "__command__(echo hi)"
    assert result["params"]["/touch"] == f"__command__(touch {marker})"
    assert result["params"]["/number"] == "__command__(seq 3)"
    assert not marker.exists()


def test_duplicate_node_names_fail_inside(tmp_path: Path) -> None:
    result = run_one(
        tmp_path,
        """
  <node pkg="pkg_a" type="a" name="twin"/>
  <node pkg="pkg_a" type="b" name="twin"/>
""",
    )
    assert result["ok"] is False
    assert result["outside"] is False
    assert "multiple nodes named [/twin]" in result["error"]
    assert result["error_type"] == "RLException"


def test_unknown_package_fails_outside(tmp_path: Path) -> None:
    result = run_one(tmp_path, '  <include file="$(find unknown_pkg)/launch/x.launch"/>')
    assert result["ok"] is False
    assert result["outside"] is True
    assert result["error_type"] == "ResourceNotFound"
    assert "unknown_pkg" in result["error"]


def test_unknown_package_in_arg_fails_outside(tmp_path: Path) -> None:
    result = run_one(tmp_path, '  <arg name="p" default="$(find unknown_pkg)"/>')
    assert result["ok"] is False
    assert result["outside"] is True
    assert "The following package was not found" in result["error"]


def test_missing_file_in_existing_package_fails_inside(tmp_path: Path) -> None:
    result = run_one(tmp_path, '  <include file="$(find pkg_a)/launch/missing.launch"/>')
    assert result["ok"] is False
    assert result["outside"] is False


def test_missing_file_outside_every_package_fails_outside(tmp_path: Path) -> None:
    result = run_one(tmp_path, '  <include file="/opt/ros/melodic/share/foo/launch/x.launch"/>')
    assert result["ok"] is False
    assert result["outside"] is True


def test_env_given_and_not_given(tmp_path: Path) -> None:
    body = '  <param name="x" value="$(env X)"/>\n  <param name="y" value="$(optenv Y dflt)"/>'
    given = run_one(tmp_path, body, env={"X": "42"})
    assert given["ok"], given
    assert given["params"] == {"/x": 42, "/y": "dflt"}

    missing = run_one(tmp_path, body)
    assert missing["ok"] is False
    assert missing["outside"] is True
    assert "environment variable" in missing["error"]


def test_env_is_exactly_the_job_env(tmp_path: Path) -> None:
    result = run_one(
        tmp_path,
        '  <param name="home" value="$(optenv HOME none)"/>\n'
        '  <param name="rpp" value="$(env ROS_PACKAGE_PATH)"/>',
    )
    assert result["ok"], result
    assert result["params"]["/home"] == "none"
    assert result["params"]["/rpp"] == str(tmp_path / "ws")


def test_args_are_passed_like_the_command_line(tmp_path: Path) -> None:
    body = (
        '  <arg name="a"/>\n  <arg name="b" default="1"/>\n'
        '  <param name="s" value="$(arg a)-$(arg b)"/>'
    )
    result = run_one(tmp_path, body, args={"a": "x", "b": "2"})
    assert result["ok"], result
    assert result["params"] == {"/s": "x-2"}

    unset = run_one(tmp_path, body)
    assert unset["ok"] is False
    assert unset["outside"] is False
    assert "requires the 'a' arg to be set" in unset["error"]


def test_anon_names_are_deterministic(tmp_path: Path) -> None:
    body = """
  <node pkg="pkg_a" type="t" name="$(anon first)"/>
  <node pkg="pkg_a" type="t" name="$(anon second.node)"/>
  <param name="same" value="$(anon first)"/>
"""
    first = run_one(tmp_path, body, job_id="anon1")
    again = shared_oracle().run(
        [
            {
                "id": "anon2",
                "roots": [str(tmp_path / "ws")],
                "files": [str(tmp_path / "ws" / "pkg_a" / "launch" / "main.launch")],
            }
        ]
    )[0]
    assert first["ok"], first
    assert [n["name"] for n in first["nodes"]] == ["/first_anon1", "/second_node_anon2"]
    assert first["params"] == {"/same": "first_anon1"}
    # the counter restarts with every job
    assert again["nodes"] == first["nodes"]


def test_rosparam_yaml_dict_is_unrolled(tmp_path: Path) -> None:
    root = tmp_path / "ws"
    pkg = make_package(
        root,
        "pkg_a",
        {
            "config/params.yaml": (
                "gains: {p: 1.5, i: 0, d: .inf}\nname: robot\nlist: [1, two, false]\n"
                "blob: !!binary aGVsbG8=\n"
            ),
            "launch/main.launch": launch(
                '  <rosparam command="load" file="$(find pkg_a)/config/params.yaml" ns="ctl"/>\n'
                '  <rosparam param="angle">rad(pi/2)</rosparam>'
            ),
        },
    )
    result = shared_oracle().run_one(
        {
            "id": "yaml",
            "roots": [str(root)],
            "files": [str(pkg / "launch" / "main.launch")],
        }
    )
    assert result["ok"], result
    params = result["params"]
    assert params["/ctl/gains/p"] == 1.5
    assert params["/ctl/gains/i"] == 0
    assert params["/ctl/gains/d"] == "inf"
    assert params["/ctl/name"] == "robot"
    assert params["/ctl/list"] == [1, "two", False]
    assert params["/ctl/blob"] == {"__binary__": "aGVsbG8="}
    assert params["/angle"] == pytest.approx(1.5707963267948966)
    assert "/ctl/gains" not in params


def test_unknown_machine_is_an_error(tmp_path: Path) -> None:
    result = run_one(tmp_path, '  <node pkg="pkg_a" type="t" name="n" machine="nowhere"/>')
    assert result["ok"] is False
    assert result["error"] == "ERROR: unknown machine [nowhere]"
    assert result["outside"] is False


def test_batch_survives_errors_and_keeps_order(tmp_path: Path) -> None:
    root = tmp_path / "ws"
    pkg = make_package(
        root,
        "pkg_a",
        {
            "launch/good.launch": launch('  <node pkg="pkg_a" type="t" name="n"/>'),
            "launch/bad.launch": "<launch><node pkg='pkg_a'",
        },
    )
    good = str(pkg / "launch" / "good.launch")
    bad = str(pkg / "launch" / "bad.launch")
    jobs = [
        {"id": i, "roots": [str(root)], "files": [bad if i % 3 == 0 else good]} for i in range(30)
    ]
    with RoslaunchOracle() as oracle:
        results = oracle.run(jobs)
        assert [r["id"] for r in results] == list(range(30))
        assert [r["ok"] for r in results] == [i % 3 != 0 for i in range(30)]
        # the same process answers later batches too
        assert oracle.run(jobs[:2])[1]["ok"] is True
