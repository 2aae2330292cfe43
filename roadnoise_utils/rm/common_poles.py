"""One pole set for all tasselli: fast relaxed vector fitting of many responses (paper Eq. 1-3, beyond the paper).

The paper fits every tassello with its own 8 poles (Eq. 1) and stacks the 8-state models
block-diagonally (Eq. 3): 8 x 71 states. Yet every local FRF :math:`H_i` of one tire sees the
same tire modes, so one pole set :math:`\\{p_k\\}` with per-tassello residues :math:`r_{ik}`
and direct terms :math:`d_i`,

.. math:: G_i(s) = \\sum_{k=1}^{n} \\frac{r_{ik}}{s - p_k} + d_i,

describes all of them with ``n`` states in all: :math:`A_F` is one modal matrix, :math:`B_F`
holds the residues (:func:`.realisation.assemble_fixed_hub`).

The poles are identified from all responses at once (Gustavsen & Semlyen 1999 with the
relaxation of Gustavsen 2006): each response :math:`h_i` contributes the rows of
:math:`[\\Phi w_i,\\; -\\mathrm{diag}(h_i w_i)\\Phi]` in its own unknowns ``c_i`` and the common
:math:`\\sigma` coefficients. A QR factorisation of each response's block eliminates its own
unknowns and leaves the :math:`\\sigma` rows :math:`R_{22}^{(i)}` (the "fast" VF of Deschrijver,
Mrozowski, Dhaene & De Zutter, IEEE MWCL 18(6), 2008); all :math:`R_{22}^{(i)}` stacked with the
relaxation row give :math:`\\sigma`, whose zeros are the next poles. Each response is scaled to
unit weighted norm for this step, so each tassello counts by its relative error whatever its
share of the hub force. The residues then follow per tassello for the common poles.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .vf_kernels import (
    basis,
    conjugate_closed,
    errors_for_poles,
    fit_for_poles,
    sigma_zeros,
    split_poles,
    stack_parts,
)


@dataclass(frozen=True)
class CommonFit:
    """Result of :func:`fit_common` in scaled ``s``.

    ``models[i]`` = ``(poles, residues, d, fitted, error)`` of row ``i`` at the kept iteration
    (:func:`.vf_kernels.fit_for_poles`); ``errors[i]`` row ``i``'s error after 0, 1, ...
    relocations; ``best_iteration`` the kept relocation (smallest worst row's error);
    ``iterations`` the relocations run.
    """

    models: list[tuple]
    errors: list[list[float]]
    best_iteration: int
    iterations: int


def relocate_common(s: np.ndarray, h: np.ndarray, w: np.ndarray, real: np.ndarray, upper: np.ndarray) -> np.ndarray:
    """One relaxed relocation of a pole set common to all rows of ``h`` (K, n_s), weights ``w`` (K, n_s).

    ``real`` (n_r,), ``upper`` (n_c,): the current real poles and upper members of the pairs
    (scaled ``s``). Returns the zeros of the fitted :math:`\\sigma(s)`, stabilised: (n,) complex.
    """
    k, n_s = h.shape
    phi = basis(s, real, upper)
    n = phi.shape[1]
    phi1 = np.concatenate([phi, np.ones((n_s, 1))], axis=1)  # the basis with the constant term
    hw = h * w
    unit = 1.0 / np.linalg.norm(hw, axis=1)  # each response to unit weighted norm
    block = np.concatenate(
        [phi1[None] * (w * unit[:, None])[..., None], -phi1[None] * (hw * unit[:, None])[..., None]], axis=2
    )
    r22 = np.linalg.qr(stack_parts(block), mode="r")[:, n + 1 :, n + 1 :]  # (K, n+1, n+1): sigma's rows
    # relaxation Re(sum_s sigma(s)) = n_s, scaled like the data rows (each of unit norm)
    scale = np.sqrt(k) / n_s
    rows = np.concatenate([r22.reshape(k * (n + 1), n + 1), scale * np.real(phi1.sum(axis=0))[None, :]])
    rhs = np.zeros(rows.shape[0])
    rhs[-1] = scale * n_s
    col = np.linalg.norm(rows, axis=0)
    col[col == 0] = 1.0
    x = np.linalg.lstsq(rows / col, rhs, rcond=None)[0] / col
    return sigma_zeros(real[None], upper[None], x[None, :n], x[None, n])[0]


def fit_common(
    s: np.ndarray,
    h: np.ndarray,
    w: np.ndarray,
    start_poles: np.ndarray,
    iterations: int,
    tolerance: float,
    dc: np.ndarray | None,
) -> CommonFit:
    """Common-pole relaxed vector fitting of the rows of ``h`` (K, n_s) at scaled ``s``.

    ``w`` (K, n_s) the weights, ``start_poles`` the starting poles (scaled ``s``,
    :func:`.vf_kernels.initial_poles`), ``dc`` (K,) the DC values to impose (or None). Relocates up to
    ``iterations`` times, stopping when the poles move less than ``tolerance`` relative to the
    largest; after each relocation every row's residues are solved, and the iteration whose
    worst row's weighted relative RMS error is the smallest is kept (ties: the earlier).
    """
    k = h.shape[0]
    poles = np.asarray(start_poles, complex)

    def row_errors(p: np.ndarray) -> np.ndarray:
        real, upper = split_poles(p)
        return errors_for_poles(s, h, w, np.tile(real, (k, 1)), np.tile(upper, (k, 1)), dc)

    history = [row_errors(poles)]
    best, best_it, used = poles, 0, 0
    for it in range(1, iterations + 1):
        real, upper = split_poles(poles)
        new = conjugate_closed(relocate_common(s, h, w, real, upper))
        history.append(row_errors(new))
        if history[-1].max() < history[best_it].max():
            best, best_it = new, it
        moved = np.max(np.abs(np.sort_complex(new) - np.sort_complex(poles))) / np.max(np.abs(poles))
        poles, used = new, it
        if moved < tolerance:
            break
    models = [fit_for_poles(s, h[i], w[i], best, None if dc is None else dc[i]) for i in range(k)]
    errors = np.array(history).T.tolist()
    for i, model in enumerate(models):
        errors[i][best_it] = model.error  # the kept poles' errors from the final (SVD) solves
    return CommonFit(models=models, errors=errors, best_iteration=best_it, iterations=used)
