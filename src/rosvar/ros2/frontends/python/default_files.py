"""Files named by a launch argument, read for the argument's default.

autoware's helpers load their configuration from a file a launch argument names
(``yaml.safe_load(open(LaunchConfiguration('config_file').perform(context)))``) and build
their nodes from its content: how many, which topics. The file is known only per
configuration, but the argument's default, declared in the same file
(``DeclareLaunchArgument('config_file', default_value=share + '/config/x.yaml')``), names one
the reading can open. So an ``OpaqueFunction`` whose function opens such a file is read twice:
once with the files the defaults name, its actions under the condition that each argument
is its default (``$(rosvar-configuration-equals config_file DEFAULT)``, true in exactly the
configurations where launch reads that file), and once as before, the file unknown, under the
negation. Each reading is correct where its condition holds, whatever value an includer gives.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from rosvar.ros2.frontends.python.text import CONFIGURATION_EQUALS, Sub, Text
from rosvar.ros2.frontends.python.values import Dynamic, Value

MAX_ASSUMED = 4
"""Arguments whose default file one function reads at once; more: none is assumed."""


@dataclass
class DefaultFiles:
    """The defaults declared so far, and the files assumed or wanted while a function is read."""

    defaults: dict[str, Text] = field(default_factory=dict)
    """Launch argument name to its default's text, as declared in the file."""
    assuming: dict[str, str] = field(default_factory=dict)
    """Arguments read as their default, to the file it names."""
    wanted: set[str] = field(default_factory=set)
    """Arguments naming a file opened whose default names a file known statically."""

    def declare(self, name: Value, default: Value) -> None:
        """A ``DeclareLaunchArgument(name, default_value=default)`` read."""
        if isinstance(default, Dynamic):
            default = default.text
        if isinstance(default, str):
            default = Text.of(default)
        if isinstance(name, str) and isinstance(default, Text):
            self.defaults[name] = default

    def opened(self, named: Text, path_of: Callable[[Value], str | None]) -> str | None:
        """The file ``open`` reads where its path is the text ``named``: the default's, when
        the argument it is is assumed its default; else ``None`` (wanted where it could)."""
        name = _argument(named)
        if name is None:
            return None
        if name in self.assuming:
            return self.assuming[name]
        default = self.defaults.get(name)
        if default is not None and path_of(default) is not None:
            self.wanted.add(name)
        return None

    def assume(self, names: set[str], path_of: Callable[[Value], str | None]) -> Text | None:
        """Read the arguments ``names`` as their defaults from now on: the condition that they
        are, or ``None`` if too many."""
        if not names or len(names) > MAX_ASSUMED:
            return None
        test: Text | None = None
        for name in sorted(names):
            path = path_of(self.defaults[name])
            assert path is not None
            self.assuming[name] = path
            equals = Text.of(Sub(CONFIGURATION_EQUALS, (Text.of(name), self.defaults[name])))
            test = equals if test is None else Text.of(Sub("and", (test, equals)))
        return test


def _argument(text: Text) -> str | None:
    """The launch argument ``text`` is the value of (``$(var name)``), if it is."""
    only = text.parts[0] if len(text.parts) == 1 else None
    if isinstance(only, Sub) and only.name == "var" and len(only.args) == 1:
        return only.args[0].literal()
    return None
