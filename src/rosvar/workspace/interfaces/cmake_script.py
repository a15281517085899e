"""CMake's language, as far as reading a package's targets needs it.

The targets of a package are often declared through the language rather than written out:
a ``foreach`` over a list of node names, a ``function`` or ``macro`` of the workspace
around ``add_executable``, ``cmake_parse_arguments`` in such a wrapper, a module brought in
with ``include``. This module runs those constructs (variables and their scopes, functions,
macros, loops, ``include``, ``add_subdirectory``) and hands every other command, with its
arguments expanded, to the reader of targets (:mod:`rosvar.workspace.interfaces.cmake`).

Nothing is executed beyond that: ``if`` is not evaluated (the commands of every branch run,
since any of them may be the one built), ``while`` runs its body once, ``execute_process``
and the like are ignored. Hostile input stays bounded: calls nest at most
:data:`MAX_CALL_DEPTH` deep, at most :data:`MAX_COMMANDS` commands run per package, a loop
runs at most :data:`MAX_ITERATIONS` times and a value holds at most :data:`MAX_VALUE`
characters; each limit reached is one warning ``cmake-limit`` at its ``file:line``.
"""

from __future__ import annotations

import bisect
import enum
import glob
import os
import re
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field

from rosvar.diagnostics import DiagnosticSink, Location
from rosvar.workspace.interfaces.reading import SourceReader

CMAKE_FILE = "CMakeLists.txt"
MAX_CALL_DEPTH = 32
MAX_COMMANDS = 20_000
MAX_ITERATIONS = 10_000
MAX_VALUE = 1 << 20
_VARIABLE = re.compile(r"\$\{([^${}]*)\}")
_COMMAND = re.compile(r"[A-Za-z_]\w*\s*\(")
_NESTED_EXPANSIONS = 32
"""Rounds of ``${A_${B}}`` expanded inside out; a value that still holds ``${`` then stays."""


@dataclass(frozen=True)
class Command:
    """One command invocation: its lower-case name, its raw arguments (quoted ones keep their
    quotes), and the file and line it is written at."""

    name: str
    arguments: tuple[str, ...]
    file: str
    line: int

    def location(self) -> Location:
        return Location(self.file, self.line)


def commands(text: str, file: str = "") -> Iterator[Command]:
    """The commands of a CMake file, in order (comments and bracket comments skipped)."""
    newlines = [index for index, char in enumerate(text) if char == "\n"]
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
        match = _COMMAND.match(text, position)
        if match is None:
            position += 1
            continue
        line = bisect.bisect_left(newlines, position) + 1
        name = match.group(0).split("(")[0].strip().lower()
        arguments, position = _arguments(text, match.end())
        yield Command(name, tuple(arguments), file, line)


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


class DefinitionKind(enum.StrEnum):
    FUNCTION = "function"
    MACRO = "macro"


@dataclass(frozen=True)
class Definition:
    """A ``function`` or ``macro`` of the workspace: its parameters and body."""

    kind: DefinitionKind
    parameters: tuple[str, ...]
    body: tuple[Command, ...]


class _Exhausted(Exception):
    """The package's command budget is spent: reading stops where it is."""


Handler = Callable[[Command, list[str], str], None]
"""Receives each command the language does not handle itself: the command, its expanded
arguments and the directory of its file."""


@dataclass
class Script:
    """The state of one package's CMake run: variable scopes, definitions, the budget."""

    root: str
    handler: Handler
    reader: SourceReader
    sink: DiagnosticSink | None = None
    scopes: list[dict[str, str]] = field(default_factory=list)
    definitions: dict[str, Definition] = field(default_factory=dict)
    visited: set[str] = field(default_factory=set)
    budget: int = MAX_COMMANDS
    depth: int = 0
    _warned: set[str] = field(default_factory=set)

    @property
    def variables(self) -> dict[str, str]:
        return self.scopes[-1]

    def warn(self, limit: str, message: str, where: Command) -> None:
        """One ``cmake-limit`` warning per limit reached."""
        if self.sink is not None and limit not in self._warned:
            self._warned.add(limit)
            self.sink.warning("cmake-limit", message, where.location())

    # -- expansion -------------------------------------------------------------------------

    def expand(self, word: str, where: Command) -> list[str]:
        """``word`` with its ``${VAR}`` replaced: one word if quoted, else split at ``;``
        (a value grown over :data:`MAX_VALUE` is dropped, with a warning)."""
        quoted = word.startswith('"')
        value = word[1:-1] if quoted else word
        for _ in range(_NESTED_EXPANSIONS):
            expanded = _VARIABLE.sub(lambda m: self.variables.get(m.group(1), ""), value)
            if len(expanded) > MAX_VALUE:
                self.warn("value", f"a value over {MAX_VALUE} characters is dropped", where)
                expanded = ""
            if expanded == value:
                break
            value = expanded
        if quoted:
            return [value]
        return [part for part in value.split(";") if part]

    def expand_all(self, words: Sequence[str], where: Command) -> list[str]:
        return [part for word in words for part in self.expand(word, where)]

    def known(self, word: str) -> bool:
        """Whether every variable ``word`` names is set."""
        return all(name in self.variables for name in _VARIABLE.findall(word))

    def set(self, name: str, value: str, where: Command, parent: bool = False) -> None:
        if len(value) > MAX_VALUE:
            self.warn("value", f"a value over {MAX_VALUE} characters is dropped", where)
            value = ""
        scope = self.scopes[-2] if parent and len(self.scopes) > 1 else self.variables
        scope[name] = value

    # -- running ---------------------------------------------------------------------------

    def run_file(self, path: str, directory: str) -> None:
        """Run the commands of the CMake file ``path`` (once; within the package)."""
        real = os.path.realpath(path)
        if real in self.visited or not _below(real, os.path.realpath(self.root)):
            return
        self.visited.add(real)
        text = self.reader.text(path)
        if text is None:
            return
        try:
            self.run(list(commands(text, path)), directory)
        except _Exhausted:
            return

    def define_from(self, path: str) -> None:
        """Take the functions and macros of another package's CMake file (its CMake
        extras); nothing else of it runs."""
        real = os.path.realpath(path)
        if real in self.visited:
            return
        self.visited.add(real)
        listed = list(commands(self.reader.text(path) or "", path))
        index = 0
        while index < len(listed):
            command = listed[index]
            closing = _BLOCKS.get(command.name)
            if closing is None:
                index += 1
                continue
            body, index = _block(listed, index, command.name, closing)
            if command.name in ("function", "macro"):
                self._define(command, body)

    def run(self, listed: Sequence[Command], directory: str) -> None:
        index = 0
        while index < len(listed):
            command = listed[index]
            block = _BLOCKS.get(command.name)
            if block is None:
                self.execute(command, directory)
                index += 1
                continue
            body, index = _block(listed, index, command.name, block)
            if command.name in ("function", "macro"):
                self._define(command, body)
            elif command.name == "foreach":
                self._foreach(command, body, directory)
            else:  # while: its condition is not evaluated; its body runs once
                self.run(body, directory)

    def execute(self, command: Command, directory: str) -> None:
        self.budget -= 1
        if self.budget < 0:
            self.warn("commands", f"more than {MAX_COMMANDS} CMake commands: stopped", command)
            raise _Exhausted
        words = self.expand_all(command.arguments, command)
        definition = self.definitions.get(command.name)
        if definition is not None:
            self._call(definition, command, words, directory)
            return
        builtin = _BUILTINS.get(command.name)
        if builtin is not None:
            builtin(self, command, words, directory)
        else:
            self.handler(command, words, directory)

    def _define(self, command: Command, body: list[Command]) -> None:
        words = self.expand_all(command.arguments, command)
        if words:
            kind = DefinitionKind(command.name)
            self.definitions[words[0].lower()] = Definition(kind, tuple(words[1:]), tuple(body))

    def _call(
        self, definition: Definition, command: Command, words: list[str], directory: str
    ) -> None:
        if self.depth >= MAX_CALL_DEPTH:
            self.warn("depth", f"CMake calls nested over {MAX_CALL_DEPTH} deep: not run", command)
            return
        bound = {name: value for name, value in zip(definition.parameters, words, strict=False)}
        bound["ARGN"] = ";".join(words[len(definition.parameters) :])
        bound["ARGV"] = ";".join(words)
        bound["ARGC"] = str(len(words))
        bound.update((f"ARGV{index}", word) for index, word in enumerate(words))
        self.depth += 1
        try:
            if definition.kind is DefinitionKind.FUNCTION:
                self.scopes.append({**self.variables, **bound})
                try:
                    self.run(definition.body, directory)
                finally:
                    self.scopes.pop()
            else:  # a macro's parameters are replaced in its text, in the caller's scope
                self.run([_substitute(c, bound) for c in definition.body], directory)
        finally:
            self.depth -= 1

    def _foreach(self, command: Command, body: list[Command], directory: str) -> None:
        words = self.expand_all(command.arguments, command)
        if not words:
            return
        variable, items = words[0], _loop_items(self, words[1:])
        if len(items) > MAX_ITERATIONS:
            self.warn("loop", f"a loop over {MAX_ITERATIONS} items runs only the first", command)
            items = items[:MAX_ITERATIONS]
        for item in items:
            self.variables[variable] = item
            self.run(body, directory)


_BLOCKS = {"function": "endfunction", "macro": "endmacro", "foreach": "endforeach"} | {
    "while": "endwhile"
}


def _block(
    listed: Sequence[Command], start: int, opening: str, closing: str
) -> tuple[list[Command], int]:
    """The body of the block opened at ``start`` and the index after its end (nested blocks
    of the same kind included; an unclosed block runs to the end of the file)."""
    depth, index = 0, start + 1
    while index < len(listed):
        name = listed[index].name
        if name == opening:
            depth += 1
        elif name == closing:
            if depth == 0:
                return list(listed[start + 1 : index]), index + 1
            depth -= 1
        index += 1
    return list(listed[start + 1 :]), index


def _substitute(command: Command, bound: dict[str, str]) -> Command:
    """A macro's body command with ``${parameter}`` replaced by the call's argument."""

    def replace(match: re.Match[str]) -> str:
        return bound.get(match.group(1), match.group(0))

    arguments = tuple(_VARIABLE.sub(replace, word) for word in command.arguments)
    return Command(command.name, arguments, command.file, command.line)


def _loop_items(script: Script, words: list[str]) -> list[str]:
    """What ``foreach(var ...)`` iterates over: items, ``IN LISTS``/``IN ITEMS``, ``RANGE``."""
    if words[:1] == ["RANGE"]:
        numbers = [int(w) for w in words[1:4] if re.fullmatch(r"-?\d+", w)]
        start, stop = (0, numbers[0]) if len(numbers) == 1 else (*numbers, 0, 0)[:2]
        step = numbers[2] if len(numbers) > 2 and numbers[2] > 0 else 1
        count = max(0, (stop - start) // step + 1)
        return [str(start + i * step) for i in range(min(count, MAX_ITERATIONS + 1))]
    if words[:1] != ["IN"]:
        return words
    items: list[str] = []
    mode = None
    for word in words[1:]:
        if word in ("LISTS", "ITEMS", "ZIP_LISTS"):
            mode = word
        elif mode == "LISTS":
            items.extend(p for p in script.variables.get(word, "").split(";") if p)
        elif mode == "ITEMS":
            items.append(word)
    return items


def _below(path: str, root: str) -> bool:
    return path == root or path.startswith(root.rstrip(os.sep) + os.sep)


# -- the language's own commands ----------------------------------------------------------------


def _set(script: Script, command: Command, words: list[str], _: str) -> None:
    if not words:
        return
    values = words[1:]
    if "CACHE" in values:
        values = values[: values.index("CACHE")]
    parent = "PARENT_SCOPE" in values
    values = [value for value in values if value != "PARENT_SCOPE"]
    script.set(words[0], ";".join(values), command, parent)


def _unset(script: Script, _: Command, words: list[str], __: str) -> None:
    if words:
        script.variables.pop(words[0], None)


def _list(script: Script, command: Command, words: list[str], _: str) -> None:
    if len(words) < 2:
        return
    operation, name = words[0], words[1]
    old = [part for part in script.variables.get(name, "").split(";") if part]
    if operation == "APPEND":
        script.set(name, ";".join(old + words[2:]), command)
    elif operation == "PREPEND":
        script.set(name, ";".join(words[2:] + old), command)
    elif operation == "REMOVE_ITEM":
        script.set(name, ";".join(p for p in old if p not in words[2:]), command)


def _string(script: Script, command: Command, words: list[str], _: str) -> None:
    if len(words) < 3:
        return
    operation = words[0]
    if operation == "APPEND":
        script.set(words[1], script.variables.get(words[1], "") + "".join(words[2:]), command)
    elif operation == "REPLACE" and len(words) >= 4:
        script.set(words[3], "".join(words[4:]).replace(words[1], words[2]), command)
    elif operation in ("TOLOWER", "TOUPPER"):
        text = words[1].lower() if operation == "TOLOWER" else words[1].upper()
        script.set(words[2], text, command)


_COMPONENTS: dict[str, Callable[[str], str]] = {
    "NAME": os.path.basename,
    "NAME_WE": lambda path: os.path.basename(path).split(".", 1)[0],
    "NAME_WLE": lambda path: os.path.splitext(os.path.basename(path))[0],
    "EXT": lambda path: (
        "." + os.path.basename(path).split(".", 1)[1] if "." in os.path.basename(path) else ""
    ),
    "DIRECTORY": os.path.dirname,
    "PATH": os.path.dirname,
}


def _get_filename_component(script: Script, command: Command, words: list[str], _: str) -> None:
    if len(words) >= 3 and words[2] in _COMPONENTS:
        script.set(words[0], _COMPONENTS[words[2]](words[1]), command)


def _parse_arguments(script: Script, command: Command, words: list[str], _: str) -> None:
    """``cmake_parse_arguments(prefix options one_value multi_value args...)`` and its
    ``PARSE_ARGV n`` form, as a wrapper of ``add_executable`` reads its arguments."""
    if words[:1] == ["PARSE_ARGV"] and len(words) >= 6:
        first = int(words[1]) if words[1].isdigit() else 0
        count = int(script.variables.get("ARGC", "0") or 0)
        words = [*words[2:6], *(script.variables.get(f"ARGV{i}", "") for i in range(first, count))]
    if len(words) < 4:
        return
    prefix, keywords = words[0], [word.split(";") for word in words[1:4]]
    options, single, multiple = (set(filter(None, kinds)) for kinds in keywords)
    values: dict[str, list[str]] = {}
    unparsed: list[str] = []
    current: str | None = None
    for word in words[4:]:
        if word in options:
            values[word], current = ["TRUE"], None
        elif word in single or word in multiple:
            values[word], current = [], word
        elif current is not None:
            values[current].append(word)
            if current in single:
                current = None
        else:
            unparsed.append(word)
    for name in options:
        script.set(f"{prefix}_{name}", "TRUE" if name in values else "FALSE", command)
    for name in single | multiple:
        script.set(f"{prefix}_{name}", ";".join(values.get(name, [])), command)
    script.set(f"{prefix}_UNPARSED_ARGUMENTS", ";".join(unparsed), command)


def _project(script: Script, _: Command, words: list[str], __: str) -> None:
    if words:
        script.variables["PROJECT_NAME"] = words[0]


def _file(script: Script, command: Command, words: list[str], directory: str) -> None:
    if len(words) >= 2 and words[0] in ("GLOB", "GLOB_RECURSE"):
        script.set(words[1], ";".join(_glob(words, directory)), command)


def _glob(words: list[str], directory: str) -> list[str]:
    rest = [w for w in words[2:] if w not in ("CONFIGURE_DEPENDS", "LIST_DIRECTORIES")]
    relative: str | None = None
    if rest[:1] == ["RELATIVE"] and len(rest) >= 2:
        relative, rest = rest[1], rest[2:]
    found: list[str] = []
    for pattern in rest:
        full = os.path.join(directory, pattern)
        if words[0] == "GLOB_RECURSE":  # CMake's recursive glob descends from the pattern's folder
            folder, name = os.path.split(full)
            full = os.path.join(folder, "**", name)
        for match in sorted(glob.glob(full, recursive=True)):
            found.append(os.path.relpath(match, relative) if relative else match)
            if len(found) > MAX_ITERATIONS:
                return found
    return found


def _add_subdirectory(script: Script, _: Command, words: list[str], directory: str) -> None:
    if not words:
        return
    child = os.path.normpath(os.path.join(directory, words[0]))
    script.scopes.append({**script.variables})  # a subdirectory has its own scope
    script.variables["CMAKE_CURRENT_SOURCE_DIR"] = child
    script.variables["CMAKE_CURRENT_LIST_DIR"] = child
    try:
        script.run_file(os.path.join(child, CMAKE_FILE), child)
    finally:
        script.scopes.pop()


def _include(script: Script, _: Command, words: list[str], directory: str) -> None:
    """``include(file)`` or ``include(Module)`` found in ``CMAKE_MODULE_PATH``: run in place."""
    if not words:
        return
    folders = [directory, *script.variables.get("CMAKE_MODULE_PATH", "").split(";")]
    for folder in filter(None, folders):
        for name in (words[0], words[0] + ".cmake"):
            path = os.path.normpath(os.path.join(directory, folder, name))
            if os.path.isfile(path):
                script.run_file(path, directory)
                return


_BUILTINS: dict[str, Callable[[Script, Command, list[str], str], None]] = {
    "set": _set,
    "unset": _unset,
    "list": _list,
    "string": _string,
    "get_filename_component": _get_filename_component,
    "cmake_parse_arguments": _parse_arguments,
    "project": _project,
    "file": _file,
    "add_subdirectory": _add_subdirectory,
    "include": _include,
}
"""The language's commands that change what later commands see."""
