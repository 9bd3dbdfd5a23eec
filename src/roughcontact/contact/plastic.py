"""Moved to :mod:`roughcontact.contact.load_unload` (kept one release, with a DeprecationWarning)."""

from .._deprecation import moved_module

moved_module(__name__, "roughcontact.contact.load_unload")
