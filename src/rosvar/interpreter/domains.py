"""Value domains of inputs: which concrete values analysis distinguishes.

An input's domain is a finite list of slots: the literal values the launch
files themselves suggest (the default, literals passed by including files,
``true``/``false`` where the arg is tested by ``if``/``unless``, literals an
``$(eval)`` compares it with), ``UNSET`` when leaving the arg out differs from
every literal, and ``OTHER`` for anything else a user may type. The domain
never changes the semantics, only how finely conditions are split.
"""

from __future__ import annotations

import os
import re
from collections import defaultdict
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field

from rosvar.frontends.entity import Entity
from rosvar.frontends.ros1_xml.parser import load_launch_file
from rosvar.interpreter.evaluator import EvalRefused, compared_literals
from rosvar.logic.inputs import OTHER, UNSET, Slot
from rosvar.workspace import Workspace

_WHOLE_ARG = re.compile(r"\s*\$\(arg\s+([^\s)]+)\s*\)\s*")
_FIND = re.compile(r"\$\(find\s+([^\s)]+)\s*\)")


@dataclass
class ArgFacts:
    """What the text of one launch file says about one of its command-line args."""

    defaults: list[str | None] = field(default_factory=list)
    has_value: bool = False
    tested: bool = False
    literals: set[str] = field(default_factory=set)


def entry_declarations(root: Entity) -> Iterator[Entity]:
    """``<arg>`` elements a command line reaches: under ``<launch>`` and ``<group>``s."""
    for child in root.children:
        if child.tag == "arg":
            yield child
        elif child.tag == "group":
            yield from entry_declarations(child)


def _walk(entity: Entity) -> Iterator[Entity]:
    yield entity
    for child in entity.children:
        yield from _walk(child)


def file_facts(root: Entity) -> dict[str, ArgFacts]:
    facts: dict[str, ArgFacts] = defaultdict(ArgFacts)
    for decl in entry_declarations(root):
        name = decl.get("name")
        if not name or "$" in name:
            continue
        entry = facts[name]
        if decl.has("value"):
            entry.has_value = True
        default = decl.get("default")
        entry.defaults.append(default)
        if default is not None and "$" not in default:
            entry.literals.add(default)
    for element in _walk(root):
        for attribute in ("if", "unless"):
            text = element.get(attribute)
            if text is None:
                continue
            match = _WHOLE_ARG.fullmatch(text)
            if match and match.group(1) in facts:
                facts[match.group(1)].tested = True
        for text in element.attributes.values():
            if text.startswith("$(eval ") and text.endswith(")"):
                try:
                    compared = compared_literals(text[7:-1])
                except EvalRefused:
                    continue
                for name, values in compared.items():
                    if name in facts:
                        facts[name].literals.update(values)
    return dict(facts)


class DomainTable:
    """Domains of every entry file's args and of environment variables."""

    def __init__(
        self,
        workspace: Workspace,
        extra_values: Mapping[str, Sequence[str]] | None = None,
        env_values: Mapping[str, Sequence[str]] | None = None,
    ) -> None:
        self.workspace = workspace
        self._facts: dict[str, dict[str, ArgFacts]] = {}
        self._passed: dict[str, dict[str, set[str]]] | None = None
        self._extra = extra_values or {}
        self._env = env_values or {}

    def facts(self, file: str) -> dict[str, ArgFacts]:
        if file not in self._facts:
            root = load_launch_file(file).root
            self._facts[file] = file_facts(root) if root is not None else {}
        return self._facts[file]

    def unset_default(self, file: str, name: str) -> str | None:
        """The literal that not giving ``name`` amounts to, if it is always the same."""
        entry = self.facts(file).get(name)
        if entry is None or entry.has_value or not entry.defaults:
            return None
        first = entry.defaults[0]
        if first is None or "$" in first or any(d != first for d in entry.defaults):
            return None
        return first

    def arg_domain(self, file: str, name: str) -> tuple[Slot, ...]:
        entry = self.facts(file).get(name, ArgFacts())
        literals: list[str] = []
        default = self.unset_default(file, name)
        if default is not None:
            literals.append(default)
        literals.extend(sorted(entry.literals))
        if entry.tested:
            literals.extend(["true", "false"])
        literals.extend(sorted(self.passed_literals(file).get(name, ())))
        literals.extend(self._extra.get(name, ()))
        slots: list[Slot] = list(dict.fromkeys(literals))
        if default is None:
            slots.append(UNSET)
        slots.append(OTHER)
        return tuple(slots)

    def env_domain(self, name: str) -> tuple[Slot, ...]:
        return (*dict.fromkeys(self._env.get(name, ())), UNSET, OTHER)

    def passed_literals(self, file: str) -> dict[str, set[str]]:
        """Literal values that including files pass to ``file``'s args."""
        if self._passed is None:
            self._passed = self._index_includes()
        return self._passed.get(os.path.realpath(file), {})

    def _index_includes(self) -> dict[str, dict[str, set[str]]]:
        index: dict[str, dict[str, set[str]]] = defaultdict(lambda: defaultdict(set))
        for launch_file in self.workspace.launch_files:
            root = load_launch_file(launch_file).root
            if root is None:
                continue
            for element in _walk(root):
                if element.tag != "include":
                    continue
                target = self._static_path(element.get("file") or "", launch_file)
                if target is None:
                    continue
                for child in element.children:
                    name, value = child.get("name"), child.get("value")
                    if child.tag == "arg" and name and value is not None and "$" not in value:
                        index[target][name].add(value)
        return index

    def _static_path(self, text: str, launch_file: str) -> str | None:
        def find(match: re.Match[str]) -> str:
            path = self.workspace.find(match.group(1))
            return path if path is not None else "\x00"

        text = _FIND.sub(find, text).replace("$(dirname)", os.path.dirname(launch_file))
        if "$" in text or "\x00" in text:
            return None
        return os.path.realpath(text)
