"""The loaded tire's footprint FRFs by a direct solve at every frequency: the reduced solve's reference.

Every DOF, no basis (:func:`roadnoise_utils.tire.loaded.dynamics.footprint_frf` is the reduced solve the
stages use): what the reduced basis must reproduce, within 1e-3 of the largest transfer (tested).
"""

from __future__ import annotations

import numpy as np

from ..cavity import CavityCoupling
from ..symmetric_factor import SymmetricFactor
from . import dynamics


def footprint_frf_direct(
    linearised: dynamics.LinearisedTire, freqs: np.ndarray, cavity: CavityCoupling | None = None
) -> dynamics.LoadedFootprintFRF:
    r"""The footprint's hub-force transfer by a direct solve of :math:`D(\omega)` at every frequency.

    The reference of the reduced solve: every DOF, no basis. Per frequency, the free DOF follow
    unit motions of each contact node and of the rim,
    :math:`u_f = -D_{ff}^{-1} D_{f,b}`, and the force on the hub is minus the rim's vertical
    reactions, :math:`-\sum_{hub}(D_{h,f} u_f + D_{h,b})`. :math:`D_{ff}`, complex symmetric, is
    factorised by :class:`~roadnoise_utils.tire.symmetric_factor.SymmetricFactor` (each solve's
    backward error below 1e-12, else pivoted). With the air ``cavity`` ``D`` carries
    :math:`-V C V^T` (:class:`roadnoise_utils.tire.cavity.CavityCoupling`), solved by Woodbury's identity on the
    same factor: the modes' pressures :math:`q = C\,V^T u` and their load :math:`V q`.
    """
    freqs = dynamics.check_freqs(freqs)
    lin = linearised
    parts, boundaries = lin.parts(), lin.boundaries()
    free_parts = [part[lin.free][:, lin.free] for part in parts]
    coupling = [(part[lin.free] @ boundary).toarray() for part, boundary in zip(parts, boundaries)]
    hub_rows = [(part[lin.hub] @ boundary).toarray().sum(axis=0) for part, boundary in zip(parts, boundaries)]
    hub_free = [np.asarray(part[lin.hub][:, lin.free].sum(axis=0)).ravel() for part in parts]
    air = None if cavity is None else _air_terms(lin, cavity)
    out = []
    for frequency in freqs:
        w = lin.weights(2 * np.pi * frequency)
        rhs = -sum(wj * c for wj, c in zip(w, coupling))
        dynamic = sum(wj * m for wj, m in zip(w, free_parts)).tocsc()
        factor = SymmetricFactor(dynamic, require_definite=False)
        rim = sum(wj * r for wj, r in zip(w, hub_rows))
        if air is None:
            u_free = factor.solve(rhs)
        else:
            free_volume, boundary_volume, hub_volume = air
            gains = np.diag(cavity.gains(2 * np.pi * frequency))
            rhs = rhs + free_volume @ (gains @ boundary_volume.T)
            solved = factor.solve(np.hstack([rhs, free_volume]))
            u_rhs, u_volume = solved[:, : rhs.shape[1]], solved[:, rhs.shape[1] :]
            small = np.eye(gains.shape[0]) - gains @ (free_volume.T @ u_volume)
            u_free = u_rhs + u_volume @ np.linalg.solve(small, gains @ (free_volume.T @ u_rhs))
            pressures = gains @ (free_volume.T @ u_free + boundary_volume.T)
            rim = rim - hub_volume @ pressures
        rim = rim + sum(wj * h for wj, h in zip(w, hub_free)) @ u_free
        out.append(-rim)
    hub = np.array(out)
    return dynamics.LoadedFootprintFRF(freqs=freqs, hub=hub[:, :-1], G_H=hub[:, -1])


def _air_terms(lin: dynamics.LinearisedTire, cavity: CavityCoupling) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The cavity modes' volume changes of the free DOF (n_free, M), of the boundary's unit motions
    (n_b, M) and of the rim's vertical DOF together (M,)."""
    dynamics.check_wall(lin, cavity)
    boundary = dynamics.boundary_columns(lin)
    return cavity.volume[lin.free], np.asarray(boundary.T @ cavity.volume), cavity.volume[lin.hub].sum(axis=0)
