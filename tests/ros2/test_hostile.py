"""Hostile ROS 2 input, end to end: ``rosvar`` run in a subprocess whose memory and time
this test bounds (``RLIMIT_AS``, a timeout), on small hostile files built here. Each case
must end in a diagnostic naming the right format and place, never a traceback, never a
value read from outside the workspace."""

from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pytest

import rosvar
from differential.ros2.test_fixtures import PACKAGE_XML

MEMORY = 1024 * 1024 * 1024
"""Address space of one run: the hostile cases blew past a gigabyte."""
SECONDS = 60.0
"""Wall time of one run, far above what a bounded run takes on a loaded machine."""
SECRET = "TOPSECRET"


def _limit() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY, MEMORY))


def run(*args: str) -> subprocess.CompletedProcess[str]:
    """``rosvar ARGS`` within :data:`MEMORY` and :data:`SECONDS`."""
    source = str(Path(rosvar.__file__).parent.parent)
    env = {**os.environ, "PYTHONPATH": source}
    return subprocess.run(
        [sys.executable, "-m", "rosvar", *args],
        capture_output=True,
        text=True,
        env=env,
        timeout=SECONDS,
        preexec_fn=_limit,
        check=False,
    )


def workspace(tmp_path: Path, files: Mapping[str, str]) -> Path:
    """A workspace ``ws`` of one package ``pkg`` holding ``files``, and a folder ``outside``
    beside it with a parameter file (and a broken one) holding :data:`SECRET`."""
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "secret.yaml").write_text(f"/**:\n  ros__parameters:\n    s: {SECRET}\n")
    (outside / "broken.yaml").write_text(f"/**:\n  ros__parameters:\n    s: {SECRET}: [\n")
    (outside / "out.launch.xml").write_text(f'<launch><node pkg="pkg" exec="{SECRET}"/></launch>')
    package = tmp_path / "ws" / "pkg"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(PACKAGE_XML)
    for name, text in files.items():
        (package / name).parent.mkdir(parents=True, exist_ok=True)
        (package / name).write_text(text)
    return tmp_path / "ws"


def resolve(ws: Path, launch: str) -> tuple[subprocess.CompletedProcess[str], dict[str, Any]]:
    """``rosvar resolve --json`` of ``launch`` (below ``ws/pkg``), checked to end in a
    document, not a traceback."""
    done = run("resolve", str(ws), "--launch", str(ws / "pkg" / launch), "--json")
    assert "Traceback" not in done.stderr, done.stderr[-2000:]
    return done, json.loads(done.stdout)


def error_codes(document: Mapping[str, Any]) -> list[str]:
    return [str(e["code"]) for e in document["errors"]]


PYTHON_HEAD = """from launch import LaunchDescription
from launch.actions import GroupAction, SetLaunchConfiguration, DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
def generate_launch_description():
"""


def _reads(path: str, python: str) -> Mapping[str, str]:
    """A node reading parameter file ``path`` (``python`` as the Python frontend's
    expression) in each way ROS 2 files name one."""
    return {
        "launch/from.launch.xml": (
            f'<launch><node pkg="pkg" exec="n"><param from="{path}"/></node></launch>'
        ),
        "launch/global.launch.xml": (
            f'<launch><set_parameters_from_file filename="{path}"/>'
            '<node pkg="pkg" exec="n"/></launch>'
        ),
        "launch/from.launch.yaml": (
            f"launch:\n- node:\n    pkg: pkg\n    exec: n\n    param:\n    - from: '{path}'\n"
        ),
        "launch/from.launch.py": "import os\n"
        + "from ament_index_python.packages import get_package_share_directory\n"
        + PYTHON_HEAD
        + f"    return LaunchDescription([Node(package='pkg', executable='n', "
        f"parameters=[{python}])])\n",
    }


LAUNCHES = sorted(_reads("", ""))


@pytest.mark.parametrize("name", ["secret.yaml", "broken.yaml"])
@pytest.mark.parametrize("how", ["absolute", "dotdot"])
@pytest.mark.parametrize("launch", LAUNCHES)
def test_parameter_files_outside_the_workspace_are_not_read(
    tmp_path: Path, launch: str, how: str, name: str
) -> None:
    if how == "absolute":
        path = str(tmp_path / "outside" / name)
        python = repr(path)
    else:
        path = f"$(find-pkg-share pkg)/../../outside/{name}"
        python = (
            f"os.path.join(get_package_share_directory('pkg'), '..', '..', 'outside', {name!r})"
        )
    ws = workspace(tmp_path, _reads(path, python))
    done, document = resolve(ws, launch)
    assert SECRET not in done.stdout + done.stderr
    assert not document["ok"]
    messages = [str(e["message"]) for e in document["errors"]]
    assert any("outside the workspace" in m and name in m for m in messages), messages
    for error in document["errors"]:
        assert error["line"] > 0, error


def test_a_launch_file_linked_from_outside_is_not_read(tmp_path: Path) -> None:
    ws = workspace(tmp_path, {})
    link = ws / "pkg" / "launch" / "link.launch.xml"
    link.symlink_to(tmp_path / "outside" / "out.launch.xml")
    done, document = resolve(ws, "launch/link.launch.xml")
    assert SECRET not in done.stdout
    assert error_codes(document) == ["file-outside-workspace"]
    assert str(link) in str(document["errors"])
    analyzed = run("analyze", str(ws), "--json")
    assert SECRET not in analyzed.stdout and "Traceback" not in analyzed.stderr


@pytest.mark.parametrize(
    ("name", "text", "told", "line"),
    [
        ("bad.launch.py", "def generate_launch_description(:\n", "ROS 2 Python launch file", 1),
        ("bad.launch.yaml", "launch:\n- arg: {name: a\n", "ROS 2 YAML launch file", 3),
        ("bad.launch.xml", "<launch>\n<arg name='a'>\n</launch>", "ROS 2 XML launch file", 3),
    ],
)
def test_errors_name_the_format_and_the_place(
    tmp_path: Path, name: str, text: str, told: str, line: int
) -> None:
    ws = workspace(tmp_path, {f"launch/{name}": text})
    _done, document = resolve(ws, f"launch/{name}")
    (error,) = document["errors"]
    assert told in error["message"] and "roslaunch" not in error["message"]
    assert error["line"] == line


BOMB = "a: &a [x,x,x,x,x,x,x,x,x]\n" + "".join(
    f"{n}: &{n} [{', '.join([f'*{p}'] * 9)}]\n" for p, n in zip("abcdefg", "bcdefgh", strict=True)
)


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        (BOMB + "/**:\n  ros__parameters:\n    p: *h\n", "more than 100000 nodes"),
        ("/**:\n  ros__parameters: &a\n    p: *a\n", "refers to a node that contains it"),
        ("/**:\n  ros__parameters:\n    p: " + "[" * 4000 + "]" * 4000 + "\n", "nest"),
        (
            "/**:\n  ros__parameters:\n    p:\n"
            + "".join("  " * (i + 3) + f"k{i}:\n" for i in range(3000))
            + "  " * 3003
            + "1\n",
            "nest",
        ),
    ],
)
def test_parameter_files_are_read_within_the_yaml_limits(
    tmp_path: Path, text: str, problem: str
) -> None:
    ws = workspace(tmp_path, _reads("$(find-pkg-share pkg)/params.yaml", ""))
    (ws / "pkg" / "params.yaml").write_text(text)
    _done, document = resolve(ws, "launch/from.launch.xml")
    assert not document["ok"]
    (error,) = document["errors"]
    assert problem in error["message"] and error["line"] == 1


def analyze(ws: Path) -> dict[str, Any]:
    """``rosvar analyze --json`` of ``ws``, checked to end in a document."""
    done = run("analyze", str(ws), "--json")
    assert "Traceback" not in done.stderr, done.stderr[-2000:]
    document: dict[str, Any] = json.loads(done.stdout)
    return document


def diagnostic_codes(document: Mapping[str, Any]) -> set[str]:
    return {d["code"] for file in document["files"] for d in file["diagnostics"]}


DOUBLINGS = 40
"""Each value twice the previous: 10 * 2^39 characters at the end."""


def _doubling(launch: str) -> str:
    last = f"v{DOUBLINGS - 1}"
    if launch.endswith(".py"):
        steps = "".join(
            f"        SetLaunchConfiguration('v{i}', "
            f"[LaunchConfiguration('v{i - 1}'), LaunchConfiguration('v{i - 1}')]),\n"
            for i in range(1, DOUBLINGS)
        )
        return (
            PYTHON_HEAD
            + "    return LaunchDescription([SetLaunchConfiguration('v0', 'xxxxxxxxxx'),\n"
            + steps
            + f"        Node(package='pkg', executable='n', name=LaunchConfiguration('{last}'))])\n"
        )
    if launch.endswith(".yaml"):
        steps = "".join(
            f"- let: {{name: v{i}, value: '$(var v{i - 1})$(var v{i - 1})'}}\n"
            for i in range(1, DOUBLINGS)
        )
        return (
            "launch:\n- let: {name: v0, value: xxxxxxxxxx}\n"
            + steps
            + f"- node: {{pkg: pkg, exec: n, name: '$(var {last})'}}\n"
        )
    tag = "let" if "let" in launch else "arg"
    value = "value" if tag == "let" else "default"
    steps = "".join(
        f'<{tag} name="v{i}" {value}="$(var v{i - 1})$(var v{i - 1})"/>'
        for i in range(1, DOUBLINGS)
    )
    return (
        f'<launch><{tag} name="v0" {value}="xxxxxxxxxx"/>{steps}'
        f'<node pkg="pkg" exec="n" name="$(var {last})"/></launch>'
    )


def _choices(launch: str, count: int) -> str:
    if launch.endswith(".py"):
        declared = "".join(
            f"        DeclareLaunchArgument('a{i}', default_value='x', choices=['x', 'y']),\n"
            for i in range(count)
        )
        name = ", ".join(f"LaunchConfiguration('a{i}')" for i in range(count))
        return (
            PYTHON_HEAD
            + f"    return LaunchDescription([\n{declared}"
            + f"        Node(package='pkg', executable='n', name=[{name}])])\n"
        )
    declared = "".join(
        f'<arg name="a{i}" default="x"><choice value="x"/><choice value="y"/></arg>'
        for i in range(count)
    )
    name = "".join(f"$(var a{i})" for i in range(count))
    return f'<launch>{declared}<node pkg="pkg" exec="n" name="{name}"/></launch>'


@pytest.mark.parametrize(
    "launch",
    [
        "launch/let.launch.xml",
        "launch/arg.launch.xml",
        "launch/let.launch.yaml",
        "launch/set.launch.py",
    ],
)
def test_doubling_values_are_bounded_in_every_frontend(tmp_path: Path, launch: str) -> None:
    ws = workspace(tmp_path, {launch: _doubling(launch)})
    _done, document = resolve(ws, launch)
    assert not document["ok"]
    assert "value-unknown" in error_codes(document) or "node-invalid" in error_codes(document)
    assert "value-too-complex" in diagnostic_codes(analyze(ws))


@pytest.mark.parametrize("count", [12, 20])
@pytest.mark.parametrize("launch", ["launch/choices.launch.xml", "launch/choices.launch.py"])
def test_concatenated_choices_are_bounded(tmp_path: Path, launch: str, count: int) -> None:
    ws = workspace(tmp_path, {launch: _choices(launch, count)})
    _done, document = resolve(ws, launch)
    # the model over every command line gives the name up; one configuration computes it
    assert document["ok"], document["errors"]
    assert [node["name"] for node in document["nodes"]] == ["/" + "x" * count]
    for command in ("analyze", "features", "check"):
        done = run(command, str(ws))
        assert "Traceback" not in done.stderr, (command, done.stderr[-2000:])
    assert "value-too-complex" in diagnostic_codes(analyze(ws))


@pytest.mark.parametrize(
    ("launch", "text"),
    [
        (
            "launch/groups.launch.xml",
            "<launch>\n" + "<group>" * 990 + '<node pkg="pkg" exec="n"/>' + "</group>" * 990,
        ),
        (
            "launch/groups.launch.py",
            PYTHON_HEAD
            + "    g = Node(package='pkg', executable='n')\n"
            + "    for i in range(5000):\n        g = GroupAction([g])\n"
            + "    return LaunchDescription([g])\n",
        ),
    ],
)
def test_deep_groups_are_nesting_too_deep(tmp_path: Path, launch: str, text: str) -> None:
    if launch.endswith(".xml"):
        text += "\n</launch>"
    ws = workspace(tmp_path, {launch: text})
    _done, document = resolve(ws, launch)
    assert error_codes(document) == ["nesting-too-deep"]
    assert document["errors"][0]["line"] == (2 if launch.endswith(".xml") else 8)
    assert "nesting-too-deep" in diagnostic_codes(analyze(ws))


def _statements(count: int) -> str:
    return (
        PYTHON_HEAD
        + "    x = 0\n"
        + "    x = x + 1\n" * count
        + "    return LaunchDescription([])\n"
    )


@pytest.mark.parametrize(
    ("count", "code"), [(180_000, "file-too-large"), (40_000, "python-budget")]
)
def test_large_python_files_are_refused_before_parsing(
    tmp_path: Path, count: int, code: str
) -> None:
    """Over 1 MiB, or 100,000 tokens: refused with a diagnostic in every command (``check``:
    an ``unread`` finding, ``metrics``: on stderr), as an entry file and as an included one,
    before ``ast.parse`` spends seconds and gigabytes."""
    include = (
        "from launch.actions import IncludeLaunchDescription\n"
        "from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        + PYTHON_HEAD
        + "    here = os.path.dirname(__file__)\n"
        + "    return LaunchDescription([IncludeLaunchDescription(\n"
        "        PythonLaunchDescriptionSource(os.path.join(here, 'big.py')))])\n"
    )
    ws = workspace(
        tmp_path,
        {
            "launch/big.launch.py": _statements(count),
            "launch/big.py": _statements(count),
            "launch/includer.launch.py": "import os\n" + include,
        },
    )
    _done, document = resolve(ws, "launch/big.launch.py")
    (error,) = document["errors"]
    assert "Python launch file" in error["message"] and error["line"] == 1
    _done, document = resolve(ws, "launch/includer.launch.py")
    (error,) = document["errors"]
    assert "big.py" in error["message"] and error["line"] > 1
    assert code in diagnostic_codes(analyze(ws))
    assert code in run("features", str(ws)).stdout
    checked = run("check", str(ws), "--format", "json")
    unread = [f for f in json.loads(checked.stdout)["findings"] if f["check"] == "unread"]
    assert [f["name"] for f in unread] == [code, code], unread  # big.launch.py, big.py
    assert f"[{code}]" in run("metrics", str(ws)).stderr


DEEP = "[" * 900 + "1" + "]" * 900
"""A typed text within the length limits, nested deeper than PyYAML's constructor can
recurse."""


@pytest.mark.parametrize(
    "node",
    [
        f'<node pkg="pkg" exec="n"><param name="p" value="{DEEP}" type="list_of_int"/></node>',
        f'<node pkg="pkg" exec="n" name="$(not {DEEP})"/>',
        '<node pkg="pkg" exec="n" name="' + "$(var " * 3000 + "x" + ")" * 3000 + '"/>',
        '<executable cmd="' + "$(not " * 3000 + "true" + ")" * 3000 + '"/>',
    ],
)
def test_deep_texts_are_read_within_the_limits(tmp_path: Path, node: str) -> None:
    """Every YAML reading of a value goes through the bounded loader, typed texts too, and
    substitutions nest 100 levels at most: a RecursionError traceback in every command
    before."""
    ws = workspace(tmp_path, {"launch/deep.launch.xml": f"<launch>{node}</launch>"})
    _done, document = resolve(ws, "launch/deep.launch.xml")
    assert not document["ok"]
    for command in ("analyze", "features", "check"):
        done = run(command, str(ws))
        assert "Traceback" not in done.stderr, (command, done.stderr[-2000:])


EVIL = """import os
import pkg.evil
from pkg.evil import later
os.system('touch {marker}')
SECRET = open('/etc/passwd').read()
ENVIRONMENT = dict(os.environ)
later = 1


def name():
    os.system('touch {marker}')
    return open('/etc/passwd').read() + os.environ.get('ROSVAR_HOSTILE', '')
"""


def test_a_helper_module_is_never_run_and_leaks_nothing(tmp_path: Path) -> None:
    """A workspace module the launch file imports: it imports itself, calls ``os.system``,
    reads ``/etc/passwd`` and the environment. Read, never run: nothing it would do happens,
    nothing it would read is printed, each step is told where it stands."""
    marker = tmp_path / "ran"
    ws = workspace(
        tmp_path,
        {
            "pkg/__init__.py": "",
            "pkg/evil.py": EVIL.format(marker=marker),
            "launch/evil.launch.py": "import pkg.evil\n"
            + PYTHON_HEAD
            + "    return LaunchDescription([Node(package='pkg', executable='n', "
            "name=pkg.evil.name(), parameters=[{'s': pkg.evil.SECRET, "
            "'e': str(pkg.evil.ENVIRONMENT)}])])\n",
        },
    )
    done = subprocess.run(
        [sys.executable, "-m", "rosvar", "resolve", str(ws), "--launch",
         str(ws / "pkg" / "launch" / "evil.launch.py"), "--json"],
        capture_output=True, text=True, timeout=SECONDS, preexec_fn=_limit, check=False,
        env={**os.environ, "PYTHONPATH": str(Path(rosvar.__file__).parent.parent),
             "ROSVAR_HOSTILE": SECRET},
    )  # fmt: skip
    assert "Traceback" not in done.stderr, done.stderr[-2000:]
    document = json.loads(done.stdout)
    assert not marker.exists()
    assert SECRET not in done.stdout + done.stderr and "root:" not in done.stdout
    assert not document["ok"]
    warned = {(w["code"], w["message"]) for w in document["warnings"]}
    assert ("python-not-followed", "call to os.system() is not followed") in warned
    assert any(code == "file-outside-workspace" and "/etc/passwd" in m for code, m in warned)


def _eval_chain(links: int) -> str:
    """Five args with choices concatenated (1,024 values, most not known), tested in an
    ``if``; then a chain of ``<let>``s of ``$(eval)``s, each reading the one before twice and
    an arg's ``<other>`` value, each tested in an ``if``."""
    lines = ["<launch>"]
    for i in range(5):
        choices = "".join(f'<choice value="{w}{i}"/>' for w in "vwu")
        lines.append(f'<arg name="a{i}" default="v{i}">{choices}</arg>')
    lines.append('<let name="v" value="$(var a0)$(var a1)$(var a2)$(var a3)$(var a4)"/>')
    lines.append('<node pkg="pkg" exec="n" name="joined" if="$(var v)"/>')
    for i in range(links):
        test = f"'$(var v)' == 'x{i}' or '$(var a0)' != '$(var v)'"
        lines.append(f'<let name="v" value="$(eval &quot;{test}&quot;)"/>')
        lines.append(f'<node pkg="pkg" exec="n" name="n{i}" if="$(var v)"/>')
    return "\n".join([*lines, "</launch>"])


def test_a_chain_of_evals_over_unknown_values_is_bounded(tmp_path: Path) -> None:
    """Every value tested stays within the terms a test may make predicates of and the size
    of the conditions computed instead of crossing: past them a ``value-too-complex`` note
    at the tag, and the value unknown until a configuration computes it."""
    launch = "launch/chain.launch.xml"
    ws = workspace(tmp_path, {launch: _eval_chain(40)})
    notes = [
        (d["line"], d["message"])
        for file in analyze(ws)["files"]
        for d in file["diagnostics"]
        if d["code"] == "value-too-complex"
    ]
    assert notes[0] == (
        8,
        "<node> attribute 'if' is not computed: it tests 781 values not known yet, over 64",
    )
    assert "tests 5711 values not known yet" in notes[1][1] and notes[1][0] == 9
    assert any("BDD nodes, over 4096" in message for _line, message in notes[2:])
    _done, document = resolve(ws, launch)
    assert not document["ok"]  # 'v0v1v2v3v4' is no bool, yet every value is computed
    assert [e["code"] for e in document["errors"]] == ["bool-invalid"]
