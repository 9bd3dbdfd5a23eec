"""Tables and files of the asperity analysis for the command line: text, JSON-ready dicts, CSV, NetCDF.

Pure functions: nothing here prints; the CLI decides what to show and where to write.
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from ..asperity.parameters import AsperityParameters
from ..errors import InputError
from ..units import format_si
from .paper002 import ComparisonRow

UNITS = {
    "m0": "m^2",
    "m2": "",
    "m4": "1/m^2",
    "bandwidth": "",
    "summit_density": "1/m^2",
    "summit_radius": "m",
    "summit_height_std": "m",
    "summit_mean_offset": "m",
    "contact_modulus": "Pa",
    "contact_pressure_factor": "",
    "critical_interference": "m",
    "critical_load": "N",
    "plasticity_index": "",
}
"""SI units of :meth:`~roughcontact.asperity.parameters.AsperityParameters.to_dict`'s entries."""


def _shown(value: float | None, unit: str) -> str:
    if value is None:
        return "-"
    return format_si(value, unit) if unit in ("m", "Pa", "N") else f"{value:.4g} {unit}".rstrip()


def format_parameters(parameters: AsperityParameters) -> str:
    """Return the asperity parameters as an aligned text table with SI-prefixed units."""
    return "\n".join(
        f"  {key:<24} {_shown(value, UNITS[key])}" for key, value in parameters.to_dict().items()
    )


def format_comparison(rows: list[ComparisonRow]) -> str:
    """Return the paper-vs-ours table as aligned text (paper, ours with (1-nu^2), ours with eq. 7 printed)."""
    lines = [f"  {'quantity':<40} {'paper':>12} {'ours (1-nu^2)':>14} {'eq. 7 printed':>14} {'dev.':>7}"]
    for row in rows:
        deviation = "" if row.deviation is None else f"{100 * row.deviation:+.2f}%"
        lines.append(
            f"  {row.symbol:<40} {_shown(row.paper, row.unit):>12} {_shown(row.standard, row.unit):>14} "
            f"{_shown(row.printed_eq7, row.unit):>14} {deviation:>7}"
        )
    return "\n".join(lines)


def comparison_records(rows: list[ComparisonRow]) -> list[dict]:
    """Return the paper-vs-ours table as JSON-ready dicts (SI)."""
    return [
        {
            "quantity": row.key,
            "symbol": row.symbol,
            "unit": row.unit,
            "paper": row.paper,
            "ours_standard_modulus": row.standard,
            "ours_eq7_printed": row.printed_eq7,
            "relative_deviation": row.deviation,
        }
        for row in rows
    ]


def write_curve_csv(path: Path, curve: dict[str, np.ndarray]) -> None:
    """Write a load-unload curve dict as CSV, one row per point, column names with SI units."""
    units = {"approach": "m", "separation": "m", "force": "N", "contact_area": "m2", "max_pressure": "Pa"}
    keys = list(curve)
    header = [f"{key}_{units[key]}" if key in units else key for key in keys]
    with open(path, "w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        for row in zip(*(np.asarray(curve[key]) for key in keys), strict=True):
            writer.writerow([value if isinstance(value, str) else f"{float(value):.10g}" for value in row])


def curves_dataset(curves: dict[str, dict[str, np.ndarray]], attributes: dict):
    """Return an xarray Dataset holding each labelled curve on its own point dimension (SI)."""
    import xarray as xr

    variables = {}
    for label, curve in curves.items():
        for key, values in curve.items():
            values = np.asarray(values)
            variables[f"{label}_{key}"] = (
                f"{label}_point",
                values.astype(str) if values.dtype.kind == "U" else values,
            )
    return xr.Dataset(variables, attrs={k: v for k, v in attributes.items() if v is not None})


def read_measured_curve(path: Path) -> dict[str, np.ndarray]:
    """Read a measured load-interference curve: CSV with columns interference [m], load [N].

    A first line that is not numeric is taken as a header. The interference should follow the same
    zero convention as the models (paper 002: zero at 25 uN).

    Parameters
    ----------
    path : Path
        CSV file.

    Returns
    -------
    dict
        "approach" [m] and "force" [N] arrays.

    Raises
    ------
    InputError
        Missing file, fewer than two numeric columns, or fewer than two rows.
    """
    try:
        with open(path, newline="") as handle:
            rows = [row for row in csv.reader(handle) if row]
    except OSError as error:
        raise InputError(
            "--measured", f"cannot read {path}: {error.strerror}.", "give an existing CSV file."
        ) from None
    try:
        float(rows[0][0])
    except (ValueError, IndexError):
        rows = rows[1:]
    try:
        data = np.array([[float(row[0]), float(row[1])] for row in rows])
    except (ValueError, IndexError):
        data = np.empty((0, 2))
    if data.shape[0] < 2:
        raise InputError(
            "--measured",
            f"{path} has no two numeric columns with at least two rows.",
            "write 'interference_m,force_N' rows in SI units.",
        )
    return {"approach": data[:, 0], "force": data[:, 1]}
