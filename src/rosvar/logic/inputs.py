"""Inputs: the free variables of a launch configuration.

A configuration is fixed by what the user gives on the command line (the entry
file's args) and by the environment. Each input ranges over a finite *domain* of
slots: the literal values analysis knows about, ``UNSET`` (not given) and
``OTHER`` (any value analysis did not foresee). Exactly one slot holds.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Final


@dataclass(frozen=True, order=True)
class ArgInput:
    """A command-line ``name:=value`` of one entry launch file."""

    file: str
    name: str

    def __str__(self) -> str:
        return self.name


@dataclass(frozen=True, order=True)
class EnvInput:
    """An environment variable read by ``$(env)``, ``$(optenv)`` or ``env()``."""

    name: str

    def __str__(self) -> str:
        return f"${self.name}"


Input = ArgInput | EnvInput


class _Special:
    """A non-literal slot; a class (not a string) so no value can collide with it."""

    def __init__(self, label: str) -> None:
        self.label = label

    def __repr__(self) -> str:
        return self.label


UNSET: Final = _Special("<unset>")
OTHER: Final = _Special("<other>")

Slot = str | _Special
