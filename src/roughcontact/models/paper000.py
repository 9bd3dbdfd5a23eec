"""Moved to :mod:`roughcontact.papers.paper000` (kept one release, with a DeprecationWarning)."""

from .._deprecation import moved_module

moved_module(__name__, "roughcontact.papers.paper000")
