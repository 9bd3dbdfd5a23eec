"""Moved to :mod:`roughcontact.papers.paper002` (kept one release, with a DeprecationWarning)."""

from .._deprecation import moved_module

moved_module(__name__, "roughcontact.papers.paper002")
