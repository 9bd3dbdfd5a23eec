"""Comparing models with experiments: simulated vs measured friction (paper 000's validation)."""

from .compare import Comparison, SampleComparison, compare, read_measured, simulate_mu
from .paper000 import (
    PAPER000_SAMPLES,
    paper000_model_options,
    paper000_scans,
    paper000_simulation,
    paper000_tip,
)

__all__ = [
    "PAPER000_SAMPLES",
    "Comparison",
    "SampleComparison",
    "compare",
    "paper000_model_options",
    "paper000_scans",
    "paper000_simulation",
    "paper000_tip",
    "read_measured",
    "simulate_mu",
]
