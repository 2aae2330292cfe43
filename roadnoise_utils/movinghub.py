"""The moving-hub tire (paper stage 9, Eq. 5-7, Fig. 7).

Paper, *Simulation of Wheel-Road Interaction*: "Owing to the linearity of the model, the force
with moving hub :math:`F_M` can be expressed as the sum of the force :math:`F_F` due to road
unevenness with fixed hub and the force :math:`F_H` due to the motion of the hub without
excitation from the road" (Eq. 5, Fig. 7): :math:`F_M = F_F + F_H`, with
:math:`F_H = G_H\\,u_H` fitted like the tasselli (Eq. 6) and both stacked into one model with
inputs :math:`[u_F; u_H]` (Eq. 7).

The check is the FE model itself with the hub free: its vertical DOF carries a mass and sits on
a suspension spring and damper to ground, the road displaces the footprint, and the hub
motion is solved directly in the frequency domain together with every belt DOF (in the exact
mirror-symmetric subspace of :mod:`.symmetry`).
"""

from __future__ import annotations

import control
import numpy as np
import scipy.linalg as sla
import scipy.sparse.linalg as spla

from .fet import FETModel
from .fitting import FitSet
from .frf import HubForceSolver
from .loaded import loaded_tire
from .statespace import _blocks, assemble_fixed_hub, realize
from .static import StaticState


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
    a_h, b_h, c_h = _blocks(hub[0])
    a = sla.block_diag(fixed.A, a_h)
    b = sla.block_diag(fixed.B, b_h[:, None])
    c = np.concatenate([np.asarray(fixed.C)[0], c_h])[None, :]
    d = np.concatenate([np.asarray(fixed.D)[0], [hub[0].direct]])[None, :]
    return control.ss(a, b, c, d)


def fe_moving_hub(
    fet: FETModel,
    static: StaticState,
    freqs: np.ndarray,
    hub_mass: float,
    stiffness: float,
    damping: float,
) -> tuple[np.ndarray, np.ndarray]:
    """Hub displacement and hub force per unit displacement of the whole footprint, FE direct.

    The hub's vertical DOF is free: mass ``hub_mass`` (kg) plus the FE's own rim-side mass, on
    a spring ``stiffness`` (N/m) and damper ``damping`` (N s/m) to ground. Returns
    ``(U_H, F_M)`` per unit road displacement (m/m, N/m), complex arrays over ``freqs`` (Hz).
    """
    for name, value in (("hub_mass", hub_mass), ("stiffness", stiffness), ("damping", damping)):
        if not (np.isfinite(value) and value >= 0):
            raise ValueError(f"{name} = {value}: valid range is [0, inf)")
    lt = loaded_tire(fet, static)
    solver = HubForceSolver(lt)
    basis = solver.basis_matrix
    own_mass = fet.hub_vertical_mass
    footprint = np.asarray(lt.road_input.sum(axis=1)).ravel()
    u_hub = np.empty(len(freqs), complex)
    f_hub = np.empty(len(freqs), complex)
    for k, f in enumerate(np.asarray(freqs, float)):
        w = 2 * np.pi * f
        row = lt.hub_row(w)
        row_reduced = np.asarray(basis.T @ row)
        corner = lt.hub_diagonal(w) - w**2 * (own_mass + hub_mass) + stiffness + 1j * w * damping
        # [[D, c], [c^T, corner]] [u; U_H] = [b; 0], with c the hub column: Schur complement on the hub
        lu = spla.splu(solver.dynamic_stiffness(w), permc_spec="NATURAL")
        b = np.asarray(basis.T @ (fet.modulus_ratio("tread", w) * footprint)).astype(complex)
        x_road = lu.solve(b)
        x_hub = lu.solve(row_reduced.astype(complex))
        u_hub[k] = -(row_reduced @ x_road) / (corner - row_reduced @ x_hub)
        u_belt = basis @ (x_road - x_hub * u_hub[k])
        f_hub[k] = -(lt.hub_diagonal(w) * u_hub[k] + row @ u_belt)
    return u_hub, f_hub


def rm_moving_hub(
    fits: FitSet,
    hub: FitSet,
    freqs: np.ndarray,
    hub_mass: float,
    stiffness: float,
    damping: float,
    tire_hub_mass: float,
) -> tuple[np.ndarray, np.ndarray]:
    """The same as :func:`fe_moving_hub` from the fitted RM model (Eq. 5-7).

    ``hub_mass``, ``stiffness`` and ``damping`` mean what they mean there; ``tire_hub_mass``
    (kg) is the FE tire's rim-side mass (:attr:`.FETModel.hub_vertical_mass`), which
    :math:`G_H` leaves out and the FE model carries itself.
    """
    f = np.asarray(freqs, float)
    w = 2 * np.pi * f
    fixed = fits.responses(f).sum(axis=0)  # F_F per unit displacement of the whole footprint
    g_h = hub[0](f)
    mass = hub_mass + tire_hub_mass
    u_hub = fixed / (-(w**2) * mass + stiffness + 1j * w * damping - g_h)
    return u_hub, fixed + g_h * u_hub
