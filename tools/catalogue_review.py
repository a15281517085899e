"""The review by hand of the bundled catalogue's nodes (``tools/build_catalogue.py``) and
the shape of its tables, shared by the ROS 1 tables there and the ROS 2 ones in
``catalogue_ros2.py``."""

from __future__ import annotations

from dataclasses import dataclass, field

ROLES = (
    "publishes",
    "subscribes",
    "services",
    "clients",
    "action_servers",
    "action_clients",
    "params",
)

Item = dict[str, object]


@dataclass(frozen=True)
class Review:
    """What reading a node's sources by hand changed: ``note`` says what and why (it is
    written to the catalogue), ``add`` holds entries the extractor cannot see, each with the
    file and line that make it, ``drop`` the names (per role) it took wrongly, ``boundary``
    the names (per role) meant for something outside the launched nodes (people and their
    tools, diagnostics monitors; see TF_TOPICS for tf)."""

    note: str
    add: dict[str, list[Item]] = field(default_factory=dict)
    drop: dict[str, list[str]] = field(default_factory=dict)
    boundary: dict[str, list[str]] = field(default_factory=dict)
    named: dict[str, dict[int, Item]] = field(default_factory=dict)
    """Per role, the entries (by line) whose name is a parameter's value: their ``named_by``
    (``{"parameter": "~imu{N}"}``) and ``default``."""
    when: dict[str, dict[int, str]] = field(default_factory=dict)
    """Per role, the entries (by line) that a condition on the node's parameters switches
    on (``param('~use_control')``, as a hint's ``when:``)."""
    defaults: dict[int, object] = field(default_factory=dict)
    """The parameter reads (by line) the extractor took for required whose code, read by
    hand, goes on when the parameter is unset: what it falls back to (a literal, or
    ``{"expression": ...}`` for what the code keeps or computes). ``param-unset`` reports
    required reads only (docs/checks.md)."""
    node_name: str | None = None
    """ROS 2: the name the code gives the node, where the extractor found several (a
    library's helper nodes) or a name passed in ``NodeOptions`` arguments."""
    loads: tuple[str, str] | None = None
    """The (package, executable) of the catalogue whose code the node runs in-process under
    its own name (a nodelet class through ``nodelet::Loader``, another package's node
    class): the node has its entries too, its own read first."""
    kind: str = "node"
    """What an extra item (one no source defines) is: ``controller`` for a controller type,
    a plugin the controller manager loads (its ``executable`` the type, as the manager's
    parameter ``NAME.type`` names it)."""


def by_parameter(parameter: str, default: object = None, namespace: str = "") -> Item:
    named: Item = {"parameter": parameter}
    if namespace:
        named["namespace"] = namespace
    return {"named_by": named, "default": default}


def use(name: str, kind: str | None, file: str, line: int) -> Item:
    return {"name": name, "type": kind, "file": file, "line": line}


def read(name: str, default: object, file: str, line: int) -> Item:
    return {"name": name, "default": default, "file": file, "line": line}


@dataclass(frozen=True)
class Source:
    """A repository to catalogue: its ``branch``, the ``folders`` holding its packages
    (``""``: the repository's root), and ``headers``, folders of packages read only for the
    headers they define (a dependency's wrapper classes: ``nav2_util``'s action server),
    whose nodes are not catalogued."""

    repository: str
    branch: str
    folders: list[str]
    headers: list[str] = field(default_factory=list)


@dataclass(frozen=True)
class Edition:
    """One ROS version's catalogue: what it is built from and the review of its nodes;
    ``extra`` holds nodes no source defines, by (repository, package, executable)."""

    sources: list[Source]
    review: dict[tuple[str, str], Review]
    extra: dict[tuple[str, str, str], Review]
