"""The mutable values each branch of an ``if`` on a launch-time value changes, kept apart.

Both branches of such an ``if`` are read, one after the other, on the same objects; Python
runs one of them. A branch therefore works on the values as they were before the ``if``:
the first time it changes a list, a dict or an object's attributes, its :class:`Journal`
keeps what the value held, and when the branch ends the journal keeps what it holds then
and puts the old content back. The interpreter then gives each changed value the choice of
the two branches' contents under the test. Aliasing inside a branch is kept (the changes
are to the objects themselves); a value may also be *forwarded* to another (a choice of two
lists of different lengths cannot be one list): the journal keeps forwarding as content.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from rosvar.ros2.frontends.python.values import Instance, Key, Value

Mutable = list[Value] | dict[Key, Value] | Instance
"""The values a branch changes in place."""

Contents = tuple[list[Value] | dict[Key, Value] | dict[str, Value], Value | None]
"""What a mutable value holds: its items (an object's attributes), and the value it is
forwarded to (``None``: none)."""


@dataclass(eq=False, slots=True)
class Forwarding:
    """Mutable values that stand for other values (a list changed by a launch-time ``if``
    into a choice of two lists), by identity; each entry keeps its object alive, so that
    identities stay unique."""

    to: dict[int, tuple[Mutable, Value]] = field(default_factory=dict)

    def resolved(self, value: Value) -> Value:
        """The value ``value`` stands for."""
        while isinstance(value, list | dict | Instance) and id(value) in self.to:
            value = self.to[id(value)][1]
        return value

    def forward(self, value: Mutable, to: Value) -> None:
        self.to[id(value)] = (value, to)


def contents(value: Mutable, forwarding: Forwarding) -> Contents:
    """A copy of what ``value`` holds (shallow: inner values are changed through their own)."""
    forwarded = forwarding.to.get(id(value))
    items = dict(value.attributes) if isinstance(value, Instance) else value.copy()
    return items, None if forwarded is None else forwarded[1]


def put(value: Mutable, held: Contents, forwarding: Forwarding) -> None:
    """Make ``value`` hold ``held`` again."""
    items, forwarded = held
    if isinstance(value, Instance):
        value.attributes = dict(items)  # type: ignore[arg-type]
    elif isinstance(value, list) and isinstance(items, list):
        value[:] = items
    elif isinstance(value, dict) and isinstance(items, dict):
        value.clear()
        value.update(items)
    if forwarded is None:
        forwarding.to.pop(id(value), None)
    else:
        forwarding.forward(value, forwarded)


@dataclass(eq=False, slots=True)
class Journal:
    """The mutable values one branch changed: what each held before, and (once the branch
    ended) what it held after."""

    before: dict[int, tuple[Mutable, Contents]] = field(default_factory=dict)
    after: dict[int, Contents] = field(default_factory=dict)

    def touch(self, value: Mutable, forwarding: Forwarding) -> None:
        """Called before ``value`` changes."""
        if id(value) not in self.before:
            self.before[id(value)] = (value, contents(value, forwarding))

    def close(self, forwarding: Forwarding) -> None:
        """Keep what the branch left and put back what was before it."""
        for key, (value, held) in self.before.items():
            self.after[key] = contents(value, forwarding)
            put(value, held, forwarding)

    def reopen(self, forwarding: Forwarding) -> None:
        """Put back what the branch left, to read on in it."""
        for key, (value, _) in self.before.items():
            put(value, self.after[key], forwarding)
