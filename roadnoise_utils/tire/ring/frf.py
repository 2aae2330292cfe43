"""Direct frequency responses of the viscoelastic FET (the paper's FETvisco, Fig. 4-5).

For every frequency the full dynamic stiffness :math:`D(\\omega) = K(\\omega) - \\omega^2 M`,
with each rubber compound at its complex modulus :math:`g_c(\\omega)`, is factorised once.
Because we only want one output (the vertical hub force) for many inputs (every contact
point), one *adjoint* solve gives them all (reciprocity):

.. math:: y = D^{-T} K_{hf}^T, \\qquad H_n(\\omega) = -g_{tread}(\\omega)\\, b_n^T y,

with :math:`b_n` the tread-spring load of a unit road displacement under contact point ``n``.
A tassello moves its contact points together, so :math:`H_i = \\sum_{n\\in i} H_n`
(paper Eq. i). The whole-footprint FRF :math:`H_{tot}` is computed separately by a forward
solve with the same factorisation, so the superposition :math:`\\sum_i H_i = H_{tot}` is a
genuine check. The hub FRF :math:`G_H = -K_{hh} + y^T K_{fh}` (hub moving, footprint held)
comes from the same adjoint field. The symmetric reduction of :mod:`roadnoise_utils.tire.ring.symmetry` makes each
frequency cost a quarter-size sparse LU.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from tqdm.auto import tqdm

from ... import guards
from ..banded import banded_sum
from ..cavity import CavityCoupling
from ..model import FRFResult
from .loaded import LoadedTire, loaded_tire
from .mechanics import FETModel
from .static import StaticState
from .symmetry import symmetric_basis

#: Highest frequency the FE tire is meant for (Hz); the RM model needs up to 400 Hz, modes to ~800 Hz.
MAX_FREQUENCY = 2000.0


class HubForceSolver:
    """Factorise :math:`D(\\omega)` and solve for the hub force, with the symmetric reduction when exact."""

    def __init__(self, loaded: LoadedTire, use_symmetry: bool = True):
        self.loaded = loaded
        parts = {"elastic": loaded.K_elastic, "mass": loaded.M, **loaded.K_compound}
        basis = None
        if use_symmetry:
            footprint = np.asarray(loaded.road_input.sum(axis=1)).ravel()
            vectors = [footprint, loaded.hub_elastic, *loaded.hub_compound.values()]
            if loaded.rolling:  # the streaming air mixes the fore-aft odd and even modes: left-right only
                flow = loaded.cavity.flow
                walls = (loaded.cavity.volume, flow.slope, flow.curvature)
                vectors += [column[loaded.free] for wall in walls for column in wall.T]
            basis = symmetric_basis(loaded.fet.mesh, list(parts.values()), vectors, fore_aft=not loaded.rolling)
        self.basis = basis
        self.symmetric = basis is not None
        if basis is None:
            basis = sp.identity(loaded.M.shape[0], format="csr")
        self._basis = basis
        self._parts = {name: (basis.T @ m @ basis).tocsc() for name, m in parts.items()}
        self._footprint = np.asarray(loaded.road_input.sum(axis=1)).ravel()
        self._banded = banded_sum(list(self._parts.values()))

    def factorise(self, omega: float, inertia: bool = True):
        """The LU of the reduced (or full) :math:`D(\\omega)` (without the mass term unless ``inertia``): banded
        (:class:`.banded.BandedSum`) when the matrices are a band, else SuperLU; either has ``solve(rhs, trans)``."""
        if self._banded is None:
            matrix = self.dynamic_stiffness(omega) if inertia else self.stiffness(omega)
            return spla.splu(matrix, permc_spec="NATURAL")
        g = self.loaded.ratios(omega)
        weights = [1.0, -(omega**2) if inertia else 0.0, *(g[name] for name in self.loaded.K_compound)]
        return self._banded.lu(np.array(weights, complex))

    def stiffness(self, omega: float, storage_only: bool = False) -> sp.csc_matrix:
        r"""Reduced (or full) stiffness :math:`K(\omega)` (complex unless ``storage_only``)."""
        g = self.loaded.ratios(omega, storage_only)
        total = self._parts["elastic"].astype(float if storage_only else complex)
        for name, g_c in g.items():
            total = total + (g_c.real if storage_only else g_c) * self._parts[name]
        return total.tocsc()

    @property
    def mass(self) -> sp.csc_matrix:
        """Reduced (or full) mass matrix."""
        return self._parts["mass"]

    @property
    def basis_matrix(self) -> sp.csr_matrix:
        """Columns spanning the solved subspace (the identity when not reduced)."""
        return self._basis

    def dynamic_stiffness(self, omega: float, storage_only: bool = False) -> sp.csc_matrix:
        r"""Reduced (or full) :math:`D(\omega) = K(\omega) - \omega^2 M`."""
        return (self.stiffness(omega, storage_only) - omega**2 * self.mass).tocsc()

    def solve(self, omega: float, inertia: bool = True) -> dict[str, np.ndarray | complex]:
        """Point FRFs, hub FRF and the forward whole-footprint FRF at ``omega`` (rad/s).

        With ``inertia=False`` the mass term is dropped: the quasi-static response with the
        moduli at ``omega`` (used by the residual correction of :mod:`.modal`).
        """
        lt = self.loaded
        solve = self._solver(self.factorise(omega, inertia), omega)
        row = lt.hub_row(omega)
        t = self._basis
        y = t @ solve(np.asarray(t.T @ row), trans="T")
        g_tread = lt.fet.modulus_ratio("tread", omega)
        points = -g_tread * (lt.road_input.T @ y)
        hub = -lt.hub_diagonal(omega) + y @ (row if lt.cavity is None else lt.hub_column(omega))
        u = t @ solve(np.asarray(t.T @ (g_tread * self._footprint)))
        return {"points": points, "G_H": hub, "H_tot": -(row @ u)}

    def _solver(self, lu, omega: float):
        """Solves with :math:`D(\\omega)`, or with the cavity's :math:`D - V C W^T` by Woodbury's identity
        :math:`x + Z C (I - W^T Z C)^{-1} W^T x`, :math:`Z = D^{-1} V`, :math:`x = D^{-1} b`; transposed
        (``trans="T"``) with :math:`V \\leftrightarrow W`, :math:`C^T` and :math:`Z_W = D^{-T} W`. At rest
        :math:`W = V` (one set of solves)."""
        terms = self.loaded.cavity_terms(omega)
        if terms is None:
            return lu.solve
        t = self._basis
        v, c, w = np.asarray(t.T @ terms[0]), terms[1], np.asarray(t.T @ terms[2])
        z_v = lu.solve(v.astype(complex))
        z_w = z_v if terms[2] is terms[0] else lu.solve(w.astype(complex), trans="T")
        forward = np.eye(c.shape[0]) - (w.T @ z_v) @ c
        adjoint = np.eye(c.shape[0]) - (v.T @ z_w) @ c.T

        def solve(rhs: np.ndarray, trans: str = "N") -> np.ndarray:
            x = lu.solve(rhs, trans=trans)
            if trans == "N":
                return x + z_v @ (c @ np.linalg.solve(forward, w.T @ x))
            return x + z_w @ (c.T @ np.linalg.solve(adjoint, v.T @ x))

        return solve

    def solve_full(self, omega: float, rhs: np.ndarray) -> np.ndarray:
        """Full-size solve :math:`D(\\omega) u = rhs` (no reduction), for checks and general loads."""
        return spla.splu(self.loaded.dynamic_stiffness(omega), permc_spec="NATURAL").solve(rhs)


def frf_visco(
    fet: FETModel,
    static: StaticState,
    freqs: np.ndarray,
    progress: bool = True,
    use_symmetry: bool = True,
    stick: bool = True,
    cavity: CavityCoupling | None = None,
) -> FRFResult:
    """Direct viscoelastic FRFs of the loaded tire with the hub fixed (FETvisco).

    Parameters
    ----------
    fet : FETModel
        The tire.
    static : StaticState
        Loaded state (footprint and tasselli) to linearise about.
    freqs : array_like
        Frequencies (Hz), >= 0.
    progress : bool
        Show a progress bar.
    use_symmetry : bool
        Use the exact mirror-symmetric reduction when the state allows it.
    stick : bool
        The footprint sticks to the road longitudinally (default) or slides freely.
    cavity : CavityCoupling, optional
        The air cavity coupled to the belt and the rim (:func:`roadnoise_utils.tire.ring.cavity.ring_cavity_coupling`);
        default none (the paper's model).

    Returns
    -------
    FRFResult
        ``H`` per tassello, ``H_tot``, ``G_H`` and the per-contact-point FRFs.
    """
    for name, value in (("progress", progress), ("use_symmetry", use_symmetry), ("stick", stick)):
        guards.flag(name, value)
    freqs = np.asarray(freqs, dtype=float)
    if freqs.ndim != 1 or freqs.size == 0 or not np.all(np.isfinite(freqs)) or np.any(freqs < 0):
        raise ValueError("freqs must be a non-empty 1-D array of finite frequencies >= 0 Hz")
    if freqs.max() > MAX_FREQUENCY:
        guards.warn(
            f"freqs reach {freqs.max():g} Hz: beyond {MAX_FREQUENCY:g} Hz the belt mesh and the tread springs no longer "
            "describe a tire (the RM model is built for 0-400 Hz)"
        )
    n_points = int(static.contact.sum())
    guards.check_memory(
        16.0 * freqs.size * (2 * n_points + 3), f"FRFs of {n_points} points at {freqs.size} frequencies", "freqs"
    )
    solver = HubForceSolver(loaded_tire(fet, static, stick=stick, cavity=cavity), use_symmetry=use_symmetry)
    points = np.empty((solver.loaded.n_contact, freqs.size), complex)
    hub = np.empty(freqs.size, complex)
    total = np.empty(freqs.size, complex)
    for i, f in enumerate(tqdm(freqs, desc="FETvisco sweep", disable=not progress, leave=False)):
        out = solver.solve(2 * np.pi * f)
        points[:, i], hub[i], total[i] = out["points"], out["G_H"], out["H_tot"]
    membership = sp.csr_matrix(static.tasselli.membership())
    reduction = "left-right symmetric reduction" if solver.loaded.rolling else "mirror-symmetric reduction"
    method = f"direct, {reduction}" if solver.symmetric else "direct, full system"
    return FRFResult(freqs=freqs, H=membership @ points, H_tot=total, G_H=hub, H_points=points, method=method)
