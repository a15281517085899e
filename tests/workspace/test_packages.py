"""Tests of workspace discovery: packages as rospkg finds them, and launch files."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from rosvar.diagnostics import Severity
from rosvar.ros.version import RosVersion
from rosvar.workspace import Package, Workspace, discover
from rosvar.workspace.launch_files import LaunchFormat

CORPUS = Path(__file__).resolve().parents[2] / ".." / "shared" / "corpus"
LAUNCH = "<launch>\n  <arg name='a'/>\n</launch>\n"


def make_package(directory: Path, name: str | None = None, manifest: str | None = None) -> Path:
    directory.mkdir(parents=True, exist_ok=True)
    if manifest is None:
        manifest = f'<?xml version="1.0"?>\n<package format="2">\n  <name>{name}</name>\n</package>'
    (directory / "package.xml").write_text(manifest)
    return directory


def write(path: Path, text: str = LAUNCH) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def codes(workspace: Workspace) -> list[str]:
    return [diagnostic.code for diagnostic in workspace.diagnostics]


def test_packages_and_launch_files(tmp_path: Path) -> None:
    src = tmp_path / "src"
    alpha = make_package(src / "alpha_dir", "alpha")
    beta = make_package(src / "group" / "beta", "beta")
    write(alpha / "launch" / "a.launch")
    write(alpha / "launch" / "includes" / "b.launch.xml")
    write(beta / "c.launch")
    write(tmp_path / "loose.launch")  # outside any package: still listed

    workspace = discover([tmp_path], ros_package_path="")

    assert workspace.roots == [str(tmp_path)]
    assert set(workspace.packages) == {"alpha", "beta"}
    assert workspace.find("alpha") == str(alpha)
    assert workspace.find("unknown") is None
    assert workspace.launch_files == sorted(
        [
            str(alpha / "launch" / "a.launch"),
            str(alpha / "launch" / "includes" / "b.launch.xml"),
            str(beta / "c.launch"),
            str(tmp_path / "loose.launch"),
        ]
    )
    assert workspace.diagnostics == []


def test_no_packages_searched_inside_a_package_but_launch_files_are(tmp_path: Path) -> None:
    outer = make_package(tmp_path / "outer", "outer")
    inner = make_package(outer / "sub" / "inner", "inner")
    write(inner / "launch" / "deep.launch")

    workspace = discover([tmp_path], ros_package_path="")

    assert set(workspace.packages) == {"outer"}
    assert workspace.launch_files == [str(inner / "launch" / "deep.launch")]
    assert workspace.package_of(inner / "launch" / "deep.launch") == workspace.packages["outer"]


def test_package_of_picks_the_innermost_package(tmp_path: Path) -> None:
    outer = make_package(tmp_path / "outer", "outer")
    inner = make_package(tmp_path / "outer_sibling" / "inner", "inner")
    workspace = discover([tmp_path], ros_package_path="")
    launch = inner / "launch" / "x.launch"
    assert workspace.package_of(launch) == workspace.packages["inner"]
    assert workspace.package_of(str(outer)) == workspace.packages["outer"]
    assert workspace.package_of(tmp_path / "elsewhere.launch") is None


def test_package_of_works_on_a_hand_built_workspace(tmp_path: Path) -> None:
    package = Package("p", str(tmp_path / "p"), None)
    workspace = Workspace([str(tmp_path)], {}, [], [])
    assert workspace.package_of(tmp_path / "p" / "x.launch") is None
    workspace.packages["p"] = package
    assert workspace.package_of(tmp_path / "p" / "x.launch") == package


def test_package_of_resolves_symlinks(tmp_path: Path) -> None:
    real = make_package(tmp_path / "real", "real")
    link = tmp_path / "link"
    link.symlink_to(real, target_is_directory=True)
    workspace = discover([tmp_path / "real"], ros_package_path="")
    assert workspace.package_of(link / "x.launch") == workspace.packages["real"]


def test_find_resource_by_file_name_as_roslaunch_pkg_file(tmp_path: Path) -> None:
    """``roslaunch PKG FILE``: FILE anywhere below PKG, hidden folders skipped."""
    package = make_package(tmp_path / "drv", "drv")
    deep = write(package / "launch" / "sub" / "deep.launch")
    twice = [write(package / d / "twice.launch") for d in ("launch", "other")]
    write(package / ".hidden" / "secret.launch")
    workspace = discover([tmp_path], ros_package_path="")
    assert workspace.find_resource("drv", "deep.launch") == [str(deep)]
    assert sorted(workspace.find_resource("drv", "twice.launch") or []) == sorted(map(str, twice))
    assert workspace.find_resource("drv", "secret.launch") == []
    assert workspace.find_resource("drv", "sub/deep.launch") == []  # a name, not a path
    assert workspace.find_resource("nowhere", "deep.launch") is None


def test_catkin_ignore_and_hidden_directories_are_skipped(tmp_path: Path) -> None:
    ignored = make_package(tmp_path / "ignored", "ignored")
    (ignored / "CATKIN_IGNORE").write_text("")
    write(ignored / "i.launch")
    write(tmp_path / "tree" / "CATKIN_IGNORE", "")
    make_package(tmp_path / "tree" / "below", "below")
    hidden = make_package(tmp_path / ".hidden" / "h", "hidden")
    write(hidden / "h.launch")
    write(tmp_path / "kept" / ".git" / "x.launch")
    write(tmp_path / "kept" / ".#lock.launch")
    kept = write(tmp_path / "kept" / "k.launch")

    workspace = discover([tmp_path], ros_package_path="")

    assert workspace.packages == {}
    assert workspace.launch_files == [str(kept)]


def test_ros_package_path_adds_packages_after_roots(tmp_path: Path) -> None:
    root = tmp_path / "ws"
    mine = make_package(root / "common", "common")
    write(mine / "mine.launch")
    opt = tmp_path / "opt"
    make_package(opt / "common", "common")
    other = make_package(opt / "stack" / "other", "other")
    write(other / "other.launch")
    direct = make_package(tmp_path / "direct", "direct")  # an entry may be a package itself

    search_path = os.pathsep.join([str(opt), "", str(tmp_path / "missing"), str(direct)])
    workspace = discover([root], ros_package_path=search_path)

    assert workspace.find("common") == str(mine)
    assert workspace.find("other") == str(other)
    assert workspace.find("direct") == str(direct)
    assert workspace.launch_files == [str(mine / "mine.launch")]
    assert codes(workspace) == ["package-duplicate"]
    assert [package.path for package in workspace.shadowed] == [str(opt / "common")]


def test_ros_package_path_defaults_to_the_environment(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    env = make_package(tmp_path / "env" / "from_env", "from_env")
    monkeypatch.setenv("ROS_PACKAGE_PATH", str(tmp_path / "env"))
    assert discover([tmp_path / "nothing_here_but_ok"]).find("from_env") == str(env)
    monkeypatch.delenv("ROS_PACKAGE_PATH")
    assert discover([tmp_path / "env"]).find("from_env") == str(env)


def test_deps_resolve_packages_but_add_no_launch_files(tmp_path: Path) -> None:
    root = make_package(tmp_path / "ws" / "mine", "mine")
    write(root / "launch" / "mine.launch")
    underlay = tmp_path / "opt" / "share"
    dep = make_package(underlay / "dep", "dep")
    write(dep / "launch" / "dep.launch")
    env = tmp_path / "env"
    make_package(env / "dep", "dep")  # ROS_PACKAGE_PATH comes after --deps
    from_env = make_package(env / "only_env", "only_env")

    workspace = discover([tmp_path / "ws"], deps=[underlay], ros_package_path=str(env))

    assert workspace.launch_files == [str(root / "launch" / "mine.launch")]
    assert workspace.find("dep") == str(dep)
    assert workspace.find("only_env") == str(from_env)
    assert [package.path for package in workspace.shadowed] == [str(env / "dep")]
    assert workspace.find_resource("dep", "dep.launch") == [str(dep / "launch" / "dep.launch")]


def test_a_missing_dep_is_reported(tmp_path: Path) -> None:
    make_package(tmp_path / "ws" / "mine", "mine")
    workspace = discover([tmp_path / "ws"], deps=[tmp_path / "nowhere"], ros_package_path="")
    assert codes(workspace) == ["path-missing"]
    assert workspace.diagnostics[0].severity is Severity.ERROR
    assert set(workspace.packages) == {"mine"}


def test_duplicate_packages_first_root_wins(tmp_path: Path) -> None:
    first = make_package(tmp_path / "b_first" / "dup", "dup")
    second = make_package(tmp_path / "a_second" / "dup", "dup")
    workspace = discover([tmp_path / "b_first", tmp_path / "a_second"], ros_package_path="")
    assert workspace.find("dup") == str(first)
    (warning,) = workspace.diagnostics
    assert (warning.code, warning.severity) == ("package-duplicate", Severity.WARNING)
    assert warning.location.file == str(second / "package.xml")
    assert str(first) in warning.message
    assert workspace.package_of(second / "x.launch") == Package("dup", str(second), None)


def test_same_directory_twice_is_not_a_duplicate(tmp_path: Path) -> None:
    make_package(tmp_path / "p", "p")
    workspace = discover([tmp_path, tmp_path / "p"], ros_package_path=str(tmp_path))
    assert list(workspace.packages) == ["p"] and workspace.diagnostics == []


def test_executables_file(tmp_path: Path) -> None:
    with_list = make_package(tmp_path / "with", "with")
    (with_list / ".executables").write_text("node_a\n\n  script.py  \nnode_a\n")
    empty = make_package(tmp_path / "empty", "empty")
    (empty / ".executables").write_text("")
    make_package(tmp_path / "without", "without")

    packages = discover([tmp_path], ros_package_path="").packages

    assert packages["with"].executables == frozenset({"node_a", "script.py"})
    assert packages["empty"].executables == frozenset()
    assert packages["without"].executables is None


@pytest.mark.parametrize(
    "manifest",
    [
        "<package><name>broken</package>",
        "<package><description>no name</description></package>",
        "<package><name>  </name></package>",
        "<launch/>",
        '<!DOCTYPE package [<!ENTITY n "evil">]><package><name>&n;</name></package>',
        "",
    ],
)
def test_invalid_package_xml_falls_back_to_directory_name(tmp_path: Path, manifest: str) -> None:
    make_package(tmp_path / "dir_name", manifest=manifest)
    workspace = discover([tmp_path], ros_package_path="")
    assert workspace.find("dir_name") == str(tmp_path / "dir_name")
    (warning,) = workspace.diagnostics
    assert (warning.code, warning.severity) == ("package-xml-invalid", Severity.WARNING)
    assert "dir_name" in warning.message


def test_package_name_is_stripped(tmp_path: Path) -> None:
    make_package(tmp_path / "d", manifest="<package><name>\n  spaced\n</name></package>")
    assert discover([tmp_path], ros_package_path="").find("spaced") == str(tmp_path / "d")


def test_xml_files_are_launch_files_only_with_a_launch_root(tmp_path: Path) -> None:
    package = make_package(tmp_path / "p", "p")
    launch_xml = write(package / "launch" / "bringup.xml")
    write(package / "nodelet_plugins.xml", '<library path="lib"><class name="a/B"/></library>')
    write(package / "urdf" / "robot.xml", "<robot name='launch'/>")
    write(package / "bad.xml", "<launch")

    workspace = discover([tmp_path], ros_package_path="")

    assert workspace.launch_files == [str(launch_xml)]


def test_single_launch_file_argument(tmp_path: Path) -> None:
    package = make_package(tmp_path / "ws" / "pkg", "pkg")
    make_package(tmp_path / "ws" / "neighbour", "neighbour")
    launch = write(package / "launch" / "one.launch")
    other = write(package / "launch" / "two.launch")

    workspace = discover([launch], ros_package_path="")

    assert workspace.launch_files == [str(launch)]
    assert str(other) not in workspace.launch_files
    assert list(workspace.packages) == ["pkg"]
    assert workspace.package_of(launch) == workspace.packages["pkg"]


def test_directory_inside_a_package_registers_that_package(tmp_path: Path) -> None:
    package = make_package(tmp_path / "pkg", "pkg")
    launch = write(package / "launch" / "one.launch")
    workspace = discover([package / "launch"], ros_package_path="")
    assert workspace.launch_files == [str(launch)]
    assert workspace.find("pkg") == str(package)


def test_relative_paths_become_absolute(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    launch = write(tmp_path / "a.launch")
    monkeypatch.chdir(tmp_path)
    workspace = discover(["."], ros_package_path="")
    assert workspace.roots == [str(tmp_path)]
    assert workspace.launch_files == [str(launch)]


def test_missing_path_is_reported_and_discovery_continues(tmp_path: Path) -> None:
    launch = write(tmp_path / "ok" / "a.launch")
    missing = tmp_path / "missing"
    workspace = discover([missing, tmp_path / "ok"], ros_package_path="")
    (error,) = workspace.diagnostics
    assert (error.code, error.severity) == ("path-missing", Severity.ERROR)
    assert error.location.file == str(missing)
    assert workspace.launch_files == [str(launch)]


def test_symlinked_directories_are_not_followed(tmp_path: Path) -> None:
    loop = tmp_path / "a"
    write(loop / "x.launch")
    (loop / "again").symlink_to(loop, target_is_directory=True)
    (tmp_path / "link").symlink_to(loop, target_is_directory=True)
    workspace = discover([tmp_path], ros_package_path="")
    assert workspace.launch_files == [str(loop / "x.launch")]


def corpus_or_skip() -> Path:
    if not CORPUS.is_dir():
        pytest.skip("shared corpus not available")
    return CORPUS.resolve()


def test_corpus_husky_launch_files() -> None:
    corpus = corpus_or_skip()
    husky = corpus / "husky"
    expected = sorted(
        os.path.join(directory, name)
        for directory, _, names in os.walk(husky)
        for name in names
        if ".launch" in name
    )
    workspace = discover([husky], ros_package_path="")
    assert len(workspace.launch_files) == 137
    assert workspace.launch_files == expected
    assert workspace.diagnostics == []
    for launch in workspace.launch_files:
        assert workspace.package_of(launch) is not None, launch


def test_corpus_husky_with_external_resolves_gazebo_ros() -> None:
    corpus = corpus_or_skip()
    workspace = discover([corpus / "husky", corpus / "_external"], ros_package_path="")
    gazebo_ros = workspace.find("gazebo_ros")
    assert gazebo_ros is not None
    assert Path(gazebo_ros, "package.xml").is_file()
    assert workspace.find("husky_gazebo") is not None
    assert discover([corpus / "husky"], ros_package_path="").find("gazebo_ros") is None


def test_corpus_husky_with_external_as_deps() -> None:
    corpus = corpus_or_skip()
    workspace = discover([corpus / "husky"], deps=[corpus / "_external"], ros_package_path="")
    assert workspace.find("gazebo_ros") is not None
    alone = discover([corpus / "husky"], ros_package_path="")
    assert workspace.launch_files == alone.launch_files


def ament_manifest(name: str, build_type: str = "ament_cmake") -> str:
    return (
        f'<?xml version="1.0"?>\n<package format="3">\n  <name>{name}</name>\n'
        f"  <buildtool_depend>{build_type}</buildtool_depend>\n"
        f"  <export><build_type>{build_type}</build_type></export>\n</package>\n"
    )


CATKIN_MANIFEST = (
    '<package format="2"><name>{}</name><buildtool_depend>catkin</buildtool_depend></package>'
)
LAUNCH_PY = "def generate_launch_description():\n    return None\n"


def test_ros2_workspace(tmp_path: Path) -> None:
    src = tmp_path / "ws" / "src"
    bringup = make_package(src / "bringup", manifest=ament_manifest("bringup"))
    tools = make_package(src / "tools", manifest=ament_manifest("tools", "ament_python"))
    write(bringup / "launch" / "robot.launch.py", LAUNCH_PY)
    write(bringup / "launch" / "sim.launch.xml")
    write(bringup / "launch" / "legacy.launch")  # a ROS 1 leftover: not a ROS 2 entry point
    write(bringup / "launch" / "utils.py", "X = 1\n")
    write(tools / "tools" / "teleop_launch.py", LAUNCH_PY)
    write(tools / "launch" / "teleop.yaml", "launch:\n- arg: {name: a}\n")
    write(src / "ignored" / "COLCON_IGNORE", "")
    make_package(src / "ignored" / "pkg", manifest=ament_manifest("ignored_pkg"))
    workspace = discover([src], ros_package_path="", ament_prefix_path="")
    assert workspace.ros_version == RosVersion.ROS2
    assert set(workspace.packages) == {"bringup", "tools"}
    assert workspace.packages["tools"].ros_version == RosVersion.ROS2
    relative = [os.path.relpath(path, src) for path in workspace.launch_files]
    assert relative == [
        "bringup/launch/robot.launch.py",
        "bringup/launch/sim.launch.xml",
        "tools/launch/teleop.yaml",
        "tools/tools/teleop_launch.py",
    ]
    assert [workspace.launch_format(path) for path in workspace.launch_files] == [
        LaunchFormat.PYTHON,
        LaunchFormat.XML,
        LaunchFormat.YAML,
        LaunchFormat.PYTHON,
    ]
    assert workspace.diagnostics == []
    # From source, a package's share folder is its own: colcon installs launch/ and config/.
    assert workspace.find_share("bringup") == str(bringup)
    assert workspace.find_prefix("bringup") is None


def test_ros1_workspace_keeps_roslaunch_rules(tmp_path: Path) -> None:
    pkg = make_package(tmp_path / "pkg", manifest=CATKIN_MANIFEST.format("pkg"))
    write(pkg / "launch" / "a.launch")
    write(pkg / "launch" / "b.launch.py", LAUNCH_PY)
    workspace = discover([tmp_path], ros_package_path="", ament_prefix_path="")
    assert workspace.ros_version == RosVersion.ROS1
    assert workspace.packages["pkg"].ros_version == RosVersion.ROS1
    assert workspace.launch_files == [str(pkg / "launch" / "a.launch")]
    assert workspace.launch_format(workspace.launch_files[0]) == LaunchFormat.XML


@pytest.mark.parametrize(
    ("files", "expected", "listed"),
    [
        (["a.launch.py"], RosVersion.ROS2, 1),
        (["a.launch.yaml", "b.launch.xml"], RosVersion.ROS2, 2),
        (["a.launch.py", "b.launch"], RosVersion.ROS1, 1),  # a ROS 1 file: not ROS 2
        (["b.launch.xml"], RosVersion.ROS1, 1),
        ([], RosVersion.ROS1, 0),
    ],
)
def test_version_without_telling_packages(
    tmp_path: Path, files: list[str], expected: RosVersion, listed: int
) -> None:
    make_package(tmp_path / "plain", "plain")  # format 2, no build tool
    for name in files:
        write(tmp_path / "plain" / "launch" / name, LAUNCH_PY if name.endswith(".py") else LAUNCH)
    workspace = discover([tmp_path], ros_package_path="", ament_prefix_path="")
    assert workspace.ros_version == expected
    assert len(workspace.launch_files) == listed


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("robot.launch.py", RosVersion.ROS2),
        ("robot.yaml", RosVersion.ROS2),
        ("robot.xml", RosVersion.ROS1),  # roslaunch reads any name given to it
        ("robot.launch.xml", RosVersion.ROS1),
    ],
)
def test_version_of_a_given_file_without_package(
    tmp_path: Path, name: str, expected: RosVersion
) -> None:
    path = write(tmp_path / name, LAUNCH_PY)
    workspace = discover([path], ros_package_path="", ament_prefix_path="")
    assert workspace.ros_version == expected
    assert workspace.launch_files == [str(path)]


def test_mixed_workspace_is_refused_explicitly(tmp_path: Path) -> None:
    for name in ("one", "two"):
        package = make_package(tmp_path / name, manifest=ament_manifest(name))
        write(package / "launch" / f"{name}.launch.xml")
    old = make_package(tmp_path / "old", manifest=CATKIN_MANIFEST.format("old"))
    write(old / "launch" / "old.launch.xml")
    write(tmp_path / "loose.launch.xml")  # in no package: kept
    workspace = discover([tmp_path], ros_package_path="", ament_prefix_path="")
    assert workspace.ros_version == RosVersion.ROS2
    (diagnostic,) = workspace.diagnostics
    assert diagnostic.code == "workspace-mixed"
    assert diagnostic.severity == Severity.ERROR
    assert "(old)" in diagnostic.message and "read as ROS 2" in diagnostic.message
    assert diagnostic.location.file == str(old / "package.xml")
    names = sorted(os.path.basename(path) for path in workspace.launch_files)
    assert names == ["loose.launch.xml", "one.launch.xml", "two.launch.xml"]
    assert "old" in workspace.packages  # still a package: $(find-pkg-share old) resolves


def test_ament_prefix_path(tmp_path: Path) -> None:
    underlay = tmp_path / "opt" / "ros" / "jazzy"
    nav = make_package(underlay / "share" / "nav2_bringup", manifest=ament_manifest("nav2_bringup"))
    write(nav / "launch" / "nav.launch.py", LAUNCH_PY)
    (underlay / "share" / "ament_index" / "resource_index").mkdir(parents=True)  # no package
    overlay = tmp_path / "ws" / "install" / "mine"
    make_package(overlay / "share" / "mine", manifest=ament_manifest("mine"))
    own = make_package(tmp_path / "ws" / "src" / "app", manifest=ament_manifest("app"))
    write(own / "launch" / "app.launch.py", LAUNCH_PY)
    prefixes = os.pathsep.join([str(overlay), str(underlay), str(tmp_path / "missing")])
    workspace = discover([own], ros_package_path="", ament_prefix_path=prefixes)
    assert set(workspace.packages) == {"app", "mine", "nav2_bringup"}
    assert workspace.launch_files == [str(own / "launch" / "app.launch.py")]
    assert workspace.dependency_roots == [str(overlay / "share"), str(underlay / "share")]
    assert workspace.find_share("nav2_bringup") == str(nav)
    assert workspace.find_prefix("nav2_bringup") == str(underlay)
    assert workspace.find_prefix("mine") == str(overlay)
    assert workspace.find_prefix("unknown") is None
    assert workspace.confinement().check(str(nav / "launch" / "nav.launch.py"))


def test_ament_prefix_path_from_the_environment(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    make_package(tmp_path / "prefix" / "share" / "dep", manifest=ament_manifest("dep"))
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(tmp_path / "prefix"))
    workspace = discover([], ros_package_path="")
    assert set(workspace.packages) == {"dep"}


ROS2_DATA = Path(__file__).resolve().parents[1] / "data" / "ros2"
# repository folder: packages, Python, XML and YAML launch files (tests/data/ros2/README.md)
ROS2_REPOSITORIES = {
    "husky": (10, 10, 0, 0),
    "clearpath_common": (11, 12, 0, 0),
    "ros2_control_demos": (20, 48, 5, 0),
    "slam_toolbox": (1, 6, 0, 0),
    "realsense-ros": (3, 9, 0, 0),
    "moveit2_tutorials": (1, 24, 0, 0),
    "Universal_Robots_ROS2_Driver": (6, 22, 0, 0),
    "moveit2": (39, 7, 0, 0),
    "ros_gz": (7, 24, 0, 0),
    "image_pipeline": (9, 17, 0, 0),
    "demos": (20, 12, 1, 1),
    "autoware.universe": (238, 22, 236, 0),
    "launch_param_builder": (1, 0, 0, 0),
    "xacro": (1, 0, 0, 0),
}


@pytest.mark.parametrize(("repository", "counts"), ROS2_REPOSITORIES.items())
def test_real_ros2_repositories(repository: str, counts: tuple[int, int, int, int]) -> None:
    workspace = discover([ROS2_DATA / repository], ros_package_path="", ament_prefix_path="")
    assert workspace.ros_version == RosVersion.ROS2
    assert workspace.diagnostics == []
    formats = [workspace.launch_format(path) for path in workspace.launch_files]
    found = (
        len(workspace.packages),
        formats.count(LaunchFormat.PYTHON),
        formats.count(LaunchFormat.XML),
        formats.count(LaunchFormat.YAML),
    )
    assert found == counts
    assert all(package.ros_version == RosVersion.ROS2 for package in workspace.packages.values())


def test_real_ros2_repositories_together() -> None:
    """All of them as one colcon workspace: every launch file of each, and the ROS 1
    leftovers (Husky's and MoveIt's ``*.launch``) still left out."""
    workspace = discover([ROS2_DATA], ros_package_path="", ament_prefix_path="")
    assert workspace.ros_version == RosVersion.ROS2
    assert len(workspace.launch_files) == sum(sum(c[1:]) for c in ROS2_REPOSITORIES.values())
    assert not [path for path in workspace.launch_files if path.endswith(".launch")]
    assert workspace.diagnostics == []  # no package name is shared between the repositories
    assert workspace.find_share("husky_control") == str(ROS2_DATA / "husky" / "husky_control")


@pytest.mark.parametrize("outputs", [("install",), ("build", "devel"), ("build", "install", "log")])
def test_a_workspace_root_reads_its_source_not_its_builds(
    tmp_path: Path, outputs: tuple[str, ...]
) -> None:
    """issue 30.6: at a workspace's root, a stale ``install/share`` copy of a package replaced
    its ``src`` copy ("…is also at …; that first one is used")."""
    ws = tmp_path / "ws"
    source = make_package(ws / "src" / "robot", "robot")
    kept = write(source / "launch" / "robot.launch")
    for output in outputs:
        stale = make_package(ws / output / "share" / "robot", "robot")
        write(stale / "launch" / "robot.launch")
        write(stale / "launch" / "old.launch")
        write(ws / output / "lib" / "robot" / "x.launch")
    workspace = discover([ws], ros_package_path="")
    assert workspace.packages["robot"].path == str(source)
    assert workspace.launch_files == [str(kept)]
    assert codes(workspace) == ["workspace-outputs-skipped"]
    [note] = workspace.diagnostics
    assert note.severity is Severity.NOTE and note.location.file == str(ws)
    assert note.message.startswith(", ".join(f"{o}/" for o in sorted(outputs)))


def test_only_a_workspace_root_skips_such_folders(tmp_path: Path) -> None:
    """A package's own ``build`` or ``log`` folder, or a folder named ``install`` where there
    is no ``src`` beside it, is read as any other."""
    install = make_package(tmp_path / "install" / "share" / "tool", "tool")
    write(install / "launch" / "tool.launch")
    pkg = make_package(tmp_path / "pkgs" / "p", "p")
    inner = write(pkg / "log" / "log.launch")
    workspace = discover([tmp_path], ros_package_path="")
    assert set(workspace.packages) == {"tool", "p"}
    assert str(inner) in workspace.launch_files
    marked = tmp_path / "ws"
    (marked / "src").mkdir(parents=True)
    write(marked / ".catkin_workspace", "")
    make_package(marked / "install" / "share" / "q", "q")
    assert "q" not in discover([marked], ros_package_path="").packages
