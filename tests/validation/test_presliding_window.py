"""The solved window of a rough ball (``window = "auto"``): it holds every point that can touch.

The README's ``roughcontact presliding --paper001 --realisations 5`` failed on its fourth HDPE
stand-in ball (replicate 3 of seed 1, 512 px): at 25 mN its contact reached the border of the old
default 160 px window. The window chosen from the ball's heights holds it, and the answer solved
on it is the answer of a much larger window.
"""

import numpy as np
import pytest

from roughcontact.contact.normal import solve_normal
from roughcontact.contact.presliding import contact_window, touches_border, window_holds
from roughcontact.errors import InputError
from roughcontact.materials import get_material
from roughcontact.papers import paper001
from roughcontact.spread import realisation_seed
from roughcontact.topography import generate
from roughcontact.topography.process import central_window

HDPE, FLAT = get_material("HDPE"), get_material(paper001.FLAT)


def _ball(ball: str, base: int, replicate: int, pixels: int):
    """The generated ball a study of seed ``base`` draws for ``replicate`` (as the runner derives it)."""
    seed = realisation_seed(base, ball.lower(), ball, replicate)
    return paper001.roughness(ball, seed=seed, pixels=pixels)


def _solve(scan, window, force):
    return solve_normal(central_window(scan, window), HDPE, counter_body=FLAT, force=force)


def test_the_readme_ball_that_failed_gets_a_window_that_holds_it():
    """Replicate 3 of the README command, at full size (512 px): 160 px is cut off, 'auto' is not."""
    scan = _ball("HDPE", 1, 3, 512)
    assert touches_border(_solve(scan, 160, 0.025).pressure)  # the failure the README command hit
    chosen = contact_window(scan, HDPE, FLAT, normal_force=0.025, radius=paper001.RADIUS)
    assert 160 < chosen.pixels < 512 and not chosen.whole
    assert f"{chosen.pixels} px" in chosen.note and "highest point" in chosen.note
    solved, wide = _solve(scan, chosen.pixels, 0.025), _solve(scan, 400, 0.025)
    assert not touches_border(solved.pressure)
    assert window_holds(scan, solved)[0]
    # nothing outside the chosen window touches: the same contact as on a window 2.5 times wider
    assert solved.approach == pytest.approx(wide.approach, rel=1e-6)
    assert solved.contact_area == pytest.approx(wide.contact_area, rel=1e-9)
    assert chosen.depth == pytest.approx(
        float(scan.heights.max()) - (float(solved.topography.heights.max()) - solved.approach), rel=1e-9
    )


def test_a_pressure_free_border_is_not_enough():
    """A high asperity just beyond the border can touch while the border does not: the region decides.

    On this 256 px ball (replicate 3 of seed 2) at 25 mN, twice the smooth ball's Hertz approach
    holds only a 20 px patch around the highest point; solved there, the pressure vanishes on the
    border, yet the approach is too deep: points outside come within it, and the wider answer
    differs. The window grows to hold them once, and then agrees with a window twice as wide.
    """
    scan = _ball("HDPE", 2, 3, 256)
    small = _solve(scan, 20, 0.025)
    assert not touches_border(small.pressure)
    holds, _ = window_holds(scan, small)
    assert not holds
    chosen = contact_window(scan, HDPE, FLAT, normal_force=0.025, radius=paper001.RADIUS)
    assert chosen.solves == 2 and chosen.pixels > 20 and "first guess, 20 px" in chosen.note
    solved, wide = _solve(scan, chosen.pixels, 0.025), _solve(scan, 2 * chosen.pixels, 0.025)
    assert window_holds(scan, solved)[0]
    assert solved.approach == pytest.approx(wide.approach, rel=1e-6)
    assert small.approach > 1.1 * solved.approach  # the 20 px answer carried the load on too little


def test_an_approach_gives_the_region_without_a_solve():
    """Given the approach, the window holds every point within it of the highest point (and margin)."""
    scan = _ball("POM", 1, 0, 256)
    chosen = contact_window(scan, HDPE, FLAT, approach=1e-6, radius=paper001.RADIUS, margin=3)
    assert chosen.solves == 0 and chosen.depth == 1e-6
    inside = np.argwhere(scan.heights >= scan.heights.max() - 1e-6)
    start = (256 - chosen.pixels) // 2
    assert start <= inside.min() - 3 and start + chosen.pixels - 1 >= inside.max() + 3
    smaller = chosen.pixels - 1
    start = (256 - smaller) // 2
    assert start > inside.min() - 3 or start + smaller - 1 < inside.max() + 3  # the smallest that does


def test_a_contact_beyond_the_whole_scan_is_refused():
    scan = generate.sphere_with_roughness((24, 24), (24e-6, 24e-6), radius=5e-3, rms_height=1e-9, seed=1)
    with pytest.raises(InputError, match="border of the whole scan"):
        contact_window(scan, HDPE, FLAT, normal_force=0.05, radius=5e-3)
    with pytest.raises(InputError, match="exactly one"):
        contact_window(scan, HDPE, FLAT, radius=5e-3)
