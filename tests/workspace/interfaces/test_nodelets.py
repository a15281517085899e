"""Nodelet classes from the plugin description that package.xml exports."""

from __future__ import annotations

from pathlib import Path

from rosvar.diagnostics import DiagnosticSink
from rosvar.workspace.interfaces.nodelets import nodelet_classes

PACKAGE = """<package format="2"><name>demo</name>
  <export><nodelet plugin="${prefix}/plugins/nodelets.xml"/></export></package>"""
PLUGINS = """<class_libraries>
  <library path="lib/libdemo_nodelets">
    <class name="demo/A" type="demo::A" base_class_type="nodelet::Nodelet"/>
    <class name="demo/B" type="demo::B" base_class_type="nodelet::Nodelet"/>
  </library>
</class_libraries>"""


def test_classes(tmp_path: Path) -> None:
    (tmp_path / "package.xml").write_text(PACKAGE)
    (tmp_path / "plugins").mkdir()
    (tmp_path / "plugins" / "nodelets.xml").write_text(PLUGINS)
    classes = nodelet_classes(str(tmp_path), DiagnosticSink())
    assert [(c.name, c.type, c.library) for c in classes] == [
        ("demo/A", "demo::A", "demo_nodelets"),
        ("demo/B", "demo::B", "demo_nodelets"),
    ]


def test_missing_plugin_file_is_a_diagnostic(tmp_path: Path) -> None:
    (tmp_path / "package.xml").write_text(PACKAGE)
    sink = DiagnosticSink()
    assert nodelet_classes(str(tmp_path), sink) == []
    assert [d.code for d in sink.items] == ["nodelet-plugins-unreadable"]


def test_several_libraries_without_a_root(tmp_path: Path) -> None:
    """pointcloud_to_laserscan's nodelets.xml: two <library> elements side by side."""
    (tmp_path / "package.xml").write_text(PACKAGE)
    (tmp_path / "plugins").mkdir()
    (tmp_path / "plugins" / "nodelets.xml").write_text(
        '<?xml version="1.0"?>\n<library path="lib/liba">\n'
        '  <class name="demo/A" type="demo::A" base_class_type="nodelet::Nodelet"/>\n'
        '</library>\n<library path="lib/libb">\n'
        '  <class name="demo/B" type="demo::B" base_class_type="nodelet::Nodelet"/>\n'
        "</library>\n"
    )
    sink = DiagnosticSink()
    classes = nodelet_classes(str(tmp_path), sink)
    assert [(c.name, c.library, c.location.line) for c in classes] == [
        ("demo/A", "a", 3),
        ("demo/B", "b", 6),
    ]
    assert sink.items == []
