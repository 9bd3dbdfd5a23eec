"""Free-surface solves on the box around the contact give the whole grid's answers (issue 18).

The sub-grid operators (``window``) of a free surface are exact on their sub-grid: checked against
the whole grid's operator to round-off. The normal solve's cascade (coarse levels, each on its
box, then the whole grid's check) gives the whole grid's answer to 1e-8 of the peak pressure,
also when the coarse levels lose a contact patch (a one-pixel peak that 2 x 2 averaging lowers
below the flat): the check then iterates on the whole grid and finds it. A loading programme
whose increments and coupling passes run on the box (the default) is compared with the same
programme forced onto the whole grid (``BOX_AREA = 0``): a coupled pair (Dundurs beta != 0,
frictional normal loading, so the coupling passes run on the box too and are checked on the whole
grid) and an uncoupled one (beta = 0, nu = 0.5 on a rigid flat). On a periodic surface the cascade's
coarse levels only warm-start the whole grid: the single-level answer to 1e-8 of the peak, also when
the coarse levels lose a one-pixel peak in a valley.
"""

from __future__ import annotations

import numpy as np
import pytest

from roughcontact.analytic import mindlin
from roughcontact.contact import (
    ShearSolver,
    _box,
    _constrained_cg,
    _programme,
    solve_normal,
    solve_tangential,
)
from roughcontact.contact.normal import compliance_for
from roughcontact.contact.paths import stroke_path
from roughcontact.elasticity import kernels
from roughcontact.elasticity.halfspace import ElasticLayer, SurfaceCompliance
from roughcontact.elasticity.tangential import TractionCompliance
from roughcontact.errors import ConvergenceError, InputError
from roughcontact.materials import Material, contact_modulus
from roughcontact.topography import Topography, generate

BALL = Material(1e9, 0.3, "ball")
FLAT = Material(3e9, 0.2, "flat")
HDPE = Material(0.98e9, 0.5, "HDPE")


def _box_fields(rng, shape, box):
    full = np.zeros(shape)
    full[box] = rng.normal(size=(box[0].stop - box[0].start, box[1].stop - box[1].start))
    return full


def test_sub_grid_operators_equal_the_whole_grids_on_their_box():
    rng = np.random.default_rng(3)
    shape, size = (40, 48), (40e-6, 52e-6)
    box = (slice(5, 17), slice(7, 27))
    sub = (12, 20)
    traction = TractionCompliance(shape, size, BALL, FLAT, boundary="free")
    qx, qy, p = (_box_fields(rng, shape, box) for _ in range(3))
    window = traction.window(sub)
    for whole, part in (
        (traction.shear(qx, qy), window.shear(qx[box], qy[box])),
        (traction.slip_from_pressure(p), window.slip_from_pressure(p[box])),
        ((traction.normal_from_shear(qx, qy),), (window.normal_from_shear(qx[box], qy[box]),)),
    ):
        for a, b in zip(whole, part, strict=True):
            assert np.max(np.abs(a[box] - b)) <= 1e-12 * np.max(np.abs(a))
    normal = SurfaceCompliance(shape, size, contact_modulus(BALL, FLAT), boundary="free")
    u = normal(p)
    assert np.max(np.abs(u[box] - normal.window(sub)(p[box]))) <= 1e-12 * np.max(np.abs(u))
    assert traction.window(sub) is window  # built once per shape
    assert traction.window(shape) is traction


@pytest.mark.parametrize(
    "build, window, field",
    [
        (lambda: TractionCompliance((16, 16), (1e-6, 1e-6), BALL), (8, 8), "boundary"),
        (lambda: TractionCompliance((16, 16), (1e-6, 1e-6), BALL, boundary="free"), (8, 17), "window"),
        (lambda: SurfaceCompliance((16, 16), (1e-6, 1e-6), 1e9), (8, 8), "boundary"),
        (
            lambda: SurfaceCompliance(
                (16, 16), (1e-6, 1e-6), layer=ElasticLayer(1e-7, BALL, "bonded"), boundary="free"
            ),
            (8, 8),
            "layer",
        ),
    ],
)
def test_a_sub_grid_that_is_not_exact_is_refused(build, window, field):
    with pytest.raises(InputError) as error:
        build().window(window)
    assert error.value.field == field


def test_the_contact_box_holds_the_contact_and_is_kept_while_it_does():
    contact = np.zeros((200, 160), dtype=bool)
    contact[60:130, 20:41] = True
    box = _box.contact_box(contact, None)
    rows, columns = box
    assert rows.start <= 60 and rows.stop >= 130 and columns.start <= 20 and columns.stop >= 41
    assert 0 <= rows.start and rows.stop <= 200 and 0 <= columns.start and columns.stop <= 160
    for side in (rows.stop - rows.start, columns.stop - columns.start):
        assert side == _box.transform_friendly(side)
    contact[70:80, 25:30] = False  # a smaller contact keeps the box
    assert _box.contact_box(contact, box) == box
    contact[10, 100] = True  # a point outside gives a new box around everything
    grown = _box.contact_box(contact, box)
    assert grown is None or (grown[0].start <= 10 and grown[1].stop > 100)
    assert _box.contact_box(np.zeros((50, 50), dtype=bool), None) is None
    assert _box.contact_box(np.ones((50, 50), dtype=bool), None) is None  # no cheaper than the grid


@pytest.mark.parametrize("length", [1, 2, 3, 17, 100, 257, 1000, 4097])
def test_transform_friendly_sides_are_small_multiples_of_powers_of_two(length):
    side = _box.transform_friendly(length)
    assert length <= side <= 1.2 * length + 1
    odd = side
    while odd % 2 == 0:
        odd //= 2
    assert odd in (1, 3, 5, 7, 9, 15)


def _rough_ball(n, material, counter):
    force, radius = 0.5, 10e-3
    a = mindlin.hertz_contact_radius(force, radius, contact_modulus(material, counter))
    topography = generate.sphere_with_roughness(
        (n, n), (4 * a, 4 * a), radius=radius, rms_height=0.05 * a**2 / radius, seed=4
    )
    return topography, force


def _loop(material, counter, steps_per_stroke):
    """The normal contact of :func:`_rough_ball` at 64^2 and a one-cycle loop from it (last fields kept)."""
    topography, force = _rough_ball(64, material, counter)
    normal = solve_normal(topography, material, counter_body=counter, force=force, tolerance=1e-11)
    path = stroke_path(2e-6, cycles=1, steps_per_stroke=steps_per_stroke)

    def loop():
        return solve_tangential(
            normal,
            material,
            counter_body=counter,
            friction_coefficient=0.3,
            displacement=path,
            fields_at="last",
            solver=ShearSolver(tolerance=1e-11),
        )

    return normal, force, path, loop


def _normal_solves(monkeypatch, narrow=None):
    """Record (on a box, iterations) of every normal solve of a stepper; ``narrow(box)`` alters its boxes."""
    calls = []
    normal_solve = _programme.Stepper.normal_solve

    def recorded(self, shear, pressure, normal, box=None):
        if box is not None and narrow is not None:
            box = narrow(box)
        result = normal_solve(self, shear, pressure, normal, box)
        calls.append((box is not None, result[2]))
        return result

    monkeypatch.setattr(_programme.Stepper, "normal_solve", recorded)
    return calls


@pytest.mark.parametrize("material, counter", [(BALL, FLAT), (HDPE, None)], ids=["coupled", "beta 0"])
def test_a_loop_on_the_contact_box_equals_the_loop_on_the_whole_grid(monkeypatch, material, counter):
    normal, force, path, loop = _loop(material, counter, 5)
    boxes = []
    contact_box = _box.contact_box
    monkeypatch.setattr(_box, "contact_box", lambda *a: boxes.append(contact_box(*a)) or boxes[-1])
    solves = _normal_solves(monkeypatch)
    boxed = loop()
    assert boxes and all(box is not None for box in boxes[1:])  # the box was used
    on_box = any(on for on, _ in solves)
    assert on_box == (counter is not None)  # coupled: the coupling passes ran on the box too
    monkeypatch.setattr(_box, "BOX_AREA", 0.0)
    whole = loop()
    scale = 0.3 * force
    assert np.max(np.abs(boxed.force - whole.force)) <= 1e-10 * scale  # measured 7e-13
    last, reference = boxed.states[len(path) - 1], whole.states[len(path) - 1]
    peak = 0.3 * np.max(reference.pressure)
    for name in ("shear_x", "shear_y", "slip_x", "slip_y"):
        difference = np.max(np.abs(getattr(last, name) - getattr(reference, name)))
        size = peak if name.startswith("shear") else np.max(np.abs(getattr(reference, name)))
        assert difference <= 1e-9 * size, name  # measured 9e-11 (coupled), 2e-16
    if counter is not None:  # coupled: the normal solves ran on the box too
        assert np.max(np.abs(last.pressure - reference.pressure)) <= 1e-9 * np.max(reference.pressure)


def _recorded(monkeypatch):
    """Record (grid shape, iterations) of every engine solve."""
    calls = []
    engine = _box._constrained_cg.solve

    def solve(operator, separation, **options):
        result = engine(operator, separation, **options)
        calls.append((separation.shape, result.iterations))
        return result

    monkeypatch.setattr(_box._constrained_cg, "solve", solve)
    return calls


def _whole_grid(topography, force, tolerance):
    compliance = compliance_for(topography, BALL, counter_body=FLAT)
    separation = topography.heights.max() - topography.heights
    return compliance, separation, dict(pixel_area=topography.pixel_area, force=force, tolerance=tolerance)


def test_the_cascade_of_boxes_gives_the_whole_grids_answer(monkeypatch):
    topography, force = _rough_ball(256, BALL, FLAT)
    compliance, separation, problem = _whole_grid(topography, force, 1e-10)
    reference = _constrained_cg.solve(compliance, separation, **problem)
    calls = _recorded(monkeypatch)
    boxed = _box.solve(compliance, separation, **problem)
    shapes = [shape for shape, _ in calls]
    assert shapes[0] == (64, 64) and shapes[-1] == (256, 256)  # coarsest level first, the check last
    assert all(shape[0] < 256 for shape in shapes[:-1])  # every other solve on a coarse grid or a box
    assert calls[-1][1] == 0  # the check did not iterate: nothing outside the box overlaps
    assert np.max(np.abs(boxed.pressure - reference.pressure)) <= 1e-8 * np.max(reference.pressure)
    assert abs(boxed.approach - reference.approach) <= 1e-8 * reference.approach


def test_a_patch_the_coarse_levels_lose_is_found_on_the_whole_grid(monkeypatch):
    """A one-pixel peak away from the ball touches; averaged over 2 x 2 pixels it does not."""
    topography, force = _rough_ball(256, BALL, FLAT)
    heights = topography.heights.copy()
    compliance, separation, problem = _whole_grid(topography, force, 1e-10)
    plain = _constrained_cg.solve(compliance, separation, **problem)
    peak = (30, 220)  # far outside the ball's contact
    assert plain.gap[peak] > 0 and _box.contact_box(plain.pressure > 0)[1].stop <= peak[1]
    heights[peak] += plain.gap[peak] + 0.5 * plain.approach  # it now overlaps by half the approach
    peaked = Topography(heights, topography.size, periodic=False)
    compliance, separation, problem = _whole_grid(peaked, force, 1e-10)
    reference = _constrained_cg.solve(compliance, separation, **problem)
    assert reference.pressure[peak] > 0
    calls = _recorded(monkeypatch)
    boxed = _box.solve(compliance, separation, **problem)
    assert calls[-1][0] == (256, 256) and calls[-1][1] > 0  # the check had to iterate
    assert calls[-2][0] != (256, 256)  # after a box solve that could not see the peak
    assert boxed.pressure[peak] > 0
    assert np.max(np.abs(boxed.pressure - reference.pressure)) <= 1e-8 * np.max(reference.pressure)


def test_coupling_passes_whose_box_misses_contact_go_on_over_the_whole_grid(monkeypatch):
    """The whole grid's check catches a box pass that left contact out; the answer is unchanged."""
    normal, force, path, loop = _loop(BALL, FLAT, 3)
    reference = loop()
    first = int(np.flatnonzero((normal.pressure > 0).any(axis=1))[0])
    # the coupling passes' boxes less the first row of the initial contact
    solves = _normal_solves(
        monkeypatch, lambda box: (slice(max(box[0].start, first + 1), box[0].stop), box[1])
    )
    caught = loop()
    # a whole-grid check right after a box pass had to iterate: the passes went on over the whole grid
    pairs = zip(solves[:-1], solves[1:], strict=True)
    assert any(before[0] and not after[0] and after[1] > 0 for before, after in pairs)
    assert np.max(np.abs(caught.force - reference.force)) <= 1e-9 * 0.3 * force
    last, whole = caught.states[len(path) - 1], reference.states[len(path) - 1]
    assert np.max(np.abs(last.pressure - whole.pressure)) <= 1e-7 * np.max(whole.pressure)  # measured 2.6e-8


def test_an_operator_keeps_its_last_sub_grid_operators():
    traction = TractionCompliance((64, 64), (64e-6, 64e-6), BALL, FLAT, boundary="free")
    first = traction.window((8, 8))
    for side in range(9, 9 + kernels.SUB_GRIDS_KEPT - 1):
        traction.window((side, side))
    assert traction.window((8, 8)) is first  # still kept
    traction.window((40, 40))  # one more: the oldest goes
    assert traction.window((8, 8)) is not first


def _periodic_rough(n):
    """A periodic self-affine surface (the benchmark's statistics) at a load giving ~10 % contact."""
    surface = generate.self_affine((n, n), (1e-4, 1e-4), hurst=0.8, rms_slope=0.1, seed=n)
    compliance = compliance_for(surface, 1e9)
    separation = surface.heights.max() - surface.heights
    return surface, compliance, separation


@pytest.mark.parametrize(
    "n, target", [(128, "force"), (256, "force"), (256, "approach"), (512, "force"), (512, "approach")]
)
def test_the_periodic_cascade_gives_the_single_level_answer(monkeypatch, n, target):
    """Coarse levels from 64^2 up (to the coarse tolerance), then the whole grid, at every size."""
    surface, compliance, separation = _periodic_rough(n)
    load = {"force": 5e6 * surface.area} if target == "force" else {"approach": 0.6 * np.std(separation)}
    problem = dict(pixel_area=surface.pixel_area, tolerance=1e-10, **load)
    reference = _constrained_cg.solve(compliance, separation, **problem)
    calls = _recorded(monkeypatch)
    cascaded = _box.solve(compliance, separation, **problem)
    levels = [(side, side) for side in (64, 128, 256, 512) if side <= n]
    assert [shape for shape, _ in calls] == levels
    assert np.max(np.abs(cascaded.pressure - reference.pressure)) <= 1e-8 * np.max(reference.pressure)
    assert abs(cascaded.approach - reference.approach) <= 1e-8 * reference.approach
    assert cascaded.residual <= 1e-10


def test_a_patch_the_periodic_coarse_levels_lose_is_found_on_the_fine_grid(monkeypatch):
    """A one-pixel peak in a valley touches; averaged over 2 x 2 pixels it stays out of contact."""
    surface, compliance, separation = _periodic_rough(256)
    problem = dict(pixel_area=surface.pixel_area, tolerance=1e-10, force=5e6 * surface.area)
    plain = _constrained_cg.solve(compliance, separation, **problem)
    peak = np.unravel_index(np.argmax(plain.gap), plain.gap.shape)  # the deepest valley
    peaked = separation.copy()
    peaked[peak] = max(plain.approach - 0.5 * plain.gap[peak] - plain.displacement[peak], 0.0)
    reference = _constrained_cg.solve(compliance, peaked, **problem)
    assert reference.pressure[peak] > 0
    calls = []
    coarse_engine = _box._constrained_cg.solve

    def solve(operator, separation, **options):
        result = coarse_engine(operator, separation, **options)
        calls.append((separation.shape, result))
        return result

    monkeypatch.setattr(_box._constrained_cg, "solve", solve)
    cascaded = _box.solve(compliance, peaked, **problem)
    coarse = calls[-2][1].pressure  # the 128^2 level's answer
    assert coarse[peak[0] // 2, peak[1] // 2] == 0  # lost there
    assert cascaded.pressure[peak] > 0
    assert np.max(np.abs(cascaded.pressure - reference.pressure)) <= 1e-8 * np.max(reference.pressure)


def test_the_coarse_operator_is_the_same_body_on_pixels_twice_as_wide():
    layer = ElasticLayer(1e-6, BALL, "bonded")
    fine = SurfaceCompliance((64, 32), (64e-6, 32e-6), layer=layer, counter_body=FLAT)
    coarse = fine.coarse()
    assert coarse.shape == (32, 16) and coarse.size == fine.size and coarse.boundary == "periodic"
    assert coarse.layer is layer and coarse.contact_modulus == fine.contact_modulus
    with pytest.raises(InputError) as error:
        SurfaceCompliance((64, 33), (64e-6, 33e-6), 1e9).coarse()
    assert error.value.field == "shape"


def test_a_coarse_level_that_does_not_converge_leaves_the_error_to_the_fine_level(monkeypatch):
    """max_iterations=3 stops each coarse level (the next starts cold) and the fine grid, which raises."""
    surface, compliance, separation = _periodic_rough(256)
    problem = dict(pixel_area=surface.pixel_area, tolerance=1e-10, force=5e6 * surface.area)
    shapes, engine = [], _box._constrained_cg.solve

    def solve(operator, separation, **options):
        shapes.append((separation.shape, options["initial_pressure"] is None))
        return engine(operator, separation, **options)

    monkeypatch.setattr(_box._constrained_cg, "solve", solve)
    with pytest.raises(ConvergenceError) as error:
        _box.solve(compliance, separation, max_iterations=3, **problem)
    assert shapes == [((64, 64), True), ((128, 128), True), ((256, 256), True)]  # each level starts cold
    assert error.value.iterations == 3 and error.value.residual > 1e-4
