"""Stages 6-9: the RM model itself — rational fits, state space (fixed and moving hub), fast simulation.

``fitting`` fits every local FRF with a rational function (paper Eq. 1, relaxed vector
fitting on the kernels of ``vf_kernels``, each FRF's poles relocated in ``relocation``; ``common_poles`` one
pole set for all tasselli;
``fitting_peer`` runs scikit-rf and pyvectorfit on the same data) -> ``realisation`` turns the fits
into the block-diagonal fixed-hub tire (Eq. 2-4) -> ``moving_hub`` adds :math:`G_H`
(Eq. 5-7) -> ``simulation`` drives either with tassello inputs in the time domain;
``aggregated`` gives the fixed-hub tire's force of a road flowing through the footprint without
forming the inputs (one kernel per track, by FFT).
"""

from . import (
    aggregated,
    common_poles,
    fitting,
    fitting_peer,
    moving_hub,
    order,
    realisation,
    relocation,
    simulation,
    vf_kernels,
)
from .aggregated import RoadHubForce, road_hub_force
from .fitting import FitSet, RationalFit, fit_tasselli, vector_fit
from .moving_hub import assemble_moving_hub, fit_hub, hub_statespace, rm_moving_hub
from .order import fit_at_order, lowest_order, order_scan
from .realisation import assemble_fixed_hub, frequency_response, realize
from .simulation import ModalSections, SimulationResult, modal_sections, response, simulate

__all__ = [
    "FitSet",
    "RoadHubForce",
    "aggregated",
    "common_poles",
    "ModalSections",
    "RationalFit",
    "SimulationResult",
    "assemble_fixed_hub",
    "assemble_moving_hub",
    "fit_at_order",
    "fit_hub",
    "fit_tasselli",
    "fitting",
    "fitting_peer",
    "frequency_response",
    "hub_statespace",
    "lowest_order",
    "modal_sections",
    "moving_hub",
    "order",
    "order_scan",
    "realisation",
    "relocation",
    "realize",
    "response",
    "rm_moving_hub",
    "road_hub_force",
    "simulate",
    "simulation",
    "vector_fit",
    "vf_kernels",
]
