"""What the checks and the queries read beside the launch models, built one way for
``rosvar check``, ``rosvar query`` and the web UI, so that they answer alike: the nodes'
interfaces, the workspace's read gate, and the simulation (the Gazebo plugins of the robot
descriptions the spawners load, the bridges, the controllers ros_control's spawners load),
which reads each model's part when it is first asked for."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from rosvar.analyses.checks import Checks, Finding, check_models
from rosvar.analyses.query.channels import channel_collections
from rosvar.analyses.query.collections import Collection
from rosvar.analyses.robot_description.edges import Simulation
from rosvar.files import Confinement
from rosvar.interpreter.model import LaunchModel
from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace.interfaces.model import Interfaces


@dataclass(frozen=True)
class GraphInputs:
    """The inputs of an analysis's checks and queries."""

    analysis: Analysis
    interfaces: Interfaces
    confinement: Confinement
    simulation: Simulation

    def checks(self) -> Checks:
        """The checks, to be taken a file at a time."""
        workspace = self.analysis.workspace
        return Checks(
            self.analysis.space,
            self.interfaces,
            self.confinement,
            self.simulation,
            workspace.of_dependency,
        )

    def findings(self, models: Sequence[LaunchModel]) -> list[Finding]:
        """The findings of ``models`` (:func:`~rosvar.analyses.checks.check_models`)."""
        analysis = self.analysis
        return check_models(
            analysis.space,
            models,
            self.interfaces,
            self.confinement,
            self.simulation,
            analysis.workspace.of_dependency,
        )

    def collections(self) -> dict[str, Collection]:
        """The query collections of the communication graph (topics, services, actions)."""
        return channel_collections(self.interfaces, self.simulation)


def graph_inputs(analysis: Analysis, interfaces: Interfaces) -> GraphInputs:
    """The inputs of ``analysis``'s checks and queries over ``interfaces``."""
    confinement = analysis.workspace.confinement()
    return GraphInputs(analysis, interfaces, confinement, Simulation(analysis, interfaces))
