"""The inputs of one case as a worker sees them: topographies built from their specifications, materials.

:class:`CaseInputs` is what a kind's ``run`` receives besides its parameters. It is picklable, so
it travels to Dask workers: file topographies go as the arrays read during validation (a worker
need not see the user's files), generated ones as their specifications and are built there.
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from dataclasses import dataclass

from ..materials import Material
from ..topography import Topography
from .schema import (
    Combined,
    FileTopography,
    Paper000Scan,
    Paper000Tip,
    Paper001Ball,
    Paper002Island,
    SelfAffine,
    Strict,
)

_GENERATOR_ONLY = {"generate", "ra"}

_CACHE_BYTES = 256 * 2**20
"""Most bytes of generated heights kept for later cases in one process (e.g. 500 surfaces of 256^2)."""
_cache: OrderedDict[str, Topography] = OrderedDict()
_cache_lock = threading.Lock()


def build_topography(spec: Strict, resolve) -> Topography:
    """Build a topography from its specification; ``resolve(name)`` builds the parts of a composite."""
    from ..topography import generate
    from ..topography.process import combine

    if isinstance(spec, Combined):
        first, second = (resolve(name) for name in spec.combine)
        return combine(first, second, resample=spec.resample)
    if isinstance(spec, FileTopography):
        raise TypeError("file topographies are read during validation and passed in")
    if isinstance(spec, Paper002Island):
        from ..papers.paper002 import paper002_island

        return paper002_island(spec.shape, seed=spec.seed, margin=spec.margin, roughness=spec.roughness)
    if isinstance(spec, Paper000Scan | Paper000Tip):
        from ..papers import paper000

        if isinstance(spec, Paper000Tip):
            return paper000.paper000_tip(shape=spec.shape, seed=spec.seed)
        return paper000.paper000_scan(spec.roughness, shape=spec.shape, seed=spec.seed)
    if isinstance(spec, Paper001Ball):
        from ..papers.paper001 import roughness

        return roughness(spec.ball, seed=spec.seed, pixels=spec.shape, rms=spec.rms)
    options = {k: v for k, v in spec.model_dump().items() if k not in _GENERATOR_ONLY}
    shape, size = options.pop("shape"), options.pop("size")
    surface = getattr(generate, spec.generate)(shape, size, **options)
    if isinstance(spec, SelfAffine) and spec.ra is not None:
        from ..topography.process import scale_to_ra

        surface = scale_to_ra(surface, spec.ra)
    return surface


@dataclass
class CaseInputs:
    """Topographies and materials of one case, resolved by name.

    Attributes
    ----------
    specs : dict
        Name -> topography specification (with the case's overrides and seeds).
    files : dict
        Name -> Topography already read, for the file topographies.
    materials : dict
        Name -> Material.
    device : str
        Where the solvers that have a GPU path run (``[study] device``: ``"cpu"`` or ``"gpu"``);
        handed to them as an argument (the normal contact engine), never through the environment.
    """

    specs: dict[str, Strict]
    files: dict[str, Topography]
    materials: dict[str, Material]
    device: str = "cpu"

    def origin(self, name: str) -> str:
        """Say where topography ``name`` comes from: ``measured`` (a file, or with one), else ``synthetic``.

        Every label of a result on it carries the word (a generated stand-in is never "the island").
        """
        spec = self.specs[name]
        if isinstance(spec, FileTopography):
            return "measured"
        if isinstance(spec, Combined) and any(self.origin(part) == "measured" for part in spec.combine):
            return "measured"
        return "synthetic"

    def identity(self, name: str) -> str:
        """Return a text that is equal for two cases exactly when they build the same topography ``name``."""
        spec = self.specs[name]
        parts = [self.identity(part) for part in spec.combine] if isinstance(spec, Combined) else []
        return spec.model_dump_json() + "".join(parts)

    def topography(self, name: str) -> Topography:
        """Return the topography called ``name``.

        Generated topographies are kept for the next cases in this process, by specification and
        seed, the least recently used dropped beyond :data:`_CACHE_BYTES`: a load sweep builds
        each surface once. Topographies are immutable, so sharing them between cases is safe.
        """
        if name in self.files:
            return self.files[name]
        key = self.identity(name)
        with _cache_lock:
            if key in _cache:
                _cache.move_to_end(key)
                return _cache[key]
        surface = build_topography(self.specs[name], self.topography)
        with _cache_lock:
            _cache[key] = surface
            while sum(t.heights.nbytes for t in _cache.values()) > _CACHE_BYTES and len(_cache) > 1:
                _cache.popitem(last=False)
        return surface

    def material(self, name: str | None) -> Material | None:
        """Return the material called ``name`` (None for None: a rigid body)."""
        return None if name is None else self.materials[name]
