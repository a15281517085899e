"""The hints file: what static analysis cannot see, given by the user.

YAML with four optional mappings (see docs/hints.md); ``nodes`` gives node interfaces::

    nodes:                  # pkg/executable (or a nodelet's pkg/Class) -> interface entries
      my_pkg/driver_node:
        publishes: [{name: scan, type: sensor_msgs/LaserScan, when: "$(arg laser)"}]

    executables:            # package -> extra executable names (values of node types)
      my_pkg: [driver_node]
    args:                   # arg name, or FILE:arg (FILE = launch file name) -> extra values
      robot: [husky, jackal]
      bringup.launch:laser: [lms1xx]
    env:                    # environment variable -> values it may take
      TURTLEBOT_3D_SENSOR: [kinect, astra]
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import yaml

from rosvar.bounded_yaml import check_limits
from rosvar.diagnostics import Diagnostic, Location, Severity
from rosvar.files import read_file
from rosvar.workspace.interfaces.model import Entry, Origin, Role

SECTIONS = ("executables", "args", "env", "nodes")
NODE_KEYS = ("name", "type", "default", "when", "boundary")


@dataclass
class Hints:
    executables: dict[str, list[str]] = field(default_factory=dict)
    args: dict[str, list[str]] = field(default_factory=dict)
    env: dict[str, list[str]] = field(default_factory=dict)
    nodes: dict[str, list[Entry]] = field(default_factory=dict)
    diagnostics: list[Diagnostic] = field(default_factory=list)


def load_hints(path: str | None) -> Hints:
    """Read a hints file; problems are diagnostics, never exceptions."""
    hints = Hints()
    if path is None:
        return hints

    def problem(message: str, line: int = 1) -> Hints:
        hints.diagnostics.append(
            Diagnostic("hints-invalid", Severity.ERROR, message, Location(path, line, 1))
        )
        return hints

    try:
        text = read_file(path).decode("utf-8")
        check_limits(text)
        loader = yaml.SafeLoader(text)
        try:
            root = loader.get_single_node()
        finally:
            loader.dispose()
    except OSError as error:
        return problem(f"cannot read hints file: {error.strerror or error}")
    except UnicodeDecodeError as error:
        return problem(f"cannot read hints file: {error}")
    except yaml.YAMLError as invalid:
        mark = getattr(invalid, "problem_mark", None)
        return problem(f"invalid YAML: {invalid}", mark.line + 1 if mark else 1)
    if root is None:
        return hints
    if not isinstance(root, yaml.MappingNode):
        return problem("the hints file must be a mapping", _line(root))
    # composed nodes rather than safe_load: each problem can then name its own line
    for key_node, section in root.value:
        key = _scalar_text(loader, key_node)
        if key not in SECTIONS:
            sections = ", ".join(SECTIONS)
            problem(f"unknown section '{key}' (expected one of {sections})", _line(key_node))
            continue
        if not isinstance(section, yaml.MappingNode):
            problem(f"section '{key}' must map names to lists of values", _line(section))
            continue
        if key == "nodes":
            for node_key, node in section.value:
                name = str(_scalar_text(loader, node_key))
                hints.nodes[name] = _node_entries(loader, path, name, node, problem)
            continue
        target: dict[str, list[str]] = getattr(hints, key)
        for name_node, values in section.value:
            name = str(_scalar_text(loader, name_node))
            items = values.value if isinstance(values, yaml.SequenceNode) else [values]
            texts = [_scalar_text(loader, item) for item in items]
            if any(text is None for text in texts):
                problem(f"'{name}' in section '{key}' must list plain values", _line(values))
                continue
            target[name] = [text for text in texts if text is not None]
    return hints


def _line(node: yaml.Node) -> int:
    return int(node.start_mark.line) + 1


def _scalar_text(loader: yaml.SafeLoader, node: yaml.Node) -> str | None:
    """A value as launch files spell it (``true``, not ``True``); None when not a plain value."""
    if not isinstance(node, yaml.ScalarNode) or node.tag == "tag:yaml.org,2002:null":
        return None
    try:
        value = loader.construct_object(node)
    except yaml.YAMLError:  # e.g. a tag that the safe loader refuses
        return None
    return str(value).lower() if isinstance(value, bool) else str(value)


def _node_entries(
    loader: yaml.SafeLoader,
    path: str,
    node_name: str,
    node: yaml.Node,
    problem: Callable[[str, int], Hints],
) -> list[Entry]:
    """The entries of one ``nodes:`` item: role -> list of {name, type|default, when,
    boundary}."""
    entries: list[Entry] = []
    if not isinstance(node, yaml.MappingNode):
        problem(f"node '{node_name}' must map roles to lists of entries", _line(node))
        return entries
    roles = {str(role) for role in Role}
    for role_node, items in node.value:
        role = _scalar_text(loader, role_node)
        if role not in roles:
            problem(f"unknown role '{role}' of node '{node_name}'", _line(role_node))
            continue
        for item in items.value if isinstance(items, yaml.SequenceNode) else [items]:
            fields: dict[str, yaml.Node] = {}
            if isinstance(item, yaml.MappingNode):
                fields = {str(_scalar_text(loader, k)): v for k, v in item.value}
            name = _scalar_text(loader, fields["name"]) if "name" in fields else None
            unknown = set(fields) - set(NODE_KEYS)
            if name is None or unknown:
                problem(f"an entry of '{node_name}' needs a name and only {NODE_KEYS}", _line(item))
                continue
            value = {k: _scalar_text(loader, fields[k]) for k in NODE_KEYS[1:] if k in fields}
            default: str | bool | int | float | None = None
            if "default" in fields and isinstance(fields["default"], yaml.ScalarNode):
                constructed = loader.construct_object(fields["default"])
                if isinstance(constructed, bool | int | float | str):
                    default = constructed
            entries.append(
                Entry(
                    Role(role),
                    name,
                    Location(path, _line(item), 1),
                    Origin.HINTS,
                    type=value.get("type"),
                    default=default,
                    when=value.get("when"),
                    boundary=value.get("boundary") == "true",
                )
            )
    return entries
