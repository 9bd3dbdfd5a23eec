r"""Time-dependent Young's modulus E(t) for friction after a hold (dwell) time (paper 000, section 2).

Paper 000 notes that friction after the surfaces were held in contact for some time can be
predicted "by assuming a time-dependent elastic modulus" (its ref. 29). Here E(t) is the relaxation
modulus of a generalised Maxwell body, written as a Prony series,

.. math:: E(t) = E_\infty + \sum_k E_k \, e^{-t/\tau_k},

of which the standard linear solid (Zener) is the one-term case with E(0) = E_0 (instantaneous)
and E(inf) = E_inf (relaxed). The Winkler-Lennard-Jones model uses E(t_hold) in place of the
surface material's Young's modulus (:func:`material_after_hold`). Any callable ``t -> E(t)`` in Pa
can be used instead of :class:`PronySeries`.

References
----------
N. W. Tschoegl, *The Phenomenological Theory of Linear Viscoelastic Behavior*, Springer, 1989,
doi:10.1007/978-3-642-73602-5 (Prony series, standard linear solid).
D. Nolbert, Z. Rymuza, Tribology - Mater. Surf. Interfaces 7 (2013) 97-102 (paper 000's ref. 29;
DOI not checked).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace

from ..checks import positive
from ..errors import InputError
from ..materials import Material


@dataclass(frozen=True)
class PronySeries:
    """Relaxation modulus E(t) = E_inf + sum_k E_k exp(-t / tau_k) [Pa].

    Parameters
    ----------
    relaxed_modulus : float
        E_inf [Pa], > 0 (the long-time modulus).
    moduli : tuple of float
        E_k [Pa], each >= 0.
    relaxation_times : tuple of float
        tau_k [s], each > 0, one per modulus.

    Raises
    ------
    InputError
        Non-positive moduli or times, or tuples of different lengths.
    """

    relaxed_modulus: float
    moduli: tuple[float, ...] = ()
    relaxation_times: tuple[float, ...] = ()

    def __post_init__(self):
        positive(self.relaxed_modulus, "relaxed_modulus", example="60e9", unit="Pa")
        if len(self.moduli) != len(self.relaxation_times):
            raise InputError(
                "relaxation_times",
                f"{len(self.relaxation_times)} times for {len(self.moduli)} moduli.",
                "give one relaxation time per Prony modulus.",
            )
        for k, (modulus, time) in enumerate(zip(self.moduli, self.relaxation_times, strict=True)):
            positive(modulus, f"moduli[{k}]", example="40e9", unit="Pa", allow_zero=True)
            positive(time, f"relaxation_times[{k}]", example="2.0", unit="s")
        object.__setattr__(self, "moduli", tuple(float(m) for m in self.moduli))
        object.__setattr__(self, "relaxation_times", tuple(float(t) for t in self.relaxation_times))

    @property
    def instantaneous_modulus(self) -> float:
        """E(0) = E_inf + sum E_k [Pa]."""
        return self.relaxed_modulus + sum(self.moduli)

    def __call__(self, time: float) -> float:
        """Return E(t) [Pa] at ``time`` [s] >= 0."""
        time = positive(time, "hold_time", example="30", unit="s", allow_zero=True)
        return self.relaxed_modulus + sum(
            m * math.exp(-time / tau) for m, tau in zip(self.moduli, self.relaxation_times, strict=True)
        )


def standard_linear_solid(
    instantaneous_modulus: float, relaxed_modulus: float, relaxation_time: float
) -> PronySeries:
    r"""Return the standard linear solid (Zener) relaxation modulus as a one-term :class:`PronySeries`.

    .. math:: E(t) = E_\infty + (E_0 - E_\infty)\, e^{-t/\tau}

    Parameters
    ----------
    instantaneous_modulus : float
        E_0 [Pa], >= ``relaxed_modulus``.
    relaxed_modulus : float
        E_inf [Pa], > 0.
    relaxation_time : float
        tau [s], > 0.

    Returns
    -------
    PronySeries

    Raises
    ------
    InputError
        E_0 < E_inf, or non-positive values.

    References
    ----------
    Tschoegl (1989), doi:10.1007/978-3-642-73602-5.
    """
    if instantaneous_modulus < relaxed_modulus:
        raise InputError(
            "instantaneous_modulus",
            f"{instantaneous_modulus!r} Pa is below the relaxed modulus {relaxed_modulus!r} Pa.",
            "a relaxing solid stiffens at short times: give E_0 >= E_inf.",
        )
    return PronySeries(relaxed_modulus, (instantaneous_modulus - relaxed_modulus,), (relaxation_time,))


def material_after_hold(
    material: Material, relaxation: Callable[[float], float], hold_time: float
) -> Material:
    """Return ``material`` with its Young's modulus replaced by E(hold_time).

    Parameters
    ----------
    material : Material
        The body whose modulus relaxes.
    relaxation : callable
        E(t) [Pa] of time [s], e.g. a :class:`PronySeries`.
    hold_time : float
        Time the surfaces were held in contact before sliding [s], >= 0.

    Returns
    -------
    Material
        A copy with ``youngs_modulus = relaxation(hold_time)`` and the hold recorded in its name.

    Raises
    ------
    InputError
        A negative hold time, or a relaxation that returns a non-positive modulus.
    """
    hold_time = positive(hold_time, "hold_time", example="30", unit="s", allow_zero=True)
    modulus = float(relaxation(hold_time))
    if not math.isfinite(modulus) or modulus <= 0:
        raise InputError(
            "relaxation", f"E({hold_time:g} s) = {modulus!r} Pa.", "give an E(t) that stays positive."
        )
    return replace(material, youngs_modulus=modulus, name=f"{material.name} after {hold_time:g} s hold")
