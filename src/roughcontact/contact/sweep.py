"""Load paths: a sequence of normal contact solves, each warm-started from the previous one."""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from ..errors import InputError
from ..materials import Material
from ..topography import Topography
from .normal import compliance_for, solve_normal
from .result import NormalContactResult


def load_path(
    topography: Topography,
    material: Material | float,
    *,
    mean_pressures: Iterable[float] | None = None,
    forces: Iterable[float] | None = None,
    approaches: Iterable[float] | None = None,
    counter_body: Material | None = None,
    boundary: str | None = None,
    hardness: float | None = None,
    tolerance: float = 1e-8,
    max_iterations: int = 10_000,
) -> Iterator[NormalContactResult]:
    """Yield the normal contact at each load of a path, reusing one operator and warm-starting.

    Parameters
    ----------
    topography, material, counter_body, boundary
        As in :func:`roughcontact.contact.solve_normal`.
    mean_pressures, forces, approaches : iterable of float
        Exactly one: the loads [Pa], [N] or approaches [m] of the path, in order.
    hardness, tolerance, max_iterations
        As in :func:`~roughcontact.contact.solve_normal`.

    Yields
    ------
    NormalContactResult
        One per load, in the order given. Being a generator, a long path can be stopped early
        and its results written as they come.
    """
    given = {
        name: values
        for name, values in (("mean_pressure", mean_pressures), ("force", forces), ("approach", approaches))
        if values is not None
    }
    if len(given) != 1:
        raise InputError("load path", "give exactly one of mean_pressures, forces, approaches.", None)
    ((name, values),) = given.items()
    compliance = compliance_for(topography, material, counter_body=counter_body, boundary=boundary)
    previous = None
    for value in values:
        previous = solve_normal(
            topography,
            compliance=compliance,
            initial=previous,
            hardness=hardness,
            tolerance=tolerance,
            max_iterations=max_iterations,
            **{name: value},
        )
        yield previous
