"""
Read an AFM scan with its units
===============================

Read the AFM scan shipped with roughcontact (a WSxM file, 256 x 256 points over 600 nm), level
it by a least-squares plane, print its roughness parameters with their units (ISO 25178-2 areal
and ISO 4287 profile parameters, and the spectral moments m0, m2, m4 and McCool's summit
parameters of paper 002, eqs. 1-5) and draw its height map and power spectral density.
"""

import importlib.resources

import numpy as np

import roughcontact as rc
from roughcontact.plotting import plot_overview
from roughcontact.topography import level, summary
from roughcontact.topography.statistics import SUMMARY
from roughcontact.units import format_si

# %%
# Read the file
# -------------
# :func:`~roughcontact.topography.read_topography` converts sizes and heights to metres from the
# units the file declares, and records those units in ``info``. A file without them would be
# refused until ``size=`` and ``height_unit=`` are given. It levels the scan as the commands do
# (``detrend="plane"``); ``detrend="none"`` returns it as stored, to see what levelling removes.

path = importlib.resources.files("roughcontact") / "data" / "top-1.top"
raw = rc.read_topography(path, detrend="none")
print(raw)
print(f"file format {raw.info['file_format']}, channel {raw.info['channel']!r}")
print(f"units in the file: size in {raw.info['size_unit']}, heights in {raw.info['height_unit']}")
print(f"size {format_si(raw.size[0], 'm')} x {format_si(raw.size[1], 'm')}, ", end="")
print(f"pixel {format_si(raw.spacing[0], 'm')}")

# %%
# Level it
# --------
# Its tilt is an artefact of mounting, and left in it would decide where a flat touches, so it is
# removed first: ``"plane"`` is what ``read_topography``, the commands and study files apply to
# every measured file unless told otherwise (``rc.read_topography(path)`` is this ``scan``).

scan = level(raw, "plane")
plane = raw.heights - scan.heights  # the fitted plane (and mean) that levelling removed [m]
print(f"levelling removed a plane spanning {format_si(float(np.ptp(plane)), 'm')} across the scan")

# %%
# Roughness parameters
# --------------------
# :func:`~roughcontact.topography.summary` returns SI numbers; the unit and meaning of each are in
# ``roughcontact.topography.statistics.SUMMARY`` (an empty unit is a dimensionless number).

for name, value in summary(scan).items():
    unit, meaning = SUMMARY[name]
    print(f"{name:<18} {format_si(value, unit):>14}   {meaning}")

# %%
# Height map and power spectral density
# -------------------------------------
# The colour scale spans the 0.5-99.5 percentiles of the heights (said on the colour bar), so
# that the few tallest particles do not turn the rest of the map into one colour. The PSD is
# radially averaged, with a Hann window since the scan is not periodic.

fig = plot_overview(scan)
