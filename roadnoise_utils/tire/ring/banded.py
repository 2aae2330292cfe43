"""Banded Cholesky factor of a sparse symmetric positive definite matrix (the ring tire's stiffness).

The ring model numbers its DOF circumference-major, so its stiffness is banded but for the
elements that close the ring, which couple the first and the last nodes. A sparse LU in that
natural order fills the whole last block of columns; reordered by reverse Cuthill-McKee
(:func:`scipy.sparse.csgraph.reverse_cuthill_mckee`) the closed ring becomes a band of about
two rings of nodes (~80 on the 165/65 R14 at 600 elements), and LAPACK's banded Cholesky
(:func:`scipy.linalg.cholesky_banded`) solves it about 5x faster than SuperLU in the natural
order (0.7 ms against 3.6 ms per right-hand side at 16 200 DOF): the one-sided contact runs
make two such solves per time step.
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
from scipy.sparse.csgraph import reverse_cuthill_mckee

#: Largest asymmetry accepted, relative to the largest entry (round-off of the assembly).
SYMMETRY_TOLERANCE = 1e-12


class BandedCholesky:
    """:math:`A = L L^T` of a sparse symmetric positive definite ``matrix``, in a band after reordering.

    :meth:`solve` takes one right-hand side ``(n,)`` or several ``(n, k)``.

    Raises
    ------
    ValueError
        ``matrix`` is not square or not symmetric (beyond :data:`SYMMETRY_TOLERANCE`).
    numpy.linalg.LinAlgError
        ``matrix`` is not positive definite.
    """

    def __init__(self, matrix: sp.spmatrix | sp.sparray):
        csr = sp.csr_array(matrix)
        n = csr.shape[0]
        if csr.shape != (n, n):
            raise ValueError(f"matrix must be square, got shape {csr.shape}")
        scale = float(abs(csr).max()) if csr.nnz else 1.0
        asymmetry = float(abs(csr - csr.T).max()) if csr.nnz else 0.0
        if asymmetry > SYMMETRY_TOLERANCE * scale:
            raise ValueError(f"matrix must be symmetric: asymmetry {asymmetry / scale:.2e} of its largest entry")
        self.order = reverse_cuthill_mckee(csr, symmetric_mode=True)
        upper = sp.triu(csr[self.order][:, self.order]).tocoo()
        self.bandwidth = int((upper.col - upper.row).max(initial=0))
        band = np.zeros((self.bandwidth + 1, n))
        band[self.bandwidth + upper.row - upper.col, upper.col] = upper.data
        self.factor = sla.cholesky_banded(band, lower=False, check_finite=False)

    @property
    def shape(self) -> tuple[int, int]:
        n = self.factor.shape[1]
        return n, n

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        """:math:`A^{-1}` ``rhs`` for ``rhs`` of shape (n,) or (n, k)."""
        rhs = np.asarray(rhs)
        if rhs.shape[0] != self.factor.shape[1]:
            raise ValueError(f"rhs must have {self.factor.shape[1]} rows, got shape {rhs.shape}")
        out = np.empty(rhs.shape, np.result_type(rhs.dtype, float))
        out[self.order] = sla.cho_solve_banded((self.factor, False), rhs[self.order], check_finite=False)
        return out
