"""The moving-hub tire (paper stage 9, Eq. 5-7, Fig. 7).

Paper, *Simulation of Wheel-Road Interaction*: "Owing to the linearity of the model, the force
with moving hub :math:`F_M` can be expressed as the sum of the force :math:`F_F` due to road
unevenness with fixed hub and the force :math:`F_H` due to the motion of the hub without
excitation from the road" (Eq. 5, Fig. 7): :math:`F_M = F_F + F_H`, with
:math:`F_H = G_H\\,u_H` fitted like the tasselli (Eq. 6) and both stacked into one model with
inputs :math:`[u_F; u_H]` (Eq. 7).

Its check, the FE model itself with the hub free, is
:func:`roadnoise_utils.tire.ring.fe_reference.fe_moving_hub`.
"""

from __future__ import annotations

import control
import numpy as np
import scipy.linalg as sla

from .fitting import FitSet
from .order import fit_at_order
from .realisation import assemble_fixed_hub, real_blocks, realize


def hub_statespace(hub: FitSet) -> control.StateSpace:
    """:math:`G_H` as a state space (Eq. 6): input the hub displacement (m), output :math:`F_H` (N)."""
    if len(hub) != 1:
        raise ValueError(f"the hub fit must hold one FRF, got {len(hub)}")
    return realize(hub[0])


def assemble_moving_hub(fits: FitSet, hub: FitSet) -> control.StateSpace:
    """The moving-hub tire of Eq. 7: inputs ``[u_1 .. u_n, u_H]`` (m), output :math:`F_M` (N).

    States ``x_M = [x_F; x_H]``; ``A_M = diag(A_F, A_H)``, ``B_M = diag(B_F, B_H)``,
    ``C_M = [C_F, C_H]``, ``D_M = [D_F, D_H]``.
    """
    fixed = assemble_fixed_hub(fits)
    a_h, b_h, c_h = real_blocks(hub[0])
    a = sla.block_diag(fixed.A, a_h)
    b = sla.block_diag(fixed.B, b_h[:, None])
    c = np.concatenate([np.asarray(fixed.C)[0], c_h])[None, :]
    d = np.concatenate([np.asarray(fixed.D)[0], [hub[0].direct]])[None, :]
    return control.ss(a, b, c, d)


def rm_moving_hub(
    fits: FitSet,
    hub: FitSet,
    freqs: np.ndarray,
    hub_mass: float,
    stiffness: float,
    damping: float,
    tire_hub_mass: float,
) -> tuple[np.ndarray, np.ndarray]:
    """The same as :func:`roadnoise_utils.tire.ring.fe_reference.fe_moving_hub` from the fitted RM model (Eq. 5-7).

    ``hub_mass``, ``stiffness`` and ``damping`` mean what they mean there; ``tire_hub_mass``
    (kg) is the FE tire's rim-side mass (:attr:`.FETModel.hub_vertical_mass`), which
    :math:`G_H` leaves out and the FE model carries itself.
    """
    f = np.asarray(freqs, float)
    fixed = fits.responses(f).sum(axis=0)  # F_F per unit displacement of the whole footprint
    return released_hub(f, fixed, hub[0](f), hub_mass + tire_hub_mass, stiffness, damping)


def released_hub(
    freqs: np.ndarray, H_tot: np.ndarray, G_H: np.ndarray, mass: float, stiffness: float, damping: float
) -> tuple[np.ndarray, np.ndarray]:
    r"""Hub motion and force per unit footprint displacement with the hub on a suspension to ground (Eq. 5-7).

    The tire is a linear two-port: the hub force is :math:`F_M = H_{tot}\,u + G_H\,U_H` (Eq. 5)
    and the hub obeys :math:`(-\omega^2 m + k + i\omega c)\,U_H = F_M`, so
    :math:`U_H = H_{tot} / (-\omega^2 m + k + i\omega c - G_H)`. ``freqs`` in Hz, ``H_tot`` and
    ``G_H`` in N/m (fitted or direct), ``mass`` (kg: hub plus the tire's rim-side mass),
    ``stiffness`` (N/m), ``damping`` (N s/m). Returns ``(U_H, F_M)`` (m/m, N/m).
    """
    w = 2 * np.pi * np.asarray(freqs, float)
    u_hub = H_tot / (-(w**2) * mass + stiffness + 1j * w * damping - G_H)
    return u_hub, H_tot + G_H * u_hub


def fit_hub(
    freqs: np.ndarray, G_H: np.ndarray, n_poles: int | None = None, f_max: float = 250.0, tolerance: float = 0.01
) -> FitSet:
    """Rational fit of the hub FRF :math:`G_H` (paper Eq. 6), like a tassello's (Eq. 1).

    ``n_poles=None`` takes the lowest order whose relative RMS error over 0-``f_max`` Hz is
    below ``tolerance`` (:func:`.order.lowest_order`); the paper uses 8.
    """
    return fit_at_order(freqs, G_H, n_poles, f_max, tolerance)
