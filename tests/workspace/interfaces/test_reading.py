"""Sources pass the read gate launch files pass, and hostile sources stay bounded: each
refusal or limit is a diagnostic at its file, and the rest of the package is still read."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from rosvar.diagnostics import Diagnostic
from rosvar.files import Confinement
from rosvar.workspace import discover
from rosvar.workspace.interfaces.extraction import extract_interfaces
from rosvar.workspace.interfaces.model import Interfaces, Role

MANIFEST = """\
<package format="2"><name>demo</name><version>0.0.0</version><description>d</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend>catkin</buildtool_depend></package>
"""
GOOD = 'int main() { ros::NodeHandle nh; nh.advertise<std_msgs::String>("good", 1); }\n'


def _package(root: Path, hostile: str | None) -> Path:
    """Package ``demo``: the node ``good`` and, built from ``src/node.cpp``, ``node``."""
    package = root / "demo"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST)
    (package / "CMakeLists.txt").write_text(
        "add_executable(good src/good.cpp)\nadd_executable(node src/node.cpp)\n"
    )
    (package / "src" / "good.cpp").write_text(GOOD)
    if hostile is not None:
        (package / "src" / "node.cpp").write_text(hostile)
    return package


def _extract(root: Path) -> tuple[Interfaces, list[Diagnostic]]:
    workspace = discover([root], ros_package_path="")
    packages = workspace.packages.values()
    interfaces = extract_interfaces(packages, workspace.confinement(), packages)
    good = interfaces.find("demo", "good")
    assert good is not None and [e.name for e in good.of(Role.PUBLISHES)] == ["good"]
    return interfaces, interfaces.diagnostics


def _refusal(diagnostics: list[Diagnostic], code: str) -> Diagnostic:
    (found,) = [d for d in diagnostics if d.code == code]
    assert found.location.file.endswith(os.path.join("src", "node.cpp"))
    return found


def test_a_source_symlinked_to_a_device_is_refused(tmp_path: Path) -> None:
    package = _package(tmp_path, None)
    (package / "src" / "node.cpp").symlink_to("/dev/zero")
    _, diagnostics = _extract(tmp_path)
    assert "/dev" in _refusal(diagnostics, "file-outside-workspace").message


def test_a_fifo_is_no_source(tmp_path: Path) -> None:
    package = _package(tmp_path, None)
    os.mkfifo(package / "src" / "node.cpp")
    _, diagnostics = _extract(tmp_path)
    assert "regular" in _refusal(diagnostics, "file-unreadable").message


def test_a_source_outside_the_workspace_is_not_read(tmp_path: Path) -> None:
    secret = tmp_path / "secret.cpp"
    secret.write_text('int main() { ros::NodeHandle nh; nh.advertise<X>("secret", 1); }\n')
    package = _package(tmp_path / "ws", None)
    (package / "src" / "node.cpp").symlink_to(secret)
    interfaces, diagnostics = _extract(tmp_path / "ws")
    _refusal(diagnostics, "file-outside-workspace")
    assert all(e.name != "secret" for n in interfaces.nodes for e in n.entries)
    # given a wider confinement (--allow-outside-workspace), it is read
    widened = extract_interfaces(
        discover([tmp_path / "ws"]).packages.values(), Confinement.of([str(tmp_path)])
    )
    node = widened.find("demo", "node")
    assert node is not None and [e.name for e in node.of(Role.PUBLISHES)] == ["secret"]


HELPERS = 24
CHAIN = "\n".join(
    f"void f{i}(ros::NodeHandle& nh, std::string a) "
    f'{{ f{i + 1}(nh, a + a); f{i + 1}(nh, a + "x"); }}'
    for i in range(HELPERS)
)


@pytest.mark.parametrize(
    ("source", "code", "published"),
    [
        (  # each helper calls the next twice: evaluated once per helper, not 2**24 times
            CHAIN + f"\nvoid f{HELPERS}(ros::NodeHandle& nh, std::string a) "
            "{ nh.advertise<std_msgs::String>(a, 1); }\n"
            'int main() { ros::NodeHandle nh; f0(nh, "t"); }\n',
            "interface-symbolic-name",
            ["{a}"],
        ),
        (
            "int main() { ros::NodeHandle nh; "
            + "{" * 40_000
            + "}" * 40_000
            + ' nh.advertise<std_msgs::String>("x", 1); }\n',
            "interface-too-nested",
            [],
        ),
        (
            "int main() { ros::NodeHandle nh; nh.advertise<"
            + "A<" * 20_000
            + "B"
            + ">" * 20_000
            + '>("x", 1); }\n',
            "interface-too-nested",
            [],
        ),
    ],
    ids=["helper-chain", "nested-braces", "nested-templates"],
)
def test_hostile_cpp_stays_bounded(
    tmp_path: Path, source: str, code: str, published: list[str]
) -> None:
    _package(tmp_path, source)
    interfaces, diagnostics = _extract(tmp_path)
    assert any(d.code == code and d.location.line >= 1 for d in diagnostics)
    node = interfaces.find("demo", "node")
    assert node is not None and [e.name for e in node.of(Role.PUBLISHES)] == published


@pytest.mark.parametrize("terms", [2_000, 100_000])
def test_a_long_sum_in_a_python_source_is_a_diagnostic(tmp_path: Path, terms: int) -> None:
    package = _package(tmp_path, None)
    (package / "scripts").mkdir()
    long_sum = "+".join(['"a"'] * terms)
    (package / "scripts" / "talker.py").write_text(
        f"import rospy\nrospy.Publisher({long_sum}, X)\nrospy.Subscriber('ok', X)\n"
    )
    interfaces, diagnostics = _extract(tmp_path)
    talker = interfaces.find("demo", "talker.py")
    assert talker is not None
    if terms > 10_000:  # the parser itself gives up
        (unparsable,) = [d for d in diagnostics if d.code == "interface-unparsable"]
        assert unparsable.location.file.endswith("talker.py") and unparsable.location.line == 1
        assert talker.entries == []
    else:  # parsed; the name is given up past its depth, the rest is read
        assert [e.static for e in talker.of(Role.PUBLISHES)] == [False]
        assert [e.name for e in talker.of(Role.SUBSCRIBES)] == ["ok"]
