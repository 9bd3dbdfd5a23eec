"""Paper 002's island compression: moved to :mod:`roughcontact.papers.paper002` (kept one release).

The model is :func:`roughcontact.contact.load_unload.load_unload`; paper 002's scenario of it is
:func:`roughcontact.papers.paper002.compress_island`.
"""

from .._deprecation import moved_module

moved_module(__name__, "roughcontact.papers.paper002")
