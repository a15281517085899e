"""Parameter values as JSON, with the same conventions as the roslaunch oracle."""

from __future__ import annotations

import base64
import datetime
import math

from rosvar.interpreter.model import Binary


def json_value(value: object) -> object:
    """``Binary`` → ``{"__binary__": base64}``, nan/inf → strings, dates → ``__datetime__``."""
    if value is None or isinstance(value, str | bool | int):
        return value
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return value
    if isinstance(value, Binary):
        return {"__binary__": base64.b64encode(value.data).decode()}
    if isinstance(value, bytes):
        return {"__binary__": base64.b64encode(value).decode()}
    if isinstance(value, datetime.date):
        return {"__datetime__": value.isoformat()}
    if isinstance(value, dict):
        return {str(k): json_value(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [json_value(v) for v in value]
    return {"__repr__": repr(value)}
