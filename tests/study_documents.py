"""Small study documents the tests of several folders share (a study file's text, composed).

``adhesive_ball`` and ``rough_scan`` start a document (its ``[study]`` and surface tables);
``ADHESION_CYCLE`` and ``NORMAL_CONTACT`` are analyses to append, each test adding its own keys.
"""


def adhesive_ball(name: str, surface_energy: str = "25 mJ/m^2") -> str:
    """Return the start of a study of a 1 um ball (32^2, 200 nm) of a 4 GPa film with ``surface_energy``."""
    return f"""[study]
name = "{name}"
[topographies.ball]
generate = "sphere"
shape = 32
size = "200 nm"
radius = "1 um"
[materials.film]
youngs_modulus = "4 GPa"
poissons_ratio = 0.3
surface_energy = "{surface_energy}"
"""


ADHESION_CYCLE = """[[analysis]]
name = "cycle"
model = "adhesion"
topography = "ball"
material = "film"
interaction_range = "1.9 nm"
max_approach = "1 nm"
"""
"""An adhesive cycle of :func:`adhesive_ball`'s ball (append ``steps``, a sweep, ...)."""


def rough_scan(name: str) -> str:
    """Return the start of a study of a self-affine scan (32^2, 2 um, H = 0.8, Rq = 5 nm, seed 1)."""
    return f"""[study]
name = "{name}"

[topographies.scan]
generate = "self_affine"
shape = 32
size = "2 um"
hurst = 0.8
rms_height = "5 nm"
seed = 1
"""


NORMAL_CONTACT = """
[[analysis]]
name = "contact"
model = "normal"
topography = "scan"
material = "polysilicon"
mean_pressure = "20 MPa"
"""
"""Normal contact of :func:`rough_scan`'s scan in polysilicon at 20 MPa (append a sweep, ...)."""


SCAN_AND_TIP = """[study]
name = "swept"
seed = 8
[topographies.scan]
generate = "self_affine"
shape = 24
size = "0.48 um"
hurst = 0.8
rms_height = "1.5 nm"
[topographies.tip]
generate = "sphere"
shape = 24
size = "0.48 um"
radius = "1 um"
"""
"""The start of a study of paper 000's kind: a self-affine scan (24^2, 20 nm pixels) and a 1 um tip."""

FRICTION_OVER_TWO_LOADS = """[[analysis]]
name = "friction"
model = "friction"
topography = "scan"
counter_topography = "tip"
material = "polysilicon"
counter_body = "SiO2"
normal_force = "1 uN"
surface_energy = "50 mJ/m^2"
[analysis.sweep]
normal_force = ["5 uN", "10 uN"]
"""
"""Friction of :data:`SCAN_AND_TIP` at 5 and 10 uN (append the sweep's other axes, ...)."""
