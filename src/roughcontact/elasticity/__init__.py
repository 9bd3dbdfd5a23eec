"""Elastic response of the bodies: Fourier kernels, the surface compliance operator, subsurface stress."""

from .halfspace import ElasticLayer, SurfaceCompliance

__all__ = ["ElasticLayer", "SurfaceCompliance"]
