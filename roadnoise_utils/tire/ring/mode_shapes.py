"""Classification of mode shapes on the belt mesh: circumferential wave number and lateral order.

Used by the closed-form ring check (:mod:`roadnoise_utils.tire.ring.closed_form`), the loaded modes and the modal
reduction (:mod:`roadnoise_utils.response`) to label each mode ``n`` (harmonic around the
circumference) and ``m`` (sign changes across the strips).
"""

from __future__ import annotations

import numpy as np

from .mechanics import UX, UZ, FETModel


def wave_numbers(fet: FETModel, shapes: np.ndarray) -> np.ndarray:
    """Dominant circumferential wave number of each mode (columns of ``shapes``).

    The harmonic with the largest radial displacement, summed over the strips; for modes
    that barely move radially (torsion, n = 0) the tangential displacement decides.
    """
    mesh = fet.mesh
    j, k = np.meshgrid(np.arange(mesh.n_strips), np.arange(mesh.n_elements), indexing="ij")
    th = mesh.theta[None, :]
    ux = shapes[mesh.dof(j, k, UX)]  # (ns, ne, modes)
    uz = shapes[mesh.dof(j, k, UZ)]
    radial = ux * np.sin(th)[..., None] - uz * np.cos(th)[..., None]
    tangential = ux * np.cos(th)[..., None] + uz * np.sin(th)[..., None]
    power_r = (np.abs(np.fft.rfft(radial, axis=1)) ** 2).sum(axis=0)
    power_t = (np.abs(np.fft.rfft(tangential, axis=1)) ** 2).sum(axis=0)
    mostly_tangential = power_r.sum(axis=0) < 0.1 * power_t.sum(axis=0)
    return np.where(mostly_tangential, np.argmax(power_t, axis=0), np.argmax(power_r, axis=0))


def lateral_order(fet: FETModel, shapes: np.ndarray) -> np.ndarray:
    """Sign changes across the strips of each strip's projection on the dominant strip."""
    mesh = fet.mesh
    j, k = np.meshgrid(np.arange(mesh.n_strips), np.arange(mesh.n_elements), indexing="ij")
    th = mesh.theta[None, :, None]
    radial = shapes[mesh.dof(j, k, UX)] * np.sin(th) - shapes[mesh.dof(j, k, UZ)] * np.cos(th)
    norms = np.linalg.norm(radial, axis=1)  # (ns, modes)
    ref = radial[np.argmax(norms, axis=0), :, np.arange(shapes.shape[1])]  # (modes, ne)
    proj = np.einsum("jkr,rk->jr", radial, ref)
    significant = np.abs(proj) > 0.05 * np.abs(proj).max(axis=0)
    orders = []
    for r in range(shapes.shape[1]):
        s = np.sign(proj[significant[:, r], r])
        orders.append(int(np.sum(s[1:] != s[:-1])))
    return np.array(orders)
