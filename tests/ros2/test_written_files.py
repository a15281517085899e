"""``$(rosvar-written-file)``: the readings of helpers' ``perform`` one analysis affords."""

from __future__ import annotations

from pathlib import Path

from rosvar.ros2 import written_files
from rosvar.workspace import discover


def test_an_analysis_reads_a_bounded_number_of_argument_sets(tmp_path: Path) -> None:
    """Each distinct set of a helper's arguments is a reading of its whole source file; past
    :data:`MAX_READINGS` the file is left to each configuration. A set read already costs
    nothing more, and another analysis has its own count."""
    first, second = discover([tmp_path]), discover([tmp_path])
    sets = [("module.py", "pkg", "Rewritten", repr(((str(i),), {}))) for i in range(9)]
    limit = written_files.MAX_READINGS
    assert [written_files._affordable(first, s) for s in sets] == [
        i < limit for i in range(len(sets))
    ]
    assert all(written_files._affordable(first, s) for s in sets[:limit])
    assert written_files._affordable(second, sets[-1])
