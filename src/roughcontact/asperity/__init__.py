"""Statistical asperity models: Greenwood-Williamson/McCool summits and elastic-plastic asperity laws.

``greenwood_williamson`` holds the summit population (Gaussian or measured heights) and the GW
integrals; ``elastic_plastic`` the single-asperity laws (Hertz, Chang-Etsion-Bogy, Kogut-Etsion,
Jackson-Green, paper 002 eq. 10, Etsion-Kligerman-Kadin unloading); ``load_unload`` the statistical
Kadin-Kogut-Etsion load-unload of a rough surface against a flat; ``comparison`` judges a statistical
prediction against a deterministic model's realisations at the level of a claim (one island, or the
mean), ``convergence`` a mesh study of the island (paper 002 Fig. 6). Theory: :doc:`/asperity`.
"""

from .comparison import Comparison, against_realisations
from .convergence import GridValue, QuantityConvergence, mesh_convergence
from .elastic_plastic import (
    contact_pressure_factor,
    critical_interference,
    critical_load,
    jackson_green_load,
    kogut_etsion_area,
    kogut_etsion_load,
    paper002_eq10_load,
    plasticity_index,
    residual_interference_ratio,
    unloading_exponent,
    unloading_load,
)
from .greenwood_williamson import (
    SummitDistribution,
    gaussian_summits,
    greenwood_williamson,
    gw_integral,
    measured_summits,
)
from .load_unload import LOADING_LAWS, StatisticalLoadUnload, statistical_load_unload

__all__ = [
    "LOADING_LAWS",
    "Comparison",
    "GridValue",
    "QuantityConvergence",
    "StatisticalLoadUnload",
    "SummitDistribution",
    "against_realisations",
    "contact_pressure_factor",
    "critical_interference",
    "critical_load",
    "gaussian_summits",
    "greenwood_williamson",
    "gw_integral",
    "jackson_green_load",
    "kogut_etsion_area",
    "kogut_etsion_load",
    "measured_summits",
    "mesh_convergence",
    "paper002_eq10_load",
    "plasticity_index",
    "residual_interference_ratio",
    "statistical_load_unload",
    "unloading_exponent",
    "unloading_load",
]
