"""The ROS 1 dialect: roslaunch's XML, substitution args and scope, what a ``<node>`` means and
the resolution of one configuration; its tag registry is filled by :mod:`rosvar.ros1.tags`."""

import functools

from rosvar.frontends.xml import load_launch_file
from rosvar.interpreter.dialect import Loader
from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.semantics import Semantics
from rosvar.interpreter.substitution_args import Substituter, shared_texts
from rosvar.ros.version import RosVersion
from rosvar.ros1 import controllers  # noqa: F401 - registers its spawners' controllers
from rosvar.ros1.entry import walk_entry
from rosvar.ros1.nodes import ROS1_NODES
from rosvar.ros1.resolve import ROS1_CHECKS, node_fields, resolve
from rosvar.ros1.scope import Scope
from rosvar.workspace import Workspace


def substituter(it: Interpretation[Scope]) -> Substituter:
    """roslaunch's substitution args, sharing resolved texts among the analysis's walks."""
    return Substituter(it, shared_texts(it.files))


def workspace_loader(workspace: Workspace) -> Loader:
    """roslaunch's XML for ``workspace``'s files, each resolved (its check of the system
    trees) as the workspace's confinement resolves paths: once per directory for the
    analysis (Husky reads 192 files)."""
    return functools.partial(load_launch_file, resolve=workspace.confinement().resolve)


ROS1: Semantics[Scope] = Semantics(
    RosVersion.ROS1,
    load_launch_file,
    substituter,
    walk_entry,
    ROS1_NODES,
    resolve,
    node_fields,
    ROS1_CHECKS,
    bind=workspace_loader,
)
tag = ROS1.tag
"""Register a ROS 1 tag handler."""
