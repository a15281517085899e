"""``bench/include_walks.py``: the census of include walks counts what the memo did and the
keys of its walks, however loosely keyed."""

from __future__ import annotations

from pathlib import Path

import bench_scripts

walks = bench_scripts.load("include_walks")

MANIFEST = """<package format="3"><name>p</name>
<export><build_type>ament_cmake</build_type></export></package>"""

INCLUDE = '<include file="$(find-pkg-share p)/launch/b.launch.xml">{}</include>'
ENTRY = (
    '<launch><arg name="x" default="1"/>'
    + INCLUDE.format('<arg name="v" value="$(var x)"/>')
    + INCLUDE.format('<arg name="v" value="2"/>')
    + INCLUDE.format('<arg name="v" value="$(var x)"/>')
    + "</launch>"
)
INCLUDED = '<launch><arg name="v" default="0"/><node pkg="p" exec="e" name="n$(var v)"/></launch>'


def test_the_census_counts_replays_walks_and_keys(tmp_path: Path) -> None:
    package = tmp_path / "p"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST)
    (package / "launch" / "a.launch.xml").write_text(ENTRY)
    (package / "launch" / "b.launch.xml").write_text(INCLUDED)
    counted, cpu = walks.census(str(tmp_path))
    # the third include reads what the first read: replayed; the second reads '2'
    assert (counted.replays, counted.walks) == (1, 2)
    assert [len(keys) for keys in counted.keys.values()] == [2, 2, 2, 2]
    assert len(counted.names) == 1  # both walks read v alone
    assert counted.files == {str(package / "launch" / "b.launch.xml")}
    assert len(counted.pairs) == 1
    assert sorted(len(passes) for passes in counted.passes.values()) == [1, 1]
    lines = walks.report(counted, cpu)
    assert "includes replayed 1, walked 2" in lines
    assert "  passes thrown away: 0, 0.0 s" in lines


def test_a_pass_thrown_away_is_counted(tmp_path: Path) -> None:
    package = tmp_path / "p"
    (package / "launch").mkdir(parents=True)
    (package / "package.xml").write_text(MANIFEST)
    read_before = '<node pkg="p" exec="e" name="m$(var w z)"/>'  # read before declared below
    included = '<include file="$(find-pkg-share p)/launch/c.launch.xml"/>'
    (package / "launch" / "a.launch.xml").write_text(f"<launch>{read_before}{included}</launch>")
    (package / "launch" / "c.launch.xml").write_text('<launch><arg name="w" default="d"/></launch>')
    counted, cpu = walks.census(str(tmp_path))
    entry = str(package / "launch" / "a.launch.xml")
    assert [late for _seconds, late in counted.passes[entry]] == [True, False]
    assert "  passes thrown away: 1," in "\n".join(walks.report(counted, cpu))
