"""A cleat's passage through the fitted chain and straight through the FE tire, both in the fits' band.

:func:`simulated_in_band` runs the RM chain (:func:`roadnoise_utils.rm.simulation.simulate`) over
the passage continued on a flat road, from rest, and band-limits its hub force to the fits' band:
the force the cleat test reads its peaks from (:mod:`roadnoise_utils.experiments.cleat`).
:func:`fe_passage` gives the same passage with no fit, the second method of :class:`FEComparison`:
the model's own direct response (capability ``direct_response``) or the frequency-domain sum over
its tassello FRFs on their grid.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import control
import numpy as np

from ..analysis import relative_rms_error
from ..repro import stages
from ..response.band_limit import band_limited, frequency_domain_response, on_frf_grid, record_length
from ..rm.simulation import ModalSections, SimulationResult, simulate
from ..road.cleat import cleat_input
from ..road.input import BAND, RoadInput
from ..tire.model import Footprint, ModelSpec, tire_model

if TYPE_CHECKING:
    from .cleat import CleatConditions


#: Record over which a run's hub force is band-limited (s): the passage simulated on over a flat road
#: to it, so that the filter sees the decay end and its circular wrap cannot reach the crossing.
RECORD = 1.0


def simulated_in_band(
    system: control.StateSpace | ModalSections, road: RoadInput, band: float = BAND, duration: float = RECORD
) -> tuple[SimulationResult, SimulationResult]:
    """The passage ``road`` through the fixed-hub tire ``system``: ``(as stepped, in the fit's band)``.

    The chain is fitted to the tire's FRFs over 0-``band`` Hz (Eq. 1-2); above the band its poles
    and residues follow nothing of the tire, and a sharp input such as the cleat at 30 km/h excites
    them. The road is continued flat to ``duration`` s (default :data:`RECORD`) and simulated from
    rest, the force band-limited (zero phase, :func:`~roadnoise_utils.response.band_limit.band_limited`)
    and both cut back to the road's length: the FE comparison's reading (:func:`rm_cleat_response`),
    which a record ending in mid-decay does not disturb.
    """
    n = road.u.shape[1]
    full = simulate(system, road.padded(record_length(road, duration)))
    stepped = SimulationResult(t=road.t, distance=road.distance, force=full.force[:n], road=road)
    return stepped, replace(stepped, force=band_limited(full.force, road.dt, band)[:n])


def rm_cleat_response(system, road: RoadInput, band: float = BAND, duration: float = 1.0) -> np.ndarray:
    """Hub force (N) of ``road`` from the RM chain, on the same footing as the FE reference: the
    passage continued over a flat road to ``duration`` s and band-limited (:func:`simulated_in_band`)."""
    return simulated_in_band(system, road, band, duration)[1].force


@dataclass(frozen=True, eq=False)
class FEComparison:
    """The RM chain against the FE model on the same record, both band-limited to 250 Hz the same way.

    Attributes
    ----------
    road : RoadInput
        The cleat's tassello inputs.
    fe_force, rm_force : ndarray
        Hub force (N) from the FE model (frequency domain) and from the RM chain (time domain).
    """

    road: RoadInput
    fe_force: np.ndarray
    rm_force: np.ndarray

    @property
    def peak_difference(self) -> float:
        """RM peak over FE peak, minus one (-)."""
        return float(self.rm_force.max() / self.fe_force.max() - 1.0)

    @property
    def rms_difference(self) -> float:
        """Relative RMS error of the RM force against the FE force (-)."""
        return relative_rms_error(self.rm_force, self.fe_force)


def fe_passage(spec: ModelSpec, test: CleatConditions, static: Footprint) -> tuple[RoadInput, np.ndarray]:
    r"""The dynamic passage straight from the FE tire, no fit: ``(road, hub force)`` (N), band-limited.

    The model's own direct response where it has one (capability ``direct_response``); otherwise
    the frequency-domain sum :math:`\sum_i H_i(\omega)\,U_i(\omega)` over its tassello FRFs on the
    drum, read on their 1 Hz grid (the record is ``test.fe_duration``, whole seconds), band-limited
    the same way (:func:`~roadnoise_utils.response.band_limit.frequency_domain_response`).
    """
    cleat = {"height": test.height, "base": test.base, "shape": test.shape}
    if tire_model(spec).has("direct_response"):
        return stages.fe_cleat_response(
            spec, test.dynamic_speed, **cleat, drum_radius=test.drum_radius,
            distance=test.fe_distance, duration=test.fe_duration,
        )  # fmt: skip
    road = cleat_input(static, test.dynamic_speed, **cleat, distance=test.fe_distance)
    frfs = stages.frf_visco(spec, road="drum", drum_radius=test.drum_radius)
    return road, frequency_domain_response(on_frf_grid(frfs), road.u, road.dt, BAND, test.fe_duration)
