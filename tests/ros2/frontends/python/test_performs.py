"""A helper's ``perform`` read again in one configuration (``performs.py``)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from rosvar.files import Confinement
from rosvar.ros2.frontends.python import performs
from rosvar.ros2.frontends.python.text import WRITTEN_PATH, Written

HELPER = """import tempfile
import launch
import yaml
from launch.utilities import perform_substitutions


class Scaled(launch.Substitution):
    def __init__(self, source, factor):
        super().__init__()
        self.source = source
        self.factor = factor

    def perform(self, context):
        data = yaml.safe_load(open(perform_substitutions(context, self.source)))
        data['rate'] = data['rate'] * float(self.factor)
        out = tempfile.NamedTemporaryFile(mode='w', delete=False)
        yaml.dump(data, out)
        return out.name
"""


def _workspace(tmp_path: Path) -> tuple[dict[str, str], Confinement, Path]:
    package = tmp_path / "helpers"
    (package / "helpers").mkdir(parents=True)
    (package / "package.xml").write_text("<package/>")
    (package / "helpers" / "__init__.py").write_text(HELPER)
    config = package / "rate.yaml"
    config.write_text("rate: 2\n")
    return {"helpers": str(package)}, Confinement.of([str(tmp_path)]), config


def _operands(package: dict[str, str], config: Path, factor: str) -> list[str]:
    module = os.path.join(package["helpers"], "helpers", "__init__.py")
    return [module, "helpers", "Scaled", repr(((str(config), factor), {}))]


def test_the_text_follows_the_file_read_and_its_path_names_it(tmp_path: Path) -> None:
    packages, confinement, config = _workspace(tmp_path)
    operands = _operands(packages, config, "1.5")
    assert performs.written(packages, confinement, operands, Written.TEXT) == "rate: 3.0\n"
    path = performs.written(packages, confinement, operands, Written.PATH)
    assert path.startswith(WRITTEN_PATH)
    chained = [*operands[:3], repr(((path, "2"), {}))]  # a written file as the source
    assert performs.written(packages, confinement, chained, Written.TEXT) == "rate: 6.0\n"
    config.write_text("rate: 10\n")  # a reading kept is not kept past a change of its file
    os.utime(config, ns=(1, 1))
    assert performs.written(packages, confinement, operands, Written.TEXT) == "rate: 15.0\n"


def test_what_cannot_be_computed_says_why(tmp_path: Path) -> None:
    packages, confinement, config = _workspace(tmp_path)
    with pytest.raises(ValueError, match="raises ValueError"):
        performs.written(packages, confinement, _operands(packages, config, "x"), Written.TEXT)
    outside = tmp_path.parent / "outside.yaml"
    outside.write_text("rate: 1\n")
    with pytest.raises(ValueError, match="outside the workspace"):
        performs.written(packages, confinement, _operands(packages, outside, "1"), Written.TEXT)
