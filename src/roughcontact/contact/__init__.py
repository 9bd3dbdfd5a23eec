"""Contact solvers: normal contact (elastic, elastic-plastic, layered), tangential programmes, load paths.

``normal`` (:func:`solve_normal`: FFT boundary elements, load or approach control, hardness, films),
``tangential`` (:func:`solve_tangential`: partial slip under a displacement or force programme),
``frictional`` (:func:`solve_frictional`: combined normal and tangential programmes with friction
from the unloaded state),
``adhesive`` (:func:`solve_adhesive`: adhesive contact through an approach programme, with the
interaction laws of ``interaction``: :class:`MaugisDugdale`, :class:`Exponential`,
:class:`LennardJones`),
``load_unload`` (:func:`load_unload`: elastic-plastic load-unload, the pressure capped at the
hardness or J2 plasticity in the volume), ``presliding``
(:func:`presliding`: a rough ball under a tangential programme, its last loop and Mindlin's smooth
ball, paper 001's model), ``sweep``
(:func:`load_path`: warm-started sequences of normal solves), ``paths`` (tangential programmes:
paper 001's stroke path, symmetric cycles, a CSV) and their results, each with ``scalars()``,
``UNITS`` and ``to_xarray()`` (:mod:`roughcontact.results`).

The names here load on first use (:mod:`roughcontact._lazy`): importing one solver's module does
not import the others.
"""

from .._lazy import attach_stub

__getattr__, __dir__, __all__ = attach_stub(__name__)  # the names: __init__.pyi
