"""Every launch description source: one registration each. An ``IncludeLaunchDescription``
of any of them is an ``<include file=...>`` of its path, whatever format the file is."""

from __future__ import annotations

from dataclasses import dataclass

from rosvar.ros2.api.registry import Registry


@dataclass(frozen=True)
class DescriptionSource:
    python: tuple[str, ...]
    """Qualified Python class names."""
    names: tuple[str, ...] = ()  # no frontend name: a source is the include's file


SOURCES: Registry[DescriptionSource] = Registry("description source")
SOURCES.expose(
    DescriptionSource(
        (
            "launch.PythonLaunchDescriptionSource",
            "launch.AnyLaunchDescriptionSource",
            "launch.FrontendLaunchDescriptionSource",
            "launch_xml.XMLLaunchDescriptionSource",
            "launch_yaml.YAMLLaunchDescriptionSource",
        )
    )
)
