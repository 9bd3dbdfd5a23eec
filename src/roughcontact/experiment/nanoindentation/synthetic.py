r"""Synthetic load-hold-unload curves whose modulus is known: the test bench of the analysis.

:func:`synthetic_indentation_curve` runs eqs. 6-8 of seed paper 001 backwards (see
:mod:`.oliver_pharr`) to build a curve that :func:`.oliver_pharr.oliver_pharr` must turn back
into the given modulus:

* loading F = C d^2 (a self-similar pyramid) at a constant rate;
* a hold at F_max creeping by the hold law of Feng and Ngan (2002) without its linear term,
  :math:`d = d_0 + a \tau^{1/3}`, with a chosen rate at the end of the hold;
* unloading along the power law of Oliver and Pharr (1992),
  :math:`F = \alpha (d_e - d_f)^m`, whose slope at F_max is the S_e of the chosen modulus,
  while the creep carries on at the hold law's rate scaled by F / F_max, so that at the onset
  of unloading it runs at the end-of-hold rate: Tang and Ngan's (2003) assumption, under which
  eq. 5 with ``|F_dot|`` recovers S_e exactly.

Paper 001's protocol (10 mN, 20 mN/min loading and unloading, 60 s hold) is the default;
``examples/paper001_indentation.py`` writes the example curve of its HDPE with it.

References
----------
Oliver and Pharr (1992), Feng and Ngan (2002), Tang and Ngan (2003): in full in :mod:`.fits`.
Seed paper 001, eqs. 5-8 and Table 2. doi:10.1115/1.4045900
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from scipy import optimize

from ..._deprecation import renamed
from ...errors import InputError
from ...materials import Material, get_material
from .curve import IndentationCurve
from .oliver_pharr import EPSILON_BERKOVICH, berkovich_area


@renamed(max_load="max_force")
def synthetic_indentation_curve(
    youngs_modulus: float,
    *,
    poissons_ratio: float = 0.5,
    indenter: Material | str = "diamond berkovich",
    hardness: float = 60e6,
    max_force: float = 10e-3,
    loading_rate: float = 20e-3 / 60.0,
    unloading_rate: float | None = None,
    hold_time: float = 60.0,
    creep_rate: float = 0.0,
    unloading_exponent: float = 1.5,
    epsilon: float = EPSILON_BERKOVICH,
    beta: float = 1.0,
    area_function: Callable[[float], float] = berkovich_area,
    sampling_rate: float = 10.0,
    depth_noise: float = 0.0,
    load_noise: float = 0.0,
    seed: int | None = 0,
) -> IndentationCurve:
    """Make a load-hold-unload curve whose Oliver-Pharr modulus with the viscous correction is known.

    * Loading at ``loading_rate``: F = C d^2 (a self-similar pyramid) up to ``max_force``.
    * Hold of ``hold_time`` at F_max: creep d = d_0 + a tau^(1/3), the hold law of Feng and Ngan
      (2002) with k = 0, with a chosen so that the rate at the end of the hold is ``creep_rate``.
    * Unloading at ``unloading_rate`` (default: the loading rate): the elastic part follows
      F = alpha (d_e - d_f)^m whose slope at F_max is the S_e that eqs. 6-8 turn into
      ``youngs_modulus``; the creep carries on, at the hold law's rate scaled by F / F_max (a
      viscous flow driven by the load), so its rate at the onset of unloading is the end-of-hold
      rate: Tang and Ngan's assumption, under which eq. 5 with ``|F_dot|`` recovers S_e.

    The contact depth comes from the hardness, A_c(d_c) = F_max / H; d_max = d_c + eps F_max / S_e.

    Parameters
    ----------
    youngs_modulus : float
        Sample modulus E_s [Pa] to be recovered.
    poissons_ratio, indenter, epsilon, beta, area_function
        As in :func:`oliver_pharr` (eq. 8 and eqs. 6-7 run backwards).
    hardness : float
        Mean contact pressure F_max / A_c [Pa] (sets the depth; 60 MPa is HDPE-like).
    max_force : float
        F_max [N].
    loading_rate, unloading_rate : float
        ``|dF/dt|`` [N/s] (paper 001: 20 mN/min).
    hold_time : float
        [s] (paper 001: 60 s).
    creep_rate : float
        Creep rate at the end of the hold [m/s] (>= 0).
    unloading_exponent : float
        m of the elastic unloading power law (1.5: paraboloid of revolution, Sneddon).
    sampling_rate : float
        Samples per second.
    depth_noise, load_noise : float
        Standard deviation of Gaussian noise added to depth [m] and load [N].
    seed : int, optional
        Seed of the noise.

    Returns
    -------
    IndentationCurve
        Depth [m], load [N], time [s].
    """
    if isinstance(indenter, str):
        indenter = get_material(indenter)
    if creep_rate < 0:
        raise InputError(
            "creep_rate", f"{creep_rate!r} is negative.", "give the creep rate into the sample, >= 0."
        )
    unloading_rate = loading_rate if unloading_rate is None else unloading_rate
    reduced = 1.0 / (
        (1.0 - poissons_ratio**2) / youngs_modulus
        + (1.0 - indenter.poissons_ratio**2) / indenter.youngs_modulus
    )
    # contact depth from the hardness: solve A_c(d_c) = F_max / H
    target = max_force / hardness
    d_c = optimize.brentq(lambda x: area_function(x) - target, 1e-12, 1.0)
    s_e = 2.0 * beta / math.sqrt(math.pi) * reduced * math.sqrt(target)  # eq. 6 backwards
    d_max = d_c + epsilon * max_force / s_e  # eq. 7
    m = unloading_exponent
    d_f = d_max - m * max_force / s_e  # S_e = m F_max / (d_max - d_f)
    alpha = max_force / (d_max - d_f) ** m
    # creep law d = d0 + a tau^(1/3): rate a/3 tau^(-2/3) = creep_rate at tau = hold_time
    a = 3.0 * creep_rate * hold_time ** (2.0 / 3.0)
    d_load_end = d_max - a * hold_time ** (1.0 / 3.0)
    if d_load_end <= 0:
        raise InputError(
            "creep_rate",
            f"{creep_rate!r} m/s creeps deeper than the whole indent.",
            "give a smaller creep rate.",
        )
    dt = 1.0 / sampling_rate
    t_load = max_force / loading_rate
    t1 = np.arange(0.0, t_load, dt)
    f1 = loading_rate * t1
    d1 = d_load_end * np.sqrt(f1 / max_force)
    tau_hold = np.arange(0.0, hold_time, dt)
    t2 = t_load + tau_hold
    f2 = np.full_like(t2, max_force)
    d2 = d_load_end + a * np.cbrt(tau_hold)
    t_unload = max_force / unloading_rate
    tau_un = np.arange(0.0, t_unload + 0.5 * dt, dt)
    t3 = t_load + hold_time + tau_un
    f3 = np.clip(max_force - unloading_rate * tau_un, 0.0, None)

    # creep during unloading: rate a/3 (hold_time + tau)^(-2/3) * F/F_max, integrated exactly
    # (F/F_max = 1 - tau/t_unload is linear in tau)
    def creep_integral(tau):
        u = hold_time + tau
        # integral of (1 - (u - T)/t_u) * a/3 u^(-2/3) du from T to T + tau
        c = 1.0 + hold_time / t_unload
        return a * (
            c * (np.cbrt(u) - np.cbrt(hold_time))
            - (u ** (4.0 / 3.0) - hold_time ** (4.0 / 3.0)) / (4.0 * t_unload)
        )

    d3 = d_f + (f3 / alpha) ** (1.0 / m) + creep_integral(tau_un)
    time = np.concatenate([t1, t2, t3])
    depth = np.concatenate([d1, d2, d3])
    load = np.concatenate([f1, f2, f3])
    rng = np.random.default_rng(seed)
    if depth_noise > 0:
        depth = depth + rng.normal(0.0, depth_noise, depth.size)
    if load_noise > 0:
        load = load + rng.normal(0.0, load_noise, load.size)
    return IndentationCurve(depth, load, time, source="synthetic")
