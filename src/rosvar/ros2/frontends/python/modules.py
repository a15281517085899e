"""Where ``import m`` finds a module the workspace provides, for the static reading.

A launch file imports its packages' Python helpers (``from nav2_common.launch import
RewrittenYaml``, ``import rs_launch`` after ``sys.path.append`` of its own directory). They are
read by the same abstract interpreter, never imported: a module is a file below a package of
the workspace or of the ``--deps`` roots, as an installed workspace has it on ``sys.path``
(an ``ament_python`` package's ``<pkg>/<module>``, a ``setup.py``/``setup.cfg`` package below
``src/`` or ``python/``), or one beside the importing file, or in a directory the file appends
to ``sys.path``. Every read goes through the one gate (:func:`rosvar.files.read_file`): inside
the workspace's confinement, within the size limit.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

from rosvar.files import Confinement

RESERVED = frozenset(
    {
        "launch",
        "launch_ros",
        "launch_xml",
        "launch_yaml",
        "launch_testing",
        "launch_testing_ros",
        "rclpy",
        "ament_index_python",
        "yaml",
        "xacro",
        "os",
        "sys",
        "test",
        "tests",
    }
)
"""Modules the reading models itself (the launch API, ``os``, ``xacro``...): a package's
folder of the same name (a ``launch/`` with an ``__init__.py``, xacro's own sources) is never
read for them."""
SOURCE_FOLDERS = ("", "src", "python")
"""Folders of a package holding its Python packages (``package_dir`` layouts seen in ROS)."""
MAX_MODULE_BYTES = 1024 * 1024
"""Largest module read (as a launch file: a larger one is refused, ``python-module``)."""
MAX_MODULES = 200
"""Modules read per launch file; more stay symbolic (a bound on work, whatever imports)."""


@dataclass
class ModulePath:
    """The packages whose Python modules an import may find, and what may be read."""

    packages: dict[str, str]
    """ROS package name to its directory (its share directory in a source workspace)."""
    confinement: Confinement | None = None
    _tops: dict[str, str] | None = field(default=None, repr=False)

    def top_level(self) -> dict[str, str]:
        """Top-level module names to the directory holding them, found once."""
        if self._tops is None:
            self._tops = {}
            for directory in sorted(self.packages.values()):
                for folder in SOURCE_FOLDERS:
                    _index(os.path.join(directory, folder), self._tops)
        return self._tops

    def find(self, dotted: str, extra: list[str]) -> str | None:
        """The file of module ``dotted`` (``a.b``): in ``extra`` directories first (beside the
        importing file, appended to ``sys.path``), then in the packages."""
        top, _, rest = dotted.partition(".")
        if top in RESERVED:
            return None
        for directory in extra:
            found = _module_file(directory, top, rest)
            if found is not None:
                return found
        home = self.top_level().get(top)
        return None if home is None else _module_file(home, top, rest)


def _index(directory: str, tops: dict[str, str]) -> None:
    try:
        names = sorted(os.listdir(directory))
    except OSError:
        return
    for name in names:
        package = os.path.join(directory, name, "__init__.py")
        if name not in RESERVED and name.isidentifier() and os.path.isfile(package):
            tops.setdefault(name, directory)


def _module_file(directory: str, top: str, rest: str) -> str | None:
    base = os.path.join(directory, top, *rest.split(".")) if rest else os.path.join(directory, top)
    for candidate in (base + ".py", os.path.join(base, "__init__.py")):
        if os.path.isfile(candidate):
            return candidate
    return None
