"""The friction kind's comparisons and tables from stored records (paper 000, sections 5-6).

The t-tests and Pearson r against ``[analysis.compare]`` (:func:`comparison`), a table per reading
and sample, the trend of mu with Ra and the paper's claims under each reading; the figures of
:mod:`roughcontact.plotting.friction` take the same comparison. Wired by the kind,
:mod:`roughcontact.study.kinds.friction`.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ...cases import at_load, by_sample, grouped, loads_of
from ...errors import InputError
from ...papers import paper000
from ..kind import CaseRecord, FigureContext
from ..store import Table

log = logging.getLogger("roughcontact.study.kinds.friction")  # the kind's logger, as before the split


def _at_one_load(records: Sequence[CaseRecord], load: float | None) -> list[CaseRecord]:
    """Return the records at ``load``, or all of them when the analysis has one load; else InputError."""
    loads = loads_of(records)
    if load is None:
        if len(loads) > 1:
            raise InputError(
                "compare.normal_force",
                f"the analysis has {len(loads)} loads ({loads[0]:.4g} to {loads[-1]:.4g} N) and the "
                "measured values are at one.",
                "add normal_force = '10 uN' (the load of the measurements) to [analysis.compare].",
            )
        return list(records)
    chosen = at_load(records, load)
    if not chosen:
        raise InputError(
            "compare.normal_force",
            f"no case at {load:.6g} N (the analysis has {', '.join(f'{x:.6g}' for x in loads)} N).",
            "set compare.normal_force to one of the analysis' loads.",
        )
    return chosen


def comparison(records: Sequence[CaseRecord], context: FigureContext):
    """Compare the simulated mu per sample with the measured CSV of ``[analysis.compare]``.

    Parameters
    ----------
    records : sequence of CaseRecord
        The analysis' finished cases.
    context : FigureContext
        ``context.compare`` is a :class:`~roughcontact.study.kinds.friction.FrictionCompare`.

    Returns
    -------
    Comparison
        From :func:`roughcontact.experiment.compare.compare`, over the samples found on both sides
        (samples on one side only are left out with a warning).

    Raises
    ------
    InputError
        Several loads and no ``compare.normal_force``, an unreadable CSV, no sample in common, or fewer
        than two values in a sample.
    """
    from ...experiment.compare import compare, read_measured

    spec = context.compare
    simulated = by_sample(_at_one_load(records, spec.normal_force), "mu")
    measured = read_measured(spec.measured)
    common = [s for s in simulated if s in measured]
    left_out = sorted(set(simulated) ^ set(measured))
    if not common:
        raise InputError(
            "compare.measured",
            f"no sample in common: simulated {list(simulated)}, measured {list(measured)}.",
            "name the samples of the analysis as in the CSV's sample column.",
        )
    if left_out:
        log.warning("%s: samples %s are on one side only and are left out", context.analysis, left_out)
    return compare(
        {s: simulated[s] for s in common},
        {s: measured[s] for s in common},
        alpha=spec.alpha,
        equal_var=spec.equal_var,
        origin=measured.origin,
    )


def by_reading(records: Sequence[CaseRecord]) -> dict[str, list[CaseRecord]]:
    """Return the records grouped by their readings (:func:`reading_label`), in order of first appearance."""
    groups: dict[str, list[CaseRecord]] = {}
    for record in records:
        groups.setdefault(reading_label(record.parameters), []).append(record)
    return groups


def comparison_or_none(records, context):
    """Return the comparison with ``[analysis.compare]`` for the figures (its errors reach the report).

    None without one, and for an analysis of several readings (the figures would pool them; the
    ``comparison`` table has a row per reading and sample).
    """
    if context.compare is None or len(by_reading(records)) > 1:
        return None
    return comparison(records, context)


def comparison_table(records, context):
    """Tabulate the t-tests and Pearson r against ``[analysis.compare]``, per reading where several."""
    if context.compare is None:
        return None
    groups = by_reading(records)
    rows, notes = [], []
    for label, group in groups.items():
        result = comparison(group, context)  # its errors are listed in the report
        common = {
            "alpha": result.alpha,
            "test": "student" if result.equal_var else "welch",
            "pearson_r": result.pearson_r,
            "pearson_p": result.pearson_p,
        }
        reading = {"reading": label} if len(groups) > 1 else {}
        rows += [reading | row | common for row in result.table()]
        notes = result.notes()
    return Table(rows, notes)


def per_reading(table):
    """Return ``table`` computed for each reading (and gap model) of the analysis apart.

    An analysis that sweeps the readings holds several models of the same scans; pooling their mu
    into one mean or one trend would mix them. With several readings each row starts with its
    ``reading`` (:func:`reading_label`).
    """

    def separately(records, context):
        groups = by_reading(records)
        rows = []
        for label, group in groups.items():
            named = {"reading": label} if len(groups) > 1 else {}
            rows += [named | row for row in table(group, context) or ()]
        return rows or None

    separately.__doc__ = table.__doc__
    return separately


def by_sample_table(records, context):
    """Mean, spread and range of mu per sample and load over its replicates (None without replicates).

    With one case per sample and load the table would only repeat the cases' own rows.
    """
    rows = []
    for sample, group in grouped(records).items():
        for load in loads_of(group):
            chosen = at_load(group, load)
            mu = np.array([float(r.scalars["mu"]) for r in chosen])
            row: dict[str, Any] = {
                "sample": sample,
                "normal_force [N]": load,
                "n": mu.size,
                "mu_mean": float(mu.mean()),
                "mu_std": float(mu.std(ddof=1)) if mu.size > 1 else None,
                "mu_min": float(mu.min()),
                "mu_max": float(mu.max()),
            }
            for name in ("friction", "adhesive_friction", "mechanical_friction", "crossover_load"):
                values = [r.scalars.get(name) for r in chosen]
                values = [float(v) for v in values if v is not None]
                if values:
                    row[f"{name}_mean [N]"] = float(np.mean(values))
            rows.append(row)
    return rows if any(row["n"] > 1 for row in rows) else None


def ra_trend_table(records, context):
    """Whether simulated mu changes with the samples' Ra beyond the scatter of the realisations.

    Per load, over every case: the least-squares slope of mu against the Ra of the sample's
    surface (``surface_ra``) with its 95 % interval and p value (``scipy.stats.linregress``),
    and the one-way ANOVA of mu across the samples (``scipy.stats.f_oneway``). ``trend`` says
    ``mu rises with Ra`` / ``mu falls with Ra`` where the slope's interval excludes 0, else
    ``within the scatter``. None with fewer than two samples or without realisations.
    """
    from scipy import stats

    rows = []
    for load in loads_of(records):
        chosen = [r for r in at_load(records, load) if r.scalars.get("surface_ra") is not None]
        samples = grouped(chosen)
        if len(samples) < 2 or len(chosen) <= len(samples):
            continue
        ra = np.array([float(r.scalars["surface_ra"]) for r in chosen])
        mu = np.array([float(r.scalars["mu"]) for r in chosen])
        if np.ptp(ra) <= 1e-12 * ra.max():
            continue
        fit = stats.linregress(ra, mu)
        half = float(stats.t.ppf(0.975, ra.size - 2)) * fit.stderr
        anova = stats.f_oneway(*[[float(r.scalars["mu"]) for r in group] for group in samples.values()])
        low, high = fit.slope - half, fit.slope + half
        trend = "mu rises with Ra" if low > 0 else "mu falls with Ra" if high < 0 else "within the scatter"
        rows.append(
            {
                "normal_force [N]": load,
                "samples": len(samples),
                "n": ra.size,
                "dmu_dRa [1/m]": fit.slope,
                "dmu_dRa 95% low [1/m]": low,
                "dmu_dRa 95% high [1/m]": high,
                "slope_p_value": fit.pvalue,
                "anova_p_value": float(anova.pvalue),
                "trend": trend,
            }
        )
    return rows or None


def reading_label(parameters: dict[str, Any]) -> str:
    """Name a case's readings in words: its preset, and the fields its ``readings`` table changes in it.

    ``default``, ``paper``, ``default but adhesive_range=all_springs, base=half_sphere``; a gap
    model other than the springs' is added (``, gap model bem``).
    """
    from ...winkler_lj.readings import Readings

    label = parameters.get("reading") or "default"
    preset = Readings.preset(label)
    given = parameters.get("readings") or {}
    changed = {key: value for key, value in given.items() if str(getattr(preset, key, None)) != str(value)}
    if changed:
        label += " but " + ", ".join(f"{key}={value}" for key, value in changed.items())
    if parameters.get("gap_model") not in (None, "winkler"):
        label += f", gap model {parameters['gap_model']}"
    return label


def _claim_cells(values: list[float], claim) -> tuple[dict[str, Any], str]:
    """Return the columns of one of paper 000's claims (our mean and intervals) and its verdict.

    ``factor from paper``: the smallest factor f for which the prediction interval lies within
    [v / f, v f] of the printed value v, so that a reader can apply another tolerance than
    :data:`~roughcontact.papers.paper000.ROUGHLY`.
    """
    from ...spread import natural_bounds, spread

    name = claim.quantity + (f" ({claim.sample})" if claim.sample else "")
    unit = " [N]" if claim.quantity.endswith("load") else ""
    verdict_column = f"paper {claim.where}: {claim.short}"
    if not values:
        why = " (crossover = true computes it)" if claim.quantity == "crossover_load" else ""
        return {verdict_column: f"not computed{why}"}, "not computed"
    summary = spread(values, bounds=natural_bounds(claim.quantity))
    low, high = summary.prediction()
    verdict = summary.within(claim.value / paper000.ROUGHLY, claim.value * paper000.ROUGHLY, of="one")
    verdict = {"inside": "kept", "outside": "not kept"}.get(verdict, verdict)
    factor = max(claim.value / low, high / claim.value) if low > 0 else math.inf
    cells = {
        f"{name} n": summary.n,
        f"{name} mean{unit}": summary.mean,
        f"{name} 95% prediction low{unit}": low,
        f"{name} 95% prediction high{unit}": high,
        f"{name} 95% mean low{unit}": summary.ci95_low,
        f"{name} 95% mean high{unit}": summary.ci95_high,
        f"{name} factor from paper": factor,
        verdict_column: verdict,
    }
    return cells, verdict


def _p_value_cell(records, context) -> tuple[str, str]:
    """Return the p values of one reading's mu against ``[analysis.compare]`` and the claim's verdict."""
    if context.compare is None:
        return "no compared values", "not tested"
    try:
        result = comparison(records, context)
    except InputError as error:  # the comparison table says why; the other claims still stand
        return f"no comparison ({error.problem})", "not tested"
    shown = ", ".join(f"{s.sample} {s.p_value:.2g}" for s in result.samples)
    if result.by_construction:
        return shown, "no verdict: the values were built from this model"
    kept = all(s.p_value > paper000.P_THRESHOLD for s in result.samples)
    against = "" if result.origin.is_measured else f" (against {result.origin.words} values)"
    return shown, ("kept" if kept else "not kept") + against


def claims_table(records, context):
    """Judge paper 000's claims about its simulations under each reading of the analysis.

    One row per reading (:func:`reading_label`) of the cases of paper 000's scenario (polysilicon
    against SiO2 at the paper's 10 uN, as ``paper000 = true`` sets it): the ratio of adhesive to
    mechanical friction over every scan (the paper: "roughly 40 times ... for all the
    SiO2-polysilicon contacts", sec. 5), the crossover load of
    the Ra 1.7 nm scans ("about 600 uN", sec. 6; with ``crossover = true``) and the t-test p
    values against ``[analysis.compare]`` (p > 0.1 for every sample, sec. 5). A claim is *kept*
    where the 95 % prediction interval of one scan lies within a factor
    :data:`~roughcontact.papers.paper000.ROUGHLY` of the printed value, *not kept* where it lies
    wholly outside, *not established* where it straddles an edge of that band. Compared values
    built from this model's output judge no reading (``by construction``). The notes say which
    claims each reading keeps and whether any keeps them all. None for other analyses, or with one
    scan per reading.
    """
    from ...cases import at_load

    bodies = (paper000.MATERIAL, paper000.TIP_MATERIAL)
    chosen = [
        r for r in records if (r.parameters.get("material"), r.parameters.get("counter_body")) == bodies
    ]
    chosen = at_load(chosen, paper000.NORMAL_FORCE) if chosen else []
    if not chosen:
        return None
    readings = by_reading(chosen)
    if all(len(group) < 2 for group in readings.values()):
        return None  # one scan per reading: no interval to judge with
    rows, kept = [], {}
    for label, group in readings.items():
        row: dict[str, Any] = {"reading": label}
        verdicts = []
        for claim in paper000.CLAIMS:
            cases = [r for r in group if claim.sample in (None, r.parameters.get("sample"))]
            values = [float(v) for r in cases if (v := r.scalars.get(claim.quantity)) is not None]
            cells, verdict = _claim_cells(values, claim)
            row |= cells
            verdicts.append(verdict)
        shown, verdict = _p_value_cell(group, context)
        row |= {"p values": shown, f"paper sec. 5: p > {paper000.P_THRESHOLD:g}": verdict}
        verdicts.append(verdict)
        judged = [v for v in verdicts if v in ("kept", "not kept", "not established")]
        row["claims kept"] = f"{judged.count('kept')} of {len(judged)} judged"
        kept[label] = verdicts
        rows.append(row)
    return Table(rows, _claims_notes(kept, context))


def _claims_notes(kept: dict[str, list[str]], context) -> list[str]:
    """Return the sentences that go with the claims table: how it judges, and what it finds."""
    names = [f"{c.short} ({c.where})" for c in paper000.CLAIMS] + [f"p > {paper000.P_THRESHOLD:g} (sec. 5)"]
    notes = [
        "Paper 000's claims: "
        + "; ".join(f"'{c.words}' ({c.where})" for c in paper000.CLAIMS)
        + f"; t-test p > {paper000.P_THRESHOLD:g} for every sample (sec. 5).",
        "Each claim is judged with the 95 % prediction interval of one scan: kept where it lies within a "
        f"factor {paper000.ROUGHLY:g} of the printed value (our reading of 'roughly' and 'about'; the "
        "paper gives none), not kept where it lies wholly outside that band, not established otherwise. "
        "'factor from paper' is the smallest factor that would keep it; the mean's interval is beside it.",
    ]
    if context.compare is not None:
        origin = comparison_origin(context)
        if origin.by_construction:
            notes.append(
                f"The compared mu are {origin.values}, built from this model's own output, so their p "
                "values judge no reading; paper 000 publishes no measured mu, so its p-value claim cannot "
                f"be tested here (their file: {origin.by_construction})."
            )
        elif not origin.is_measured:
            notes.append(origin.caveat())
    full = [label for label, verdicts in kept.items() if all(v == "kept" for v in verdicts)]
    if full:
        notes.append(f"Keeps every claim: {', '.join(full)}.")
    else:
        parts = []
        for label, verdicts in kept.items():
            which = [name for name, v in zip(names, verdicts, strict=True) if v == "kept"]
            parts.append(f"{label}: {', '.join(which) if which else 'none'}")
        notes.append("No reading keeps every claim. Kept, per reading: " + "; ".join(parts) + ".")
    return notes


def comparison_origin(context):
    """Return the origin of the values of ``[analysis.compare]`` (measured unless their file says so)."""
    from ...experiment.compare import read_measured

    return read_measured(context.compare.measured).origin
