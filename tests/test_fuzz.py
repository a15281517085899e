"""A short seeded mutation-fuzzing campaign over corpus launch files (``bench/fuzz.py``).

Every mutant must be analysed and resolved without an exception, within the time limit,
and the campaign must not grow the process's peak memory much: hostile input becomes
diagnostics, never a crash. The long campaign (100 000 mutants) is run off CI.
"""

from __future__ import annotations

import resource
from pathlib import Path

import pytest

import bench_scripts

fuzz = bench_scripts.load("fuzz")

MUTANTS = 2000
MEMORY_GROWTH_MB = 500


@pytest.mark.skipif(not fuzz.CORPUS.is_dir(), reason="the corpus is not beside the repository")
def test_mutants_of_corpus_files_never_break_rosvar() -> None:
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    report = fuzz.campaign(MUTANTS, seed=16, time_limit=30.0)
    assert report.mutants == MUTANTS
    assert report.failures == [], report.failures[0][1]
    assert report.peak_rss_mb - before < MEMORY_GROWTH_MB


def test_the_hostile_snippets_are_spliced_in() -> None:
    """The campaign's mutants do contain the inputs of issue 16 (else it could not fail)."""
    rng = fuzz.random.Random(3)
    mutants = [fuzz._splice_hostile("<launch>\n</launch>\n", rng) for _ in range(200)]
    assert {snippet for snippet in fuzz.HOSTILE if any(snippet in m for m in mutants)} == set(
        fuzz.HOSTILE
    )


ROS2_MUTANTS = 100


@pytest.mark.skipif(not fuzz.ROS2_DATA.is_dir(), reason="the ROS 2 test data is absent")
def test_mutants_of_ros2_launch_files_never_break_rosvar(tmp_path: Path) -> None:
    """XML, YAML and Python mutants of the ROS 2 test data, hostile snippets of issue 28
    spliced in (a helper calling ``os.system`` among them: it must never run)."""
    ran = Path("/tmp/rosvar-fuzz-ran")
    ran.unlink(missing_ok=True)
    before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    report = fuzz.campaign(ROS2_MUTANTS, seed=28, time_limit=30.0, ros2=True)
    assert report.mutants == ROS2_MUTANTS
    assert report.failures == [], report.failures[0][1]
    assert report.peak_rss_mb - before < MEMORY_GROWTH_MB
    assert not ran.exists()


def test_every_ros2_format_is_mutated() -> None:
    assert {suffix for suffix, _text in fuzz.ros2_seeds()} == set(fuzz.ROS2_SUFFIXES)
