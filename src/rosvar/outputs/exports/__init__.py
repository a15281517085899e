"""Feature-model exports, one writer per format (flamapy style): ``write(model, "uvl")``.

A registry rather than a chain of ``if``s so that the CLI can list the formats and a new
one is a module plus a line here. Each format is the module of its writer, imported when
it is used: listing the formats (the CLI's parser, ``--help``) imports none of them.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import TYPE_CHECKING, cast

if TYPE_CHECKING:
    from rosvar.analyses.feature_model.model import FeatureModel

Writer = Callable[["FeatureModel"], str]

FORMATS = ("text", "json", "uvl", "featureide", "dot")
"""The formats, each the name of its module here (which defines ``write``)."""


def writer(format: str) -> Writer:
    """The writer of ``format`` (one of :data:`FORMATS`)."""
    if format not in FORMATS:
        known = ", ".join(sorted(FORMATS))
        raise ValueError(f"unknown feature-model format {format!r} (known: {known})")
    return cast(Writer, importlib.import_module(f"{__name__}.{format}").write)


def write(model: FeatureModel, format: str) -> str:
    """The model in ``format`` (one of :data:`FORMATS`)."""
    return writer(format)(model)


__all__ = ["FORMATS", "Writer", "write", "writer"]
