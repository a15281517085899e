"""Which sources make which executable: a small reader of a package's ``CMakeLists.txt``.

Only what decides targets and their sources is read: ``set``/``list(APPEND)`` variables and
``${VAR}`` expansion, ``file(GLOB)``, ``add_subdirectory``, ``add_executable``/``add_library``,
``target_link_libraries`` (a library of the same package brings its sources along),
``include_directories``, a target's ``OUTPUT_NAME`` (the name ``rosrun`` and launch files use)
and the ``PROGRAMS`` of ``catkin_install_python``/``install``; for ament packages also
``ament_auto_add_executable``/``ament_auto_add_library`` and the executable
``rclcpp_components_register_node(... EXECUTABLE name)`` makes of a component.
Conditions (``if``) are not evaluated: every branch's targets are kept, since any of them may
be the one built.
"""

from __future__ import annotations

import enum
import glob
import os
import re
from collections.abc import Iterator
from dataclasses import dataclass, field

from rosvar.workspace.interfaces.reading import read_text

CMAKE_FILE = "CMakeLists.txt"
_VARIABLE = re.compile(r"\$\{([^${}]*)\}")
_TARGET_OPTIONS = frozenset(
    {"WIN32", "MACOSX_BUNDLE", "EXCLUDE_FROM_ALL", "STATIC", "SHARED", "MODULE", "OBJECT"}
)
_SKIPPED_LIBRARIES = frozenset({"IMPORTED", "ALIAS", "INTERFACE"})
# ament_cmake_auto's keywords; its targets' sources may also come from a DIRECTORY glob.
_AUTO_OPTIONS = frozenset({"DIRECTORY", "NO_TARGET_LINK_LIBRARIES", "NO_TARGET_LINK_DEPENDENCIES"})
_LINK_KEYWORDS = frozenset({"PUBLIC", "PRIVATE", "INTERFACE", "debug", "optimized", "general"})
_INSTALL_KEYWORDS = frozenset(
    {"DESTINATION", "PERMISSIONS", "CONFIGURATIONS", "COMPONENT", "RENAME", "OPTIONAL"}
)
_SOURCE_SUFFIXES = (".cpp", ".cc", ".cxx", ".c++", ".c", ".h", ".hpp", ".hh", ".hxx")
"""What CMake appends to a source named without its suffix (``add_executable(x src/x)``)."""


class TargetKind(enum.StrEnum):
    EXECUTABLE = "executable"
    LIBRARY = "library"


# The commands that declare a target, and the kind they declare.
TARGET_COMMANDS: dict[str, TargetKind] = {
    "add_executable": TargetKind.EXECUTABLE,
    "add_library": TargetKind.LIBRARY,
    "ament_auto_add_executable": TargetKind.EXECUTABLE,
    "ament_auto_add_library": TargetKind.LIBRARY,
}
COMPONENT_COMMAND = "rclcpp_components_register_node"


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


@dataclass
class Build:
    """What a package's CMake files declare."""

    targets: dict[str, Target] = field(default_factory=dict)
    programs: list[str] = field(default_factory=list)
    include_dirs: list[str] = field(default_factory=list)
    # Targets named with a variable this reader does not know (set by a parent project, a
    # toolchain): their names here are guesses, not executables to offer.
    vague_names: set[str] = field(default_factory=set)

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


def commands(text: str) -> Iterator[tuple[str, list[str]]]:
    """The commands of a CMake file: lower-case name and raw arguments (quoted kept quoted)."""
    position, size = 0, len(text)
    while position < size:
        char = text[position]
        if char == "#":
            if text.startswith("#[[", position) or text.startswith("#[=", position):
                end = text.find("]]", position)
                position = size if end < 0 else end + 2
            else:
                end = text.find("\n", position)
                position = size if end < 0 else end
            continue
        match = re.compile(r"[A-Za-z_]\w*\s*\(").match(text, position)
        if match is None:
            position += 1
            continue
        name = match.group(0).split("(")[0].strip().lower()
        arguments, position = _arguments(text, match.end())
        yield name, arguments


def _arguments(text: str, position: int) -> tuple[list[str], int]:
    arguments: list[str] = []
    depth, current, size = 0, "", len(text)
    while position < size:
        char = text[position]
        if char == '"':
            end = position + 1
            while end < size and text[end] != '"':
                end += 2 if text[end] == "\\" else 1
            arguments.append(text[position : end + 1])
            position = end + 1
            continue
        if char == "#" and not current:
            end = text.find("\n", position)
            position = size if end < 0 else end
            continue
        if char == "(":
            depth += 1
        elif char == ")":
            if depth == 0:
                if current:
                    arguments.append(current)
                return arguments, position + 1
            depth -= 1
        if char.isspace() or char in "()":
            if current:
                arguments.append(current)
            current = ""
        else:
            current += char
        position += 1
    if current:
        arguments.append(current)
    return arguments, position


class _Reader:
    def __init__(self, package_dir: str, package_name: str) -> None:
        self.root = package_dir
        self.variables = {
            "PROJECT_NAME": package_name,
            "PROJECT_SOURCE_DIR": package_dir,
            "CMAKE_SOURCE_DIR": package_dir,
            "CMAKE_CURRENT_SOURCE_DIR": package_dir,
            "CMAKE_CURRENT_LIST_DIR": package_dir,
        }
        self.build = Build()
        self.visited: set[str] = set()

    def expand(self, word: str) -> list[str]:
        quoted = word.startswith('"')
        value = word[1:-1] if quoted else word
        for _ in range(32):  # nested ${A_${B}} expand inside out
            expanded = _VARIABLE.sub(lambda m: self.variables.get(m.group(1), ""), value)
            if expanded == value:
                break
            value = expanded
        if quoted:
            return [value]
        return [part for part in value.split(";") if part]

    def unknown_variable(self, word: str) -> bool:
        return any(name not in self.variables for name in _VARIABLE.findall(word))

    def read(self, directory: str) -> None:
        path = os.path.join(directory, CMAKE_FILE)
        real = os.path.realpath(path)
        if real in self.visited or not real.startswith(os.path.realpath(self.root)):
            return
        self.visited.add(real)
        text = read_text(path)
        if text is None:
            return
        saved = self.variables["CMAKE_CURRENT_SOURCE_DIR"]
        self.variables["CMAKE_CURRENT_SOURCE_DIR"] = directory
        self.variables["CMAKE_CURRENT_LIST_DIR"] = directory
        for name, raw in commands(text):
            words = [part for word in raw for part in self.expand(word)]
            self.command(name, words, directory)
            if name in TARGET_COMMANDS and words and self.unknown_variable(raw[0]):
                self.build.vague_names.add(words[0])
        self.variables["CMAKE_CURRENT_SOURCE_DIR"] = saved
        self.variables["CMAKE_CURRENT_LIST_DIR"] = saved

    def command(self, name: str, words: list[str], directory: str) -> None:
        if name == "project" and words:
            self.variables["PROJECT_NAME"] = words[0]
        elif name == "set" and words:
            values = [w for w in words[1:] if w not in ("CACHE", "PARENT_SCOPE")]
            if "CACHE" in words[1:]:
                values = words[1 : words.index("CACHE")]
            self.variables[words[0]] = ";".join(values)
        elif name == "list" and len(words) >= 2 and words[0] == "APPEND":
            old = self.variables.get(words[1], "")
            self.variables[words[1]] = ";".join([p for p in old.split(";") if p] + words[2:])
        elif name == "file" and len(words) >= 2 and words[0] in ("GLOB", "GLOB_RECURSE"):
            self.variables[words[1]] = ";".join(self.glob(words, directory))
        elif name == "add_subdirectory" and words:
            self.read(os.path.normpath(os.path.join(directory, words[0])))
        elif name in TARGET_COMMANDS and words:
            if _SKIPPED_LIBRARIES & set(words[1:2]):
                return
            sources = [
                _source(directory, w)
                for w in words[1:]
                if w not in _TARGET_OPTIONS and w not in _AUTO_OPTIONS
            ]
            declared = Target(words[0], TARGET_COMMANDS[name], [])
            self.build.targets.setdefault(words[0], declared).sources.extend(sources)
        elif name == COMPONENT_COMMAND and "EXECUTABLE" in words[1:-1]:
            # The executable runs the component library's plugin: its sources are the library's.
            executable = words[words.index("EXECUTABLE", 1) + 1]
            plugin = (
                words[words.index("PLUGIN") + 1].strip('"') if "PLUGIN" in words[1:-1] else None
            )
            component = Target(
                executable, TargetKind.EXECUTABLE, [], links=[words[0]], plugin=plugin
            )
            self.build.targets.setdefault(executable, component)
        elif name == "target_link_libraries" and words:
            target = self.build.targets.get(words[0])
            if target is not None:
                target.links.extend(w for w in words[1:] if w not in _LINK_KEYWORDS)
        elif name == "set_target_properties" and "PROPERTIES" in words:
            split = words.index("PROPERTIES")
            properties = dict(zip(words[split + 1 :: 2], words[split + 2 :: 2], strict=False))
            for word in words[:split]:
                target = self.build.targets.get(word)
                if target is not None and "OUTPUT_NAME" in properties:
                    target.output_name = properties["OUTPUT_NAME"]
        elif name == "include_directories":
            for word in words:
                if word not in ("BEFORE", "AFTER", "SYSTEM"):
                    self.build.include_dirs.append(os.path.normpath(os.path.join(directory, word)))
        elif name in ("catkin_install_python", "install") and words[:1] == ["PROGRAMS"]:
            for word in words[1:]:
                if word in _INSTALL_KEYWORDS:
                    break
                self.build.programs.append(os.path.normpath(os.path.join(directory, word)))

    def glob(self, words: list[str], directory: str) -> list[str]:
        rest = [w for w in words[2:] if w not in ("CONFIGURE_DEPENDS", "LIST_DIRECTORIES")]
        relative: str | None = None
        if rest[:1] == ["RELATIVE"] and len(rest) >= 2:
            relative, rest = rest[1], rest[2:]
        found: list[str] = []
        for pattern in rest:
            full = os.path.join(directory, pattern)
            if (
                words[0] == "GLOB_RECURSE"
            ):  # CMake's recursive glob descends from the pattern's folder
                folder, name = os.path.split(full)
                full = os.path.join(folder, "**", name)
            matches = glob.glob(full, recursive=True)
            for match in sorted(matches):
                found.append(os.path.relpath(match, relative) if relative else match)
        return found


def _source(directory: str, word: str) -> str:
    path = os.path.normpath(os.path.join(directory, word))
    if os.path.isfile(path):
        return path
    return next((path + s for s in _SOURCE_SUFFIXES if os.path.isfile(path + s)), path)


def read_build(package_dir: str, package_name: str) -> Build:
    """The targets, Python programs and include folders of the package at ``package_dir``."""
    reader = _Reader(os.path.abspath(package_dir), package_name)
    reader.read(reader.root)
    return reader.build
