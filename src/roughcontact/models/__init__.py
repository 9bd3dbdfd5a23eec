"""The seed papers' scenarios under their release-0.1 name: moved to :mod:`roughcontact.papers`.

``roughcontact.models.paper001`` and the other modules stand in for their new homes for one
release, with a DeprecationWarning.
"""
