"""Command lines to try on a real ROS 2 launch file, read from the repository's own text.

The sample is independent of rosvar (whose reading is what the differential test checks) and
never runs the files: declared arguments, their defaults and ``choices`` are read from the
syntax (``ast`` for Python, the XML and YAML trees), as are the literal values that the
repository's other launch files pass when they include the file. A configuration is

1. the defaults, where an argument without default gets a value (:func:`guess`): so do the
   launch configurations the file or the files it includes read but nothing declares or
   sets (autoware's ``vehicle_model``, which the repository's users pass);
2. each boolean argument flipped alone (``true`` ↔ ``false``, in the default's case);
3. each other value of a ``choices`` list, alone;
4. the literal arguments of each include of the file found in the repository, together.

Duplicates are dropped, the first kept, with every rule that named it (:class:`Origin`: a
passed set equal to the defaults counts for both). What cannot be read literally (a default
computed by a substitution, an argument declared in a loop) is left out: apart from
:data:`PLACEHOLDER`, the sample only names values that the repository itself writes.
"""

from __future__ import annotations

import ast
import os
import re
import xml.etree.ElementTree as ElementTree
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from pathlib import Path
from typing import Any

import yaml

Config = dict[str, str]

PLACEHOLDER = "sample"
"""The value of a required argument whose possible values no file names."""
_PATH_NAME = re.compile(
    r"(?:.*/)?(\w+?)_(?:param_path|param_file|params_file|config_file|path|file)"
)
"""An argument naming a parameter file: ``ekf_localizer_param_path`` → ``ekf_localizer``."""
BOOLEANS = {"true": "false", "false": "true", "True": "False", "False": "True"}
_LAUNCH_NAME = re.compile(r"[\w.-]+(\.launch\.(py|xml|ya?ml)|_launch\.(py|xml|ya?ml)|\.launch)$")


@dataclass
class Argument:
    """A declared launch argument: its default (None: required, or not a literal) and the
    values named for it (``choices``, values includers pass)."""

    name: str
    required: bool
    default: str | None = None
    choices: list[str] = field(default_factory=list)


@dataclass
class Include:
    """An include found in a launch file: the file names its path mentions, the literal
    values it passes and the names of every argument it passes."""

    targets: list[str]
    arguments: Config
    names: set[str] = field(default_factory=set)


@dataclass
class Reading:
    """What a launch file declares and which files it includes with which values; which
    launch configurations it reads, sets (``<let>``) and tests whole (``if="$(var x)"``).
    ``complete``: every declaration was read (none has a computed name)."""

    arguments: dict[str, Argument] = field(default_factory=dict)
    includes: list[Include] = field(default_factory=list)
    reads: set[str] = field(default_factory=set)
    sets: set[str] = field(default_factory=set)
    conditions: set[str] = field(default_factory=set)
    complete: bool = True

    def declare(self, argument: Argument) -> None:
        self.arguments.setdefault(argument.name, argument)


# -- Python -------------------------------------------------------------------------------------
def _call_name(node: ast.Call) -> str:
    function = node.func
    if isinstance(function, ast.Attribute):
        return function.attr
    return function.id if isinstance(function, ast.Name) else ""


def _constants(tree: ast.AST) -> dict[str, str]:
    """Names bound once, to a string literal, anywhere in the module (``ur_type = "ur5e"``)."""
    seen: dict[str, list[ast.expr]] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if isinstance(target, ast.Name):
                    seen.setdefault(target.id, []).append(node.value)
    return {
        name: values[0].value
        for name, values in seen.items()
        if len(values) == 1
        and isinstance(values[0], ast.Constant)
        and isinstance(values[0].value, str)
    }


def _literal(node: ast.AST | None, constants: Mapping[str, str]) -> str | None:
    """The text of a string literal, a name bound to one, or a list of them joined (as a
    list of substitutions is); None for anything computed."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    if isinstance(node, ast.Constant) and isinstance(node.value, bool):
        return str(node.value).lower()
    if isinstance(node, ast.Name):
        return constants.get(node.id)
    if isinstance(node, ast.List | ast.Tuple):
        parts = [_literal(element, constants) for element in node.elts]
        return None if None in parts else "".join(p for p in parts if p is not None)
    return None


def _keyword(node: ast.Call, name: str) -> ast.expr | None:
    return next((k.value for k in node.keywords if k.arg == name), None)


def _passed(
    node: ast.expr | None, constants: Mapping[str, str], literal_values: bool = True
) -> Config:
    """The literal pairs of ``launch_arguments=``: a dict (``.items()`` or not) or a list of
    pairs; with ``literal_values`` false, every pair whose name is literal (its value "")."""
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
        node = node.func.value  # {...}.items()
    pairs: list[tuple[ast.expr | None, ast.expr]] = []
    if isinstance(node, ast.Dict):
        pairs = list(zip(node.keys, node.values, strict=True))
    elif isinstance(node, ast.List | ast.Tuple):
        pairs = [
            (e.elts[0], e.elts[1])
            for e in node.elts
            if isinstance(e, ast.Tuple | ast.List) and len(e.elts) == 2
        ]
    found: Config = {}
    for key, value in pairs:
        name, text = _literal(key, constants), _literal(value, constants)
        if name is not None and (text is not None or not literal_values):
            found[name] = text or ""
    return found


def _file_names(node: ast.AST) -> list[str]:
    """Launch file names among the string literals of an include's source."""
    names = []
    for child in ast.walk(node):
        if isinstance(child, ast.Constant) and isinstance(child.value, str):
            name = os.path.basename(child.value.strip())
            if _LAUNCH_NAME.fullmatch(name):
                names.append(name)
    return names


def read_python(text: str) -> Reading:
    reading = Reading()
    try:
        tree = ast.parse(text)
    except (SyntaxError, ValueError):
        return reading
    constants = _constants(tree)
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        kind = _call_name(node)
        first = _literal(node.args[0] if node.args else _keyword(node, "name"), constants)
        if kind == "LaunchConfiguration" and first is not None and not _keyword(node, "default"):
            reading.reads.add(first)
        elif kind == "SetLaunchConfiguration" and first is not None:
            reading.sets.add(first)
        elif kind in ("IfCondition", "UnlessCondition") and node.args:
            tested = node.args[0]
            if isinstance(tested, ast.Call) and _call_name(tested) == "LaunchConfiguration":
                name = _literal(tested.args[0] if tested.args else None, constants)
                reading.conditions |= {name} if name is not None else set()
        elif kind == "DeclareLaunchArgument":
            name = first
            if name is None:
                reading.complete = False
                continue
            default_node = _keyword(node, "default_value")
            choices_node = _keyword(node, "choices")
            choices = []
            if isinstance(choices_node, ast.List | ast.Tuple):
                choices = [c for e in choices_node.elts if (c := _literal(e, constants))]
            reading.declare(
                Argument(name, default_node is None, _literal(default_node, constants), choices)
            )
        elif kind == "IncludeLaunchDescription":
            source = node.args[0] if node.args else _keyword(node, "launch_description_source")
            if source is not None:
                given = _keyword(node, "launch_arguments")
                names = set(_passed(given, constants, literal_values=False))
                passed = _passed(given, constants)
                reading.includes.append(Include(_file_names(source), passed, names))
    return reading


# -- XML and YAML -------------------------------------------------------------------------------
def _literal_text(value: object) -> str | None:
    """A value written without substitutions, as text."""
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, int | float | str):
        text = str(value)
        return None if "$(" in text else text
    return None


_VAR = re.compile(r"\$\(var\s+([^\s)]+)\s*\)")
_WHOLE_VAR = re.compile(r"\s*\$\(var\s+([^\s)]+)\s*\)\s*")


def _substitutions(reading: Reading, text: str) -> None:
    """The ``$(var)`` reads of an XML or YAML file's text, and its whole-arg conditions."""
    reading.reads |= set(_VAR.findall(text))
    for attribute in re.findall(r"(?:if|unless)\s*[=:]\s*[\"']([^\"']*)[\"']", text):
        whole = _WHOLE_VAR.fullmatch(attribute)
        reading.conditions |= {whole.group(1)} if whole else set()


def _parsed(text: str, parse: Callable[[str], Any], error: type[Exception]) -> tuple[Reading, Any]:
    """A new reading with the text's substitutions, and its tree (None if it does not parse:
    then the reading stays empty, as the file declares nothing ``ros2 launch`` could load)."""
    reading = Reading()
    try:
        tree = parse(text)
    except error:
        return reading, None
    _substitutions(reading, text)
    return reading, tree


def read_xml(text: str) -> Reading:
    reading, root = _parsed(text, ElementTree.fromstring, ElementTree.ParseError)
    if root is None:
        return reading
    for element in root.iter():
        if element.tag == "let" and "name" in element.attrib:
            reading.sets.add(element.attrib["name"])
        if element.tag == "arg" and "name" in element.attrib and "value" not in element.attrib:
            default = element.get("default")
            choices = [c.get("value", "") for c in element if c.tag == "choice"]
            reading.declare(
                Argument(
                    element.attrib["name"],
                    default is None,
                    None if default is None else _literal_text(default),
                    [c for c in choices if _literal_text(c) is not None],
                )
            )
        elif element.tag == "include" and "file" in element.attrib:
            given = [a for a in element if a.tag == "arg" and "name" in a.attrib]
            passed = {
                a.attrib["name"]: literal
                for a in given
                if (literal := _literal_text(a.get("value", "$("))) is not None
            }
            names = {a.attrib["name"] for a in given}
            reading.includes.append(Include(_names_in(element.attrib["file"]), passed, names))
    return reading


def _names_in(path: str) -> list[str]:
    name = os.path.basename(path.strip())
    return [name] if _LAUNCH_NAME.fullmatch(name) else []


def _yaml_entries(node: object) -> Iterator[tuple[str, object]]:
    """Every ``{tag: body}`` entry of a YAML launch tree, depth first."""
    if isinstance(node, list):
        for item in node:
            yield from _yaml_entries(item)
    elif isinstance(node, dict):
        for key, value in node.items():
            yield str(key), value
            yield from _yaml_entries(value)


def read_yaml(text: str) -> Reading:
    reading, document = _parsed(text, yaml.safe_load, yaml.YAMLError)
    for tag, body in _yaml_entries(document):
        if not isinstance(body, dict):
            continue
        if tag == "let" and "name" in body:
            reading.sets.add(str(body["name"]))
        if tag == "arg" and "name" in body and "value" not in body:
            default = body.get("default")
            reading.declare(
                Argument(
                    str(body["name"]),
                    "default" not in body,
                    None if default is None else _literal_text(default),
                )
            )
        elif tag == "include" and "file" in body:
            passed: Config = {}
            names = set()
            for arg in body.get("arg") or []:
                if isinstance(arg, dict) and "name" in arg:
                    names.add(str(arg["name"]))
                    literal = _literal_text(arg.get("value", "$("))
                    if literal is not None:
                        passed[str(arg["name"])] = literal
            reading.includes.append(Include(_names_in(str(body["file"])), passed, names))
    return reading


def read(path: Path) -> Reading:
    """What ``path`` declares and includes, by its frontend (as ``ros2 launch`` picks it)."""
    text = path.read_text(encoding="utf-8", errors="replace")
    if path.suffix == ".py":
        return read_python(text)
    if path.suffix in (".yaml", ".yml"):
        return read_yaml(text)
    return read_xml(text)


# -- configurations -----------------------------------------------------------------------------
def passed_values(readings: Mapping[Path, Reading]) -> dict[str, list[Config]]:
    """For each launch file name, the literal argument sets its includers pass."""
    found: dict[str, list[Config]] = {}
    for reading in readings.values():
        for include in reading.includes:
            for name in include.targets:
                found.setdefault(name, []).append(include.arguments)
    return found


def undeclared(readings: Mapping[Path, Reading]) -> dict[Path, set[str]]:
    """For each file, the launch configurations it or the files it includes (found by name
    among ``readings``) read without anything on the way declaring, setting or passing them:
    a user of the file gives them. Files with a declaration not read add none of their own."""
    by_name: dict[str, list[Path]] = {}
    for path in readings:
        by_name.setdefault(path.name, []).append(path)
    found: dict[Path, set[str]] = {}

    def visit(path: Path, stack: frozenset[Path]) -> set[str]:
        if path in found:
            return found[path]
        if path in stack:
            return set()
        reading = readings[path]
        names = set(reading.reads) if reading.complete else set()
        for include in reading.includes:
            for target in (t for name in include.targets for t in by_name.get(name, [])):
                names |= visit(target, stack | {path}) - include.names
        names -= set(reading.arguments) | reading.sets
        found[path] = names
        return names

    for path in readings:
        visit(path, frozenset())
    return found


def guess(name: str, conditions: set[str], files: Mapping[str, Path]) -> str:
    """A value for an argument nothing gives: ``true`` for one tested as a condition, the
    repository's parameter file of the argument's name (``ekf_localizer_param_path`` →
    ``ekf_localizer.param.yaml``) for a path, else :data:`PLACEHOLDER`."""
    if name in conditions:
        return "true"
    path = _PATH_NAME.fullmatch(name)
    if path is not None:
        stem = path.group(1)
        found = files.get(f"{stem}.param.yaml") or files.get(f"{stem}.yaml")
        if found is not None:
            return str(found)
    return PLACEHOLDER


class Origin(StrEnum):
    """Why a configuration is in the sample (the module's four rules)."""

    DEFAULTS = "defaults"
    FLIPPED = "boolean flipped"
    CHOICE = "other choice"
    PASSED = "passed by an includer"


@dataclass(frozen=True)
class Sample:
    """One sampled configuration and every rule that named it."""

    config: Config
    origins: frozenset[Origin]


def configurations(
    reading: Reading,
    passed: Sequence[Config],
    given: Sequence[str] = (),
    conditions: set[str] | None = None,
    files: Mapping[str, Path] | None = None,
) -> list[Sample]:
    """The sample of :mod:`this module <samples>` for one file (defaults first); ``given``
    are the undeclared names a user gives, ``conditions`` the names tested as conditions
    (in the repository), ``files`` its files by name."""
    declared = reading.arguments
    conditions = reading.conditions if conditions is None else conditions
    files = files or {}
    base: Config = {}
    for name in sorted({n for n, a in declared.items() if a.required} | set(given)):
        argument = declared.get(name, Argument(name, True))
        named = [config[name] for config in passed if name in config] + argument.choices
        base[name] = named[0] if named else guess(name, conditions, files)
    candidates: list[tuple[Config, Origin]] = [(base, Origin.DEFAULTS)]
    for name in sorted(set(declared) | set(base)):
        argument = declared.get(name, Argument(name, True))
        value = base.get(name, argument.default)
        if value in BOOLEANS:
            candidates.append(({**base, name: BOOLEANS[value]}, Origin.FLIPPED))
        candidates += [({**base, name: c}, Origin.CHOICE) for c in argument.choices if c != value]
    for config in passed:
        known = {k: v for k, v in config.items() if k in declared}
        candidates.append(({**base, **known}, Origin.PASSED))
    unique: dict[tuple[tuple[str, str], ...], tuple[Config, set[Origin]]] = {}
    for config, origin in candidates:
        unique.setdefault(tuple(sorted(config.items())), (config, set()))[1].add(origin)
    return [Sample(config, frozenset(origins)) for config, origins in unique.values()]


def sample(readings: Mapping[Path, Reading], root: Path) -> dict[Path, list[Sample]]:
    """The configurations of every launch file of one repository (below ``root``)."""
    passed = passed_values(readings)
    missing = undeclared(readings)
    conditions = set().union(*(r.conditions for r in readings.values()))
    files = {p.name: p for p in sorted(root.rglob("*.yaml"), reverse=True)}
    return {
        path: configurations(
            reading, passed.get(path.name, []), sorted(missing[path]), conditions, files
        )
        for path, reading in readings.items()
    }
