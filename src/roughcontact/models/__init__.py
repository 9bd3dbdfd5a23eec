"""Models of the papers' scenarios, composed from the engines below them.

``paper002`` (the printed numbers of seed paper 002 and the paper-vs-ours table) and
``thin_film_island`` (BEM elastic-plastic flat-punch compression of the raised SU-8 island). A
scenario lives here, not in ``contact/`` or ``asperity/``, because it combines a topography, both
the statistical and the deterministic contact models and the subsurface stress.
"""
