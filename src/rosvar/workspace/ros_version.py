"""Which ROS a package, and so a workspace, belongs to.

ROS 1 and ROS 2 launch files share names (``*.launch.xml``) and tags (``<arg>``, ``<node>``)
but not their meaning, so a workspace is read as one or the other, never both. A package
says which through its build tool: ``catkin`` for ROS 1, an ``ament_*`` tool for ROS 2,
named by ``<buildtool_depend>`` or ``<export><build_type>`` in ``package.xml``.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable

from rosvar.frontends.entity import Entity
from rosvar.ros.version import RosVersion

# Build tools by name; a prefix entry (ending in "_") covers the tool's variants
# (ament_cmake_auto, ament_cmake_python, ...).
BUILD_TOOLS: dict[str, RosVersion] = {
    "catkin": RosVersion.ROS1,
    "ament_": RosVersion.ROS2,
}
_BUILD_TOOL_TAGS = ("buildtool_depend", "buildtool_export_depend")
VERSION_TAGS = frozenset({"export", "build_type", *_BUILD_TOOL_TAGS})
"""The manifest elements :func:`package_version` reads."""


def build_tool_version(name: str) -> RosVersion | None:
    """The ROS a build tool belongs to; None for neutral ones (plain ``cmake``)."""
    for key, version in BUILD_TOOLS.items():
        if name == key or (key.endswith("_") and name.startswith(key)):
            return version
    return None


def package_version(manifest: Entity) -> RosVersion | None:
    """The ROS of the package whose ``package.xml`` root is ``manifest``; None if it names
    no build tool of either (such a package goes with whatever workspace holds it).

    ``<export><build_type>`` wins over ``<buildtool_depend>``: a package may depend on
    ``ament_cmake`` only to be built by it.
    """
    declared: list[str] = []
    for child in manifest.children:
        if child.tag == "export":
            declared[:0] = [c.text.strip() for c in child.children if c.tag == "build_type"]
        elif child.tag in _BUILD_TOOL_TAGS:
            declared.append(child.text.strip())
    for name in declared:
        version = build_tool_version(name)
        if version is not None:
            return version
    return None


def majority(versions: Iterable[RosVersion]) -> RosVersion | None:
    """The version most packages have (ROS 1 on a tie, as rosvar was ROS 1 first); None
    for no versions at all."""
    counts = Counter(versions)
    if not counts:
        return None
    return max(RosVersion, key=lambda version: (counts[version], version == RosVersion.ROS1))
