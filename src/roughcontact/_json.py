"""JSON-ready values for the command line's ``--json`` output and the study records."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any


def json_ready(value: Any) -> Any:
    """Return ``value`` with numpy scalars as Python numbers, tuples as lists, non-finite floats as None.

    Dictionary keys become strings and paths their text, so ``json.dumps`` takes the result and
    writes no ``NaN`` or ``Infinity`` (which JSON does not have).
    """
    if isinstance(value, dict):
        return {str(k): json_ready(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [json_ready(v) for v in value]
    if hasattr(value, "item") and getattr(value, "ndim", 1) == 0:
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, Path):
        return str(value)
    return value
