"""Moved to :mod:`roughcontact.winkler_lj.viscoelastic` (kept one release, with a DeprecationWarning)."""

from .._deprecation import moved_module

moved_module(__name__, "roughcontact.winkler_lj.viscoelastic")
