"""A registry of one kind of launch API name: each entry once, found by its frontend name
(an XML/YAML tag) and by its Python name(s), aliases included."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Generic, Protocol, TypeVar

PythonName = tuple[str, str]
"""A Python callable by (package, name): ``launch_ros.actions.Node`` and
``launch_ros.actions.node.Node`` are both ``("launch_ros", "Node")``."""


def python_name(qualified: str) -> PythonName:
    """The (package, name) of a qualified Python name."""
    return qualified.partition(".")[0], qualified.rpartition(".")[2]


class Exposed(Protocol):
    """What a registry finds an entry by."""

    @property
    def names(self) -> tuple[str, ...]:
        """The frontend names (XML/YAML tags, ``$(name)``s); the first is the one the Python
        frontend writes; none for what has no name of its own (a condition is an attribute)."""
        ...

    @property
    def python(self) -> tuple[str, ...]:
        """Qualified Python names (``launch_ros.PushRosNamespace``), aliases included."""
        ...


T = TypeVar("T", bound=Exposed)


class Registry(Generic[T]):
    """The entries of one kind, by frontend name and by Python name."""

    def __init__(self, kind: str) -> None:
        self.kind = kind
        self.entries: list[T] = []
        self.by_name: dict[str, T] = {}
        self.by_python: dict[PythonName, T] = {}

    def expose(self, entry: T) -> T:
        """Register ``entry`` under each of its names; a name taken twice is refused (a
        second entry would silently replace the first)."""
        for name in entry.names:
            if name in self.by_name:
                raise ValueError(f"{self.kind} <{name}> is exposed twice")
        keys = [python_name(qualified) for qualified in entry.python]
        for key in keys:
            if key in self.by_python:
                raise ValueError(f"{self.kind} {'.'.join(key)} is exposed twice")
        self.entries.append(entry)
        self.by_name.update(dict.fromkeys(entry.names, entry))
        self.by_python.update(dict.fromkeys(keys, entry))
        return entry

    def __iter__(self) -> Iterator[T]:
        """Each entry once, in registration order."""
        return iter(self.entries)
