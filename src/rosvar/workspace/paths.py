"""Resolved (symlink-free) paths, cached: every launch file is resolved by several steps."""

from __future__ import annotations

import functools
import os

from rosvar.files import real_path_from


def real_path(path: str) -> str:
    """``os.path.realpath``, with one ``lstat`` per new absolute path instead of one per
    component (relative paths depend on the working directory: never cached)."""
    # ``os.path.isabs``, without its calls (every include and domain question asks)
    return _real_absolute(path) if path.startswith(os.sep) else os.path.realpath(path)


@functools.lru_cache(maxsize=65536)
def _real_absolute(path: str) -> str:
    """A path's directory is resolved once (and cached) for all the files in it, so only
    the last component is checked; ``.`` and ``..``, whose meaning depends on the
    symlinks before them, go to ``os.path.realpath`` whole."""
    return real_path_from(path, _real_absolute)
