"""Reading files named by untrusted input: the one way rosvar reads any file.

Launch files come from repositories nobody vetted, and their paths (``textfile=``,
``<rosparam file>``, ``<include>``) are theirs to choose: ``/dev/zero`` would be read
forever, a FIFO would block, ``/etc/passwd`` or ``/proc/self/environ`` would end up in
the output. So every read goes through :func:`read_file`: regular files only (opened
without blocking, checked on the open descriptor), at most a size limit, never below
``/proc``, ``/sys`` or ``/dev``, and, given a :class:`Confinement`, only inside the
workspace. A refusal is a :class:`FileRefused`, an ``OSError`` as the failed ``open``
would have been, so that every caller already reports it rather than stopping; its
message does not name the file (callers place it).
"""

from __future__ import annotations

import enum
import os
import stat
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from typing import BinaryIO

MAX_FILE_BYTES = 64 * 1024 * 1024
"""Largest file read (launch, parameter, text, binary, hints); larger ones are refused."""
SYSTEM_TREES = ("/proc", "/sys", "/dev")
"""Never read, whatever the options: they describe the machine running rosvar."""


class FileCode(enum.StrEnum):
    """Diagnostic codes of refused reads."""

    UNREADABLE = "file-unreadable"
    TOO_LARGE = "file-too-large"
    OUTSIDE = "file-outside-workspace"


class FileRefused(OSError):
    """A read refused by rosvar's rules rather than by the operating system."""

    def __init__(self, code: FileCode, message: str) -> None:
        super().__init__(message)
        self.code = code
        self.message = message

    def __str__(self) -> str:
        return self.message


@dataclass(frozen=True)
class Confinement:
    """The directories a workspace may read below (symlinks resolved), unless told otherwise,
    and where a path's file is: ``installed`` maps a path of a package's share folder, which
    a ROS 2 source package's own folder stands for, to the source file its build installs
    there (:mod:`rosvar.workspace.share`), as symlinks map a path to their target.

    A workspace's confinement lives as long as its analysis, one moment (as its parsed
    files, :class:`rosvar.frontends.xml.Snapshot`): a path's resolution and verdict are kept
    for it, since an analysis checks each file at every include and load of it (Husky: 1,075
    checks of 199 paths, each an ``lstat`` per component and a test against 48 roots).
    """

    roots: tuple[str, ...]
    allow_outside: bool = False
    installed: Callable[[str], str] | None = field(default=None, compare=False, repr=False)
    _resolved: dict[str, str] = field(default_factory=dict, compare=False, repr=False)
    _allowed: dict[str, str] = field(default_factory=dict, compare=False, repr=False)
    _trees: _Trees = field(init=False, compare=False, repr=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "_trees", _Trees(self.roots))

    @staticmethod
    def of(
        directories: Iterable[str],
        allow_outside: bool = False,
        installed: Callable[[str], str] | None = None,
    ) -> Confinement:
        confinement = Confinement((), allow_outside)
        real = {confinement.resolve(directory) for directory in directories}
        return Confinement(tuple(sorted(real)), allow_outside, installed, confinement._resolved)

    def source(self, path: str) -> str:
        """The file ``path`` names: the source an install copies there, else ``path``."""
        return path if self.installed is None else self.installed(path)

    def resolve(self, path: str) -> str:
        """``os.path.realpath(path)``, kept for the moment: the files of a directory share
        its resolution (:func:`real_path_from`)."""
        real = self._resolved.get(path)
        if real is None:
            real = self._resolved[path] = real_path_from(path, self.resolve)
        return real

    def check(self, path: str) -> str:
        """The file ``path`` names (:meth:`source`), resolved (``..`` and symlinks), or
        :class:`FileRefused` if it is outside."""
        real = self._allowed.get(path)
        if real is not None:
            return real
        real = self.resolve(self.source(path))
        _check_system(real)
        if not self.allow_outside and not self._trees.hold(real):
            raise FileRefused(
                FileCode.OUTSIDE,
                "outside the workspace (--allow-outside-workspace allows it)",
            )
        self._allowed[path] = real
        return real


def real_path_from(path: str, real_directory: Callable[[str], str]) -> str:
    """``os.path.realpath(path)`` given ``real_directory``, a (cached) ``realpath`` of
    directories: only the last component is checked, one ``lstat`` per file instead of one
    per component. Relative paths (the working directory's), ``.`` and ``..`` (whose meaning
    depends on the symlinks before them) go to ``os.path.realpath`` whole."""
    head, tail = os.path.split(path)
    if tail in ("", ".", "..") or head == path or not os.path.isabs(path):
        return os.path.realpath(path)
    joined = os.path.join(real_directory(head), tail)
    return os.path.realpath(joined) if os.path.islink(joined) else joined


class _Trees:
    """Directories, to tell whether a path is one of them or below one in a single test
    (a workspace has dozens of roots: Husky's confinement has 48)."""

    __slots__ = ("_prefixes", "_roots")

    def __init__(self, roots: Iterable[str]) -> None:
        self._roots = frozenset(roots)
        self._prefixes = tuple(root.rstrip(os.sep) + os.sep for root in self._roots)

    def hold(self, path: str) -> bool:
        return path in self._roots or path.startswith(self._prefixes)


_SYSTEM = _Trees(SYSTEM_TREES)


def _check_system(real: str) -> None:
    if _SYSTEM.hold(real):
        tree = next(t for t in SYSTEM_TREES if _Trees((t,)).hold(real))
        raise FileRefused(FileCode.OUTSIDE, f"below {tree}, which rosvar never reads")


def read_file(
    path: str,
    confinement: Confinement | None = None,
    limit: int = MAX_FILE_BYTES,
    real: str | None = None,
) -> bytes:
    """The whole content of the regular file ``path``, at most ``limit`` bytes.

    Raises ``OSError`` as ``open`` does (a missing file, a permission), or
    :class:`FileRefused`: not a regular file, larger than ``limit``, a system tree, or
    outside ``confinement``. ``real``: its resolution, where the caller has it.
    """
    if confinement is not None:
        path = real = confinement.check(path)
    descriptor, size = _open_regular(path, real)  # a descriptor: no file object to build
    try:
        if size > limit:
            raise _too_large(size, limit)
        # The size found, plus one byte to see the end: ``read(n)`` allocates n bytes first.
        data = _read_up_to(descriptor, size + 1)
        if len(data) > size:  # grew since: the rest, up to the limit
            data += _read_up_to(descriptor, limit + 1 - len(data))
    finally:
        os.close(descriptor)
    if len(data) > limit:
        raise _too_large(len(data), limit)
    return data


def _read_up_to(descriptor: int, count: int) -> bytes:
    """``count`` bytes, or fewer at the end of the file (a buffered file's ``read``), in
    reads of at most :data:`_CHUNK` beyond the first (each allocates what it asks)."""
    parts: list[bytes] = []
    while count > 0:
        chunk = os.read(descriptor, count if not parts else min(count, _CHUNK))
        if not chunk:
            break
        parts.append(chunk)
        count -= len(chunk)
    return parts[0] if len(parts) == 1 else b"".join(parts)


_CHUNK = 1 << 20


def python_text(data: bytes, encoding: str = "utf-8") -> str:
    """``data`` as Python's ``open(path).read()`` gives it: decoded, its ``\r\n`` and ``\r``
    read as ``\n`` (universal newlines), as launch's ``FileContent`` and a launch file's
    own reads see a file. Raises ``UnicodeDecodeError``."""
    return data.decode(encoding).replace("\r\n", "\n").replace("\r", "\n")


def open_regular(path: str, real: str | None = None) -> BinaryIO:
    """``path`` opened for reading if it is a regular file outside the system trees, else
    :class:`FileRefused` (checked on the open descriptor: nothing can swap the file).
    ``real`` is its resolution, where the caller has it."""
    descriptor, _size = _open_regular(path, real)
    return os.fdopen(descriptor, "rb")


def _open_regular(path: str, real: str | None) -> tuple[int, int]:
    """:func:`open_regular`'s descriptor, and the file's size when opened."""
    _check_system(os.path.realpath(path) if real is None else real)
    flags = os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0)
    descriptor = os.open(path, flags)  # O_NONBLOCK: opening a FIFO must not wait
    info = os.fstat(descriptor)
    if not stat.S_ISREG(info.st_mode):
        os.close(descriptor)
        raise FileRefused(FileCode.UNREADABLE, "not a regular file")
    return descriptor, info.st_size


def _too_large(size: int, limit: int) -> FileRefused:
    return FileRefused(FileCode.TOO_LARGE, f"file is {size} bytes, over the limit of {limit} bytes")
