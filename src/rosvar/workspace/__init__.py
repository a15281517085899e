"""Workspace discovery: packages and launch files below the user's paths."""

from rosvar.workspace.packages import Package, Workspace, discover

__all__ = ["Package", "Workspace", "discover"]
