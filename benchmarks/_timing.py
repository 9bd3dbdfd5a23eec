"""Timing helper shared by the benchmark scripts (run them from the repository root)."""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np


def best_of(function: Callable[[], object], repeats: int) -> tuple[float, object]:
    """Return the best wall time [s] of ``repeats`` calls of ``function`` and its last result."""
    best, result = np.inf, None
    for _ in range(repeats):
        start = time.perf_counter()
        result = function()
        best = min(best, time.perf_counter() - start)
    return best, result
