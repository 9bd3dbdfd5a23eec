"""Moved to :mod:`roughcontact.papers.thin_film_island` (kept one release, with a DeprecationWarning)."""

from .._deprecation import moved_module

moved_module(__name__, "roughcontact.papers.thin_film_island")
