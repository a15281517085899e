"""``$(rosvar-written-file ...)``: the text of a file a workspace helper's ``perform`` writes.

The Python frontend leaves the file a ``Substitution`` subclass writes (nav2's
``RewrittenYaml``: the parameter file a launch argument names, rewritten with launch-time
values) to this substitution (:mod:`rosvar.ros2.frontends.python.written`): its last argument
is the Python literal of the object's constructor arguments, which each configuration makes
concrete. The text is the helper's ``perform`` read again with them
(:mod:`rosvar.ros2.frontends.python.performs`): never imported nor run, its reads through the
workspace's gate. A value known only once the command line gives it is a term, computed so
by ``resolve``.
"""

from __future__ import annotations

import weakref
from collections.abc import Mapping

from rosvar.files import Confinement
from rosvar.interpreter.interpretation import Interpretation
from rosvar.interpreter.model import Raw
from rosvar.logic.choice import Choice, Fail
from rosvar.logic.terms import Apply, PackageTable, TermError, register
from rosvar.ros2.context import Context
from rosvar.ros2.frontends.python.performs import written
from rosvar.ros2.frontends.python.text import WRITTEN_FILE, Written
from rosvar.ros2.substitutions import Value, substitution
from rosvar.workspace import Workspace


@substitution(WRITTEN_FILE, merged_terms="a file written")
def _written_file(
    host: Interpretation[Context], context: Context, args: list[Raw]
) -> Choice[Value]:
    if len(args) != 5 or args[0] not in tuple(Written):
        message = f"$({WRITTEN_FILE}) takes an aspect and four operands"
        return Choice.const(host.space, Fail(message, "substitution-invalid"))
    if not all(isinstance(arg, str) for arg in args):
        return Choice.const(host.space, Apply(WRITTEN_FILE, tuple(args), "⟨a file written⟩"))
    workspace = host.workspace
    aspect, *operands = (str(arg) for arg in args)
    if not _affordable(workspace, tuple(operands)):
        host.note_too_complex(
            f"{MAX_READINGS} argument sets of helpers' perform read already: the file a "
            f"helper writes ({operands[1]}.{operands[2]}) is computed per configuration"
        )
        return Choice.const(host.space, Apply(WRITTEN_FILE, tuple(args), "⟨a file written⟩"))
    packages = {name: package.path for name, package in workspace.packages.items()}
    try:
        text = written(packages, workspace.confinement(), operands, Written(aspect))
    except ValueError as error:
        return Choice.const(host.space, Fail(str(error), "value-unknown"))
    return Choice.const(host.space, text)


MAX_READINGS = 4
"""Distinct argument sets whose helper's ``perform`` one analysis reads again: a reading
walks the whole source file (nav2's 500-leaf parameter file, rewritten), and the crossing of
launch arguments gives one set per combination. Past them the file is a term, which
``resolve`` computes for its one configuration (docs/performance.md has the cost)."""
_readings: dict[int, set[tuple[str, ...]]] = {}


def _affordable(workspace: Workspace, operands: tuple[str, ...]) -> bool:
    """Whether the analysis of ``workspace`` may read ``operands``' file: read already, or
    one of its first :data:`MAX_READINGS`."""
    key = id(workspace)
    read = _readings.get(key)
    if read is None:
        read = _readings[key] = set()
        weakref.finalize(workspace, _readings.pop, key, None)
    if operands in read:
        return True
    if len(read) >= MAX_READINGS:
        return False
    read.add(operands)
    return True


def _term(host: object, aspect: object, *operands: object) -> str:
    """The same once a configuration gives the operands (``resolve``): the packages are the
    host's, and so is the confinement (their folders)."""
    packages: Mapping[str, str] = host.paths if isinstance(host, PackageTable) else {}
    confinement = Confinement.of(packages.values())
    try:
        return written(
            dict(packages), confinement, [str(o) for o in operands], Written(str(aspect))
        )
    except ValueError as error:
        raise TermError(str(error)) from None


register(WRITTEN_FILE, _term)
