"""The methods paragraph of a study's report: what a paper's methods section needs, in sentences.

:func:`methods_paragraph` writes, from a finished study's records and provenance: the software and
the version of every dependency; each measured surface's file, channel, grid, size, levelling and
filled points; every material's properties as used; per analysis its model, its cases and the
solver settings; and every combined quantity with how it was combined (the contact modulus E* of
two bodies, the work of adhesion of two surface energies), so that a reader can redo the numbers.
"""

from __future__ import annotations

import math
from typing import Any

from ..cases import axis_words
from ..units import format_si


def methods_paragraph(analyses: list, provenance: dict[str, Any], surfaces: list[str]) -> list[str]:
    """Return the methods section as sentences (plain text, one paragraph each).

    Parameters
    ----------
    analyses : list of StoredAnalysis
        The study's analyses (:func:`roughcontact.study.outputs.read_study`).
    provenance : dict
        ``OUT/provenance.json``.
    surfaces : list of str
        One sentence per measured surface (how it was read and levelled).
    """
    paragraphs = [_software(provenance)]
    if surfaces:
        paragraphs.append("Measured surfaces: " + " ".join(_sentence(line) for line in surfaces))
    materials = provenance.get("materials") or []
    if materials:
        paragraphs.append("Materials as used: " + "; ".join(_material(m) for m in materials) + ".")
    for analysis in analyses:
        if analysis.finished:
            paragraphs.append(_analysis(analysis, {m["material"]: m for m in materials}))
    return paragraphs


def _sentence(text: str) -> str:
    return text if text.endswith(".") else text + "."


def _software(provenance: dict[str, Any]) -> str:
    packages = provenance.get("packages") or {}
    listed = ", ".join(f"{name} {version}" for name, version in packages.items())
    python = provenance.get("python")
    return (
        f"Computed with roughcontact {provenance.get('roughcontact', '?')}"
        + (f" on Python {python}" if python else "")
        + (f" ({listed})" if listed else "")
        + "."
    )


def _material(row: dict[str, Any]) -> str:
    parts = [f"E = {format_si(row['youngs_modulus [Pa]'], 'Pa', digits=3)}", f"ν = {row['poissons_ratio']:g}"]
    for key, symbol, unit in (
        ("hardness [Pa]", "H", "Pa"),
        ("yield_strength [Pa]", "σ_y", "Pa"),
        ("surface_energy [J/m^2]", "γ", "J/m²"),
    ):
        if row.get(key) is not None:
            parts.append(f"{symbol} = {format_si(row[key], unit, digits=3)}")
    entry = row.get("library entry")
    source = f", library entry {entry!r}" if entry and entry != row["material"] else ""
    return f"{row['material']} ({', '.join(parts)}{source})"


def _analysis(analysis, materials: dict[str, dict]) -> str:
    records = analysis.finished
    count = len(records)
    text = f"Analysis {analysis.name!r}: {analysis.summary}; {count} case{'s' if count != 1 else ''}"
    varied = varied_axes(analysis)
    if varied:
        text += " over " + ", ".join(varied)
    if analysis.realisations > 1:
        text += ": " + _realisations(analysis)
    text += "."
    first = records[0]
    settings = [
        f"{axis_words(key)} {first.parameters[key]:g}"
        for key in ("tolerance",)
        if isinstance(first.parameters.get(key), int | float)
    ]
    boundary = first.scalars.get("boundary") or first.parameters.get("boundary")
    if boundary:
        settings.append(f"{boundary} boundary")
    if settings:
        text += " Solver: " + ", ".join(settings) + "."
    readings = _readings(first)
    if readings:
        text += " Model readings: " + ", ".join(readings) + "."
    combined = combined_quantities(analysis, materials)
    return " ".join([text, *combined])


def _realisations(analysis) -> str:
    """Say how an analysis' finished cases make up its settings and realisations (one case each).

    A case is one realisation of one setting (a load, a sample, ...): 30 cases of 6 settings on 5
    realisations read ``6 settings, each on 5 realisations (one case per realisation)``, never "30
    cases each on 5 realisations". Settings of an unfinished study may have fewer; the words say so.
    """
    from ..cases import realisations_of

    sizes = [len(group) for group in realisations_of(analysis.finished).values()]
    if not sizes:
        return f"none of its {analysis.realisations} realisations finished"
    low, high = min(sizes), max(sizes)
    on = f"{high}" if low == high else f"{low} to {high}"
    planned = analysis.realisations
    planned = "" if low == high == planned else f" of the {planned} planned"
    if len(sizes) == 1:
        return f"one setting on {on}{planned} realisations (one case per realisation)"
    return f"{len(sizes)} settings, each on {on}{planned} realisations (one case per realisation)"


def combined_quantities(analysis, materials: dict[str, dict]) -> list[str]:
    """Return how the analysis' combined quantities were found: E* of two bodies, Δγ of two surface energies.

    ``materials`` maps the study's material names to their rows as used
    (:func:`roughcontact.study.run.materials_used`). Empty where the analysis combines nothing.
    """
    records = analysis.finished
    if not records:
        return []
    return [
        text
        for text in (_contact_modulus(records[0], materials), _work_of_adhesion(records[0], materials))
        if text
    ]


READING_KEYS = ("law", "reading", "readings", "combining_rule", "normal_loading", "plasticity", "method")
"""Parameters that choose between readings of a model (a paper's printed formula or the sound one,
a loading law, ...): the methods paragraph states each one a case has."""


def _readings(record) -> list[str]:
    """Return ``key value`` of each model-reading choice of a record (its parameters, then its scalars)."""
    found = []
    for key in READING_KEYS:
        value = record.parameters.get(key)
        if value is None or value == {}:
            value = record.scalars.get(key)
        if isinstance(value, dict):
            value = ", ".join(f"{k} {v}" for k, v in value.items())
        if value not in (None, ""):
            found.append(f"{axis_words(key)} {value}")
    return found


def _contact_modulus(record, materials: dict[str, dict]) -> str:
    """How E* of the record was combined from its materials (empty when the record has none)."""
    value = record.scalars.get("contact_modulus")
    body = materials.get(record.parameters.get("material") or "")
    if value is None or body is None:
        return ""
    counter = materials.get(record.parameters.get("counter_body") or "")
    if counter is None:
        how = f"E/(1 − ν²) of {body['material']} against a rigid counter-body"
    else:
        how = f"1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ of {body['material']} and {counter['material']}"
    return f"Contact modulus E* = {format_si(float(value), 'Pa', digits=4)} from {how}."


RULES = {
    "2 √(γ₁ γ₂) (Girifalco and Good 1957)": 2.0,
    "√(γ₁ γ₂) (paper 000 as printed)": 1.0,
}
"""The combining rules of two surface energies, by the factor on sqrt(g1 g2)."""


def _work_of_adhesion(record, materials: dict[str, dict]) -> str:
    """How the work of adhesion of a case was found: given, or combined from two surface energies.

    The rule is the one that reproduces the case's own work of adhesion from the two energies (a
    reading can choose it: ``combining_rule``, or a friction case's ``readings``); where none does,
    the value is stated without a formula.
    """
    value = record.scalars.get("work_of_adhesion")
    if value is None:
        return ""
    value = float(value)
    if record.parameters.get("work_of_adhesion") is not None:
        return f"Work of adhesion Δγ = {format_si(value, 'J/m²', digits=3)}, as given."
    energies = []
    for key, role in (("surface_energy", "material"), ("counter_surface_energy", "counter_body")):
        given = record.parameters.get(key)
        body = materials.get(record.parameters.get(role) or "")
        if given is not None:
            energies.append((float(given), "given"))
        elif body is not None and body.get("surface_energy [J/m^2]") is not None:
            energies.append((float(body["surface_energy [J/m^2]"]), f"{body['material']}'s surface energy"))
    stated = f"Work of adhesion Δγ = {format_si(value, 'J/m²', digits=3)}"
    if len(energies) != 2:
        return stated + "."
    root = math.sqrt(energies[0][0] * energies[1][0])
    rule = next(
        (name for name, factor in RULES.items() if math.isclose(factor * root, value, rel_tol=1e-6)), None
    )
    if rule is None:
        return stated + "."
    parts = ", ".join(f"{format_si(g, 'J/m²', digits=3)} ({whence})" for g, whence in energies)
    shown = format_si(value, "J/m²", digits=3)
    return f"Work of adhesion Δγ = {rule} = {shown} of the surface energies {parts}."


def varied_axes(analysis) -> list[str]:
    """Return the sweep axes whose value differs between the analysis' finished cases, in words.

    A key swept over one value (a command's one case, a zip of single values) is no sweep to a reader.
    """
    values: dict[str, set[str]] = {axis: set() for axis in analysis.sweep_axes}
    for record in analysis.finished:
        for axis, value in (record.data.get("axes") or {}).items():
            values.setdefault(axis, set()).add(str(value))
    names = [axis_words(axis) for axis, seen in values.items() if len(seen) > 1]
    return list(dict.fromkeys(names))  # a zip of a sample with its surface's key reads as one axis
