"""The one way files are read: regular files only, bounded, never the host's system trees,
and within the workspace when confined."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from rosvar.files import Confinement, FileCode, FileRefused, python_text, read_file


def _refused(code: FileCode, path: str, confinement: Confinement | None = None) -> str:
    with pytest.raises(FileRefused) as raised:
        read_file(path, confinement)
    assert raised.value.code == code
    return raised.value.message


def test_regular_file_is_read_whole(tmp_path: Path) -> None:
    path = tmp_path / "a.txt"
    path.write_bytes(b"x" * 10_000)
    assert read_file(str(path), Confinement.of([str(tmp_path)])) == b"x" * 10_000


def test_fifo_is_refused_without_blocking(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    assert _refused(FileCode.UNREADABLE, str(fifo)) == "not a regular file"


@pytest.mark.parametrize("path", ["/dev/zero", "/dev/null", "/proc/self/environ", "/sys/kernel"])
def test_system_trees_are_never_read(path: str) -> None:
    _refused(FileCode.OUTSIDE, path)
    _refused(FileCode.OUTSIDE, path, Confinement.of(["/"], allow_outside=True))
    _refused(FileCode.OUTSIDE, path, Confinement.of(["/"]))


def test_symlink_into_a_system_tree_is_refused(tmp_path: Path) -> None:
    link = tmp_path / "env"
    link.symlink_to("/proc/self/environ")
    _refused(FileCode.OUTSIDE, str(link), Confinement.of([str(tmp_path)], allow_outside=True))


def test_confinement_resolves_symlinks_and_dot_dot(tmp_path: Path) -> None:
    inside, outside = tmp_path / "ws", tmp_path / "secret"
    inside.mkdir()
    outside.mkdir()
    (outside / "key").write_text("secret")
    (inside / "link").symlink_to(outside / "key")
    (inside / "ok").write_text("fine")
    confined = Confinement.of([str(inside)])
    for path in (inside / "link", inside / ".." / "secret" / "key", outside / "key"):
        assert "outside the workspace" in _refused(FileCode.OUTSIDE, str(path), confined)
    assert read_file(str(inside / "ok"), confined) == b"fine"
    assert read_file(str(inside / "link"), Confinement.of([str(inside)], True)) == b"secret"
    sibling = tmp_path / "ws2"  # a prefix of the name is not a parent directory
    sibling.mkdir()
    (sibling / "f").write_text("x")
    _refused(FileCode.OUTSIDE, str(sibling / "f"), confined)


def test_size_limit(tmp_path: Path) -> None:
    path = tmp_path / "big"
    path.write_bytes(b"x" * 100)
    with pytest.raises(FileRefused, match="over the limit of 50 bytes"):
        read_file(str(path), limit=50)
    assert len(read_file(str(path), limit=100)) == 100


def _fstat_says(monkeypatch: pytest.MonkeyPatch, size: int) -> None:
    """``os.fstat`` reports ``size``: the file grew after it was looked at."""
    real_fstat = os.fstat

    def fstat(descriptor: int) -> os.stat_result:
        fields = list(real_fstat(descriptor))
        fields[6] = size  # st_size
        return os.stat_result(fields)

    monkeypatch.setattr(os, "fstat", fstat)


def test_file_grown_after_stat_is_read_whole(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "grown"
    path.write_bytes(b"0123456789" * 5)
    _fstat_says(monkeypatch, 10)
    assert read_file(str(path)) == b"0123456789" * 5


def test_file_grown_past_the_limit_after_stat_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    path = tmp_path / "grown"
    path.write_bytes(b"x" * 100)
    _fstat_says(monkeypatch, 20)
    with pytest.raises(FileRefused, match="file is 51 bytes"):
        read_file(str(path), limit=50)


def test_short_reads_are_continued(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """``read`` may return less than asked (a signal, a file system's own sizes): the rest
    is read, as a buffered file's ``read`` does."""
    path = tmp_path / "f"
    path.write_bytes(b"0123456789" * 5)
    real_read = os.read
    sizes: list[int] = []

    def read(descriptor: int, count: int) -> bytes:
        sizes.append(count)
        return real_read(descriptor, min(count, 7))

    monkeypatch.setattr(os, "read", read)
    assert read_file(str(path)) == b"0123456789" * 5
    assert len(sizes) > 2


def test_missing_file_is_the_systems_error(tmp_path: Path) -> None:
    with pytest.raises(FileNotFoundError):
        read_file(str(tmp_path / "nope"))


def test_a_text_read_has_the_line_ends_python_text_mode_gives(tmp_path: Path) -> None:
    path = tmp_path / "f.txt"
    path.write_bytes(b"a\r\nb\rc\n\xc3\xa9")
    with open(path) as handle:  # what a launch file's open().read() gets
        expected = handle.read()
    assert python_text(read_file(str(path))) == expected == "a\nb\nc\né"
