"""Modal reduction of the ring FE tire (paper stages 3-5, Fig. 4-5)."""

from __future__ import annotations

import numpy as np
import scipy.sparse.linalg as spla

from ...response.modal_reduction import (
    ModalModel,
    ModalReduction,
    check_options,
    identify_modes,
    modal_damping,
    reference_mode,
)
from ..model import FRFResult
from .frf import HubForceSolver, frf_visco
from .loaded import loaded_tire
from .mechanics import FETModel
from .mode_shapes import lateral_order, wave_numbers
from .static import StaticState


def _frozen_modes(
    solver: HubForceSolver, omega_ref: float, frozen: str, f_min_top: float
) -> tuple[np.ndarray, np.ndarray]:
    """Eigenpairs of the frozen model in the solver's (symmetric) subspace, up to at least ``f_min_top`` Hz."""
    storage = frozen == "storage"
    k = solver.stiffness(omega_ref, storage_only=storage)
    m = solver.mass
    n_modes = 20
    # ARPACK's starting vector, fixed (its default is random: the modes would differ in their last bits run to run)
    start = np.random.default_rng(0).standard_normal(k.shape[0]).astype(k.dtype)
    while True:
        n_modes = min(n_modes, k.shape[0] - 2)
        if storage:
            vals, vecs = spla.eigsh(k, k=n_modes, M=m, sigma=0.0, v0=start)
        else:
            vals, vecs = spla.eigs(k, k=n_modes, M=m, sigma=0.0, v0=start)
        order = np.argsort(vals.real)
        vals, vecs = vals[order], vecs[:, order]
        if np.sqrt(vals.real.max()) / (2 * np.pi) >= f_min_top or n_modes >= k.shape[0] - 2:
            break
        n_modes += 20
    keep = np.sqrt(np.abs(vals.real)) / (2 * np.pi) <= f_min_top * 1.25
    vals, vecs = vals[keep].astype(complex), vecs[:, keep].astype(complex)
    vecs = vecs / np.sqrt(np.einsum("ir,ir->r", vecs, m @ vecs))  # phi^T M phi = 1 (unconjugated)
    return vals, solver.basis_matrix @ vecs


def modal_reduction(
    fet: FETModel,
    static: StaticState,
    freqs: np.ndarray | None = None,
    visco: FRFResult | None = None,
    reference_frequency: float | None = None,
    frozen: str = "complex",
    damping: str = "identified",
    f_band: float = 250.0,
    anchors: tuple[float, ...] | None = None,
    progress: bool = False,
) -> ModalReduction:
    """The paper's procedure of Fig. 4: identify damping, freeze, reduce, compute local FRFs.

    Parameters
    ----------
    fet, static : FETModel, StaticState
        The tire and its loaded state.
    freqs : ndarray, optional
        Frequencies of the returned FRFs (Hz); default those of ``visco``.
    visco : FRFResult, optional
        Direct FRFs of the viscoelastic model over at least 0-``f_band`` (computed if not given).
    reference_frequency : float, optional
        Frozen frequency (Hz); default the identified vertical mode with the largest static
        share of :math:`H_{tot}(0)` (the "most relevant vertical mode").
    frozen : {"complex", "storage"}
        Freeze the complex moduli (default) or only their storage part (the paper's FET70Hz).
    damping : {"identified", "model"}
        Give the modes seen in :math:`H_{tot}` the identified loss factors (default, the paper)
        or keep the frozen model's own (``frozen="complex"`` only).
    f_band : float
        Band of the identification (Hz); modes are kept up to at least ``2 * f_band``.
    anchors : tuple of float, optional
        Frequencies (Hz) of the quasi-static solves of the residual correction; default
        0, 0.1, 0.25, 0.5, 1 and 1.6 times ``f_band``.
    """
    check_options(frozen, damping, f_band)
    if visco is None:
        visco = frf_visco(fet, static, np.arange(0.0, f_band + 1.0, 1.0), progress=progress)
    if not isinstance(visco, FRFResult):
        raise TypeError(f"visco must be the FRFResult of ru.frf_visco(fet, static, freqs), got {type(visco).__name__}")
    ident = identify_modes(visco.freqs, visco.H_tot, f_max=f_band)
    reference_frequency = reference_mode(ident, reference_frequency)
    anchor_freqs = np.array(anchors if anchors is not None else [0.0, 0.1, 0.25, 0.5, 1.0, 1.6]) * (
        1.0 if anchors is not None else f_band
    )
    if anchor_freqs[0] != 0.0 or np.any(np.diff(anchor_freqs) <= 0):
        raise ValueError("anchors must start at 0 Hz and increase")

    lt = loaded_tire(fet, static)
    solver = HubForceSolver(lt)
    omega_ref = 2 * np.pi * reference_frequency
    frozen_vals, shapes = _frozen_modes(solver, omega_ref, frozen, 2 * f_band)
    storage = frozen == "storage"
    row = lt.hub_row(omega_ref, storage_only=storage)
    g_tread = fet.modulus_ratio("tread", omega_ref)
    hub_gain = row @ shapes
    point_gain = ((g_tread.real if storage else g_tread) * (lt.road_input.T @ shapes)).T
    eigenvalues, source = modal_damping(frozen_vals, hub_gain, ident, frozen, damping, f_band)
    quasi = [solver.solve(2 * np.pi * f, inertia=False) for f in anchor_freqs]
    model = ModalModel(
        reference_frequency=float(reference_frequency),
        frozen=frozen,
        eigenvalues=eigenvalues,
        damping_source=source,
        hub_gain=hub_gain,
        point_gain=point_gain,
        anchor_freqs=anchor_freqs,
        anchor_points=np.array([q["points"] for q in quasi]),
        anchor_hub=np.array([q["G_H"] for q in quasi]),
        membership=static.tasselli.membership(),
    )
    full_shapes = np.zeros((fet.n_dof, shapes.shape[1]), complex)
    full_shapes[lt.free] = shapes
    return ModalReduction(
        identification=ident,
        reference_frequency=float(reference_frequency),
        model=model,
        frozen_eigenvalues=frozen_vals,
        wave_number=wave_numbers(fet, full_shapes.real),
        lateral_order=lateral_order(fet, full_shapes.real),
        frf=model.frf(visco.freqs if freqs is None else freqs),
    )
