"""Resolving one configuration: what it keeps of the launch tool's failures."""

from __future__ import annotations

import gc
from pathlib import Path

import dd.cudd

from rosvar.interpreter.workspace_models import Analysis
from rosvar.workspace import discover

MANIFEST = """<package format="3"><name>p</name>
<export><build_type>ament_cmake</build_type></export></package>"""


def test_an_error_of_a_value_failing_here_keeps_no_frames(tmp_path: Path) -> None:
    """A value tested by an error event that fails in the configuration resolved is the
    error reported; kept with its traceback it would tie the result, the analysis and its
    diagrams into a cycle the collector frees in any order, the BDD manager first (CUDD
    then warns of nodes still referenced)."""
    package = tmp_path / "p"
    package.mkdir()
    (package / "package.xml").write_text(MANIFEST)
    main = package / "main.launch.xml"
    test = "$(eval &quot;'_$(var x)' == '_q'&quot;)"
    main.write_text(
        f'<launch><arg name="x" default="a"/><node pkg="p" exec="e" name="n" if="{test}"/></launch>'
    )
    gc.collect()
    enabled = gc.isenabled()
    gc.disable()
    try:
        analysis = Analysis(discover([str(package)]))
        errors = analysis.resolve([str(main)], {"x": "'"}).errors
        [message] = [error.message for error in errors]
        assert message.startswith(
            "<node> attribute 'if': $(eval '_'' == '_q'): invalid Python expression"
        )
        del analysis, errors
        gc.set_debug(gc.DEBUG_SAVEALL)
        gc.collect()
        cycled = [o for o in gc.garbage if isinstance(o, dd.cudd.Function | dd.cudd.BDD)]
    finally:
        gc.set_debug(0)
        gc.garbage.clear()
        if enabled:
            gc.enable()
    assert not cycled
