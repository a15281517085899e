"""Which sources make which executable: the targets a package's CMake files declare.

The language itself (variables, ``foreach``, the workspace's functions and macros,
``include``, ``add_subdirectory``) is run by :mod:`rosvar.workspace.interfaces.cmake_script`;
this module reads what its commands declare: targets (:data:`TARGET_COMMANDS`: CMake's own,
ament_cmake_auto's, catkin_simple's, rosbuild's, FindCUDA's), ``target_link_libraries`` (a
library of the same package brings its sources along), ``include_directories``, a target's
``OUTPUT_NAME`` (the name ``rosrun`` and launch files use), the ``PROGRAMS`` of
``catkin_install_python``/``install``, the scripts ``catkin_python_setup`` installs from
``setup.py``, the executable ``rclcpp_components_register_node(... EXECUTABLE name)``
makes of a component, and what ``install(DIRECTORY|FILES ...)`` and ament_cmake_auto's
``ament_auto_package(INSTALL_TO_SHARE ...)`` copy into the package's share folder
(:mod:`rosvar.workspace.share` maps ``$(find-pkg-share)`` paths back to those sources).
A function or macro another package of the workspace defines in its CMake extras
(``cmake/*.cmake``) is known once ``find_package`` names that package, as CMake's package
configuration would load it.
"""

from __future__ import annotations

import enum
import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from rosvar.diagnostics import Diagnostic, DiagnosticSink, Severity
from rosvar.workspace.interfaces.cmake_script import CMAKE_FILE, Command, Script
from rosvar.workspace.interfaces.reading import SourceReader
from rosvar.workspace.python_setup import setup_scripts

__all__ = ["CMAKE_FILE", "Build", "Shared", "Target", "TargetKind", "read_build"]

_TARGET_OPTIONS = frozenset(
    {"WIN32", "MACOSX_BUNDLE", "EXCLUDE_FROM_ALL", "STATIC", "SHARED", "MODULE", "OBJECT"}
)
_SKIPPED_LIBRARIES = frozenset({"IMPORTED", "ALIAS", "INTERFACE"})
_AUTO_OPTIONS = frozenset({"NO_TARGET_LINK_LIBRARIES", "NO_TARGET_LINK_DEPENDENCIES"})
"""ament_cmake_auto's flags; its ``DIRECTORY dir`` adds the folder's sources."""
_LINK_KEYWORDS = frozenset({"PUBLIC", "PRIVATE", "INTERFACE", "debug", "optimized", "general"})
_INSTALL_KEYWORDS = frozenset(
    {"DESTINATION", "PERMISSIONS", "CONFIGURATIONS", "COMPONENT", "RENAME", "OPTIONAL"}
)
_INSTALL_KINDS = frozenset({"DIRECTORY", "FILES", "PROGRAMS"})
"""The ``install`` signatures that copy files named by path (not targets)."""
_DIRECTORY_OPTIONS = frozenset(
    {
        "FILE_PERMISSIONS",
        "DIRECTORY_PERMISSIONS",
        "USE_SOURCE_PERMISSIONS",
        "FILES_MATCHING",
        "PATTERN",
        "REGEX",
        "MESSAGE_NEVER",
        "EXCLUDE_FROM_ALL",
        "TYPE",
        *_INSTALL_KEYWORDS,
    }
)
"""Where the paths of ``install(DIRECTORY|FILES ...)`` end."""
SHARE_FOLDER = "share"
INSTALL_UNREAD = "install-unread"
_SOURCE_SUFFIXES = (".cpp", ".cc", ".cxx", ".c++", ".c", ".h", ".hpp", ".hh", ".hxx")
"""What CMake appends to a source named without its suffix (``add_executable(x src/x)``);
also what ament_cmake_auto's ``DIRECTORY`` collects."""
_EXTRAS_FOLDER = "cmake"
_INSTALL_DIRS = {
    "CMAKE_INSTALL_DATADIR": SHARE_FOLDER,
    "CMAKE_INSTALL_BINDIR": "bin",
    "CMAKE_INSTALL_LIBDIR": "lib",
    "CMAKE_INSTALL_INCLUDEDIR": "include",
}
"""GNUInstallDirs' folders relative to the install prefix, as ament's builds have them."""
COMPONENT_COMMAND = "rclcpp_components_register_node"


class TargetKind(enum.StrEnum):
    EXECUTABLE = "executable"
    LIBRARY = "library"


@dataclass(frozen=True)
class TargetCommand:
    """A command that declares a target: its kind, and the keyword after which its
    arguments are no longer sources (FindCUDA's ``OPTIONS``)."""

    kind: TargetKind
    end: str | None = None


TARGET_COMMANDS: dict[str, TargetCommand] = {
    "add_executable": TargetCommand(TargetKind.EXECUTABLE),
    "add_library": TargetCommand(TargetKind.LIBRARY),
    "ament_auto_add_executable": TargetCommand(TargetKind.EXECUTABLE),
    "ament_auto_add_library": TargetCommand(TargetKind.LIBRARY),
    "cs_add_executable": TargetCommand(TargetKind.EXECUTABLE),  # catkin_simple
    "cs_add_library": TargetCommand(TargetKind.LIBRARY),
    "rosbuild_add_executable": TargetCommand(TargetKind.EXECUTABLE),
    "rosbuild_add_library": TargetCommand(TargetKind.LIBRARY),
    "cuda_add_executable": TargetCommand(TargetKind.EXECUTABLE, end="OPTIONS"),
    "cuda_add_library": TargetCommand(TargetKind.LIBRARY, end="OPTIONS"),
}
"""The commands that declare a target: CMake's own and the known wrappers of other tools
(a workspace's own wrappers are expanded before they reach this table)."""


@dataclass
class Target:
    """A build target with its source files (absolute paths) and the targets it links."""

    name: str
    kind: TargetKind
    sources: list[str]
    links: list[str] = field(default_factory=list)
    output_name: str | None = None
    plugin: str | None = None  # a component's executable runs this class (``ns::Class``)

    @property
    def installed_name(self) -> str:
        """The file name the target builds: ``OUTPUT_NAME`` when set."""
        return self.output_name or self.name


@dataclass(frozen=True)
class Shared:
    """A file or folder an install rule copies into the package's share folder: its source
    (absolute; a folder named with a trailing ``/`` gives its contents), where it lands
    relative to ``share/<package>`` ("" is the folder itself), and for a folder the
    ``PATTERN`` globs its files must match (none: all) and those it leaves out."""

    source: str
    destination: str
    contents: bool = False
    patterns: tuple[str, ...] = ()
    excluded: tuple[str, ...] = ()


@dataclass
class Build:
    """What a package's CMake files declare."""

    targets: dict[str, Target] = field(default_factory=dict)
    programs: list[str] = field(default_factory=list)
    include_dirs: list[str] = field(default_factory=list)
    # Targets named with a variable this reader does not know (set by a parent project, a
    # toolchain): their names here are guesses, not executables to offer.
    vague_names: set[str] = field(default_factory=set)
    shared: list[Shared] = field(default_factory=list)
    # Install rules that may copy into the share folder but name a variable not known here.
    unread_installs: list[Diagnostic] = field(default_factory=list)

    def sources(self, name: str) -> list[str]:
        """The sources of target ``name`` and of the package's libraries it links."""
        found: list[str] = []
        pending, seen = [name], set()
        while pending:
            current = pending.pop(0)
            target = self.targets.get(current)
            if target is None or current in seen:
                continue
            seen.add(current)
            found.extend(s for s in target.sources if s not in found)
            pending.extend(target.links)
        return found


class _Reader:
    """The handler of the commands the language leaves to it: what declares targets."""

    def __init__(
        self, package_dir: str, package_name: str, extras: Mapping[str, list[str]]
    ) -> None:
        self.root = package_dir
        self.package = package_name
        self.build = Build()
        self.extras = extras
        self.script: Script | None = None

    def command(self, command: Command, words: list[str], directory: str) -> None:
        handler = _HANDLERS.get(command.name)
        if handler is not None:
            handler(self, command, words, directory)
        elif command.name in TARGET_COMMANDS and words:
            self.target(command, words, directory)

    def target(self, command: Command, words: list[str], directory: str) -> None:
        declaring = TARGET_COMMANDS[command.name]
        if _SKIPPED_LIBRARIES & set(words[1:2]):
            return
        arguments = words[1:]
        if declaring.end is not None and declaring.end in arguments:
            arguments = arguments[: arguments.index(declaring.end)]
        sources: list[str] = []
        folder_next = False
        for word in arguments:
            if word == "DIRECTORY":
                folder_next = True
            elif folder_next:
                sources.extend(_folder_sources(os.path.join(directory, word)))
                folder_next = False
            elif word not in _TARGET_OPTIONS and word not in _AUTO_OPTIONS:
                sources.append(_source(directory, word))
        declared = Target(words[0], declaring.kind, [])
        self.build.targets.setdefault(words[0], declared).sources.extend(sources)
        if self.script is not None and not self.script.known(command.arguments[0]):
            self.build.vague_names.add(words[0])

    def share(self, command: Command, words: list[str], directory: str) -> None:
        """What ``install(DIRECTORY|FILES|PROGRAMS paths... DESTINATION share/<package>[/sub]
        ...)`` copies into the share folder; a rule whose paths or destination name a
        variable not known here is told (it may be one)."""
        at = words.index("DESTINATION") if "DESTINATION" in words else len(words)
        destination = os.path.normpath(words[at + 1]).lstrip("/") if at + 1 < len(words) else ""
        share = f"{SHARE_FOLDER}/{self.package}"
        sub = _below(destination, share)
        unknown = self.script is not None and not all(map(self.script.known, command.arguments))
        if unknown and (sub is not None or destination in ("", ".")):
            self.build.unread_installs.append(
                Diagnostic(
                    INSTALL_UNREAD,
                    Severity.WARNING,
                    f"{command.name}({' '.join(command.arguments)[:120]}) names a variable "
                    "rosvar does not know: the files it puts in the share folder are looked "
                    "for at the same path in the source package",
                    command.location(),
                )
            )
            return
        if sub is None:
            return
        paths: list[str] = []
        for word in words[1:]:
            if word in _DIRECTORY_OPTIONS:
                break
            paths.append(word)
        if words[0] == "DIRECTORY":
            patterns, excluded = _patterns(words)
            for path in paths:
                source = os.path.normpath(os.path.join(directory, path))
                contents = path.endswith("/")
                landing = sub if contents else os.path.join(sub, os.path.basename(source))
                self.build.shared.append(Shared(source, landing, contents, patterns, excluded))
            return
        rename = words.index("RENAME") + 1 if "RENAME" in words else len(words)
        for path in paths:
            source = os.path.normpath(os.path.join(directory, path))
            name = words[rename] if rename < len(words) else os.path.basename(source)
            self.build.shared.append(Shared(source, os.path.join(sub, name)))

    def find_package(self, _: Command, words: list[str], __: str) -> None:
        """``find_package(pkg)`` (or a catkin ``COMPONENTS`` list) loads the CMake extras of
        a workspace package: only their functions and macros are taken."""
        for name in words:
            for path in self.extras.get(name, ()):
                if self.script is not None:
                    self.script.define_from(path)


def _register_component(reader: _Reader, _: Command, words: list[str], __: str) -> None:
    """``rclcpp_components_register_node(lib PLUGIN "ns::Class" EXECUTABLE name)``: the
    executable runs the component library's plugin, its sources are the library's."""
    if "EXECUTABLE" not in words[1:-1]:
        return
    executable = words[words.index("EXECUTABLE", 1) + 1]
    plugin = words[words.index("PLUGIN") + 1].strip('"') if "PLUGIN" in words[1:-1] else None
    component = Target(executable, TargetKind.EXECUTABLE, [], links=[words[0]], plugin=plugin)
    reader.build.targets.setdefault(executable, component)


def _link(reader: _Reader, _: Command, words: list[str], __: str) -> None:
    target = reader.build.targets.get(words[0]) if words else None
    if target is not None:
        target.links.extend(w for w in words[1:] if w not in _LINK_KEYWORDS)


def _properties(reader: _Reader, _: Command, words: list[str], __: str) -> None:
    if "PROPERTIES" not in words:
        return
    split = words.index("PROPERTIES")
    properties = dict(zip(words[split + 1 :: 2], words[split + 2 :: 2], strict=False))
    for word in words[:split]:
        target = reader.build.targets.get(word)
        if target is not None and "OUTPUT_NAME" in properties:
            target.output_name = properties["OUTPUT_NAME"]


def _include_directories(reader: _Reader, _: Command, words: list[str], directory: str) -> None:
    for word in words:
        if word not in ("BEFORE", "AFTER", "SYSTEM"):
            reader.build.include_dirs.append(os.path.normpath(os.path.join(directory, word)))


def _install(reader: _Reader, command: Command, words: list[str], directory: str) -> None:
    """``install``: the programs it installs, and what it copies into the share folder."""
    _programs(reader, command, words, directory)
    if words[:1] and words[0] in _INSTALL_KINDS:
        reader.share(command, words, directory)


def _auto_package(reader: _Reader, _: Command, words: list[str], directory: str) -> None:
    """``ament_auto_package(INSTALL_TO_SHARE folder...)`` installs each folder into the
    share folder (as ``install(DIRECTORY folder DESTINATION share/${PROJECT_NAME})``)."""
    if "INSTALL_TO_SHARE" not in words:
        return
    for word in words[words.index("INSTALL_TO_SHARE") + 1 :]:
        if word.isupper():  # the next keyword (INSTALL_TO_PATH, USE_SCOPED_HEADER_...)
            break
        source = os.path.normpath(os.path.join(directory, word))
        reader.build.shared.append(Shared(source, os.path.basename(source)))


def _below(path: str, folder: str) -> str | None:
    """``path`` relative to ``folder`` ("" for the folder itself), None if not below it."""
    if path == folder:
        return ""
    return path[len(folder) + 1 :] if path.startswith(folder + "/") else None


def _patterns(words: list[str]) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """A folder rule's ``PATTERN glob`` options: those its files must match (with
    ``FILES_MATCHING``), and those ``EXCLUDE`` leaves out."""
    matching: list[str] = []
    excluded: list[str] = []
    for index, word in enumerate(words[:-1]):
        if word == "PATTERN":
            glob = words[index + 1]
            (excluded if "EXCLUDE" in words[index + 2 : index + 3] else matching).append(glob)
    return (tuple(matching) if "FILES_MATCHING" in words else ()), tuple(excluded)


def _programs(reader: _Reader, _: Command, words: list[str], directory: str) -> None:
    if words[:1] != ["PROGRAMS"]:
        return
    for word in words[1:]:
        if word in _INSTALL_KEYWORDS:
            break
        reader.build.programs.append(os.path.normpath(os.path.join(directory, word)))


def _python_setup(reader: _Reader, _: Command, __: list[str], directory: str) -> None:
    """``catkin_python_setup()`` installs the ``scripts`` of the package's ``setup.py``."""
    if reader.script is None:
        return
    text = reader.script.reader.text(os.path.join(directory, "setup.py"))
    for script in setup_scripts(text or ""):
        reader.build.programs.append(os.path.normpath(os.path.join(directory, script)))


_HANDLERS: dict[str, Callable[[_Reader, Command, list[str], str], None]] = {
    COMPONENT_COMMAND: _register_component,
    "target_link_libraries": _link,
    "set_target_properties": _properties,
    "include_directories": _include_directories,
    "install": _install,
    "ament_auto_package": _auto_package,
    "catkin_install_python": _programs,
    "catkin_python_setup": _python_setup,
    "find_package": _Reader.find_package,
}


def _source(directory: str, word: str) -> str:
    path = os.path.normpath(os.path.join(directory, word))
    if os.path.isfile(path):
        return path
    return next((path + s for s in _SOURCE_SUFFIXES if os.path.isfile(path + s)), path)


def _folder_sources(folder: str) -> list[str]:
    """The sources below ``folder``, as ament_cmake_auto's ``DIRECTORY`` globs them."""
    found: list[str] = []
    for root, dirs, files in os.walk(folder):
        dirs.sort()
        found.extend(os.path.join(root, f) for f in sorted(files) if f.endswith(_SOURCE_SUFFIXES))
    return found


def cmake_extras(package_dir: str) -> list[str]:
    """The CMake files a package exports to its dependents (``cmake/*.cmake``, the
    ``-extras.cmake.in`` ament and catkin configure)."""
    folder = os.path.join(package_dir, _EXTRAS_FOLDER)
    if not os.path.isdir(folder):
        return []
    return sorted(
        os.path.join(folder, name)
        for name in os.listdir(folder)
        if name.endswith((".cmake", ".cmake.in"))
    )


def read_build(
    package_dir: str,
    package_name: str,
    reader: SourceReader | None = None,
    extras: Mapping[str, list[str]] | None = None,
    sink: DiagnosticSink | None = None,
) -> Build:
    """The targets, Python programs and include folders of the package at ``package_dir``;
    ``extras``: the CMake extras of the workspace's packages, by package name."""
    root = os.path.abspath(package_dir)
    handler = _Reader(root, package_name, extras or {})
    script = Script(root, handler.command, reader or SourceReader(), sink)
    handler.script = script
    script.scopes.append(
        {
            "PROJECT_NAME": package_name,
            "PROJECT_SOURCE_DIR": root,
            "CMAKE_SOURCE_DIR": root,
            "CMAKE_CURRENT_SOURCE_DIR": root,
            "CMAKE_CURRENT_LIST_DIR": root,
            **_INSTALL_DIRS,
        }
    )
    script.run_file(os.path.join(root, CMAKE_FILE), root)
    return handler.build
