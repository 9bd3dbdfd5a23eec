"""Moved to :mod:`roughcontact.contact.lennard_jones` (kept one release, with a DeprecationWarning)."""

from .._deprecation import moved_module

moved_module(__name__, "roughcontact.contact.lennard_jones")
