"""The scripts of ``bench/`` as modules, for their tests: ``bench`` is no package, so each
is loaded from its file (and registered, so that its dataclasses and pickles find it)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

BENCH = Path(__file__).resolve().parent.parent / "bench"


def load(name: str) -> ModuleType:
    """``bench/NAME.py`` as the module ``rosvar_bench_NAME``."""
    spec = importlib.util.spec_from_file_location(f"rosvar_bench_{name}", BENCH / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module
