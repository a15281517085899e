"""The attributes and child tags ros2/launch's frontends accept, per tag, checked as they do.

The frontend parses a whole file when it is loaded and fails on an element it does not
know or an attribute nothing read, even inside a group that is never entered: so the check
runs over the whole tree at each load, under the path of the load.
"""

from __future__ import annotations

from collections.abc import Iterator

from rosvar.diagnostics import Location
from rosvar.frontends.entity import Entity
from rosvar.interpreter.interpretation import Interpretation
from rosvar.memo import Memo
from rosvar.ros.version import RosVersion
from rosvar.ros2.api.actions import ACTIONS, SHARED
from rosvar.ros2.context import Context
from rosvar.workspace.launch_files import LaunchFormat, format_of

ATTRIBUTES: dict[str, frozenset[str]] = {
    name: action.attributes for action in ACTIONS for name in action.names if not action.python_only
}
"""What the XML and YAML frontends accept, per tag (:data:`rosvar.ros2.api.actions.ACTIONS`)."""
PYTHON_ATTRIBUTES = ATTRIBUTES | {
    name: action.attributes for action in ACTIONS for name in action.names if action.python_only
}
"""What the Python frontend's elements may be (``LifecycleNode`` has no XML or YAML tag)."""
PYTHON_CHILD_ATTRIBUTES = ATTRIBUTES | {
    "param": ATTRIBUTES["param"] | {"content"},
    "remap": ATTRIBUTES["remap"] | {SHARED},
}
"""What the Python frontend's inner elements may hold: a parameter file its Python writes
is a ``<param>`` with its text (``content``, :mod:`rosvar.ros2.frontends.python.written`);
a remap the file gives to several nodes is marked so (:mod:`.frontends.python.shared_remaps`)."""
ALWAYS = frozenset({"if", "unless"})
CONTAINERS = frozenset(name for action in ACTIONS if action.holds_actions for name in action.names)


Problem = tuple[str, str, Location]
"""A frontend failure: its code, message and place."""
_problems: Memo[Entity, tuple[Problem, ...]] = Memo()
"""Each parsed file's problems, found once: a file is checked at every include of it."""


def check(it: Interpretation[Context], root: Entity) -> None:
    """Record the frontend's failure for every unknown element or attribute below ``root``."""
    problems = _problems.get(root)
    if problems is None:
        python = format_of(root.location.file, RosVersion.ROS2) is LaunchFormat.PYTHON
        if python:
            problems = tuple(_check(root, PYTHON_ATTRIBUTES, PYTHON_CHILD_ATTRIBUTES))
        else:
            problems = tuple(_check(root, ATTRIBUTES, ATTRIBUTES))
        _problems[root] = problems
    for code, message, location in problems:
        it.fail(it.space.true, code, message, location)


def _check(
    root: Entity, attributes: dict[str, frozenset[str]], inner: dict[str, frozenset[str]]
) -> Iterator[Problem]:
    """The problems of every element below ``root``, in document order; a loop rather than
    a recursion: a hostile file nests thousands of groups, and the walk itself stops at its
    nesting limit (``nesting-too-deep``), not here."""
    pending: list[tuple[Entity, bool]] = [(child, True) for child in reversed(root.children)]
    while pending:
        entity, action = pending.pop()
        allowed = (attributes if action else inner).get(entity.tag)
        if allowed is None:
            if action:
                yield (
                    "tag-unknown",
                    f"Unrecognized entity of the type: {entity.tag}",
                    entity.location,
                )
                continue
            allowed = frozenset()
        container = action and entity.tag in CONTAINERS  # its children are actions
        children = [] if container or not action else [child.tag for child in entity.children]
        unexpected = sorted(
            name
            for name in [*entity.attributes, *children]
            if name not in allowed and name not in ALWAYS
        )
        if unexpected:
            yield (
                "attribute-unexpected",
                f"Unexpected attribute(s) found in `{entity.tag}`: {set(unexpected)}",
                entity.location,
            )
            if action:
                continue
        # a container's children are actions; a leaf action's (``<param>`` in a node, ``<arg>``
        # in an include...) are checked for their attributes only, at every depth
        pending.extend((child, container) for child in reversed(entity.children))
