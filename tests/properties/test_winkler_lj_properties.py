"""Property tests of the Winkler-Lennard-Jones model: disjoint spring sets, finite forces, balance.

Bonded springs (the adhesive range) are a subset of the adhesive ones; the others add no friction.
"""

import numpy as np
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from roughcontact.errors import InputError
from roughcontact.materials import Material
from roughcontact.topography import Topography
from roughcontact.winkler_lj import Readings, WinklerLJOptions, winkler_lj_model
from roughcontact.winkler_lj.readings import CHOICES

readings_strategy = st.builds(
    Readings,
    **{name: st.sampled_from(allowed) for name, allowed in CHOICES.items()},
    adhesive_cutoff=st.one_of(st.just(np.inf), st.floats(1e-10, 1e-6)),
)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    heights=st.lists(st.floats(-20e-9, 20e-9), min_size=36, max_size=36),
    pixel=st.floats(1e-9, 1e-7),
    load_fraction=st.floats(1e-6, 0.9),
    modulus=st.floats(1e8, 1e12),
    poissons_ratio=st.floats(0.0, 0.45),
    energy=st.floats(1e-3, 1.0),
    layer=st.floats(5e-9, 1e-6),
    epsilon=st.floats(1e-10, 5e-9),
    readings=readings_strategy,
    tip_pixels=st.floats(0.5, 10.0),
)
def test_springs_are_never_both_and_totals_are_finite(
    heights, pixel, load_fraction, modulus, poissons_ratio, energy, layer, epsilon, readings, tip_pixels
):
    surface = Topography(np.reshape(heights, (6, 6)), 6 * pixel)
    body = Material(modulus, poissons_ratio, "body", surface_energy=energy)
    model = winkler_lj_model(
        surface,
        body,
        body,
        options=WinklerLJOptions(
            layer_thickness=layer,
            epsilon=epsilon,
            readings=readings,
            tip_radius=tip_pixels * pixel,  # used by base="half_sphere" only
        ),
    )
    load = load_fraction * model.load_capacity()
    assume(load > 0)
    try:
        result = model.solve(load)
    except InputError as error:  # only printed readings may refuse a state, each naming its field
        printed_sign = readings.adhesion_sign == "printed" and error.field == "load"
        printed_height = error.field in ("readings.cuboid_height", "readings.mechanical_height")
        assert printed_sign or printed_height, error
        return
    assert not np.any(result.mechanical & result.adhesive)
    assert not np.any(result.bonded & ~result.adhesive)  # bonded springs are adhesive springs
    assert np.all(result.lateral_force[result.adhesive & ~result.bonded] == 0)
    for values in (result.stress, result.extension, result.lateral_force):
        assert np.all(np.isfinite(values))
    assert np.all(np.isfinite(result.gap) | (result.gap == np.inf))  # inf: outside the half-sphere tip
    assert np.all(result.lateral_force >= 0)
    totals = [
        result.mu,
        result.friction,
        result.adhesive_friction,
        result.mechanical_friction,
        result.separation,
    ]
    assert np.all(np.isfinite(totals))
    # The balance holds to round-off in the approach: within brentq's tolerance of the returned value
    # the residual changes sign (a steep force law against soft springs can make 1 ulp worth 1e-7 N/N).
    step = 8 * np.finfo(float).eps * (layer + abs(result.approach))
    below = model.net_normal_force(result.approach - step) - load
    above = model.net_normal_force(result.approach + step) - load
    assert result.residual <= 1e-9 or below * above <= 0
