"""Value domains of inputs: which concrete values analysis distinguishes.

An input's domain is a finite list of slots: the literal values the launch
files themselves suggest (the default, literals passed by including files,
``true``/``false`` where the arg is tested by ``if``/``unless`` or ROS 2's boolean
substitutions, literals an ``$(eval)`` or ROS 2's ``$(equals)`` compares it with),
``UNSET`` when leaving the arg out differs from every literal, and ``OTHER`` for
anything else a user may type. The domain never changes the semantics, only how
finely conditions are split.
"""

from __future__ import annotations

import os
import re
from collections import defaultdict
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from graphlib import CycleError, TopologicalSorter

from rosvar.frontends.entity import Entity
from rosvar.frontends.xml import Snapshot
from rosvar.interpreter.safe_eval import EvalRefused, compared_literals
from rosvar.logic.inputs import OTHER, UNSET, Slot
from rosvar.ros.version import RosVersion
from rosvar.workspace import Workspace
from rosvar.workspace.executables import executables
from rosvar.workspace.paths import real_path

_WHOLE_ARG = {
    RosVersion.ROS1: re.compile(r"\s*\$\(arg\s+([^\s)]+)\s*\)\s*"),
    RosVersion.ROS2: re.compile(r"\s*\$\(var\s+([^\s)]+)\s*\)\s*"),
}
"""An ``if``/``unless`` testing one arg: ``$(arg x)`` in ROS 1, ``$(var x)`` in ROS 2."""
_FIND = re.compile(r"\$\(find\s+([^\s)]+)\s*\)")
_ONE_ARG = re.compile(r"([^$]*)\$\(arg\s+([^\s)]+)\s*\)([^$]*)")
_VAR = r"\$\(var\s+([\w/-]+)\s*\)"
_LITERAL = r"('[^']*'|\"[^\"]*\"|[^\s()'\"$]+)"
_ROS2_COMPARED = (
    re.compile(rf"\$\((?:not-)?equals\s+{_VAR}\s+{_LITERAL}\s*\)"),
    re.compile(rf"\$\(rosvar-configuration-equals\s+([\w/-]+)\s+{_LITERAL}\s*\)"),
    re.compile(rf"\$\((?:not-)?equals\s+{_LITERAL}\s+{_VAR}\s*\)"),
)
"""``$(equals $(var x) a)`` (either order, ``not-equals`` too; ``LaunchConfigurationEquals``
as the Python frontend writes it): ``x`` compared with ``a``."""
_ROS2_BOOLEAN_OPERANDS = re.compile(
    r"\$\((?:not|and|or|all|any|if)\s+((?:[^()$]|\$(?!\()|\$\(var\s[^()]*\))*)"
)
"""The operands of launch's boolean substitutions (up to a nested one other than ``$(var)``):
an arg among them is tested as ``true``/``false``."""
PARAM_TYPES = ("str", "string", "int", "double", "bool", "boolean", "yaml", "auto")


@dataclass
class ArgFacts:
    """What the text of one launch file says about one of its command-line args."""

    defaults: list[str | None] = field(default_factory=list)
    plain: bool = True  # declared once, directly under <launch>, without if/unless
    has_value: bool = False
    tested: bool = False
    literals: set[str] = field(default_factory=set)
    executables: list[tuple[str, str, str]] = field(default_factory=list)  # (pkg, prefix, suffix)
    paths: list[tuple[str, str]] = field(default_factory=list)  # (prefix, suffix) of a file path
    param_type: bool = False


_NO_FACTS = ArgFacts()
"""The facts of an arg its file does not declare (read only)."""


def entry_declarations(root: Entity) -> Iterator[Entity]:
    """``<arg>`` elements a command line reaches: under ``<launch>`` and ``<group>``s, in
    document order (a stack, not recursion: groups may nest as deep as the parser allows)."""
    pending = [iter(root.children)]
    while pending:
        child = next(pending[-1], None)
        if child is None:
            pending.pop()
        elif child.tag == "arg":
            yield child
        elif child.tag == "group":
            pending.append(iter(child.children))


def _passed_args(include: Entity, root: Entity) -> Iterator[tuple[str | None, str | None]]:
    """``(name, value)`` pairs an ``<include>`` passes: its ``<arg>`` children, and with
    ``pass_all_args`` every arg of the including file, both as its literal and as itself."""
    for child in include.children:
        if child.tag == "arg":
            yield child.get("name"), child.get("value")
    if (include.get("pass_all_args") or "").lower() in ("true", "1"):
        for arg in _walk(root):
            name, value = arg.get("name"), arg.get("value")
            if arg.tag == "arg" and name:
                yield name, value if value is not None else arg.get("default")
                yield name, f"$(arg {name})"


def _walk(entity: Entity) -> Iterator[Entity]:
    """``entity`` and every element below it, in document order (a stack, not nested
    generators: those pass each element up through every level)."""
    stack = [entity]
    while stack:
        element = stack.pop()
        yield element
        stack.extend(reversed(element.children))


def file_facts(root: Entity, version: RosVersion = RosVersion.ROS1) -> dict[str, ArgFacts]:
    facts: dict[str, ArgFacts] = defaultdict(ArgFacts)
    for decl in entry_declarations(root):
        name = decl.get("name")
        if not name or "$" in name:
            continue
        entry = facts[name]
        if entry.defaults or decl.has("if") or decl.has("unless") or decl not in root.children:
            entry.plain = False
        if decl.has("value"):
            entry.has_value = True
        default = decl.get("default")
        entry.defaults.append(default)
        if default is not None and "$" not in default:
            entry.literals.add(default)
        # a ROS 2 argument's <choice value=...>: the values it accepts
        entry.literals.update(c.get("value") or "" for c in decl.children if c.tag == "choice")
    whole_arg = _WHOLE_ARG[version]
    ros2 = version is RosVersion.ROS2
    stack = [root]  # as _walk, inlined: this visits every element of every file read
    while stack:
        element = stack.pop()
        if element.children:
            stack.extend(reversed(element.children))
        if element.tag in _PATTERN_TAGS:
            _patterns(element, facts)
        for attribute, text in element.attributes.items():
            if "$(" not in text:  # most texts are literals (and a test of one arg has "$(")
                continue
            if attribute in _GUARDS:
                match = whole_arg.fullmatch(text)
                if match and match.group(1) in facts:
                    facts[match.group(1)].tested = True
            if ros2:
                _ros2_tests(text, facts)
            if text.startswith("$(eval ") and text.endswith(")"):
                expression = _ros2_expression(text[7:-1]) if ros2 else text[7:-1]
                try:
                    compared = compared_literals(expression) if expression else {}
                except EvalRefused:
                    continue
                for name, values in compared.items():
                    if name in facts:
                        facts[name].literals.update(values)
    return dict(facts)


_GUARDS = frozenset({"if", "unless"})
_ROS2_ARG_TEXT = (
    re.compile(rf"'{_VAR}'"),
    re.compile(rf'"{_VAR}"'),
    re.compile(rf"\$\(rosvar-python-string\s+{_VAR}\s*\)"),
    re.compile(_VAR),
)
"""An arg's text in a ROS 2 ``$(eval)``'s Python: a string literal of it alone (XML's
``'$(var x)'``, the Python frontend's ``repr``), or the bare text (a number, a name)."""


def _ros2_expression(argument: str) -> str | None:
    """A ROS 2 ``$(eval)``'s argument as roslaunch's ``$(eval)`` would write it (each arg's
    text ``arg('x')``), for :func:`compared_literals`; None where it holds other
    substitutions or is not one quoted argument."""
    argument = argument.strip()
    if len(argument) < 2 or argument[0] not in "'\"" or argument[-1] != argument[0]:
        return None
    quote = argument[0]
    expression = argument[1:-1].replace("\\" + quote, quote)
    for pattern in _ROS2_ARG_TEXT:
        expression = pattern.sub(lambda match: f"arg('{match.group(1)}')", expression)
    return None if "$(" in expression else expression


def _ros2_tests(text: str, facts: dict[str, ArgFacts]) -> None:
    """What launch's boolean substitutions say of an arg: the literals ``$(equals)``
    compares it with, and ``true``/``false`` where it is an operand of ``$(not)``,
    ``$(and)``, ``$(if)``..."""
    for pattern in _ROS2_COMPARED:
        for match in pattern.finditer(text):
            first, second = match.group(1), match.group(2)
            name, literal = (second, first) if first not in facts else (first, second)
            if name in facts:
                facts[name].literals.add(literal.strip("'\"") if literal[0] in "'\"" else literal)
    for match in _ROS2_BOOLEAN_OPERANDS.finditer(text):
        for name in re.findall(_VAR, match.group(1)):
            if name in facts:
                facts[name].tested = True


_PATTERN_TAGS = frozenset({"node", "test", "include", "param"})
"""The tags whose attributes :func:`_patterns` reads."""


def _patterns(element: Entity, facts: dict[str, ArgFacts]) -> None:
    """Uses of one arg inside a literal pattern: node types, include paths, param types."""
    if element.tag in ("node", "test"):
        match = _ONE_ARG.fullmatch(element.get("type") or "")
        package = element.get("pkg") or ""
        if match and match.group(2) in facts and "$" not in package:
            facts[match.group(2)].executables.append((package, match.group(1), match.group(3)))
    elif element.tag == "include":
        text = element.get("file") or ""
        prefix_match = _FIND.match(text)
        rest = text[prefix_match.end() :] if prefix_match else ""
        match = _ONE_ARG.fullmatch(rest)
        if prefix_match and match and match.group(2) in facts:
            facts[match.group(2)].paths.append(
                (prefix_match.group(0) + match.group(1), match.group(3))
            )
    elif element.tag == "param":
        match = _WHOLE_ARG[RosVersion.ROS1].fullmatch(element.get("type") or "")
        if match and match.group(1) in facts:
            facts[match.group(1)].param_type = True


def _matching(candidates: Iterable[str], prefix: str, suffix: str) -> set[str]:
    return {
        c[len(prefix) : len(c) - len(suffix)]
        for c in candidates
        if c.startswith(prefix) and c.endswith(suffix) and len(c) > len(prefix) + len(suffix)
    }


class DomainTable:
    """Domains of every entry file's args and of environment variables."""

    def __init__(
        self,
        workspace: Workspace,
        extra_values: Mapping[str, Sequence[str]] | None = None,
        env_values: Mapping[str, Sequence[str]] | None = None,
        extra_executables: Mapping[str, Sequence[str]] | None = None,
        files: Snapshot | None = None,
    ) -> None:
        self.workspace = workspace
        self._files = files or Snapshot()
        self._executables = extra_executables or {}
        self._forwards: dict[str, list[tuple[str, str]]] = {}
        self._facts: dict[str, dict[str, ArgFacts]] = {}
        self._passed: dict[str, dict[str, set[str]]] | None = None
        self._forwards_loop = False  # whether a chain of forwarded args comes back (indexed)
        self._domains: dict[tuple[str, str], tuple[Slot, ...]] = {}
        self._extra = extra_values or {}
        self._env = env_values or {}

    def facts(self, file: str) -> dict[str, ArgFacts]:
        """What ``file`` says of its args (an included share path's file is read from the
        source its package installs there)."""
        if file not in self._facts:
            root = self._files.load(self.workspace.installed(file)).root
            version = self.workspace.ros_version
            self._facts[file] = file_facts(root, version) if root is not None else {}
        return self._facts[file]

    def unset_default(self, file: str, name: str) -> str | None:
        """The literal that not giving ``name`` amounts to, if it is always the same."""
        entry = self.facts(file).get(name)
        if entry is None or entry.has_value or not entry.plain or len(entry.defaults) != 1:
            return None
        default = entry.defaults[0]
        return None if default is None or "$" in default else default

    def arg_domain(
        self, file: str, name: str, seen: frozenset[str] = frozenset()
    ) -> tuple[Slot, ...]:
        """The slots of ``file``'s arg ``name`` (``seen``: the forwarded args followed to
        it). Each is computed once where no chain of forwarded args loops: a domain then
        does not depend on the chain that asks, and the chains ask again for the domains of
        the files they reach (Husky: 558 questions, 438 distinct; ROS 2 asks again at each
        pass of :data:`~rosvar.interpreter.workspace_models.MAX_PASSES`)."""
        self._indexed()
        if self._forwards_loop:
            return self._arg_domain(file, name, seen)
        key = (file, name)
        found = self._domains.get(key)
        if found is None:
            found = self._domains[key] = self._arg_domain(file, name, seen)
        return found

    def _arg_domain(self, file: str, name: str, seen: frozenset[str]) -> tuple[Slot, ...]:
        entry = self.facts(file).get(name, _NO_FACTS)
        literals: list[str] = []
        default = self.unset_default(file, name)
        if default is not None:
            literals.append(default)
        literals.extend(sorted(entry.literals))
        if entry.tested:
            literals.extend(["true", "false"])
        real = real_path(file)
        literals.extend(sorted(self._indexed().get(real, {}).get(name, ())))
        literals.extend(sorted(self._forwarded(real, name, seen)))
        if entry.executables or entry.paths or entry.param_type:
            literals.extend(sorted(self._inferred(entry)))
        if self._extra:
            literals.extend(self._extra.get(name, ()))
            literals.extend(self._extra.get(f"{os.path.basename(file)}:{name}", ()))
        slots: list[Slot] = list(dict.fromkeys(literals))
        if default is None:
            slots.append(UNSET)
        slots.append(OTHER)
        return tuple(slots)

    def _inferred(self, entry: ArgFacts) -> set[str]:
        """Values that make a pattern name something that exists (GETVALUES)."""
        values: set[str] = set()
        for package_name, prefix, suffix in entry.executables:
            package = self.workspace.packages.get(package_name)
            known = set(self._executables.get(package_name, ()))
            if package is not None:
                known |= executables(package)
            values |= _matching(known, prefix, suffix)
        for prefix, suffix in entry.paths:
            directory_text, _, name_prefix = prefix.rpartition("/")
            directory = self._static_path(directory_text, "")
            if directory is None or not os.path.isdir(directory):
                continue
            values |= _matching(os.listdir(directory), name_prefix, suffix)
        if entry.param_type:
            values |= set(PARAM_TYPES)
        return values

    def env_domain(self, name: str) -> tuple[Slot, ...]:
        return (*dict.fromkeys(self._env.get(name, ())), UNSET, OTHER)

    def read_all(self) -> None:
        """Read every launch file and index their includes now rather than at the first
        question (``Analysis.map_models`` shares them with forked processes)."""
        self._indexed()

    def _indexed(self) -> dict[str, dict[str, set[str]]]:
        """The literals passed to each file's args (and ``_forwards``), indexed once."""
        if self._passed is None:
            self._passed = self._index_includes()
            forwards = {
                source: {f"{target}\x00{name}" for target, name in targets}
                for source, targets in self._forwards.items()
            }
            try:
                TopologicalSorter(forwards).prepare()
            except CycleError:
                self._forwards_loop = True
        return self._passed

    def _forwarded(self, real: str, name: str, seen: frozenset[str]) -> set[str]:
        """Values the files the file resolved to ``real`` passes ``$(arg name)`` on to know
        for their arg.

        ``<include><arg name="y" value="$(arg x)"/></include>`` makes ``x`` range over
        the included file's values of ``y`` (e.g. its ``true``/``false`` when ``y``
        decides an ``if``), followed through chains of includes.
        """
        key = f"{real}\x00{name}"
        if key in seen:
            return set()
        values: set[str] = set()
        for target, target_name in self._forwards.get(key, ()):
            domain = self.arg_domain(target, target_name, seen | {key})
            values |= {slot for slot in domain if isinstance(slot, str)}
        return values

    def _index_includes(self) -> dict[str, dict[str, set[str]]]:
        index: dict[str, dict[str, set[str]]] = defaultdict(lambda: defaultdict(set))
        for launch_file in self.workspace.launch_files:
            root = self._files.load(launch_file).root
            if root is None:
                continue
            for element in _walk(root):
                if element.tag != "include":
                    continue
                target = self._static_path(element.get("file") or "", launch_file)
                if target is None:
                    continue
                for name, value in _passed_args(element, root):
                    if not name or value is None:
                        continue
                    if "$" not in value:
                        index[target][name].add(value)
                    elif forwarded := _WHOLE_ARG[self.workspace.ros_version].fullmatch(value):
                        source = f"{real_path(launch_file)}\x00{forwarded.group(1)}"
                        self._forwards.setdefault(source, []).append((target, name))
        return index

    def _static_path(self, text: str, launch_file: str) -> str | None:
        def find(match: re.Match[str]) -> str:
            path = self.workspace.find(match.group(1))
            return path if path is not None else "\x00"

        text = _FIND.sub(find, text).replace("$(dirname)", os.path.dirname(launch_file))
        if "$" in text or "\x00" in text:
            return None
        return str(real_path(text))
