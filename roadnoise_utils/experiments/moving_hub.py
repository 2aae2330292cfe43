"""The moving-hub check: the RM moving-hub tire against the FE tire with its hub free (paper Eq. 5-7).

"Owing to the linearity of the model, the force with moving hub :math:`F_M` can be expressed as
the sum of the force :math:`F_F` due to road unevenness with fixed hub and the force
:math:`F_H` due to the motion of the hub" (Eq. 5). The check releases the FE tire's hub on a
suspension to ground (``data/conditions/moving_hub_check.toml``, read once by
:func:`suspension_conditions`) and compares the hub motion and force, per unit displacement
of the whole footprint, with the RM model's.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import guards
from ..analysis import relative_rms_error
from ..repro import stages
from ..rm.fitting import FitSet
from ..rm.moving_hub import released_hub, rm_moving_hub
from ..tire.model import ModelSpec, tire_model
from .conditions import load_conditions, resolve

#: The tire the check runs on by default: the quarter car's.
CHECK_TIRE = "195_65R15"


@dataclass(frozen=True)
class Suspension:
    """The hub's suspension to ground in the check: mass (kg, without the tire), stiffness (N/m), damping (N s/m)."""

    mass: float
    stiffness: float
    damping: float

    def __post_init__(self) -> None:
        guards.real("mass", self.mass, 0.0, 1e4, unit="kg")
        guards.real("stiffness", self.stiffness, 0.0, 1e9, unit="N/m")
        guards.real("damping", self.damping, 0.0, 1e7, unit="N s/m")


def suspension_conditions(
    mass: float | None = None, stiffness: float | None = None, damping: float | None = None
) -> Suspension:
    """The check's suspension (``data/conditions/moving_hub_check.toml``, read once), any value given overriding it."""
    hub = resolve(load_conditions("moving_hub_check"), "hub", mass=mass, stiffness=stiffness, damping=damping)
    return Suspension(hub["mass"], hub["stiffness"], hub["damping"])


@dataclass(frozen=True, eq=False)
class MovingHubCheck:
    """FE with a free hub vs the RM moving-hub model, per unit road displacement of the whole footprint.

    Attributes
    ----------
    tire : ModelSpec
        The tire.
    suspension : Suspension
        The hub's suspension.
    freqs : ndarray
        Frequencies (Hz).
    fe_hub, rm_hub : ndarray (complex)
        Hub displacement per road displacement (m/m), FE and RM.
    fe_force, rm_force : ndarray (complex)
        Hub force :math:`F_M` per road displacement (N/m), FE and RM.
    fits, hub : FitSet
        The tassello fits and the hub fit the RM model uses.
    """

    tire: ModelSpec
    suspension: Suspension
    freqs: np.ndarray
    fe_hub: np.ndarray
    fe_force: np.ndarray
    rm_hub: np.ndarray
    rm_force: np.ndarray
    fits: FitSet
    hub: FitSet

    def errors(self) -> dict[str, float]:
        """Relative RMS errors of the RM model against the FE model: hub acceleration and hub force."""
        omega2 = (2 * np.pi * self.freqs) ** 2
        return {
            "hub acceleration": relative_rms_error(omega2 * self.rm_hub, omega2 * self.fe_hub),
            "hub force F_M": relative_rms_error(self.rm_force, self.fe_force),
        }


def moving_hub_check(
    tire: str | ModelSpec = CHECK_TIRE,
    freqs: np.ndarray | None = None,
    suspension: Suspension | None = None,
) -> MovingHubCheck:
    """Solve the FE tire with its hub free and the RM moving-hub model (Eq. 5-7) on the same suspension.

    ``freqs`` (Hz) default to 1-250 Hz every 1 Hz; ``suspension`` to :func:`suspension_conditions`.
    """
    freqs = np.arange(1.0, 251.0) if freqs is None else np.asarray(freqs, float)
    if freqs.ndim != 1 or freqs.size == 0 or not np.all(np.isfinite(freqs)) or np.any(freqs < 0):
        raise ValueError("freqs must be a non-empty 1-D array of finite frequencies >= 0 Hz")
    hub_suspension = suspension_conditions() if suspension is None else suspension
    if not isinstance(hub_suspension, Suspension):
        raise TypeError(
            f"suspension must be a Suspension(mass, stiffness, damping), got {type(hub_suspension).__name__}"
        )
    model = tire_model(tire)
    model.require("hub_transfer")
    values = (hub_suspension.mass, hub_suspension.stiffness, hub_suspension.damping)
    fits, hub = stages.fit_tasselli(model), stages.fit_hub(model)
    own_mass = model.rim_side_mass()
    case = model.case("flat")
    if model.has("released_hub"):
        fe_hub, fe_force = model.released_hub(case, freqs, *values)
    else:  # the direct two-port: H_tot and G_H of the model's fixed-hub solve, closed on the hub
        direct = model.fixed_hub_frfs(case, freqs)
        fe_hub, fe_force = released_hub(freqs, direct.H_tot, direct.G_H, values[0] + own_mass, *values[1:])
    rm_hub, rm_force = rm_moving_hub(fits, hub, freqs, *values, tire_hub_mass=own_mass)
    return MovingHubCheck(model.spec, hub_suspension, freqs, fe_hub, fe_force, rm_hub, rm_force, fits, hub)
