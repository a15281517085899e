"""Workspace discovery: which ROS packages exist and which launch files to analyse.

``$(find pkg)`` and ``<include>`` only mean something relative to a set of packages, so
the crawl follows rospkg's rules (a ``package.xml`` makes a directory a package and
ends the search for packages below it; ``CATKIN_IGNORE`` and hidden directories are
skipped) while still listing the launch files that live inside packages. At the root of a
catkin or colcon workspace (a ``src`` folder beside its build's outputs), the outputs
(``build``, ``devel``, ``install``, ``log``) are skipped: their copies of the packages are
the source's, built at some time, and a stale ``install/share`` copy replaced the one in
``src``.

A workspace is ROS 1 or ROS 2 (:mod:`rosvar.workspace.ros_version`): its packages' build
tools decide, and with them which files are launch files (:mod:`rosvar.workspace.launch_files`).
ROS 2's installed packages are found through ``AMENT_PREFIX_PATH`` (``<prefix>/share/<pkg>``);
a ROS 2 source package's folder stands for its share folder, read through its install
rules (:mod:`rosvar.workspace.share`).
"""

from __future__ import annotations

import os
from collections.abc import Collection, Sequence
from dataclasses import dataclass, field

from rosvar.diagnostics import Diagnostic, DiagnosticSink, Location
from rosvar.files import Confinement, read_file
from rosvar.frontends.xml import parse_xml_file
from rosvar.ros.version import RosVersion
from rosvar.workspace.launch_files import PACKAGE_FILE, LaunchFormat, format_of, launch_format
from rosvar.workspace.paths import real_path
from rosvar.workspace.ros_version import VERSION_TAGS, majority, package_version
from rosvar.workspace.share import ShareMap, share_map

EXECUTABLES_FILE = ".executables"
IGNORE_MARKERS = ("CATKIN_IGNORE", "rospack_nosubdirs", "COLCON_IGNORE", "AMENT_IGNORE")
SHARE_FOLDER = "share"
_MANIFEST_TAGS = frozenset({"name", *VERSION_TAGS})
"""The elements of a ``package.xml`` discovery reads: the name and the ROS it is for."""
SOURCE_FOLDER = "src"
BUILD_OUTPUTS = ("build", "devel", "install", "log")
"""What catkin_make, catkin build and colcon write beside a workspace's ``src``."""
WORKSPACE_MARKERS = (".catkin_workspace", ".catkin_tools", ".colcon")
"""Files or folders that make a directory a workspace root even before a build."""


@dataclass(frozen=True)
class Package:
    """A ROS package: its name (from ``package.xml``), directory, known executables and the
    ROS its build tool belongs to (None: it names neither catkin nor ament)."""

    name: str
    path: str
    executables: frozenset[str] | None
    ros_version: RosVersion | None = None


@dataclass
class Workspace:
    """The packages a launch file can refer to, and the launch files to analyse."""

    roots: list[str]
    packages: dict[str, Package]
    launch_files: list[str]
    diagnostics: list[Diagnostic]
    # Packages hidden by an earlier one of the same name: $(find) never returns them,
    # but files inside them still belong to them.
    shadowed: list[Package] = field(default_factory=list)
    # ROS_PACKAGE_PATH's directories: with the roots and the packages, what may be read.
    dependency_roots: list[str] = field(default_factory=list)
    allow_outside: bool = False
    ros_version: RosVersion = RosVersion.ROS1

    def __post_init__(self) -> None:
        # Packages by directory, rebuilt when packages are added (so that a hand-built
        # Workspace works too); not fields, since they are only a cache.
        self._index: dict[str, Package] = {}
        self._indexed = -1
        self._confinement: Confinement | None = None
        self._confinement_key: tuple[int, int, int, int, bool] = (0, 0, 0, 0, False)
        self._shares: dict[str, ShareMap] = {}  # by package folder, read on first use

    def confinement(self) -> Confinement:
        """The directories the analysis may read files in (``file-outside-workspace``): the
        given ones (a given file's own), the packages, ROS_PACKAGE_PATH's."""
        # asked at every include and load: the key is counted, the packages listed on change
        key = (
            len(self.roots),
            len(self.packages),
            len(self.shadowed),
            len(self.dependency_roots),
            self.allow_outside,
        )
        if self._confinement is None or self._confinement_key != key:
            packages = [*self.packages.values(), *self.shadowed]
            given = [r if os.path.isdir(r) else os.path.dirname(r) for r in self.roots]
            directories = [*given, *self.dependency_roots, *(p.path for p in packages)]
            installed = self.installed if self.ros_version is RosVersion.ROS2 else None
            self._confinement = Confinement.of(directories, self.allow_outside, installed)
            self._confinement_key = key
        return self._confinement

    def find(self, name: str) -> str | None:
        """Directory of package ``name``; ``None`` leaves unknown packages to the caller."""
        package = self.packages.get(name)
        return package.path if package is not None else None

    def find_share(self, name: str) -> str | None:
        """ROS 2's share directory of package ``name`` (``$(find-pkg-share)``): the
        installed ``<prefix>/share/<pkg>``, or for a source package its own folder, which
        holds what ``colcon build`` installs there (launch files, parameter files)."""
        return self.find(name)

    def installed(self, path: str) -> str:
        """The file ``path`` names when a ROS 2 source package's folder stands for its share
        folder: ``path`` itself if it exists (the common ``install(DIRECTORY launch ...)``
        keeps the source's layout; the rules are read only for a path not found), else the
        source its install rules copy to that place of the share, else ``path`` (as for an
        installed package, or a ROS 1 one, whose ``$(find)`` is its source)."""
        if self.ros_version is not RosVersion.ROS2 or os.path.exists(path):
            return path
        share = self.share_of(path)
        if share is None:
            return path
        package, shared = share
        relative = os.path.relpath(os.path.abspath(path), package.path)
        found = shared.source(relative) if relative != "." else None
        return path if found is None else found

    def share_of(self, path: str) -> tuple[Package, ShareMap] | None:
        """The ROS 2 source package whose folder holds ``path`` and its share map (read on
        first use); None for a path outside one."""
        if self.ros_version is not RosVersion.ROS2:
            return None
        package = self.package_of(path)
        if package is None or _install_prefix(package) is not None:
            return None
        shared = self._shares.get(package.path)
        if shared is None:
            shared = self._shares[package.path] = share_map(package.path, package.name)
        return package, shared

    def find_prefix(self, name: str) -> str | None:
        """ROS 2's install prefix of package ``name`` (``$(find-pkg-prefix)``); None for an
        unknown package or a source package, which has no install space yet."""
        package = self.packages.get(name)
        return None if package is None else _install_prefix(package)

    def of_dependency(self, path: str) -> bool:
        """Whether ``path`` is a dependency's file (below ``--deps``, ROS_PACKAGE_PATH or an
        AMENT_PREFIX_PATH share), not one of the user's paths: a dependency is read from its
        sources, where an installed file may be a build's product (``gz_sim.launch.py`` of
        a ``.in`` template), so what rosvar cannot read of it is rosvar's gap, not the
        user's mistake."""
        absolute = os.path.abspath(path)

        def below(roots: Sequence[str]) -> bool:
            return any(absolute == r or absolute.startswith(r + os.sep) for r in roots)

        return below(self.dependency_roots) and not below(self.roots)

    def launch_format(self, path: str) -> LaunchFormat:
        """The frontend that reads launch file ``path`` in this workspace's ROS."""
        return format_of(path, self.ros_version)

    def package_of(self, path: str | os.PathLike[str]) -> Package | None:
        """The innermost package whose directory contains ``path`` (symlinks resolved last)."""
        index = self._path_index()
        absolute = os.path.abspath(os.fspath(path))
        found = _innermost(index, absolute)
        if found is None:
            real = os.path.realpath(absolute)
            if real != absolute:
                found = _innermost(index, real)
        return found

    def find_resource(self, package: str, name: str) -> list[str] | None:
        """Files called ``name`` anywhere below ``package`` (None: no such package).

        roslaunch's ``roslaunch PKG FILE`` looks the file up this way (roslib's
        ``find_resource``): by file name, symlinks followed, hidden folders skipped.
        """
        directory = self.find(package)
        if directory is None:
            return None
        found = []
        for folder, subfolders, files in os.walk(directory, followlinks=True):
            if name in files:
                found.append(os.path.abspath(os.path.join(folder, name)))
            subfolders[:] = [d for d in subfolders if not d.startswith(".")]
        return found

    def _path_index(self) -> dict[str, Package]:
        size = len(self.packages) + len(self.shadowed)
        if size != self._indexed:
            self._index = {package.path: package for package in self.shadowed}
            self._index.update((package.path, package) for package in self.packages.values())
            self._indexed = size
        return self._index


def _install_prefix(package: Package) -> str | None:
    """The install prefix of an installed package (``<prefix>/share/<pkg>``), else None."""
    share = os.path.dirname(package.path)
    if os.path.basename(share) != SHARE_FOLDER or os.path.basename(package.path) != package.name:
        return None
    return os.path.dirname(share)


def _innermost(index: dict[str, Package], path: str) -> Package | None:
    current = path
    while True:
        package = index.get(current)
        if package is not None:
            return package
        parent = os.path.dirname(current)
        if parent == current:
            return None
        current = parent


def _read_executables(directory: str) -> frozenset[str] | None:
    path = os.path.join(directory, EXECUTABLES_FILE)
    try:
        data = read_file(path, real=real_path(path))  # its folder resolved already
    except OSError:
        return None
    lines = data.decode("utf-8", errors="replace").splitlines()
    return frozenset(line.strip() for line in lines if line.strip())


class _Discovery:
    """Mutable state of one :func:`discover` call."""

    def __init__(self) -> None:
        self.sink = DiagnosticSink()
        self.packages: dict[str, Package] = {}
        self.shadowed: list[Package] = []
        self.package_dirs: set[str] = set()
        # Launch files as each ROS would see them: which one applies is known at the end.
        self.launch_files: dict[RosVersion, set[str]] = {version: set() for version in RosVersion}
        self.given: set[str] = set()  # files given as paths: launch files of either ROS

    def add_package(self, directory: str, files: Collection[str] | None = None) -> None:
        """Register the package in ``directory``; ``files``: the directory's files, where
        the crawl listed them (a package without an executables file, most of them, is
        not asked for one)."""
        real = real_path(directory)
        if real in self.package_dirs:
            return  # reached twice (overlapping roots, or a root also on ROS_PACKAGE_PATH)
        self.package_dirs.add(real)
        manifest = os.path.join(directory, PACKAGE_FILE)
        name, version = self._read_manifest(manifest, directory)
        listed = files is None or EXECUTABLES_FILE in files
        executables = _read_executables(directory) if listed else None
        package = Package(name, directory, executables, version)
        first = self.packages.get(name)
        if first is None:
            self.packages[name] = package
            return
        self.shadowed.append(package)
        self.sink.warning(
            "package-duplicate",
            f"package '{name}' is also at {first.path}; that first one is used",
            Location(manifest),
        )

    def _read_manifest(self, manifest: str, directory: str) -> tuple[str, RosVersion | None]:
        """The package's name and ROS; a broken manifest gives the folder's name."""
        fallback = os.path.basename(directory)
        # its folder resolved already; only what is read here built (Husky: 1 in 4 elements)
        result = parse_xml_file(manifest, real_path, _MANIFEST_TAGS)
        root = result.root
        problem: str
        location = Location(manifest)
        if root is None:
            diagnostic = result.diagnostics[0]
            problem, location = diagnostic.message, diagnostic.location
        elif root.tag != "package":
            problem, location = f"root element is <{root.tag}>, not <package>", root.location
        else:
            for child in root.children:
                if child.tag == "name":
                    name = child.text.strip(" \n\r\t")
                    if name:
                        return name, package_version(root)
                    problem, location = "<name> is empty", child.location
                    break
            else:
                problem = "no <name> element"
        self.sink.warning(
            "package-xml-invalid",
            f"cannot read the package name ({problem}); using the directory name '{fallback}'",
            location,
        )
        return fallback, None

    def enclosing_package(self, directory: str) -> bool:
        """Register the package holding ``directory`` (itself included), if any."""
        current = directory
        while True:
            if os.path.isfile(os.path.join(current, PACKAGE_FILE)):
                self.add_package(current)
                return True
            parent = os.path.dirname(current)
            if parent == current:
                return False
            current = parent

    def crawl(self, top: str, *, list_launch: bool, inside_package: bool) -> None:
        """Walk ``top`` for packages and, when ``list_launch``, for launch files."""
        in_package: set[str] = {top} if inside_package else set()

        def unreadable(error: OSError) -> None:
            self.sink.warning(
                "path-unreadable",
                f"cannot list directory: {error.strerror or error}",
                Location(error.filename or top),
            )

        for dirpath, dirnames, filenames in os.walk(top, onerror=unreadable):
            if any(marker in filenames for marker in IGNORE_MARKERS):
                dirnames.clear()
                continue
            inside = dirpath in in_package
            if not inside and PACKAGE_FILE in filenames:
                self.add_package(dirpath, filenames)
                inside = True
            if not inside and _workspace_root(dirnames, filenames):
                outputs = sorted(set(BUILD_OUTPUTS) & set(dirnames))
                dirnames[:] = [name for name in dirnames if name not in BUILD_OUTPUTS]
                if outputs:
                    self.sink.note(
                        "workspace-outputs-skipped",
                        f"{', '.join(f'{o}/' for o in outputs)} of this workspace skipped: "
                        f"its packages are read from {SOURCE_FOLDER}/",
                        Location(dirpath),
                    )
            if inside and not list_launch:
                dirnames.clear()  # rospkg: a package is a leaf
                continue
            dirnames[:] = sorted(name for name in dirnames if not name.startswith("."))
            if inside:
                in_package.update(os.path.join(dirpath, name) for name in dirnames)
            if list_launch:
                for name in filenames:
                    for version, found in self.launch_files.items():
                        if launch_format(dirpath, name, version) is not None:
                            found.add(os.path.join(dirpath, name))

    def add_prefix(self, prefix: str) -> str | None:
        """Register the packages installed in ament prefix ``prefix``; its share folder."""
        share = os.path.join(prefix, SHARE_FOLDER)
        try:
            names = sorted(os.listdir(share))
        except OSError:
            return None
        for name in names:
            if os.path.isfile(os.path.join(share, name, PACKAGE_FILE)):
                self.add_package(os.path.join(share, name))
        return share

    def ros_version(self, own: list[Package]) -> RosVersion:
        """The ROS of ``own`` packages; without packages that tell, the launch files' kinds."""
        decided = majority(p.ros_version for p in own if p.ros_version is not None)
        if decided is not None:
            return decided
        ros1, ros2 = self.launch_files[RosVersion.ROS1], self.launch_files[RosVersion.ROS2]
        # A given file votes by its extension: roslaunch reads only XML.
        given_ros2 = {p for p in self.given if format_of(p, RosVersion.ROS2) != LaunchFormat.XML}
        ros2_only = (ros2 - ros1) | given_ros2
        return RosVersion.ROS2 if ros2_only and not ros1 - ros2 else RosVersion.ROS1

    def refuse_mixed(self, own: list[Package], version: RosVersion) -> set[str]:
        """Report ``own`` packages of the other ROS (an error: a workspace is one or the
        other); their directories, whose launch files are left out."""
        others = [p for p in own if p.ros_version not in (None, version)]
        if not others:
            return set()
        names = ", ".join(sorted(p.name for p in others)[:5])
        more = f" and {len(others) - 5} more" if len(others) > 5 else ""
        self.sink.error(
            "workspace-mixed",
            f"the workspace mixes ROS 1 and ROS 2 packages; it is read as {version.label} "
            f"(most of its packages), and the launch files of the other packages ({names}"
            f"{more}) are left out",
            Location(os.path.join(others[0].path, PACKAGE_FILE)),
        )
        return {p.path for p in others}


def _workspace_root(dirnames: Sequence[str], filenames: Sequence[str]) -> bool:
    """Whether a directory is a catkin or colcon workspace's root: a ``src`` folder beside
    a build's outputs or a workspace tool's marker."""
    if SOURCE_FOLDER not in dirnames:
        return False
    present = {*dirnames, *filenames}
    return any(name in present for name in (*BUILD_OUTPUTS, *WORKSPACE_MARKERS))


def discover(
    paths: Sequence[str | os.PathLike[str]],
    *,
    deps: Sequence[str | os.PathLike[str]] = (),
    ros_package_path: str | None = None,
    ament_prefix_path: str | None = None,
    allow_outside: bool = False,
) -> Workspace:
    """Find packages and launch files below ``paths``, then packages below ``deps``, on
    ROS_PACKAGE_PATH and in AMENT_PREFIX_PATH's prefixes.

    A path may be a directory or a single launch file (listed as given, with its
    enclosing package registered). ``deps`` (a sourced ROS installation's ``share``, an
    underlay), ``ros_package_path`` and ``ament_prefix_path`` (default: the environment's)
    play the same part: their packages come after the roots', in that order, and
    contribute no launch files. Files outside the roots, the packages, the deps and those
    paths are not read unless ``allow_outside``.
    """
    state = _Discovery()
    roots = [os.path.abspath(os.fspath(path)) for path in paths]
    for root in roots:
        if os.path.isdir(root):
            inside = state.enclosing_package(root)
            state.crawl(root, list_launch=True, inside_package=inside)
        elif os.path.exists(root):
            for found in state.launch_files.values():
                found.add(root)
            state.given.add(root)
            state.enclosing_package(os.path.dirname(root))
        else:
            state.sink.error("path-missing", f"no such file or directory: {root}", Location(root))
    own = [*state.packages.values(), *state.shadowed]  # the user's: they decide the ROS

    dependency_roots = []
    for dep in deps:
        directory = os.path.abspath(os.path.expanduser(os.fspath(dep)))
        if os.path.isdir(directory):
            dependency_roots.append(directory)
            state.crawl(directory, list_launch=False, inside_package=False)
        else:
            state.sink.error("path-missing", f"no such directory: {directory}", Location(directory))
    if ros_package_path is None:
        ros_package_path = os.environ.get("ROS_PACKAGE_PATH", "")
    for entry in ros_package_path.split(os.pathsep):
        if not entry.strip():
            continue
        directory = os.path.abspath(os.path.expanduser(entry))
        if os.path.isdir(directory):
            dependency_roots.append(directory)
            state.crawl(directory, list_launch=False, inside_package=False)
    if ament_prefix_path is None:
        ament_prefix_path = os.environ.get("AMENT_PREFIX_PATH", "")
    for entry in ament_prefix_path.split(os.pathsep):
        if entry.strip():
            share = state.add_prefix(os.path.abspath(os.path.expanduser(entry)))
            if share is not None:
                dependency_roots.append(share)

    version = state.ros_version(own)
    left_out = state.refuse_mixed(own, version)
    workspace = Workspace(
        roots=roots,
        packages=state.packages,
        launch_files=sorted(state.launch_files[version]),
        diagnostics=state.sink.items,
        shadowed=state.shadowed,
        dependency_roots=dependency_roots,
        allow_outside=allow_outside,
        ros_version=version,
    )
    if left_out:
        workspace.launch_files = [
            path
            for path in workspace.launch_files
            if (owner := workspace.package_of(path)) is None or owner.path not in left_out
        ]
    return workspace
