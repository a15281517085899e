"""Expanding xacro files with rosvar and with the real xacro, and comparing them.

rosvar expands a file once, with its args as inputs of the analysis' condition space (each
over the values a test names, ``<unset>`` and ``<other>``), and the model restricted to each
configuration must be what the real xacro prints for it, or fail where xacro fails.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from analyses.robot_description.xacro_oracle import XacroFailed, run_xacro
from rosvar.analyses.robot_description.document import Description, Node, concrete
from rosvar.analyses.robot_description.reading import XacroReader
from rosvar.interpreter.model import Raw
from rosvar.interpreter.substitution_args import MISSING, Missing
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.inputs import OTHER, UNSET, ArgInput, EnvInput, Input
from rosvar.logic.terms import Hole, PackageTable, evaluate
from rosvar.workspace import discover

UNKNOWN = "unknown"
Config = tuple[Mapping[str, str], Mapping[str, str]]  # (xacro args, environment)


@dataclass
class Expanded:
    """One file expanded once, for every configuration."""

    analysis: Analysis
    file: str
    description: Description
    arg_inputs: dict[str, ArgInput]

    @property
    def packages(self) -> dict[str, str]:
        return {name: p.path for name, p in self.analysis.workspace.packages.items()}

    def restricted(self, args: Mapping[str, str], env: Mapping[str, str]) -> Node | str | None:
        """The description in one configuration (None where xacro fails), or ``"unknown"``
        where rosvar says it could not follow a part."""
        space = self.analysis.space
        values: dict[Input, str | None] = {}
        for name, input_ in self.arg_inputs.items():
            values[input_] = args.get(name)
        for other in space.inputs():
            if isinstance(other, EnvInput):
                values[other] = env.get(other.name)
        host = PackageTable(self.packages)
        assignment = space.assignment(values, host)
        known = {k: v for k, v in values.items() if v is not None}

        def holds(condition: BDD) -> bool:
            return space.evaluate(condition, assignment)

        if holds(self.description.unknown):
            return UNKNOWN
        return concrete(self.description, holds, lambda text: evaluate(text, known, host))


def expand(
    roots: Sequence[Path | str],
    file: str,
    args: Mapping[str, Sequence[str]],
    env: Mapping[str, Sequence[str]] | None = None,
) -> Expanded:
    """``file`` expanded with each of ``args`` an input over the values given (and
    ``<unset>``, ``<other>``); ``env``: the values each variable's slots hold."""
    workspace = discover([Path(r) for r in roots], ros_package_path="")
    analysis = Analysis(workspace, env_values=env or {})
    space = analysis.space
    inputs: dict[str, ArgInput] = {}
    choices: dict[str, Choice[Raw | Missing]] = {}
    for name, values in args.items():
        input_ = ArgInput(file, name)
        space.declare_input(input_, (*dict.fromkeys(values), UNSET, OTHER))
        inputs[name] = input_
        branches: list[tuple[BDD, Raw | Missing]] = []
        for slot, atom in space.slot_atoms(input_):
            leaf = MISSING if slot is UNSET else Hole(input_) if slot is OTHER else str(slot)
            branches.append((atom, leaf))
        choices[name] = Choice.of(branches)
    reader = XacroReader(
        space, workspace.find, analysis.domains.env_domain, workspace.confinement()
    )
    return Expanded(analysis, file, reader.expand(file, choices, space.true), inputs)


def differences(
    expanded: Expanded, configurations: Iterable[Config], unknown: list[Config] | None = None
) -> list[str]:
    """The configurations where rosvar's restriction and the real xacro differ; those where
    rosvar says it does not know go to ``unknown``."""
    found = []
    for args, env in configurations:
        ours = expanded.restricted(args, env)
        if ours == UNKNOWN:
            if unknown is not None:
                unknown.append((args, env))
            continue
        theirs = run_xacro(expanded.file, args, env, expanded.packages)
        if isinstance(theirs, XacroFailed):
            if ours is not None:
                found.append(f"{dict(args)} {dict(env)}: xacro fails ({theirs.message})")
        elif ours != theirs:
            found.append(f"{dict(args)} {dict(env)}:\n  rosvar {ours}\n  xacro  {theirs}")
    return found


def one_at_a_time(
    args: Mapping[str, Sequence[str]], env: Mapping[str, Sequence[str]]
) -> list[Config]:
    """The defaults, then each arg and variable alone at each of its values."""
    found: list[Config] = [({}, {})]
    found += [({name: v}, {}) for name, values in args.items() for v in values]
    found += [({}, {name: v}) for name, values in env.items() for v in values]
    return found


def pairs(args: Mapping[str, Sequence[str]], env: Mapping[str, Sequence[str]]) -> list[Config]:
    """Every two choices together (bounded: tests pick few inputs)."""
    keyed = [("arg", n, v) for n, vs in args.items() for v in vs]
    keyed += [("env", n, v) for n, vs in env.items() for v in vs]
    found = one_at_a_time(args, env)
    for first, second in itertools.combinations(keyed, 2):
        if first[1] == second[1]:
            continue
        config: tuple[dict[str, str], dict[str, str]] = ({}, {})
        for kind, name, value in (first, second):
            config[0 if kind == "arg" else 1][name] = value
        found.append(config)
    return found


_ENV = re.compile(r"\$\((?:opt)?env\s+([A-Za-z_][A-Za-z0-9_]*)")
_ARG = re.compile(r"<xacro:arg\s+name=\"([^\"]+)\"")


def read_inputs(files: Iterable[str]) -> tuple[list[str], list[str]]:
    """The xacro args the first file declares and the variables all of them read."""
    args: list[str] = []
    env: list[str] = []
    for index, file in enumerate(files):
        text = Path(file).read_text(errors="replace")
        if index == 0:
            args += _ARG.findall(text)
        env += _ENV.findall(text)
    return list(dict.fromkeys(args)), list(dict.fromkeys(env))
