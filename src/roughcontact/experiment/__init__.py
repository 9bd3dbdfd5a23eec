"""Comparing models with experiments: measured friction, friction loops and indentation curves.

:mod:`.compare` (simulated vs measured friction per sample: t-tests and the Pearson r of the means,
paper 000's validation), :mod:`.friction_loop` (stroke, mu, eq. 9 fit and K_L of a friction loop,
paper 001) and :mod:`.nanoindentation` (Oliver-Pharr modulus with the hold-creep correction, paper
001 eqs. 5-8). Paper 000's own scenario is in :mod:`roughcontact.papers.paper000`.
"""

from .._deprecation import moved
from .compare import Comparison, SampleComparison, compare, read_measured

__all__ = ["Comparison", "SampleComparison", "compare", "read_measured"]

_MOVED = dict.fromkeys(
    (
        "PAPER000_SAMPLES",
        "paper000_model_options",
        "paper000_scans",
        "paper000_simulation",
        "paper000_tip",
        "simulate_mu",
    ),
    "roughcontact.papers.paper000",
)


def __getattr__(name: str):
    """Serve the names that moved to :mod:`roughcontact.papers.paper000`, with a warning."""
    return moved(__name__, name, _MOVED)
