"""The robot descriptions' Gazebo plugins (and the bridges, :mod:`.bridges`) as edges of the
communication graph.

Each plugin's use of a name is an edge of the spawner that loads the description, under the
spawner's condition (its fields' branch, its ``args``), the description's (the parameter or
topic it is read from, xacro not failing) and the plugin's own (``<xacro:if>``, a conditional
value). The edge's node is the plugin, named after the spawner (``/spawn_model: gazebo
plugin imu_controller``): Gazebo runs it, the spawner decides whether and where it exists.
What cannot be read is a :class:`~rosvar.analyses.communication.Gap` with its condition:
xacro failing (the spawner spawns nothing there), a part of the description not followed, a
plugin of a library rosvar does not know.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace

from rosvar.analyses.communication import Edge, Gap
from rosvar.analyses.controllers import controller_edges
from rosvar.analyses.robot_description.bridges import Bridges
from rosvar.analyses.robot_description.document import Description
from rosvar.analyses.robot_description.plugins import plugin_uses
from rosvar.analyses.robot_description.reading import XacroReader
from rosvar.analyses.robot_description.spawns import Spawn, Spawns
from rosvar.diagnostics import Location, Severity
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.resolution import ResolutionError, Restriction
from rosvar.interpreter.workspace_models import Analysis
from rosvar.logic.atoms import SlotAtom
from rosvar.logic.bdd import BDD
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import OTHER
from rosvar.workspace.interfaces.model import Interfaces

PARTIAL_CODES = frozenset({"xacro-unsupported", "xacro-too-large", "package-unknown"})


class Simulation:
    """What a simulation adds to the graph of the launch models of one analysis, read once
    per model: the plugins of the descriptions their spawners load, their bridges, the
    controllers their spawners load (their types' uses from ``interfaces``)."""

    def __init__(self, analysis: Analysis, interfaces: Interfaces) -> None:
        workspace = analysis.workspace
        self.space = analysis.space
        self.interfaces = interfaces
        self.confinement = workspace.confinement()
        self.reader = XacroReader(
            analysis.space, workspace.find, analysis.domains.env_domain, workspace.confinement()
        )
        self.spawns = Spawns(analysis.space, self.reader, interfaces)
        self.bridges = Bridges(analysis.space, workspace.confinement())
        self._read: dict[str, tuple[list[Edge], list[Gap]]] = {}
        self._spawned: dict[str, list[Spawn]] = {}
        self._fails: dict[str, BDD] = {}

    def edges(self, model: LaunchModel) -> list[Edge]:
        return self._of(model)[0]

    def gaps(self, model: LaunchModel) -> list[Gap]:
        return self._of(model)[1]

    def fails(self, model: LaunchModel) -> BDD:
        found = self._fails.get(model.file)
        if found is None:
            found = self.space.false
            for spawn in self._spawns(model):
                found |= spawn.condition & spawn.description.fails
            self._fails[model.file] = found
        return found

    def _spawns(self, model: LaunchModel) -> list[Spawn]:
        self._of(model)
        return self._spawned[model.file]

    def _of(self, model: LaunchModel) -> tuple[list[Edge], list[Gap]]:
        found = self._read.get(model.file)
        if found is None:
            spawns, gaps = self.spawns.of(model)
            self._spawned[model.file] = spawns
            edges, bridge_gaps = self.bridges.of(model)
            gaps.extend(bridge_gaps)
            edges.extend(controller_edges(self.space, model, self.interfaces, self.confinement))
            for spawn in spawns:
                edges.extend(self._spawn_edges(model, spawn, gaps))
                gaps.extend(_description_gaps(self.space, spawn))
            found = self._read[model.file] = (edges, gaps)
        return found

    def _spawn_edges(self, model: LaunchModel, spawn: Spawn, gaps: list[Gap]) -> list[Edge]:
        description = spawn.description
        if description.root is None:
            return []
        present = spawn.condition  # where xacro fails, the launch does: not on the edges
        uses, unread = plugin_uses(self.space, description.root, spawn.ros, spawn.spawning)
        spawner = spawn.launched.full_name
        for plugin in unread:
            condition = present & plugin.condition
            if self.space.satisfiable(condition):
                gaps.append(
                    Gap(
                        str(plugin.filename),
                        f"{spawner} spawns a Gazebo plugin {plugin.filename} whose topics "
                        "rosvar does not know",
                        condition,
                        (spawn.node.location, plugin.location),
                        Severity.NOTE,
                    )
                )
        edges = []
        for use in uses:
            condition = present & use.condition
            if condition == self.space.false:
                continue
            name = use.name if isinstance(use.name, str) else str(use.name)
            edges.append(
                Edge(
                    model.file,
                    f"{spawner}: gazebo plugin {use.plugin}",
                    use.role,
                    name,
                    use.type,
                    condition,
                    spawn.node.location,
                    use.location,
                    isinstance(use.name, str) and "{" not in name,
                    use.boundary,
                    None if isinstance(use.name, str) else use.name,
                )
            )
        return edges


def _description_gaps(space: ConditionSpace, spawn: Spawn) -> list[Gap]:
    """Where xacro fails (the launch stops) or the description is read only in part; a
    failure only values nobody foresaw cause (``<other>``) is a note."""
    description = spawn.description
    spawner = spawn.launched.full_name
    gaps = []
    for failure in description.failures:
        condition = spawn.condition & failure.condition
        foreseen = space.satisfiable(foreseen_only(space, condition))
        gaps.append(
            Gap(
                description.file,
                f"xacro fails on {description.file} (the launch stops, {spawner} spawns "
                f"nothing): {failure.message}",
                condition,
                (spawn.node.location, failure.location),
                Severity.WARNING if foreseen else Severity.NOTE,
                stops=True,
            )
        )
    for diagnostic in description.diagnostics:
        if diagnostic.code == "description-unexpanded":
            gaps.append(
                Gap(
                    description.file,
                    f"{spawner} spawns a description that holds xacro, unexpanded (a "
                    f"textfile or a file, not a xacro command): {diagnostic.message}",
                    spawn.condition,
                    (spawn.node.location, diagnostic.location),
                    Severity.WARNING,
                )
            )
    partial = [d for d in description.diagnostics if d.code in PARTIAL_CODES]
    if partial and description.unknown is not None:
        gaps.append(
            Gap(
                description.file,
                f"{spawner} spawns {description.file}, read only in part: {partial[0].message}",
                spawn.condition & description.unknown & description.present,
                (spawn.node.location, *_locations(description)),
                Severity.NOTE,
            )
        )
    return gaps


def foreseen_only(space: ConditionSpace, condition: BDD) -> BDD:
    """``condition`` where no input holds a value analysis did not foresee (``<other>``)."""
    fixed = {}
    for name in space.support(condition):
        atom = space.atom_of(name)
        if isinstance(atom, SlotAtom) and atom.slot is OTHER:
            fixed[name] = False
    return space.cofactor(condition, fixed) if fixed else condition


def _locations(description: Description) -> tuple[Location, ...]:
    return tuple(
        dict.fromkeys(d.location for d in description.diagnostics if d.code in PARTIAL_CODES)
    )[:3]


@dataclass
class ConfigurationEdges:
    """What a simulation adds to one configuration: its edges, and the errors that stop the
    launch (xacro failing on a description a spawner reads)."""

    edges: list[Edge] = field(default_factory=list)
    errors: list[ResolutionError] = field(default_factory=list)


def configuration_edges(
    analysis: Analysis,
    files: Sequence[str],
    args: Mapping[str, str],
    env: Mapping[str, str],
    interfaces: Interfaces,
) -> ConfigurationEdges:
    """The variational edges of ``files`` restricted to the configuration ``args``/``env``
    (``rosvar resolve``'s), read before the restriction is made: reading a description
    declares the environment variables it reads."""
    simulation = Simulation(analysis, interfaces)
    models = [analysis.model(file) for file in files]
    for model in models:
        simulation.edges(model)
    found = ConfigurationEdges()
    for model in models:
        restriction = Restriction(analysis, model, args, env)
        for edge in simulation.edges(model):
            if not restriction.holds(edge.condition):
                continue
            if edge.term is not None:
                try:
                    name = restriction.evaluate(edge.term, edge.source, "plugin name")
                except ResolutionError:
                    continue
                edge = replace(edge, name=name, static="{" not in name, term=None)
            found.edges.append(edge)
        for gap in simulation.gaps(model):
            if gap.stops and restriction.holds(gap.condition) and not found.errors:
                found.errors.append(ResolutionError("launch-stops", gap.message, gap.locations[0]))
    return found
