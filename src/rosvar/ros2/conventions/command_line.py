"""A ROS 2 node's command line as rcl reads it: ``--ros-args`` sections (up to ``--``) hold
remappings (``-r from:=to``, ``__node``/``__ns`` renaming the node), parameters (``-p
name:=value``, ``--params-file path``) and other ROS options; everything else is the
program's own arguments."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import yaml

from rosvar import bounded_yaml

REMAP = frozenset({"-r", "--remap"})
PARAM = frozenset({"-p", "--param"})
PARAMS_FILE = "--params-file"


@dataclass
class RosArguments:
    """What the ``--ros-args`` sections of one command line set, in order."""

    remaps: list[tuple[str, str]] = field(default_factory=list)
    parameters: list[tuple[str, object] | str] = field(default_factory=list)
    """``(name, value)`` for ``-p``, a path for ``--params-file``, in command-line order."""
    name: str | None = None
    namespace: str | None = None
    program: list[str] = field(default_factory=list)
    """The arguments outside ``--ros-args`` sections: the program's own."""


def parse(argv: Sequence[str]) -> RosArguments:
    """``argv`` (without the executable) read as rcl does; the first ``__node`` and ``__ns``
    rules win, as rcl's first matching rule does."""
    result = RosArguments()
    ros: list[str] = []
    in_ros = False
    for word in argv:
        if word == "--ros-args":
            in_ros = True
        elif word == "--" and in_ros:
            in_ros = False
        else:
            (ros if in_ros else result.program).append(word)
    at = 0
    while at < len(ros):
        option, value = ros[at], ros[at + 1] if at + 1 < len(ros) else None
        at += 1
        if value is None:
            continue
        if option in REMAP:
            source, _, target = value.partition(":=")
            if source in ("__node", "__name"):
                result.name = result.name or target
            elif source == "__ns":
                result.namespace = result.namespace or target
            else:
                result.remaps.append((source, target))
        elif option in PARAM:
            name, _, text = value.partition(":=")
            result.parameters.append((name, _value(text)))
        elif option == PARAMS_FILE:
            result.parameters.append(value)
        else:
            continue
        at += 1
    return result


def _value(text: str) -> object:
    """``-p``'s value: YAML, or the text where it is not YAML."""
    try:
        return bounded_yaml.safe_load(text)
    except yaml.YAMLError:
        return text
