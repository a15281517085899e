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


@substitution(WRITTEN_FILE)
def _written_file(
    host: Interpretation[Context], context: Context, args: list[Raw]
) -> Choice[Value]:
    if len(args) != 5 or args[0] not in tuple(Written):
        message = f"$({WRITTEN_FILE}) takes an aspect and four operands"
        return Choice.const(host.space, Fail(message, "substitution-invalid"))
    if not all(isinstance(arg, str) for arg in args):
        return Choice.const(host.space, Apply(WRITTEN_FILE, tuple(args), "⟨a file written⟩"))
    workspace = host.workspace
    packages = {name: package.path for name, package in workspace.packages.items()}
    aspect, *operands = (str(arg) for arg in args)
    try:
        text = written(packages, workspace.confinement(), operands, Written(aspect))
    except ValueError as error:
        return Choice.const(host.space, Fail(str(error), "value-unknown"))
    return Choice.const(host.space, text)


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
