"""Simulated vs compared friction per sample: two-sample t-tests and the Pearson r of the means.

Paper 000 validates its model by scanning each sample at several spots (seven), simulating mu for
each scan against the AFM tip, measuring mu at as many spots, and comparing per sample with a
two-sample t-test (p > 0.1 taken as agreement) and across samples with the Pearson correlation of
the means (r = 0.96 in the paper). :func:`read_measured` reads the compared distributions from a
CSV and :func:`compare` does the statistics; the simulated ones are paper 000's scenario
(:func:`roughcontact.papers.paper000.simulate_mu`).

The compared values keep their origin (:mod:`roughcontact.origin`): measured, reconstructed from
reported statistics, or synthetic, as the CSV's header says, and every column, verdict and
sentence of the comparison says which. Values built from this model's own output (the header's
``# by construction:`` line) give no agreement verdict: their p values are what they were built
to be.

References
----------
B. L. Welch, "The generalization of 'Student's' problem when several different population
variances are involved", Biometrika 34 (1947) 28-35. doi:10.1093/biomet/34.1-2.28.
Seed paper 000, section 5 (t-test p values 0.13, 0.12, 0.79; Pearson r 0.96).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from scipy import stats

from .._deprecation import moved
from .._text_table import read_text_table
from ..errors import InputError
from ..origin import MEASURED, DataOrigin


@dataclass(frozen=True)
class SampleComparison:
    """Simulated and compared mu of one sample and their two-sample t-test.

    Attributes
    ----------
    sample : str
        Sample name.
    simulated, measured : tuple of float
        The mu values: simulated, and those compared with (measured, reconstructed or synthetic:
        the :class:`Comparison`'s ``origin`` says which).
    t_statistic, p_value : float
        Two-sample t-test of the means (Welch unless ``equal_var`` was asked).
    agrees : bool or None
        ``p_value > alpha``: the test does not distinguish simulation from the compared values;
        None where those were built from this model's output (no verdict: by construction).
    """

    sample: str
    simulated: tuple[float, ...]
    measured: tuple[float, ...]
    t_statistic: float
    p_value: float
    agrees: bool | None

    @property
    def simulated_mean(self) -> float:
        """Mean simulated mu."""
        return float(np.mean(self.simulated))

    @property
    def measured_mean(self) -> float:
        """Mean compared mu (measured, reconstructed or synthetic)."""
        return float(np.mean(self.measured))

    @property
    def simulated_std(self) -> float:
        """Sample standard deviation of the simulated mu (ddof = 1)."""
        return float(np.std(self.simulated, ddof=1))

    @property
    def measured_std(self) -> float:
        """Sample standard deviation of the compared mu (ddof = 1)."""
        return float(np.std(self.measured, ddof=1))

    def verdict(self, alpha: float) -> str:
        """Say what the t-test shows: agrees, differs, or by construction (no verdict)."""
        if self.agrees is None:
            return "by construction: no verdict"
        return f"agrees: p > {alpha:g}" if self.agrees else f"differs: p <= {alpha:g}"


@dataclass(frozen=True)
class Comparison:
    """Per-sample t-tests and the Pearson correlation of the per-sample means.

    Attributes
    ----------
    samples : tuple of SampleComparison
        In the order the samples were given.
    pearson_r, pearson_p : float
        Pearson r of (simulated mean, measured mean) over the samples and its p value.
    alpha : float
        Significance threshold of the t-tests.
    equal_var : bool
        Student's pooled-variance test (True) or Welch's (False).
    origin : DataOrigin
        Where the compared values come from (measured unless their file says otherwise).
    """

    samples: tuple[SampleComparison, ...]
    pearson_r: float
    pearson_p: float
    alpha: float
    equal_var: bool
    origin: DataOrigin = MEASURED

    @property
    def by_construction(self) -> bool:
        """True where the compared values were built from this model's output (no verdict)."""
        return self.origin.by_construction is not None

    def table(self) -> list[dict]:
        """Return one JSON-ready row per sample: means and spreads named by origin, t, p and verdict.

        The compared columns are named for what the values are (``measured_mean``,
        ``reconstructed_mean`` or ``synthetic_mean``), and ``verdict`` says "by construction"
        instead of agreeing where they were built from this model's output.
        """
        word = self.origin.word
        return [
            {
                "sample": s.sample,
                "simulated_mean": s.simulated_mean,
                "simulated_std": s.simulated_std,
                f"{word}_mean": s.measured_mean,
                f"{word}_std": s.measured_std,
                "n_simulated": len(s.simulated),
                f"n_{word}": len(s.measured),
                "t_statistic": s.t_statistic,
                "p_value": s.p_value,
                "verdict": s.verdict(self.alpha),
            }
            for s in self.samples
        ]

    def notes(self) -> list[str]:
        """Return the sentences a reader needs with the table: what the compared values are."""
        notes = [f"Compared with {self.origin.values}."]
        if caveat := self.origin.caveat():
            notes.append(caveat)
        if self.by_construction:
            notes.append(
                f"Pearson r of the means = {self.pearson_r:.3g}: by construction too, not evidence of a "
                "correlation."
            )
        return notes


def _values(values: Sequence[float], field: str) -> np.ndarray:
    array = np.asarray(values, dtype=float).ravel()
    if array.size < 2 or not np.all(np.isfinite(array)):
        raise InputError(
            field,
            f"needs at least 2 finite values, got {array.tolist()}.",
            "give several scans / measurements per sample (paper 000 uses seven).",
        )
    return array


def compare(
    simulated: Mapping[str, Sequence[float]],
    measured: Mapping[str, Sequence[float]],
    *,
    alpha: float = 0.1,
    equal_var: bool = False,
    origin: DataOrigin | None = None,
) -> Comparison:
    """Compare simulated and measured mu per sample (t-test) and across samples (Pearson r).

    Parameters
    ----------
    simulated, measured : mapping of str to sequence of float
        mu values per sample; both must name the same samples (order taken from ``simulated``).
        ``measured`` may be a :class:`MuTable` (from :func:`read_measured`), which brings its
        origin.
    alpha : float
        Threshold of the t-tests (paper 000: 0.1).
    equal_var : bool
        Student's pooled-variance t-test if True; Welch's (default) does not assume the scatter
        of simulation and measurement to be equal.
    origin : DataOrigin, optional
        Where the compared values come from; default: ``measured.origin`` of a :class:`MuTable`,
        else measured. Values built from this model's own output give no verdict.

    Returns
    -------
    Comparison
        Pearson r needs at least 3 samples with different means; with fewer it is reported as 0
        with p = 1 (no evidence of correlation).

    Raises
    ------
    InputError
        Samples missing on one side, or fewer than 2 finite values in a sample.
    """
    missing = sorted(set(simulated) ^ set(measured))
    if missing:
        raise InputError(
            "measured",
            f"samples {missing} are not on both sides "
            f"(simulated: {list(simulated)}, measured: {list(measured)}).",
            "name the samples the same way in the scans and in the measured CSV.",
        )
    if origin is None:
        origin = getattr(measured, "origin", MEASURED)
    rows = []
    for name in simulated:
        sim = _values(simulated[name], f"simulated[{name!r}]")
        meas = _values(measured[name], f"measured[{name!r}]")
        if np.ptp(sim) == 0 and np.ptp(meas) == 0:
            t, p = (0.0, 1.0) if sim[0] == meas[0] else (math.copysign(math.inf, sim[0] - meas[0]), 0.0)
        else:
            test = stats.ttest_ind(sim, meas, equal_var=equal_var)
            t, p = float(test.statistic), float(test.pvalue)
        agrees = None if origin.by_construction else p > alpha
        rows.append(SampleComparison(name, tuple(sim), tuple(meas), t, p, agrees))
    means = np.array([[s.simulated_mean, s.measured_mean] for s in rows])
    if len(rows) >= 3 and np.ptp(means[:, 0]) > 0 and np.ptp(means[:, 1]) > 0:
        pearson = stats.pearsonr(means[:, 0], means[:, 1])
        r, r_p = float(pearson.statistic), float(pearson.pvalue)
    else:
        r, r_p = 0.0, 1.0
    return Comparison(tuple(rows), r, r_p, float(alpha), bool(equal_var), origin)


@dataclass(frozen=True)
class MuTable(Mapping[str, np.ndarray]):
    """mu values per sample read from a CSV, with where they come from.

    A mapping of sample name to its mu values (file order; also ``mu``, a dict), and ``origin``,
    the :class:`~roughcontact.origin.DataOrigin` the file's header declares.
    """

    mu: dict[str, np.ndarray]
    origin: DataOrigin = MEASURED
    path: Path | None = field(default=None, compare=False)

    def __getitem__(self, sample: str) -> np.ndarray:
        return self.mu[sample]

    def __iter__(self) -> Iterator[str]:
        return iter(self.mu)

    def __len__(self) -> int:
        return len(self.mu)


def read_measured(path: str | Path) -> MuTable:
    """Read mu per sample from a CSV with columns ``sample`` and ``mu``, and the values' origin.

    Read through :func:`roughcontact._text_table.read_text_table`: lines starting with ``#`` are
    comments, the header names the columns (in any case, in any order); other columns are ignored.
    The comments say where the values come from (``# origin: measured | reconstructed |
    synthetic`` and ``# by construction: ...``, :func:`roughcontact.origin.origin_of`).

    Parameters
    ----------
    path : str or Path
        CSV file.

    Returns
    -------
    MuTable
        mu values per sample, in file order, and their origin.

    Raises
    ------
    InputError
        A missing or empty file, missing columns, or a mu that is not a finite number.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError(
            "measured", f"{path} does not exist.", "give the path of a CSV with columns sample,mu."
        )
    try:
        table = read_text_table(path, expected="columns sample,mu", delimiter=",")
    except InputError as error:  # no data lines: named as the measured file, with this reader's fix
        raise InputError("measured", error.problem, "give a header line 'sample,mu'.") from error
    if table.names is None or not {"sample", "mu"} <= set(table.names):
        raise InputError("measured", f"{path} has columns {table.names}.", "give a header line 'sample,mu'.")
    sample_column, mu_column = table.names.index("sample"), table.names.index("mu")
    values: dict[str, list[float]] = {}
    for number, row in enumerate(table.rows, start=1):
        cell = row[mu_column] if mu_column < len(row) else None
        try:
            mu = float(cell)
        except (TypeError, ValueError):
            mu = math.nan
        if not math.isfinite(mu):
            raise InputError("measured", f"{path}, data row {number}: mu {cell!r}.", "give a number.")
        if mu < 0:
            raise InputError(
                "measured",
                f"{path}, data row {number}: mu {cell} is negative; a friction coefficient is F/N >= 0.",
                "give the magnitude of the friction force over the normal force (a loop's two branches "
                "give -mu and +mu: use their half difference).",
            )
        sample = row[sample_column] if sample_column < len(row) else ""
        values.setdefault(sample, []).append(mu)
    origin = table.origin("measured")
    return MuTable({name: np.array(v) for name, v in values.items()}, origin, path)


def __getattr__(name: str):
    """Serve :func:`simulate_mu`, which moved to :mod:`roughcontact.papers.paper000`, with a warning."""
    return moved(__name__, name, {"simulate_mu": "roughcontact.papers.paper000"})
