"""Where the xacro walk reads from: one analysis' files (each parsed once, through rosvar's
confined reader and safe XML parser), packages and environment domains."""

from __future__ import annotations

from collections.abc import Callable, Mapping

from rosvar.analyses.robot_description import xacro_tags  # noqa: F401 - registers the tags
from rosvar.analyses.robot_description.document import Description
from rosvar.analyses.robot_description.xacro import Expansion
from rosvar.files import Confinement, FileRefused, read_file
from rosvar.frontends.entity import ParseResult
from rosvar.frontends.xml import parse_xml_bytes
from rosvar.interpreter.model import Raw
from rosvar.interpreter.substitution_args import Missing
from rosvar.logic.bdd import BDD
from rosvar.logic.choice import Choice
from rosvar.logic.conditions import ConditionSpace
from rosvar.logic.inputs import Slot


class XacroReader:
    """The files and packages of one analysis, as xacro reads them (parsed files shared by
    every expansion)."""

    def __init__(
        self,
        space: ConditionSpace,
        find_package: Callable[[str], str | None],
        env_domain: Callable[[str], tuple[Slot, ...]],
        confinement: Confinement,
    ) -> None:
        self.space = space
        self.find_package = find_package
        self.env_domain = env_domain
        self.confinement = confinement
        self._parsed: dict[str, ParseResult | str] = {}

    def parse(self, path: str) -> ParseResult | str:
        """The file's tree, or why it cannot be read (xacro's IOError)."""
        found = self._parsed.get(path)
        if found is None:
            if not path.strip():
                return "an empty file name"
            try:
                data = read_file(path, self.confinement)
            except FileRefused as refused:
                found = f"{path}: {refused.message}"
            except (OSError, ValueError) as error:
                found = f"{getattr(error, 'strerror', None) or error}: {path}"
            else:
                found = parse_xml_bytes(data, path)
            self._parsed[path] = found
        return found

    def expand(
        self,
        file: str,
        args: Mapping[str, Choice[Raw | Missing]],
        condition: BDD,
        plain: bool = False,
    ) -> Description:
        """``xacro FILE name:=value...`` where ``condition`` holds, each arg a choice; with
        ``plain``, the file as it is (a URDF or SDF file a spawner reads)."""
        return Expansion(self, file, dict(args), condition, plain).run()

    def expand_text(self, text: str, file: str, condition: BDD) -> Description:
        """A description given as text (a parameter's value, a ``textfile``), as it is;
        ``file``: where it is written, for locations."""
        parsed = parse_xml_bytes(text.encode("utf-8", "surrogateescape"), file)
        expansion = Expansion(self, file, {}, condition, plain=True, root=parsed.root)
        for diagnostic in parsed.diagnostics:
            expansion.sink.add(diagnostic)
        if parsed.root is None:
            expansion.fail(self.space.true, "the robot description is no XML", "xacro-invalid")
        return expansion.run()
