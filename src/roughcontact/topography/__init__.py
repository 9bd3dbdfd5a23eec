"""Surfaces: the :class:`Topography` container, instrument readers, generators, processing and statistics."""

from .surface import Topography

__all__ = ["Topography"]
