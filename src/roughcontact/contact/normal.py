r"""Normal contact of a rough surface against a rigid flat: :func:`solve_normal`.

The surface is an elastic half-space (or a layer, see
:class:`roughcontact.elasticity.halfspace.ElasticLayer`) whose undeformed heights are the
topography; the counter-body is a flat. Two rough elastic bodies are handled through their
composite topography (:func:`roughcontact.topography.process.combine`) and the contact modulus
of the pair, which is exact for the normal problem of two elastic half-spaces under the
small-slope assumption of the boundary-element method, when the tangential tractions are
ignored (Johnson 1985 sec. 13.1; with the Dundurs beta != 0 coupling see the tangential solver).

The contact conditions are paper 001 eq. 4 (complementarity of gap and pressure); with a
hardness the pressure is capped and the overlap becomes plastic deformation (paper 002's
elastic-perfectly-plastic surface model, see :mod:`roughcontact.contact.load_unload`).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import scipy

from .._device import gpu_module, to_host
from .._version import __version__
from ..checks import no_string, positive
from ..elasticity.halfspace import ElasticLayer, SurfaceCompliance
from ..errors import ConvergenceError, InputError
from ..materials import Material, check_material, contact_modulus
from ..topography import Topography
from ..topography.plausible import doubts, is_flat
from ..topography.surface import topography_argument
from ..units import format_si
from . import _box, _constrained_cg
from .result import NormalContactResult

# Width given to the y axis of a line scan solved as a (n, 1) grid; any value gives the same answer.
_LINE_WIDTH = 1.0


def resolve_boundary(topography: Topography, boundary: str | None) -> str:
    """Return the boundary to solve: ``boundary``, else "periodic" for a periodic topography or a profile.

    A line scan (1D) is solved as a plane-strain line contact, which exists only periodic: the
    displacement of a free half-plane under a line load grows without bound (logarithmically), so
    a profile is solved as repeated with its length as the period, whatever its own flag says.
    """
    check_line_boundary(topography.dim, boundary)
    if topography.dim == 1:
        return "periodic"
    return boundary or ("periodic" if topography.periodic else "free")


def check_line_boundary(dim: int, boundary: str | None) -> None:
    """Refuse a free boundary for a line scan (``dim`` 1), see :func:`resolve_boundary`."""
    if dim != 1 or boundary != "free":
        return
    said = "the profile is repeated with its length as the period."
    raise InputError(
        "boundary",
        "a line scan is solved as a plane-strain line contact, which is periodic only (a free "
        "half-plane's displacement under a line load has no finite value).",
        f"leave «boundary» out, or give «boundary=periodic»: {said}",
    )


def compliance_for(
    topography: Topography,
    material: Material | float | None,
    *,
    counter_body: Material | None = None,
    layer: ElasticLayer | None = None,
    boundary: str | None = None,
    workers: int | None = None,
    device: str | None = None,
    precision: str = "double",
) -> SurfaceCompliance:
    """Build the surface compliance operator of a topography's grid for a body (and counter-body).

    Parameters
    ----------
    topography : Topography
        Gives the grid and physical size.
    material : Material or float or None
        The body's material, or directly the contact modulus E* [Pa]; None when ``layer`` is given.
    counter_body : Material, optional
        The flat (default: rigid).
    layer : ElasticLayer, optional
        The body is this layer instead of a half-space.
    boundary : {"periodic", "free"}, optional
        Default: "periodic" for a periodic topography, else "free".
    workers : int, optional
        Threads for scipy.fft.
    device, precision : str, optional
        Where the contact solver runs, and its fields' precision (:class:`SurfaceCompliance`).
    """
    boundary = resolve_boundary(topography, boundary)
    check_material(counter_body, "counter_body", rigid=True)
    if material is None and layer is None:
        raise InputError(
            "material", "no material given.", "pass a Material, the contact modulus E* in Pa, or layer=."
        )
    shape = topography.shape if topography.dim == 2 else (topography.shape[0], 1)
    size = topography.size if topography.dim == 2 else (topography.size[0], _LINE_WIDTH)
    if layer is not None:
        if material is not None:
            raise InputError("material", "both a material and a layer were given.", "pass material=None.")
        return SurfaceCompliance(
            shape, size, layer=layer, counter_body=counter_body, boundary=boundary, workers=workers,
            device=device, precision=precision,
        )  # fmt: skip
    check_material(material, "material", modulus=True)
    if isinstance(material, Material):
        modulus = contact_modulus(material, counter_body)
    else:
        if counter_body is not None:
            raise InputError(
                "counter_body", "a contact modulus already includes both bodies.", "pass a Material instead."
            )
        modulus = material
    return SurfaceCompliance(
        shape, size, modulus, boundary=boundary, workers=workers, device=device, precision=precision
    )


def _one_target(**targets) -> tuple[str, float]:
    given = {k: v for k, v in targets.items() if v is not None}
    if len(given) != 1:
        raise InputError(
            "load",
            f"give exactly one of {', '.join(targets)}; got {', '.join(given) or 'none'}.",
            "e.g. mean_pressure=1e6 (Pa), force=1e-3 (N) or approach=1e-8 (m).",
        )
    name, value = next(iter(given.items()))
    unit = {"mean_pressure": "Pa", "force": "N", "approach": "m"}.get(name, "")
    return name, positive(value, name, unit=unit, allow_zero=True)


def check_heights(topography: Topography) -> None:
    """Refuse a topography with undefined (NaN or infinite) heights, naming the fix."""
    if not np.all(np.isfinite(topography.heights)):
        raise InputError(
            "heights",
            "the topography has undefined (NaN or infinite) heights.",
            "fill them first (read_topography(..., undefined='interpolate')).",
        )


def solve_normal(
    topography: Topography,
    material: Material | float | None = None,
    *,
    mean_pressure: float | None = None,
    force: float | None = None,
    approach: float | None = None,
    counter_body: Material | None = None,
    layer: ElasticLayer | None = None,
    hardness: float | None = None,
    boundary: str | None = None,
    tolerance: float = 1e-8,
    max_iterations: int = 10_000,
    initial: NormalContactResult | np.ndarray | None = None,
    compliance: SurfaceCompliance | None = None,
    precondition: bool = True,
    device: str | None = None,
    precision: str = "double",
) -> NormalContactResult:
    r"""Solve the normal contact of ``topography`` against a flat.

    The rough surface (heights :math:`h`, initial separation :math:`h_0 = \max h - h`) is pressed
    by a rigid approach :math:`\delta`; the pressure :math:`p` and the gap :math:`g` satisfy the
    complementarity conditions of paper 001 eq. 4,

    .. math::

        g = K p + h_0 - \delta, \qquad p \ge 0, \quad g \ge 0, \quad p\, g = 0,
        \qquad \int p \, \mathrm{d}A = F \ \text{(load control)},

    with :math:`K` the elastic surface compliance: in Fourier space
    :math:`\hat u(q) = 2 \hat p(q) / (E^* |q|)` for a periodic half-space, Love's influence
    coefficients on a zero-padded grid for a free one, and
    :math:`1/E^* = (1 - \nu_1^2)/E_1 + (1 - \nu_2^2)/E_2`. Solved by Polonsky and Keer's
    constrained conjugate gradients (with ``hardness``: :math:`p \le H`), to the scale-free
    residual ``tolerance``; theory and validation in :doc:`/normal_contact`.

    Parameters
    ----------
    topography : Topography
        Heights [m] pointing towards the flat (2D map, or a periodic 1D profile solved as a
        plane-strain line contact). Detrend it first; undefined heights are refused.
    material : Material or float
        The body's material (against a rigid flat unless ``counter_body``), or the contact
        modulus E* [Pa] directly.
    mean_pressure, force, approach : float
        Exactly one. Load control by the nominal mean pressure [Pa] or the total force [N]
        (per unit length [N/m] for a profile); displacement control by the rigid approach [m]
        from the first touch.
    counter_body : Material, optional
        Material of the flat (default rigid); E* combines both.
    layer : ElasticLayer, optional
        The body is an elastic layer of finite thickness (on a rigid base or a substrate).
    hardness : float, optional
        Caps the pressure [Pa] (elastic-perfectly-plastic surface, paper 002); the overlap at
        the cap is the plastic deformation. Load control then finds the approach by root finding.
    boundary : {"periodic", "free"}, optional
        Default: the topography's periodic flag.
    tolerance : float
        Scale-free residual to reach (see :mod:`roughcontact.contact._constrained_cg`).
    max_iterations : int
        Iteration limit; beyond it :class:`~roughcontact.errors.ConvergenceError` is raised.
    initial : NormalContactResult or ndarray, optional
        Warm start (a previous solution on the same grid, e.g. the last step of a load path).
    compliance : SurfaceCompliance, optional
        A prebuilt operator for this grid (reuse it along load paths; overrides the material).
    precondition : bool
        Build the conjugate directions from the Fourier-inverse preconditioned gap (default;
        several times fewer iterations on rough surfaces, one more FFT pair each). False gives
        plain Polonsky-Keer.
    device : {"cpu", "gpu"}, optional
        Run the iteration on the CPU (numpy and numba, the default) or on a CUDA GPU (CuPy, the
        ``roughcontact[gpu]`` extra): the same algorithm and, in double precision, the same answer
        to round-off. Default: the environment variable ``ROUGHCONTACT_DEVICE``, else the CPU.
        A given ``compliance`` brings its own device.
    precision : {"double", "single"}
        The solver's fields in float64, or (GPU only) in float32 with float64 sums: half the
        memory, for the largest grids; the answer is then good to about 1e-6 of the peak pressure,
        and tolerances below about 1e-6 stall (reported as a :class:`ConvergenceError`).

    Returns
    -------
    NormalContactResult

    Raises
    ------
    InputError
        No or several load targets, negative loads, undefined heights, a load the capped
        surface cannot carry, grids that do not match the operator.
    ConvergenceError
        The solver did not reach the tolerance.

    References
    ----------
    Polonsky, I. A. and Keer, L. M. (1999). Wear 231, 206-219. doi:10.1016/S0043-1648(99)00113-1
    Seed paper 001, eq. 4; seed paper 002 (elastic-plastic compression).
    """
    topography = topography_argument(topography, "topography")
    name, value = _one_target(mean_pressure=mean_pressure, force=force, approach=approach)
    if value == 0.0:  # no load: the unloaded state, where the highest point touches the flat
        name = "approach"
    check_heights(topography)
    if compliance is None:
        compliance = compliance_for(
            topography,
            material,
            counter_body=counter_body,
            layer=layer,
            boundary=boundary,
            device=device,
            precision=precision,
        )
    shape = compliance.shape
    if int(np.prod(shape)) != topography.heights.size or shape[0] != topography.shape[0]:
        raise InputError("compliance", f"operator grid {shape} does not match {topography.shape}.", None)
    no_string(hardness, "hardness")
    heights = topography.heights.reshape(shape)
    # A flat surface touches everywhere at once: its round-off is no roughness (plausible.is_flat).
    separation = np.zeros(shape) if is_flat(heights) else heights.max() - heights
    measure = topography.pixel_area if topography.dim == 2 else topography.spacing[0]
    nominal = topography.area if topography.dim == 2 else topography.size[0]
    target_force = value * nominal if name == "mean_pressure" else value
    check_single_precision(float(np.ptp(heights)), topography, compliance.contact_modulus)
    if name != "approach":
        check_carried(
            name, value, target_force / nominal, topography.size, compliance.contact_modulus, hardness
        )
    elif compliance.boundary == "periodic" and hardness is None:
        check_periodic_approach(value, float(separation.mean()))
    guess = initial.approach if isinstance(initial, NormalContactResult) else None
    if initial is not None:
        initial = (initial.pressure if isinstance(initial, NormalContactResult) else initial).reshape(shape)
    if compliance.device == "gpu":  # the whole solve, its cascade included, runs on the device
        separation = gpu_module().cupy.asarray(separation, dtype=compliance.field_dtype)
        initial = None if initial is None else gpu_module().cupy.asarray(initial)
    common = dict(
        pixel_area=measure,
        cap=hardness,
        precondition=precondition,
        tolerance=tolerance,
        max_iterations=max_iterations,
        solver="solve_normal",
    )
    try:
        if name == "approach":
            raw = _box.solve(compliance, separation, approach=value, initial_pressure=initial, **common)
        elif hardness is None:
            raw = _box.solve(compliance, separation, force=target_force, initial_pressure=initial, **common)
        else:
            raw = _capped_at_force(
                compliance, separation, target_force, initial, guess, measure, hardness, common
            )
    except ConvergenceError as error:
        displacement = (
            value
            if name == "approach"
            else target_force / nominal * _length(topography) / compliance.contact_modulus
        )
        raise _explained(error, topography, displacement) from None
    return NormalContactResult(
        topography=topography,
        pressure=to_host(raw.pressure).astype(float, copy=False).reshape(topography.shape),
        gap=to_host(raw.gap).astype(float, copy=False).reshape(topography.shape),
        displacement=to_host(raw.displacement).astype(float, copy=False).reshape(topography.shape),
        approach=raw.approach,
        contact_modulus=compliance.contact_modulus,
        boundary=compliance.boundary,
        iterations=raw.iterations,
        residual=raw.residual,
        tolerance=tolerance,
        hardness=hardness,
        parameters={name: value, "version": __version__},
    )


SCALE_RATIO = 1e3
"""Displacement of the load over the surface's rms height beyond which a failed solve is put down to
the scale (:func:`_explained`): the pressure differences that shape the contact are then a
thousandth of the mean pressure or less, and the solver's round-off (1e-13 to 1e-10 of the
displacement, rising with the grid) reaches the default tolerance 1e-8 of the roughness. Measured
problems lie far below: a 600 nm AFM scan of 3 nm rms at 20 MPa on E* = 44 GPa is at 0.1;
SurfaceTopography's ``nms-1.nms`` read as 160 m x 160 m is at 2e6 and stalls at 3e-6."""


def _length(topography: Topography) -> float:
    """Return a length of the scan [m]: the square root of its area (a profile: its length)."""
    return float(np.sqrt(topography.area)) if topography.dim == 2 else topography.size[0]


def _explained(error: ConvergenceError, topography: Topography, displacement: float) -> ConvergenceError:
    """Return ``error`` with its cause where the scale of the problem explains it, else ``error`` itself.

    ``displacement`` [m] is the load's elastic displacement scale: the mean pressure times the
    scan's length over E* (load control) or the approach (displacement control). Where it is
    :data:`SCALE_RATIO` times the surface's rms height or more, the roughness is at the round-off of
    the displacement: the cause is the scale, and where the surface's numbers are implausible
    (:func:`~roughcontact.topography.plausible.doubts`: a scan of 160 m) they are the cause of that.
    """
    rms = float(np.std(topography.heights))
    if not displacement > 0 or rms > 0 and displacement < SCALE_RATIO * rms:
        return error
    ratio = f", {displacement / rms:.2g} times its rms height {format_si(rms, 'm')}" if rms > 0 else ""
    cause = (
        f"the load displaces the surface by about {format_si(displacement, 'm')}{ratio}, so the "
        "pressure differences that shape its contact are at the round-off of the mean pressure"
    )
    found = [
        doubt.problem for doubt in doubts(topography) if not doubt.problem.startswith("the surface is flat")
    ]
    if found:
        cause = "; ".join(found) + f" (implausible), and {cause}"
        fix = (
            "check the scan's size and height unit (the file's metadata, or give them: size, "
            "height_unit, override_file_values); at a plausible scale the roughness is resolved."
        )
    else:
        floor = error.suggested_tolerance
        allowed = f"a tolerance of {floor:g} is met at this load, or " if floor is not None else ""
        fix = (
            f"the contact is full or nearly so, its roughness too small to matter: {allowed}give a lower "
            "load to resolve the roughness."
        )
    return ConvergenceError(
        error.solver,
        error.residual,
        error.iterations,
        error.tolerance,
        error.stalled_at,
        cause=cause,
        fix=fix,
    )


SINGLE_PRECISION_MARGIN = 1e-3
"""Fraction of the largest float32 (3.4e38) that the solver's single-precision fields may reach."""


def check_single_precision(span: float, topography: Topography, modulus: float) -> None:
    """Refuse heights whose span overflows the solver's single-precision steering.

    The conjugate directions and the step's quadratic form are computed in single precision
    (:mod:`roughcontact.contact._constrained_cg`): pressures of the order of E* span / pixel (the
    pressure that closes the span over one pixel), summed over the grid by the transforms. Beyond
    :data:`SINGLE_PRECISION_MARGIN` of float32's largest number they would overflow (numpy says
    so on stderr and the answer is lost); such heights (1e30 m: a wrong height unit) are refused
    here, with the size of what they ask.

    Raises
    ------
    InputError
        (field ``heights``) the span of the heights overflows.
    """
    pixel = min(topography.spacing)
    pressure = modulus * span / pixel * topography.heights.size
    if pressure <= SINGLE_PRECISION_MARGIN * float(np.finfo(np.float32).max):
        return
    raise InputError(
        "heights",
        f"the heights span {span:.3g} m over pixels of {format_si(pixel, 'm')}: the pressures that "
        f"close such gaps (E* x span / pixel, {modulus * span / pixel:.3g} Pa) overflow the solver's "
        "single-precision arithmetic.",
        "check the height unit of the surface (heights of a real surface span less than 1 m).",
    )


def check_periodic_approach(approach: float, mean_separation: float) -> None:
    """Refuse an approach that a periodic elastic surface cannot reach: its mean separation or more.

    The periodic half-space takes its mean displacement as zero (the displacement of a uniform
    pressure on an infinite surface has no finite value), so the flat, pressed down by
    ``approach``, touches everywhere once it passes the mean initial separation (the mean of
    ``max h - h``), with a mean pressure that grows without bound as it gets there: beyond, no
    pressure keeps the surface out of the flat. A flat surface (mean separation 0) has no approach
    but 0, and a tilted one repeated (a ramp, a sawtooth) reaches it at half its height. Under load
    control (a mean pressure or a force) the same surfaces are solved (full contact at a uniform
    pressure for a flat); a free boundary or a hardness has no such limit.

    Raises
    ------
    InputError
        (field ``approach``) a positive approach at or beyond the mean separation.
    """
    if not 0 < approach >= mean_separation:
        return
    beyond = (
        f"a periodic surface is in full contact at its mean separation {format_si(mean_separation, 'm')} "
        "(the mean of max(h) - h), with a mean pressure that grows without bound as the flat gets there"
        if mean_separation > 0
        else "the surface is flat, and a periodic flat surface carries any mean pressure at approach 0"
    )
    raise InputError(
        "approach",
        f"an approach of {format_si(approach, 'm')} is not reached: {beyond} (the periodic half-space "
        "takes its mean displacement as zero).",
        "give the load instead («mean_pressure» or «force»), or an approach below the mean separation, "
        "or «boundary=free».",
    )


CARRIED_PRESSURE = 1.0
"""Largest nominal mean pressure, in units of E*, a load may ask of an elastic surface."""


def check_carried(
    name: str, value: float, pressure: float, size: tuple[float, ...], modulus: float, hardness: float | None
) -> None:
    """Refuse a load the scan cannot carry, before solving: a nominal pressure of E* or more, or the hardness.

    An elastic half-space under a mean pressure of order E* is strained by order one: beyond
    small-strain elasticity whatever the roughness (:data:`CARRIED_PRESSURE`); so is an
    ``approach`` of the scan's size or more (the mean pressure of a window pressed by delta is of
    order E* delta / L). An elastic-perfectly-plastic surface carries at most its hardness over the
    whole nominal area.
    Such a load is usually a wrong unit or a wrong scan size, so both are shown in engineering
    units. ``size`` is the scan's physical size [m] (one value: a profile, the load per length).

    Raises
    ------
    InputError
        Naming the load (``force`` or ``mean_pressure``).
    """
    if hardness is not None and not (np.isfinite(hardness) and hardness > 0):
        raise InputError(
            "hardness", f"must be positive, got {format_si(hardness, 'Pa')}.", "e.g. '0.46 GPa'."
        )
    line = len(size) == 1
    extent = " x ".join(format_si(side, "m") for side in size)
    if name == "approach":
        if value >= CARRIED_PRESSURE * min(size):
            raise InputError(
                name,
                f"an approach of {format_si(value, 'm')} on a scan of {extent} compresses it by its own "
                "size or more: strains of order one, beyond the small-strain elastic model.",
                "check the approach's unit (a few times the scan's rms height reaches full contact).",
            )
        return
    unit = {"force": "N/m" if line else "N", "mean_pressure": "Pa"}[name]
    asked = (
        f"a force of {format_si(value, unit)} over the nominal {'length' if line else 'area'} {extent} "
        f"is a mean pressure of {format_si(pressure, 'Pa')}"
        if name == "force"
        else f"a mean pressure of {format_si(value, unit)}"
    )
    joined = " is" if name == "mean_pressure" else ","
    if hardness is not None and pressure >= hardness:
        raise InputError(
            name,
            f"{asked}{joined} at or above the hardness {format_si(hardness, 'Pa')}, the most an "
            "elastic-perfectly-plastic surface carries (over its whole area).",
            "check the load's unit and the scan's size; lower the load or use a larger scan.",
        )
    if hardness is None and pressure >= CARRIED_PRESSURE * modulus:
        raise InputError(
            name,
            f"{asked}{joined} {pressure / modulus:.3g} times the contact modulus E* = "
            f"{format_si(modulus, 'Pa')}: strains of order one, beyond the small-strain elastic model "
            "(whatever the roughness).",
            "check the load's unit and the scan's size (the load of a scan is its nominal pressure "
            "times its area); give a «hardness» for a plastic surface.",
        )


def _capped_at_force(compliance, separation, target_force, initial, guess, measure, hardness, common):
    """Displacement-controlled capped solves, with the approach of ``target_force`` found by Brent's method.

    The root is bracketed around ``guess`` (the approach of the warm start, e.g. the previous step
    of a load path) when there is one, else in [0, 2^k ptp(h0)]; every solve is warm-started from
    the last one and evaluated once (Brent's method revisits its bracket ends). The result is the
    solve at the root, with the iterations of all the solves of the search.
    """
    capacity = hardness * separation.size * measure
    if target_force >= capacity:
        raise InputError(
            "force",
            f"{target_force:.4g} N needs a mean pressure at or above the hardness over the whole "
            f"surface (capacity {capacity:.4g} N).",
            "lower the load or enlarge the nominal area.",
        )
    if target_force == 0:
        return _constrained_cg.solve(compliance, separation, approach=0.0, **common)
    solved = {}  # approach -> engine result
    state = {"pressure": initial}

    def excess(delta: float) -> float:
        if delta not in solved:
            raw = _box.solve(
                compliance, separation, approach=delta, initial_pressure=state["pressure"], **common
            )
            state["pressure"], solved[delta] = raw.pressure, raw
        return float(solved[delta].pressure.sum()) * measure - target_force

    if guess is not None and guess > 0:
        low, high = _bracket_around(excess, guess, target_force)
    else:
        low, high = 0.0, float(separation.max() - separation.min()) or (target_force / capacity) * 1e-6
        while excess(high) < 0:
            low, high = high, 2.0 * high
    relative = common["tolerance"]
    delta = scipy.optimize.brentq(excess, low, high, xtol=relative * high, rtol=max(relative, 4e-16))
    excess(delta)
    return dataclasses.replace(solved[delta], iterations=sum(raw.iterations for raw in solved.values()))


def _bracket_around(excess, guess: float, target_force: float) -> tuple[float, float]:
    """Return approaches (low, high) with excess(low) <= 0 <= excess(high), stepping out from ``guess``.

    The first step is the force error over the stiffness 1.5 F / delta of a Hertzian contact
    (an estimate: too short a step only costs a doubling), doubled until the sign changes; the
    approach 0 (no load, excess -target) bounds it from below.
    """
    error = excess(guess)
    force = error + target_force
    step = abs(error) * guess / (1.5 * force) if force > 0 else guess
    step = max(step, 1e-6 * guess)
    if error < 0:
        low, high = guess, guess + step
        while excess(high) < 0:
            step *= 2.0
            low, high = high, high + step
        return low, high
    low, high = max(guess - step, 0.0), guess
    while low > 0 and excess(low) > 0:
        step *= 2.0
        low, high = max(low - step, 0.0), low
    return low, high
