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
