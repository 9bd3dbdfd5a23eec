"""The bridge from paper 000's model to the adhesive boundary elements (``gap_model="bem"``).

:func:`bem_state_at_load` finds the state of an adhesive boundary-element programme
(:func:`roughcontact.contact.solve_adhesive` with the Lennard-Jones law of eq. 7) that carries a
given load, whose gap field the friction sums of the model then use.
"""

from __future__ import annotations

import numpy as np
from scipy import optimize

from ..checks import positive
from ..errors import InputError
from ..topography import Topography

GAP_MODELS = ("winkler", "bem")
"""Gap fields the friction sums (eqs. 8-17) can use: the Winkler springs' (paper 000) or the BEM's."""

BEM_LOAD_RTOL = 1e-6
"""Relative tolerance on the normal force of the boundary-element state found for a load."""


def bem_state_at_load(
    topography: Topography,
    contact_modulus: float,
    law,
    normal_force: float,
    *,
    boundary: str = "free",
    load_rtol: float = BEM_LOAD_RTOL,
    tolerance: float = 1e-6,
):
    """Return the adhesive boundary-element state on the loading branch that carries ``normal_force``.

    :func:`~roughcontact.contact.solve_adhesive` loads the surface from apart (approach -2 eps) in
    steps of eps / 2 until the force passes the load (the programme doubles its reach until it
    does); then Brent's method on the last approach, each evaluation one loading programme from
    apart through the bracket's lower step to the trial approach (so every state lies on the
    loading branch, with its jumps bracketed by the solver), stops when |F - N| <= ``load_rtol`` N.

    Parameters
    ----------
    topography : Topography
        The (composite) surface [m].
    contact_modulus : float
        E* [Pa].
    law : interaction law
        E.g. ``LennardJones(dgamma, eps)`` (:mod:`roughcontact.contact.interaction`).
    normal_force : float
        Compressive load N [N], > 0.
    boundary : {"free", "periodic"}
        Boundary of the boundary-element window (default free: a tip is not periodic).
    load_rtol : float
        Relative tolerance on the force.
    tolerance : float
        The solver's tolerance (largest force imbalance of a pixel relative to the peak tension).

    Returns
    -------
    AdhesiveResult
        The last programme; its last step (``maps["end"]``: pressure and gap) carries the load.

    Raises
    ------
    InputError
        A load that is not positive, or one the law's bound l >= eps / 2 does not let the surface
        carry (raised by the solver).
    """
    from ..contact.adhesive import solve_adhesive

    load = positive(normal_force, "normal_force", example="10e-6", unit="N")
    length = law.length
    start, stride = -2.0 * length, 0.5 * length

    def programme(lower: float, upper: float) -> np.ndarray:
        steps = np.arange(start, lower + 0.5 * stride, stride)
        return np.append(steps[steps < upper], upper)

    def run(points: np.ndarray):
        return solve_adhesive(
            topography,
            contact_modulus,
            law,
            approach=points,
            boundary=boundary,
            tolerance=tolerance,
            until_detached=False,
        )

    reach = 2.0 * length
    for _ in range(40):
        result = run(programme(reach, reach))
        above = np.flatnonzero(result.force >= load)
        if above.size:
            break
        reach *= 2.0
    else:  # pragma: no cover - the law's bound refuses first
        raise InputError("normal_force", f"{load:.4g} N was not reached.", "lower the load.")
    first = int(above[0])
    if abs(result.force[first] - load) <= load_rtol * load:
        return run(programme(result.delta[first], result.delta[first]))
    if first == 0:  # pragma: no cover - apart at the start, the force is tensile
        raise InputError("normal_force", f"{load:.4g} N is carried at the start.", "give a larger load.")
    low, high = float(result.delta[first - 1]), float(result.delta[first])
    found = {}

    class _Done(Exception):
        pass

    def residual(approach: float) -> float:
        trial = run(programme(low, approach))
        found["result"] = trial
        error = float(trial.force[-1]) - load
        if abs(error) <= load_rtol * load:
            raise _Done
        return error

    try:
        optimize.brentq(residual, low, high, xtol=1e-9 * length, rtol=4 * np.finfo(float).eps, maxiter=100)
    except _Done:
        return found["result"]
    trial = found["result"]
    raise InputError(
        "normal_force",
        f"the boundary-element force {trial.force[-1]:.6g} N misses {load:.6g} N by more than "
        f"{load_rtol:g} of it at the closest approach (a jump across the load?).",
        "give another load, or a larger load tolerance.",
    )
