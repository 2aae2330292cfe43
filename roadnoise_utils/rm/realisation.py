"""State-space realisation of the fitted tasselli and the fixed-hub tire (paper Eq. 2-4).

Each tassello's transfer function (:class:`.fitting.RationalFit`) becomes a real state-space
model (Eq. 2),

.. math:: \\dot x_i = A_i x_i + B_i u_i, \\qquad F_i = C_i x_i + D_i u_i,

built straight from the pole-residue form, never through polynomial coefficients (degree-8
polynomials are hopelessly ill-conditioned): one 1x1 block per real pole
(:math:`a = p, b = 1, c = r`) and one 2x2 block per conjugate pair
:math:`p = \\sigma + i\\omega`, :math:`r = \\alpha + i\\beta`:

.. math:: A = \\begin{bmatrix}\\sigma & \\omega\\\\ -\\omega & \\sigma\\end{bmatrix},\\quad
          B = \\begin{bmatrix}2\\\\0\\end{bmatrix},\\quad C = [\\alpha\\ \\ \\beta],

which reproduces :math:`r/(s-p) + \\bar r/(s-\\bar p)` exactly. The whole tire (Eq. 3-4)
stacks them block-diagonally: one input per tassello, the hub force as the output,
:math:`F_F = \\sum_i F_i`. Everything is a python-control ``StateSpace``.

Fits with one pole set for all tasselli (``fit_tasselli(..., common_poles=True)``) share their
states instead: :math:`F_F = \\sum_k \\frac{1}{s-p_k}\\sum_i r_{ik} u_i + \\sum_i d_i u_i`, so
:math:`A_F` is the modal matrix of the ``n`` poles (transposed blocks
:math:`[\\sigma\\ -\\omega;\\ \\omega\\ \\sigma]`), :math:`B_F` holds the residues,
:math:`[\\alpha_i\\ \\beta_i]^T` per pair and tassello, and :math:`C_F = [2\\ 0\\ \\dots]`:
``n`` states in all instead of ``n`` per tassello (the transpose of the single-input
realisation, the same transfer functions).
"""

from __future__ import annotations

import control
import numpy as np
import scipy.linalg as sla

from .fitting import FitSet, RationalFit


def realize(fit: RationalFit) -> control.StateSpace:
    """Real block-diagonal state space of one fitted transfer function (paper Eq. 2)."""
    if not isinstance(fit, RationalFit):
        raise TypeError(
            f"fit must be a RationalFit (ru.vector_fit, or one of ru.fit_tasselli's), got {type(fit).__name__}"
        )
    a, b, c = real_blocks(fit)
    return control.ss(a, b[:, None], c[None, :], np.array([[fit.direct]]))


def real_blocks(fit: RationalFit) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(A, b, c) of one fit, conjugate pairs as 2x2 blocks.

    A fit with a proportional term :math:`e s` has no state space (it is improper: the output
    would need the input's derivative) and is refused.
    """
    if fit.proportional != 0.0:
        raise ValueError(
            f"this fit has a proportional term e = {fit.proportional:.3g} (vector_fit(..., proportional=True)): an "
            "improper transfer function has no state space; fit with proportional=False"
        )
    tol = 1e-12 * np.max(np.abs(fit.poles))
    blocks_a, blocks_b, blocks_c = [], [], []
    k = 0
    poles, residues = fit.poles, fit.residues
    while k < poles.size:
        p, r = poles[k], residues[k]
        if abs(p.imag) <= tol:
            blocks_a.append(np.array([[p.real]]))
            blocks_b.append([1.0])
            blocks_c.append([r.real])
            k += 1
        else:
            if not (np.isclose(poles[k + 1], np.conj(p)) and np.isclose(residues[k + 1], np.conj(r))):
                raise ValueError("complex poles and residues must come in conjugate pairs, upper member first")
            if p.imag < 0:
                p, r = np.conj(p), np.conj(r)
            blocks_a.append(np.array([[p.real, p.imag], [-p.imag, p.real]]))
            blocks_b.append([2.0, 0.0])
            blocks_c.append([r.real, r.imag])
            k += 2
    return sla.block_diag(*blocks_a), np.concatenate(blocks_b), np.concatenate(blocks_c)


def assemble_fixed_hub(fits: FitSet | list[RationalFit]) -> control.StateSpace:
    """The fixed-hub tire of Eq. 3-4: block-diagonal A_F, B_F; C_F, D_F summing the tasselli.

    Parameters
    ----------
    fits : FitSet or list of RationalFit
        One fit per tassello (:func:`.fitting.fit_tasselli`).

    Returns
    -------
    control.StateSpace
        Inputs: the vertical displacement of each tassello (m), in tassello order; output: the
        vertical force on the hub (N), positive upward. States: 2 per conjugate pole pair,
        1 per real pole, tassello after tassello (``x_F = [x_1; x_2; ...]``); for a
        :class:`~.fitting.FitSet` with ``common_poles``, one set shared by all tasselli
        (:func:`shared_realisation`).
    """
    if not isinstance(fits, (FitSet, list, tuple)):
        raise TypeError(f"fits must be a FitSet or a list of RationalFit, got {type(fits).__name__}")
    source, fits = fits, list(fits)
    if not fits:
        raise ValueError("no fits to assemble")
    wrong = [type(f).__name__ for f in fits if not isinstance(f, RationalFit)]
    if wrong:
        raise TypeError(f"fits must hold RationalFit objects (ru.fit_tasselli), got {sorted(set(wrong))}")
    if getattr(source, "common_poles", False):
        return shared_realisation(fits)
    blocks = [real_blocks(f) for f in fits]
    a = sla.block_diag(*[blk[0] for blk in blocks])
    b = sla.block_diag(*[blk[1][:, None] for blk in blocks])
    c = np.concatenate([blk[2] for blk in blocks])[None, :]
    d = np.array([[f.direct for f in fits]])
    return control.ss(a, b, c, d)


def shared_realisation(fits: list[RationalFit]) -> control.StateSpace:
    """The fixed-hub tire (Eq. 3-4) of fits that share one pole set: ``n_poles`` states in all.

    Per pole pair :math:`p = \\sigma + i\\omega` the block :math:`[\\sigma\\ -\\omega;\\ \\omega\\ \\sigma]`,
    tassello ``i``'s input column :math:`[\\alpha_i;\\ \\beta_i]` (its residue
    :math:`r_i = \\alpha_i + i\\beta_i`) and the output row :math:`[2\\ 0]`; per real pole
    :math:`a = p`, :math:`b_i = r_i`, :math:`c = 1`. Raises ``ValueError`` if the poles differ.
    """
    first = fits[0].poles
    if any(f.poles.shape != first.shape or not np.array_equal(f.poles, first) for f in fits):
        raise ValueError("common_poles: every fit must have the same poles (fit_tasselli(..., common_poles=True))")
    blocks = [real_blocks(f) for f in fits]
    a = blocks[0][0].T  # the transposed realisation: residues into B, the common part into C
    b = np.column_stack([blk[2] for blk in blocks])
    c = blocks[0][1][None, :]
    d = np.array([[f.direct for f in fits]])
    return control.ss(a, b, c, d)


def frequency_response(system: control.StateSpace, freqs: np.ndarray) -> np.ndarray:
    """Complex response of every input to the output at ``freqs`` (Hz), (n_inputs, n_freq).

    Evaluated by python-control (a dense solve per frequency, O(n_states^3)), independently of
    the block structure: meant for checks at a few frequencies.
    """
    response = system(2j * np.pi * np.asarray(freqs, float), squeeze=False)  # (outputs, inputs, freqs)
    return np.asarray(response)[0]
