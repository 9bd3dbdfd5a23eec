"""Bad input to solve_tangential and the path builders: InputError naming the field; ConvergenceError."""

from __future__ import annotations

import numpy as np
import pytest

from roughcontact.contact import ShearSolver, solve_normal
from roughcontact.contact.paths import as_path, stroke_path, symmetric_path
from roughcontact.contact.tangential import solve_tangential
from roughcontact.errors import ConvergenceError, InputError
from roughcontact.materials import Material
from roughcontact.topography import generate

MATERIAL = Material(1e9, 0.3, "body")
N = 24
SIZE = 40e-6
FORCE = 1e-3


@pytest.fixture(scope="module")
def free_normal():
    topography = generate.sphere((N, N), (SIZE, SIZE), radius=1e-3, kind="paraboloid")
    return solve_normal(topography, MATERIAL, force=FORCE, tolerance=1e-10)


@pytest.fixture(scope="module")
def periodic_normal():
    topography = generate.sphere((N, N), (SIZE, SIZE), radius=1e-3, kind="paraboloid", periodic=True)
    return solve_normal(topography, MATERIAL, force=FORCE, tolerance=1e-10)


def _field_error(field, call):
    with pytest.raises(InputError) as error:
        call()
    assert error.value.field == field
    assert str(error.value).startswith(f"{field}:")
    return error.value


@pytest.mark.parametrize("mu", [0.0, -0.1, float("nan"), float("inf"), -float("inf")])
def test_bad_friction_coefficient(free_normal, mu):
    _field_error(
        "friction_coefficient",
        lambda: solve_tangential(free_normal, MATERIAL, friction_coefficient=mu, displacement=[1e-9]),
    )


def test_non_numeric_friction_coefficient(free_normal):
    _field_error(
        "friction_coefficient",
        lambda: solve_tangential(free_normal, MATERIAL, friction_coefficient="0.3", displacement=[1e-9]),
    )


@pytest.mark.parametrize(
    "path",
    [[1e-9, float("nan")], [[1e-9, 0.0], [0.0, float("nan")]], [float("inf")], []],
    ids=["nan-1d", "nan-2d", "inf", "empty"],
)
def test_displacement_path_with_non_finite_or_no_values(free_normal, path):
    error = _field_error(
        "displacement",
        lambda: solve_tangential(free_normal, MATERIAL, friction_coefficient=0.3, displacement=path),
    )
    if path and not np.all(np.isfinite(np.asarray(path, dtype=float))):
        assert "step 1" in str(error) or "step 0" in str(error)


def test_force_path_with_nan(free_normal):
    _field_error(
        "force",
        lambda: solve_tangential(free_normal, MATERIAL, friction_coefficient=0.3, force=[1e-5, np.nan]),
    )


def test_path_of_wrong_shape():
    _field_error("displacement", lambda: as_path(np.zeros((3, 3)), "displacement"))


def test_both_or_neither_path(free_normal):
    _field_error("path", lambda: solve_tangential(free_normal, MATERIAL, friction_coefficient=0.3))
    _field_error(
        "path",
        lambda: solve_tangential(
            free_normal, MATERIAL, friction_coefficient=0.3, displacement=[1e-9], force=[1e-5]
        ),
    )


def test_periodic_surface_needs_force_control(periodic_normal):
    error = _field_error(
        "displacement",
        lambda: solve_tangential(periodic_normal, MATERIAL, friction_coefficient=0.3, displacement=[1e-9]),
    )
    assert "periodic" in str(error)
    # force control of the same surface is accepted
    result = solve_tangential(periodic_normal, MATERIAL, friction_coefficient=0.3, force=[0.2 * 0.3 * FORCE])
    assert result.force[0, 0] == pytest.approx(0.2 * 0.3 * FORCE, rel=1e-10)


@pytest.mark.parametrize("fraction", [1.0, 1.5])
@pytest.mark.parametrize("direction", [(1.0, 0.0), (0.6, -0.8)])
def test_force_at_or_above_sliding_is_refused_with_the_sliding_force(free_normal, fraction, direction):
    mu = 0.3
    sliding = mu * free_normal.force
    target = [[fraction * sliding * direction[0], fraction * sliding * direction[1]]]
    error = _field_error(
        "force", lambda: solve_tangential(free_normal, MATERIAL, friction_coefficient=mu, force=target)
    )
    assert f"{sliding:.6g}" in str(error)
    assert "mu F_0" in str(error)


def test_force_above_sliding_later_in_the_path_is_refused(free_normal):
    sliding = 0.3 * free_normal.force
    _field_error(
        "force",
        lambda: solve_tangential(
            free_normal, MATERIAL, friction_coefficient=0.3, force=[0.5 * sliding, 1.01 * sliding]
        ),
    )


@pytest.mark.parametrize(
    "material, counter_body",
    [
        (Material(2e9, 0.3), None),  # stiffer body
        (Material(1e9, 0.1), None),  # other Poisson's ratio
        (MATERIAL, Material(1e9, 0.3)),  # a deformable counter body the normal solve did not have
    ],
    ids=["modulus", "poisson", "counter_body"],
)
def test_materials_must_match_the_normal_solution(free_normal, material, counter_body):
    error = _field_error(
        "material",
        lambda: solve_tangential(
            free_normal, material, counter_body=counter_body, friction_coefficient=0.3, displacement=[1e-9]
        ),
    )
    assert "E*" in str(error)


def test_material_must_be_a_material(free_normal):
    _field_error(
        "material",
        lambda: solve_tangential(free_normal, 1e9, friction_coefficient=0.3, displacement=[1e-9]),
    )


def test_normal_must_be_a_normal_result(free_normal):
    _field_error(
        "normal",
        lambda: solve_tangential(
            free_normal.pressure, MATERIAL, friction_coefficient=0.3, displacement=[1e-9]
        ),
    )


def test_elastic_plastic_normal_solution_is_refused():
    topography = generate.sphere((N, N), (SIZE, SIZE), radius=1e-3, kind="paraboloid")
    elastic = solve_normal(topography, MATERIAL, force=FORCE, tolerance=1e-10)
    hardness = 0.8 * elastic.pressure.max()
    plastic = solve_normal(topography, MATERIAL, force=FORCE, hardness=hardness, tolerance=1e-9)
    assert plastic.hardness is not None
    error = _field_error(
        "normal",
        lambda: solve_tangential(plastic, MATERIAL, friction_coefficient=0.3, displacement=[1e-9]),
    )
    assert "plastic" in str(error)


@pytest.mark.parametrize("builder, name", [(stroke_path, "stroke"), (symmetric_path, "amplitude")])
@pytest.mark.parametrize("value", [0.0, -1e-6, float("nan"), float("inf")])
def test_path_builders_refuse_bad_amplitudes(builder, name, value):
    _field_error(name, lambda: builder(value))


@pytest.mark.parametrize("builder", [stroke_path, symmetric_path])
@pytest.mark.parametrize("counts", [{"cycles": 0}, {"cycles": -2}, {"steps_per_stroke": 0}])
def test_path_builders_refuse_bad_counts(builder, counts):
    _field_error("cycles", lambda: builder(1e-6, **counts))


def test_path_builders_shapes():
    path = stroke_path(2e-6, cycles=2, steps_per_stroke=4)
    assert len(path) == 2 * 2 * 4
    assert path.max() == 2e-6 and path[-1] == 0.0 and np.all(path >= 0)
    sym = symmetric_path(1e-6, cycles=1, steps_per_stroke=3)
    assert sym[0] > 0 and sym.min() == -1e-6 and sym[-1] == 1e-6


@pytest.mark.parametrize("fields_at", ["first", "ALL", ""])
def test_fields_at_bad_value(free_normal, fields_at):
    _field_error(
        "fields_at",
        lambda: solve_tangential(
            free_normal, MATERIAL, friction_coefficient=0.3, displacement=[1e-9], fields_at=fields_at
        ),
    )


def test_fields_at_selects_states(free_normal):
    path = [1e-9, 2e-9, 3e-9]
    kept = {
        choice: set(
            solve_tangential(
                free_normal, MATERIAL, friction_coefficient=0.3, displacement=path, fields_at=choice
            ).states
        )
        for choice in ("all", "none", "last")
    }
    assert kept == {"all": {0, 1, 2}, "none": set(), "last": {2}}
    indexed = solve_tangential(
        free_normal, MATERIAL, friction_coefficient=0.3, displacement=path, fields_at=[0, -1]
    )
    assert set(indexed.states) == {0, 2}


def test_non_convergence_raises_with_residual_and_iterations(free_normal):
    mu = 0.3
    with pytest.raises(ConvergenceError) as error:
        solve_tangential(
            free_normal,
            MATERIAL,
            friction_coefficient=mu,
            force=[0.6 * mu * free_normal.force],
            solver=ShearSolver(tolerance=1e-12, max_iterations=1),
        )
    assert error.value.iterations == 1
    assert error.value.residual > 1e-12
    assert error.value.tolerance == 1e-12
    assert "solve_tangential" in str(error.value)


@pytest.mark.parametrize("fields_at", [[7], [-4], [1.5], 5, ["x"]], ids=["7", "-4", "1.5", "int", "str"])
def test_fields_at_bad_indices(free_normal, fields_at):
    _field_error(
        "fields_at",
        lambda: solve_tangential(
            free_normal,
            MATERIAL,
            friction_coefficient=0.3,
            displacement=[1e-9, 2e-9, 3e-9],
            fields_at=fields_at,
        ),
    )


@pytest.mark.parametrize("mu", [np.float32(0.3), np.int64(1)], ids=["float32", "int64"])
def test_numpy_scalar_friction_coefficient_is_accepted(free_normal, mu):
    result = solve_tangential(free_normal, MATERIAL, friction_coefficient=mu, displacement=[1e-9])
    assert result.parameters["friction_coefficient"] == pytest.approx(float(mu))


def test_coupling_non_convergence_raises(free_normal):
    hard = Material(100e9, 0.2)
    normal = solve_normal(free_normal.topography, MATERIAL, counter_body=hard, force=FORCE, tolerance=1e-10)
    with pytest.raises(ConvergenceError) as error:
        solve_tangential(
            normal,
            MATERIAL,
            counter_body=hard,
            friction_coefficient=0.3,
            force=[0.5 * 0.3 * FORCE],
            solver=ShearSolver(max_coupling_iterations=1),
        )
    assert error.value.iterations == 1
    assert error.value.residual > error.value.tolerance
    assert "coupling" in str(error.value)
