r"""Study kind ``presliding``: a rough ball on a flat under a tangential programme, K_L against Mindlin.

One case is one rough ball (heights *with* its spherical shape, as paper 001 Fig. 4) pressed on a
flat with a constant normal force F0 and taken through a tangential programme: paper 001's (give
``stroke``) or your own (give ``path``, a CSV file). It wraps
:func:`roughcontact.contact.presliding.presliding`:

1. Normal contact (paper 001 eq. 4): FFT boundary elements on a free (non-periodic) grid, load
   control, complementarity p = 0 where g > 0 and p > 0 where g = 0, with the integral of p equal
   to F0. With ``window`` only the central ``window`` x ``window`` pixels are solved
   (:func:`~roughcontact.topography.process.central_window`; only the centre of the ball touches,
   paper Figs. 8-9); the pressure must vanish on the window's border, else the case fails and
   asks for a larger window (a given window whose outside holds points within the approach of
   the highest point gets a warning: they may touch). ``window = "auto"`` chooses per case the
   smallest window that holds every point that can touch
   (:func:`roughcontact.contact.presliding.contact_window`); ``window_pixels`` and
   ``window_choice`` say which window each case solved and why.
2. The programme. Paper 001's (``stroke``): the displacement path of Fig. 6, delta_x: 0 -> d_s -> 0
   repeated ``cycles`` times (default 4, as the paper), ``steps_per_stroke`` steps per branch
   spaced quadratically from each reversal so the short pre-sliding part is resolved. Yours
   (``path``): a CSV with one row per step, x and optionally y, and a unit in every column's
   header (:func:`roughcontact.contact.paths.read_path_csv`); lengths (``x [um], y [um]``)
   prescribe the rigid tangential displacement of the flat, forces (``Q_x [mN], Q_y [mN]``) the
   tangential force, which must stay below mu_f F0 (gross sliding under force control is refused).
   Each step is an increment under the local Coulomb law of eq. 3: a point sticks (|q| < mu_f p
   and no change of the relative displacement s = u - delta, eq. 1) or slips (|q| = mu_f p, s
   changes). With ``coupling`` (default) the pressure is re-solved under the shear of dissimilar
   materials (paper sec. 2, "included in an iterative manner"); without it Goodman's approximation
   holds. The file is read and checked when the study is validated, and its content is part of
   each case's key (editing it reruns the cases on ``--resume``); it must be readable where the
   case runs (a Dask worker on another machine needs the same path).
3. The last loop (the converged one, paper sec. 4), where the x programme closes one that slides,
   is analysed by :func:`roughcontact.experiment.friction_loop.analyse_loop`: the stroke, mu from
   the sliding plateaus, the energy dissipated, and the eq. 9 fit F_x = c1 (1 - (1 - c2
   delta_x)^n) of the branch along increasing displacement, with K_L = dF_x/d delta_x = c1 c2 n
   (1 - c2 delta_x)^(n - 1) at the points A, B, C (Fig. 10). A loop that never slides, a force
   programme and a pre-sliding part with fewer than the 4 steps the fit needs are not analysed:
   those scalars are NaN and ``analysis_note`` says why.
4. Mindlin's smooth-ball reference for a ball of ``radius`` (eqs. 10-12): a^3 = 3 F0 R / (4 E_s)
   with 1/E_s = sum (1 - nu^2)/E (eq. 11), and K_L = 8 a G (1 - F_x/(mu_f F0))^(1/3) (eq. 12)
   at the same points, in two readings (:func:`roughcontact.contact.presliding.mindlin_reference`):
   ``johnson``, the textbook one, 1/G = 1/G* = sum (2 - nu)/G_i, to which eq. 12's prefactor 8
   belongs; ``printed``, the paper's 1/G_s = sum (2 - nu)(1 + nu)/(2E) = sum (2 - nu)/(4 G_i),
   which makes K_L exactly 4 times Johnson's (a known typo of the paper, kept to reproduce its
   Fig. 15).

Stated assumptions (the paper does not define these; from :mod:`roughcontact.experiment.friction_loop`
and :mod:`roughcontact.papers.paper001`): points A, B and C lie where the fitted force change has
reached 0.25, 0.5 and 0.75 of the branch's pre-sliding force span (2 mu_f F0 for a loop that slides
both ways), so Mindlin's K_L there is eq. 12 at F_x = f mu_f F0; the bodies are linear elastic (the
paper argues the polymer balls stay elastic) without visco-elasticity (so the measured loops'
curved corners are absent); static and kinetic friction coefficients are equal; the counter-face
(paper: a silicon wafer) is smooth; no ``counter_body`` means a rigid flat.

Scalars: :meth:`roughcontact.contact.presliding.PreslidingResult.scalars` (units in its ``UNITS``),
with ``window_choice`` (the window solved and how it was chosen: given, the whole scan, or
``auto: ...``) and, for a generated paper 001 ball, ``flattened_rq`` beside ``table2_rq``.
Dataset: :meth:`~roughcontact.contact.presliding.PreslidingResult.to_xarray` (every step from the
unloaded start, the pressure map, the normalised shear sqrt(q_x^2 + q_y^2)/(mu_f p) at the points
A, B, C of the last loop, or at the last reversals and step of your programme, in single
precision). With few steps in the pre-sliding part two points can share a step, which the
``stick_slip`` titles show by the displacement from the reversal.

Figures: ``path`` (the displacement programme with the analysed last loop and the points A, B, C;
Fig. 6), ``pressure`` (the contact pressure of up to three cases, whole field beside a zoom on
the contact; Figs. 8-9), ``loops`` (every case's hysteresis loops, one panel per sample, with the
loop of ``[analysis.compare]``, named by its origin; Figs. 13-14), ``stick_slip`` (stick/slip maps
of up to three cases, zoomed to the contact; Figs. 11-12), ``lateral_stiffness`` (K_L at A, B, C
against F0 with both Mindlin readings, one panel per sample, with the mean's and one ball's
intervals over realisations and one ball's verdict in the title; Fig. 15). Tables:
``lateral_stiffness`` (per case K_L simulated against Mindlin, with their ratios),
``lateral_stiffness_spread`` (over realisations, e.g. paper 001's stand-in balls: one ball's
verdict against Mindlin in each reading, judged by the 95 % prediction interval of one more
realisation, with the mean's interval beside it, and where eq. 12's printed factor 4 decides
the verdict) and, with ``[analysis.compare]``, ``measured_loop`` (stroke, mu and K_L at A, B, C of
the compared loop beside the simulated cases at its normal force; its row, columns and note name
the loop's origin, measured or synthetic, from its file's ``# origin:`` header).

References
----------
Seed paper 001, "Evaluation of pre-sliding behavior at a rough interface: modeling and experiment",
J. Appl. Mech. (2020), eqs. 1-4 and 9-12, Figs. 6, 8-15, Tables 1-2. doi:10.1115/1.4045900

K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985, secs. 7.2 and 7.4.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import Field, model_validator
from pydantic_core import PydanticCustomError

from ...contact.presliding import MINDLIN_READINGS as READINGS
from ...contact.presliding import POINT_NAMES as POINTS
from ...contact.presliding import PreslidingResult
from ...papers import paper001
from ..kind import CaseOutput, CaseParameters, Kind, figure, fill_from_paper
from ..schema import Force, ForceUnit, Length, LengthUnit, MaterialName, Strict, TopographyName

_Positive = Field(gt=0.0, allow_inf_nan=False)


class PreslidingParameters(CaseParameters):
    """Keys of a ``model = "presliding"`` analysis (SI after validation).

    Attributes
    ----------
    topography : str
        The ball: a topography with its spherical shape (paper Fig. 4), e.g. a generated
        ``sphere_with_roughness``.
    window : int, "auto" or None
        Solve only the central ``window`` x ``window`` pixels (free boundary); ``"auto"`` chooses,
        per case, the smallest central window that holds every point of the ball that can touch
        at the case's normal force (:func:`roughcontact.contact.presliding.contact_window`); None
        solves the whole surface.
    material, counter_body : str
        The ball's material and the flat's (None: a rigid flat).
    normal_force : float
        F0 [N] (paper Table 1: 25, 50, 75 mN); not with a ``path`` that has a normal column.
    friction_coefficient : float
        mu_f of the local Coulomb law (Table 1), > 0.
    radius : float
        Ball radius R for Mindlin's reference [m] (default 5 mm: the paper's 10 mm balls).
    stroke : float
        d_s [m], the range of paper 001's displacement path (Table 1); or give ``path``.
    cycles, steps_per_stroke : int
        Cycles of the Fig. 6 path (default 4) and steps per branch (default 20).
    path : Path
        Your programme instead of paper 001's: a CSV relative to the study file, one row per step,
        ``x [um]`` (and ``y [um]``) for displacement control or ``Q_x [mN]`` (and ``Q_y [mN]``)
        for force control; with a normal column (``F_n [mN]`` or ``z [um]``) a combined
        programme from the unloaded state (:func:`roughcontact.contact.frictional.solve_frictional`).
    maps : int
        With ``path``: steps whose shear maps are stored, the last ``maps - 1`` reversals and the
        last step.
    coupling : bool
        Normal-tangential coupling of dissimilar materials (default True, as the paper).
    normal_loading : {"auto", "frictional", "frictionless"}
        How F0 is applied before the programme: with friction (locked-in shear, Spence 1975), or
        frictionless (Goodman's start); "auto" (default) is "frictional" for dissimilar materials.
    loading_steps : int
        Steps of the frictional normal loading (default 10; raise it to 30 or more when beta/mu
        approaches 1; the documentation's page on frictional programmes).
    max_stick_change : float
        Step control: steps are inserted where the stick fraction would fall by more than this in
        one step (default 0.1: at least 10 steps from each reversal to full slip); 0 turns it off
        (the programme's points only).
    tolerance : float
        Relative tolerance of the normal and tangential solvers.
    paper001 : bool
        Fill in paper 001's ball material, the wafer, the radius and, at a load of Table 1, its
        stroke and mu (:func:`roughcontact.papers.paper001.presliding_keys`) where the analysis
        leaves them out; the ball is ``material`` or else ``sample`` (HDPE or POM).
    """

    topography: TopographyName
    window: Annotated[int, Field(ge=3)] | Literal["auto"] | None = None
    material: MaterialName
    counter_body: MaterialName | None = None
    normal_force: Annotated[Force, _Positive] | None = None
    friction_coefficient: Annotated[float, _Positive]
    radius: Annotated[Length, _Positive] = paper001.RADIUS
    stroke: Annotated[Length, _Positive] | None = None
    cycles: Annotated[int, Field(ge=1)] = 4
    steps_per_stroke: Annotated[int, Field(ge=4)] = 20
    path: Path | None = None
    maps: Annotated[int, Field(ge=1, le=12)] = 4
    coupling: bool = True
    normal_loading: Literal["auto", "frictional", "frictionless"] = "auto"
    loading_steps: Annotated[int, Field(ge=2)] = 10
    max_stick_change: Annotated[float, Field(ge=0.0, lt=1.0)] = 0.1
    tolerance: float = Field(default=1e-8, gt=0.0, lt=1.0)
    paper001: bool = Field(default=False, exclude=True)
    """Fill in paper 001's scenario (stored as the keys it fills, not as the flag)."""

    @model_validator(mode="before")
    @classmethod
    def _paper001_scenario(cls, data: Any) -> Any:
        return fill_from_paper(data, "paper001", _paper001_keys)

    @model_validator(mode="after")
    def _one_programme(self) -> PreslidingParameters:
        if (self.stroke is None) == (self.path is None):
            given = "both" if self.stroke is not None else "neither"
            raise PydanticCustomError(
                "quantity",
                "give the «stroke» of paper 001's programme or your own «path», exactly one (found {given})",
                {
                    "given": given,
                    "fix": "e.g. «stroke=2.8 um», or «path=programme.csv»",
                    "field": "stroke",
                },
            )
        return self


def _paper001_keys(given: Mapping[str, Any]) -> dict[str, Any]:
    """Return paper 001's keys for the ball of ``material`` (or ``sample``) at ``normal_force``."""
    from ...errors import InputError
    from ...units import quantity

    ball = given.get("material") or given.get("sample")
    try:
        name = paper001.ball_name(str(ball))
    except InputError:
        raise PydanticCustomError(
            "quantity",
            "«paper001=true» needs the ball (HDPE or POM), found {ball}",
            {"ball": repr(ball), "fix": "give «sample=HDPE» (or POM), or «material=HDPE»"},
        ) from None
    try:
        force = quantity(given.get("normal_force"), "force")
    except (InputError, TypeError, ValueError):
        force = None  # no load (or one the validation reports): no stroke and mu from Table 1
    needed = "friction_coefficient" not in given or not {"stroke", "path"} & set(given)
    if force is not None and needed:
        try:
            paper001.table1(name, force)
        except InputError as error:
            raise PydanticCustomError(
                "quantity", "{problem}", {"problem": error.problem, "fix": error.fix, "field": "normal_force"}
            ) from None
    return paper001.presliding_keys(name, force)


class PreslidingCompare(Strict):
    """The ``[analysis.compare]`` table: a friction loop (CSV) to set beside the cases.

    The key keeps the name ``measured_loop``; what the loop is (measured, reconstructed or
    synthetic) its file's ``# origin:`` header says, and the tables and figures name it so.

    Attributes
    ----------
    measured_loop : Path
        CSV of displacement and force (:func:`roughcontact.experiment.friction_loop.read_loop_csv`:
        columns found by name, ``#`` comments, ``# origin: synthetic`` for a synthetic loop),
        relative to the study file.
    displacement_unit, force_unit : str or None
        Units of its columns where its header gives none (no default: a column without a unit
        in its header needs one); one that contradicts the header is refused, naming the cell.
    normal_force : float
        F0 of the compared loop [N]; the loop is compared with the cases at this force.
    sample : str or None
        The sample (ball) the loop belongs to; None compares it with every sample.
    """

    measured_loop: Path
    displacement_unit: LengthUnit | None = None
    force_unit: ForceUnit | None = None
    normal_force: Annotated[Force, _Positive]
    sample: str | None = None

    def check(self) -> None:
        """Read the loop at validation time, so a file without units fails before the cases run.

        Raises
        ------
        InputError
            As :func:`roughcontact.experiment.friction_loop.read_loop_csv`; the command line's fix
            names ``presliding``'s own options (``--measured-displacement-unit``).
        """
        from ...errors import InputError
        from ...experiment.friction_loop import read_loop_csv

        try:
            read_loop_csv(self.measured_loop, self.displacement_unit, self.force_unit)
        except InputError as error:
            cli = error.fix_in("cli") or ""
            for unit in ("displacement", "force"):
                cli = cli.replace(f"--{unit}-unit", f"--measured-{unit}-unit")
            raise type(error)(
                error.field, error.problem, error.fix, fixes=error.fixes | {"cli": cli}
            ) from None


def check(parameters: PreslidingParameters) -> None:
    """Read a programme file at validation time (its errors name the file, row or column).

    The normal force comes from ``normal_force`` or from the path's normal column, exactly one.
    """
    from ...errors import InputError

    combined = False
    if parameters.path is not None:
        from ...contact.paths import read_programme_csv

        combined = read_programme_csv(parameters.path).normal is not None
    if combined and parameters.normal_force is not None:
        raise InputError(
            "normal_force",
            f"{parameters.path} has a normal column, which sets the normal force of every step.",
            "remove normal_force, or the path's normal column.",
        )
    if not combined and parameters.normal_force is None:
        raise InputError("normal_force", "missing.", "e.g. «normal_force=25 mN» (paper 001 Table 1).")


def _case_words(parameters: PreslidingParameters, inputs, label: str) -> str:
    """Name a case in its errors: its label, sample, replicate and the seed of its ball."""
    spec = inputs.specs.get(parameters.topography)
    seed = getattr(spec, "seed", None)
    ball = f"seed {seed}" if seed is not None else "a measured or fixed surface"
    sample = f"sample {parameters.sample}, " if parameters.sample else ""
    return (
        f"{label} ({sample}replicate {parameters.replicate}, {ball} of topography {parameters.topography!r})"
    )


def run(parameters: PreslidingParameters, inputs) -> CaseOutput:
    """Run the programme on one ball at one load; scalars and dataset of :class:`PreslidingResult`.

    Every error names the case: its label, sample, replicate and the seed of its ball.
    """
    from ...contact.presliding import presliding
    from ...errors import ConvergenceError, InputError

    ball = parameters.sample or parameters.topography
    label = ball if parameters.normal_force is None else f"{ball} at {parameters.normal_force * 1e3:g} mN"
    where = _case_words(parameters, inputs, label)
    if parameters.path is not None:
        from ...contact.paths import read_programme_csv

        path, control, normal_path, normal_control = read_programme_csv(parameters.path)
        programme = {"path": path, "control": control, "maps": parameters.maps}
        if normal_path is not None:
            programme |= {"normal_path": normal_path, "normal_control": normal_control}
    else:
        programme = {
            "stroke": parameters.stroke,
            "cycles": parameters.cycles,
            "steps_per_stroke": parameters.steps_per_stroke,
        }
    scan = inputs.topography(parameters.topography)
    material, counter_body = inputs.material(parameters.material), inputs.material(parameters.counter_body)
    try:
        result = presliding(
            scan,
            material,
            counter_body,
            normal_force=parameters.normal_force,
            friction_coefficient=parameters.friction_coefficient,
            radius=parameters.radius,
            coupling=parameters.coupling,
            normal_loading=parameters.normal_loading,
            loading_steps=parameters.loading_steps,
            max_stick_change=parameters.max_stick_change or None,
            tolerance=parameters.tolerance,
            window=parameters.window,
            label=label,
            **programme,
        )
    except InputError as error:
        problem = error.problem.removeprefix(f"{label}: ")
        raise InputError(error.field, f"{where}: {problem}", error.fix, fixes=error.fixes) from error
    except ConvergenceError as error:
        raise ConvergenceError(
            f"{where}: {error.solver}", error.residual, error.iterations, error.tolerance, error.stalled_at
        ) from error
    scalars = result.scalars() | {"window_choice": result.window_choice}
    if scan.info.get("rms") in ("drawn", "flattened") and parameters.sample in paper001.ROUGHNESS:
        scalars |= paper001.flattened_roughness(scan, parameters.sample)  # a generated ball of paper 001
    return CaseOutput(scalars, result.to_xarray(), tuple(result.range_warnings()))


# --- figures and tables (from stored records only) -----------------------------------------------


def _number(record, name: str) -> float:
    """Return a stored scalar as a float (nan where it was not finite, stored as None)."""
    value = record.scalars.get(name)
    return math.nan if value is None else float(value)


def _measured(context):
    """Return the compared loop of ``[analysis.compare]`` and its analysis, or None (none, or file gone).

    The loop carries its origin (measured, reconstructed or synthetic: its file's ``# origin:``
    header, :func:`roughcontact.experiment.friction_loop.read_loop_csv`).

    A file that was there when the study ran but is missing now (a report drawn on another
    machine) leaves the measured overlay out rather than failing the figure.
    """
    from ...contact.presliding import POINTS as FRACTIONS
    from ...experiment.friction_loop import analyse_loop, read_loop_csv

    compare = context.compare
    if compare is None or not Path(compare.measured_loop).is_file():
        return None
    loop = read_loop_csv(compare.measured_loop, compare.displacement_unit, compare.force_unit)
    return loop, analyse_loop(loop.displacement, loop.force, compare.normal_force, fractions=FRACTIONS)


def _measured_loop(records, context):
    """Return the compared loop of ``[analysis.compare]`` as the figures draw it, with its origin, or None."""
    from ...plotting.presliding import MeasuredLoop

    measured = _measured(context)
    if measured is None:
        return None
    compare = context.compare
    loop, analysis = measured
    name = Path(compare.measured_loop).name
    return MeasuredLoop(loop, analysis, name, compare.normal_force, compare.sample, loop.origin)


def _analysis_name(records, context) -> str:
    return context.analysis


def _compares_with(compare, sample: str) -> bool:
    return compare is not None and (compare.sample is None or compare.sample == sample)


def _ratio(numerator: float, denominator: float) -> float:
    return numerator / denominator if denominator and math.isfinite(denominator) else math.nan


_INPUTS = {
    "normal_force [N]": "normal_force",
    "stroke [m]": "stroke",
    "friction_coefficient": "friction_coefficient",
    "mu_from_loop": "mu_from_loop",
}
_LOOP = {
    "stroke [m]": "stroke_from_loop",
    "mu": "mu_from_loop",
    "energy_last_loop [J]": "energy_last_loop",
    "presliding_distance [m]": "presliding_distance",
}
"""Table column -> stored scalar, of the cases' inputs and of their last loop."""


def _columns(record, columns: dict[str, str]) -> dict[str, float]:
    return {header: _number(record, name) for header, name in columns.items()}


def _stand_in(records) -> bool:
    """Return True where the balls are generated paper 001 balls (stand-ins of Table 2's roughness)."""
    return any(record.scalars.get("table2_rq") is not None for record in records)


def _window_notes(records) -> list[str]:
    """Say which windows were solved where ``window = "auto"`` chose them, per sample."""
    chosen: dict[str, list[int]] = {}
    for record in records:
        if str(record.scalars.get("window_choice", "")).startswith("auto"):
            pixels = record.scalars.get("window_pixels")
            if pixels is not None:
                chosen.setdefault(record.parameters.get("sample", ""), []).append(int(pixels))
    if not chosen:
        return []
    spans = "; ".join(
        f"{sample or 'the cases'} {min(p)}-{max(p)} px" if min(p) != max(p) else f"{sample} {p[0]} px"
        for sample, p in chosen.items()
    )
    return [
        f"Solved windows, chosen per case («window=auto»): {spans}. Each holds every point of the "
        "ball within the case's approach of its highest point, so nothing outside it can touch "
        "(window_choice in results.csv says how each was found)."
    ]


def _lateral_stiffness_table(records, context):
    """Per case: K_L at A, B, C simulated, Mindlin (Johnson and as printed) and their ratios [N/m]."""
    from ..store import Table

    rows = []
    for record in records:
        row = {"case": record["case"], "sample": record.parameters.get("sample", "")}
        row |= _columns(record, _INPUTS)
        pixels = record.scalars.get("window_pixels")
        row["window_pixels"] = "" if pixels is None else int(pixels)
        for point in POINTS:
            simulated = _number(record, f"K_L_{point}")
            row[f"K_L_{point} [N/m]"] = simulated
            for reading in READINGS:
                reference = _number(record, f"K_L_{point}_mindlin_{reading}")
                row[f"K_L_{point}_mindlin_{reading} [N/m]"] = reference
                row[f"K_L_{point} / mindlin_{reading}"] = _ratio(simulated, reference)
        rows.append(row)
    return Table(rows, _window_notes(records))


def _tally(verdicts: list[str]) -> str:
    """Count verdict words: ``below at 9 of 9`` or ``not established at 8 of 9, below at 1 of 9``."""
    counts: dict[str, int] = {}
    for word in verdicts:
        counts[word] = counts.get(word, 0) + 1
    order = sorted(counts, key=lambda word: -counts[word])
    return ", ".join(f"{word} at {counts[word]} of {len(verdicts)}" for word in order)


def _lateral_stiffness_spread_table(records, context):
    """Per sample, load and point: one ball's K_L against Mindlin's smooth ball (paper 001's claim).

    The claim (the rough ball is laterally softer than the smooth one, paper 001 sec. 5, Fig. 15) is
    about one ball, so ``rough vs smooth, one ball`` judges the 95 % prediction interval of K_L /
    Mindlin for one more realisation (:func:`roughcontact.contact.presliding.rough_vs_smooth`):
    ``below`` or ``above`` where the whole interval lies on that side of 1, ``not established``
    where it holds 1. Beside it, the ratio's mean and the 95 % confidence interval of the mean, and
    K_L's mean with its interval [N/m]. Where the verdict under eq. 12 as printed (Mindlin's K_L 4x
    Johnson's) differs from Johnson's, the printed cell says that the factor 4 decides it. The
    notes (CSV, report, terminal) say what the intervals are and sum up the verdicts per sample.
    None without realisations.
    """
    from ...cases import realisations_of
    from ...contact.presliding import READING_WORDS, mindlin_ratios, rough_vs_smooth, verdict_words
    from ...spread import spread
    from ..store import Table

    groups = list(realisations_of(records).values())
    if all(len(group) < 2 for group in groups):
        return None
    rows, tally, means, cut = [], {}, {}, set()
    for group in groups:
        sample, force = group[0].parameters.get("sample", ""), _number(group[0], "normal_force")
        for point in POINTS:
            values = [_number(r, f"K_L_{point}") for r in group]
            stiffness = spread(values, bounds=(0.0, math.inf))
            references = {
                reading: [_number(r, f"K_L_{point}_mindlin_{reading}") for r in group] for reading in READINGS
            }
            ratios = mindlin_ratios(values, references)
            verdicts = rough_vs_smooth(ratios)
            row = {"sample": sample, "normal_force [N]": force, "point": point, "n": stiffness.n}
            row |= {"K_L mean [N/m]": stiffness.mean, "K_L mean 95% low [N/m]": stiffness.ci95_low}
            row["K_L mean 95% high [N/m]"] = stiffness.ci95_high
            for reading in READINGS:
                ratio, verdict = ratios[reading], verdicts[reading]
                row[f"K_L / mindlin_{reading} mean"] = ratio.mean
                row[f"K_L / mindlin_{reading} mean 95% low"] = ratio.ci95_low
                row[f"K_L / mindlin_{reading} mean 95% high"] = ratio.ci95_high
                row[f"K_L / mindlin_{reading} one ball 95% low"] = verdict.interval[0]
                row[f"K_L / mindlin_{reading} one ball 95% high"] = verdict.interval[1]
                row[f"rough vs smooth, one ball ({reading})"] = verdict_words(verdicts, reading)
                tally.setdefault((sample, reading), []).append(verdict.word)
                means.setdefault((sample, reading), []).append(ratio.mean)
                if ratio.note:
                    cut.add(ratio.note)
                if verdict.interval[0] == 0.0:
                    cut.add(
                        "Where a 'one ball 95% low' is 0, Student's prediction interval reached below 0 and "
                        "was cut there (K_L / Mindlin cannot be negative): the scatter of the balls is wide "
                        "against their mean."
                    )
            rows.append(row)
    count = max(len(group) for group in groups)
    balls = "stand-in balls" if _stand_in(records) else "realisations"
    notes = [
        "rough vs smooth, one ball: the claim that a rough ball is laterally softer than Mindlin's "
        "smooth ball is about one ball, so it is judged with the 95 % prediction interval of K_L / "
        f"Mindlin for one more of the {balls} (the 'one ball 95%' columns): below or above where that "
        "whole interval lies on that side of 1, not established where it holds 1. The 95 % "
        f"confidence interval of the mean over the {balls} ('mean 95%') is shown beside it: it narrows "
        "with more of them and judges their mean, not one ball."
    ]
    if _stand_in(records):
        notes.append(
            f"The {count} realisations per load are stand-in balls: balls generated with Table 2's "
            "roughness (seeds derived from the study's seed), not the paper's balls, nor its five "
            "spots on the wafer."
        )
    for (sample, reading), words in tally.items():
        low, high = min(means[sample, reading]), max(means[sample, reading])
        notes.append(
            f"{sample or 'cases'}, {READING_WORDS[reading]}: mean K_L / Mindlin {low:.2f}-{high:.2f} "
            f"over the loads and points; one ball {_tally(words)}."
        )
    decided = [
        row
        for row in rows
        if row["rough vs smooth, one ball (printed)"] != row["rough vs smooth, one ball (johnson)"]
    ]
    if decided:
        where = sorted({row["sample"] for row in decided})
        notes.append(
            f"Eq. 12 as printed makes Mindlin's K_L 4x Johnson's textbook value (a typo of the paper). "
            f"At {len(decided)} of {len(rows)} rows ({', '.join(where)}) its verdict differs from "
            "Johnson's: the factor 4 decides it there, not the roughness."
        )
    notes += sorted(cut)
    return Table(rows, notes + _window_notes(records))


def _measured_loop_table(records, context):
    """Tabulate the compared loop's stroke, mu and K_L at A, B, C beside the simulated cases at its F0.

    The loop's origin (its file's ``# origin:`` header, :mod:`roughcontact.origin`) names its row
    and columns: a synthetic loop is never called measured. Its caveat is the table's note.
    """
    from ..store import Table

    measured = _measured(context)
    if measured is None:
        return None
    loop, analysis = measured
    compare = context.compare
    word = loop.origin.word
    row = {
        "source": f"{word}: {Path(compare.measured_loop).name}",
        "sample": compare.sample or "",
        "normal_force [N]": compare.normal_force,
        "stroke [m]": analysis.stroke,
        "mu": analysis.mu,
        "energy_last_loop [J]": analysis.energy,
        "presliding_distance [m]": analysis.branch.sliding_distance,
    }
    row |= {f"K_L_{p} [N/m]": analysis.lateral_stiffness[p] for p in POINTS}
    rows = [row]
    for record in records:
        sample = record.parameters.get("sample", "")
        force = _number(record, "normal_force")
        if not _compares_with(compare, sample) or not math.isclose(force, compare.normal_force, rel_tol=1e-6):
            continue
        simulated = {
            "source": f"simulated: case {record['case']}",
            "sample": sample,
            "normal_force [N]": force,
        }
        simulated |= _columns(record, _LOOP)
        for point in POINTS:
            value = _number(record, f"K_L_{point}")
            simulated[f"K_L_{point} [N/m]"] = value
            simulated[f"K_L_{point} simulated / {word}"] = _ratio(value, analysis.lateral_stiffness[point])
        rows.append(simulated)
    balls = "stand-in balls" if _stand_in(records) else "realisations"
    by_sample: dict[str, list[dict]] = {}
    for simulated in rows[1:]:
        by_sample.setdefault(simulated["sample"], []).append(simulated)
    for group in by_sample.values():  # one sample's realisations, never two samples' mixed
        if len(group) > 1:
            rows.append(_realisations_row(group, analysis.lateral_stiffness, word, balls))
    notes = [f"The compared loop {Path(compare.measured_loop).name} is {loop.origin.words}."]
    if loop.origin.caveat():
        notes.append(loop.origin.caveat())
    return Table(rows, notes)


def _realisations_row(
    simulated: list[dict], measured: Mapping[str, float], word: str = "measured", balls: str = "realisations"
) -> dict:
    """Return the simulated cases' mean K_L and whether the compared loop's K_L lies within their scatter.

    The compared loop is one ball: it is set against the 95 % prediction interval of one
    realisation (:meth:`roughcontact.spread.Spread.prediction`), not the interval of the mean.
    ``word`` is the loop's origin (measured, synthetic, ...), ``balls`` what the realisations are.
    """
    from ...spread import spread

    row = {"source": f"simulated: mean of {len(simulated)} {balls}", "sample": simulated[0]["sample"]}
    row["normal_force [N]"] = simulated[0]["normal_force [N]"]
    for point in POINTS:
        summary = spread((r[f"K_L_{point} [N/m]"] for r in simulated), bounds=(0.0, math.inf))
        low, high = summary.prediction()
        row[f"K_L_{point} [N/m]"] = summary.mean
        row[f"K_L_{point} simulated / {word}"] = _ratio(summary.mean, measured[point])
        row[f"K_L_{point} {word} in the {balls}' 95% prediction"] = bool(low <= measured[point] <= high)
    return row


KIND = Kind(
    name="presliding",
    summary="rough ball on a flat: partial-slip loops under paper 001's programme (Fig. 6) or yours (CSV), "
    "last-loop K_L at A, B, C vs Mindlin",
    parameters=PreslidingParameters,
    run=run,
    units=PreslidingResult.UNITS | {"flattened_rq": "m", "table2_rq": "m"},
    figures={
        "path": figure("presliding.path_figure"),
        "pressure": figure("presliding.pressure_figure"),
        "loops": figure("presliding.loops_figure", {"measured": _measured_loop, "title": _analysis_name}),
        "stick_slip": figure("presliding.stick_slip_figure"),
        "lateral_stiffness": figure(
            "presliding.lateral_stiffness_figure", {"measured": _measured_loop, "title": _analysis_name}
        ),
    },
    tables={
        "lateral_stiffness": _lateral_stiffness_table,
        "lateral_stiffness_spread": _lateral_stiffness_spread_table,
        "measured_loop": _measured_loop_table,
    },
    compare=PreslidingCompare,
    check=check,
    headline=(
        "contact_area",
        "last_stick_fraction",
        "mu_from_loop",
        "stroke_from_loop",
        "K_L_A",
        "K_L_B",
        "K_L_C",
    ),
    renamed={"surface": "topography", "counter": "counter_body"},
    missing={
        **dict.fromkeys(
            (
                "stroke_from_loop",
                "mu_from_loop",
                "presliding_distance",
                "eq9_c1",
                "eq9_c2",
                "eq9_n",
                *(f"K_L_{point}" for point in POINTS),
            ),
            "no loop analysed: see analysis_note",
        ),
        "energy_last_loop": "no closed loop",
        "locked_in_stick_fraction": "no normal loading steps",
        "locked_in_shear_rms": "no normal loading steps",
    },
    references=(
        "paper001",
        "bazrafshan2019",
        "cattaneo1938",
        "mindlin1949",
        "mindlin1953",
        "johnson1985",
        "polonsky1999",
        "liu2000",
        "frigo2005",
    ),
)
