"""Feature-model exports, one writer per format (flamapy style): ``write(model, "uvl")``.

A registry rather than a chain of ``if``s so that the CLI can list the formats and a new
one is a module plus a line here.
"""

from __future__ import annotations

from collections.abc import Callable

from rosvar.analyses.feature_model.model import FeatureModel
from rosvar.outputs.exports import dot, featureide, json, text, uvl

Writer = Callable[[FeatureModel], str]

WRITERS: dict[str, Writer] = {
    "text": text.write,
    "json": json.write,
    "uvl": uvl.write,
    "featureide": featureide.write,
    "dot": dot.write,
}


def write(model: FeatureModel, format: str) -> str:
    """The model in ``format`` (a key of :data:`WRITERS`)."""
    try:
        writer = WRITERS[format]
    except KeyError:
        known = ", ".join(sorted(WRITERS))
        raise ValueError(f"unknown feature-model format {format!r} (known: {known})") from None
    return writer(model)


__all__ = ["WRITERS", "Writer", "write"]
