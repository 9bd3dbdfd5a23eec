"""Invariants of the single-asperity laws and the GW integrals over their whole ranges."""

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from roughcontact.asperity import (
    gw_integral,
    kogut_etsion_area,
    kogut_etsion_load,
    paper002_eq10_load,
    residual_interference_ratio,
    unloading_exponent,
    unloading_load,
)
from roughcontact.asperity.elastic_plastic import unloading_area

W_STAR = st.floats(min_value=0.0, max_value=110.0, allow_nan=False)


@given(W_STAR, W_STAR)
def test_loading_laws_never_decrease(a, b):
    low, high = min(a, b), max(a, b)
    assert kogut_etsion_load(high) >= kogut_etsion_load(low)
    assert kogut_etsion_area(high) >= kogut_etsion_area(low)
    assert paper002_eq10_load(high, critical_load=1.0) >= paper002_eq10_load(low, critical_load=1.0)


@given(st.floats(min_value=1.0, max_value=110.0))
def test_residual_and_exponent_stay_in_their_physical_bounds(w_max):
    ratio = residual_interference_ratio(w_max)
    assert 0.0 <= ratio < 1.0  # the summit keeps some elastic recovery
    assert 1.0 < unloading_exponent(w_max) <= 1.5


@given(st.floats(min_value=1.0, max_value=110.0), st.floats(min_value=0.0, max_value=1.0))
def test_unloading_stays_between_zero_and_the_peak_and_below_loading(w_max, fraction):
    omega_c = 1e-8
    peak = kogut_etsion_load(w_max)
    omega = fraction * w_max * omega_c
    load = unloading_load(
        omega, max_interference=w_max * omega_c, max_force=peak, critical_interference=omega_c
    )
    assert 0.0 <= load <= peak
    # an unloaded summit carries less than on first loading to the same interference (up to the 3 % KE jump)
    assert load <= 1.03 * kogut_etsion_load(fraction * w_max) + 1e-12


# fractions of omega_max: 0, or above 1e-12 (below it x^1.5 underflows to 0 while x does not)
FRACTION = st.one_of(st.just(0.0), st.floats(min_value=1e-12, max_value=1.0))


@given(st.floats(min_value=1e-6, max_value=110.0), FRACTION, FRACTION)
def test_unloading_area_is_finite_bounded_monotonic_and_vanishes_with_the_load(w_max, f1, f2):
    omega_c = 1e-8
    max_area = kogut_etsion_area(w_max)  # in units of pi R omega_c
    omega = np.array([min(f1, f2), max(f1, f2)]) * w_max * omega_c
    kwargs = dict(max_interference=w_max * omega_c, critical_interference=omega_c)
    area = unloading_area(omega, max_area=max_area, **kwargs)
    load = unloading_load(omega, max_force=kogut_etsion_load(w_max), **kwargs)
    assert np.all(np.isfinite(area))
    assert np.all((area >= 0.0) & (area <= max_area))
    assert area[0] <= area[1]  # never grows as the flat withdraws
    assert np.all((area > 0) == (load > 0))  # both vanish at omega_res


@given(
    st.sampled_from([0.0, 1.0, 1.5, 2.0]),
    st.floats(min_value=-6, max_value=6),
    st.floats(min_value=1e-3, max_value=2),
)
def test_gw_integrals_are_positive_and_decrease_with_separation(order, h, dh):
    values = gw_integral(order, np.array([h, h + dh]))
    assert values[0] > 0
    assert values[1] < values[0]
