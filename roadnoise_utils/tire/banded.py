"""Banded factors of the sparse matrices of a closed ring of nodes: the ring tire's and the loaded tire's stiffness.

Both models number their DOF circumference-major, so a stiffness is banded but for the
elements that close the circumference, which couple the first and the last nodes. A sparse LU
in that natural order fills the whole last block of columns; reordered by reverse
Cuthill-McKee (:func:`scipy.sparse.csgraph.reverse_cuthill_mckee`) the closed ring becomes a
band of about two rings of nodes, and LAPACK's banded Cholesky
(:func:`scipy.linalg.cholesky_banded`) solves it several times faster than SuperLU: the ring
tire's 16 200 DOF at 600 elements (a band of ~80) in 0.7 ms against 3.6 ms per right-hand side.
Where the ring is many nodes around (the loaded tire: 255 DOF per ring, a band of 1703), a
minimum-degree order that cuts the ring does better
(:class:`~roadnoise_utils.tire.symmetric_factor.SymmetricFactor`).
"""

from __future__ import annotations

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
from scipy.sparse.csgraph import reverse_cuthill_mckee

#: Largest asymmetry accepted, relative to the largest entry (round-off of the assembly).
SYMMETRY_TOLERANCE = 1e-12


def require_symmetric(matrix: sp.sparray | sp.spmatrix) -> None:
    """Refuse (``ValueError``) a sparse ``matrix`` that is not square or not symmetric beyond :data:`SYMMETRY_TOLERANCE`."""
    if matrix.shape[0] != matrix.shape[1]:
        raise ValueError(f"matrix must be square, got shape {matrix.shape}")
    scale = float(abs(matrix).max()) if matrix.nnz else 1.0
    asymmetry = float(abs(matrix - matrix.T).max()) if matrix.nnz else 0.0
    if asymmetry > SYMMETRY_TOLERANCE * scale:
        raise ValueError(f"matrix must be symmetric: asymmetry {asymmetry / scale:.2e} of its largest entry")


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
        require_symmetric(csr)
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


#: A band wider than this fraction of the size is no band: :class:`BandedSum` refuses it (the sparse LU is then better).
MAX_BAND_FRACTION = 0.1


class BandedLU:
    """LAPACK's banded LU (``?gbtrf``) of one matrix, solved with ``?gbtrs``: a drop-in for SuperLU's ``solve``.

    ``order`` is the row and column permutation the band was built in (``None``: the natural order).
    """

    def __init__(self, band: np.ndarray, lower: int, upper: int, order: np.ndarray | None):
        factor = sla.get_lapack_funcs("gbtrf", (band,))
        self._lu, self._pivots, info = factor(band, lower, upper, overwrite_ab=True)
        if info > 0:
            raise np.linalg.LinAlgError(f"the banded matrix is singular (zero pivot in row {info})")
        self._solve = sla.get_lapack_funcs("gbtrs", (self._lu,))
        self._lower, self._upper, self._order = lower, upper, order

    def solve(self, rhs: np.ndarray, trans: str = "N") -> np.ndarray:
        """:math:`A^{-1}` ``rhs`` (``trans="N"``) or :math:`A^{-T}` ``rhs`` (``"T"``, not conjugated), rhs (n,) or (n, k)."""
        rhs = np.asarray(rhs, self._lu.dtype)
        if self._order is not None:
            rhs = rhs[self._order]
        x, info = self._solve(self._lu, self._lower, self._upper, rhs, self._pivots, trans={"N": 0, "T": 1}[trans])
        if info != 0:
            raise ValueError(f"?gbtrs: argument {-info} is invalid")
        if self._order is None:
            return x
        out = np.empty_like(x)
        out[self._order] = x
        return out


class BandedSum:
    """A weighted sum of sparse matrices of one size, :math:`A(w) = \\sum_j w_j A_j`, held as bands: factorised by
    :meth:`lu` in LAPACK's banded storage without forming a sparse matrix per weight set.

    The ring tire's dynamic stiffness (elastic, compound and mass parts, weights :math:`g_c(\\omega)` and
    :math:`-\\omega^2`) at every frequency of a sweep: the parts' bands are stacked once, a frequency costs
    one weighted sum of bands and one banded LU (about 3x less than summing sparse matrices and
    SuperLU). In the natural order when that is already a band (the mirror-reduced tire), else after
    reverse Cuthill-McKee (the closed ring); :func:`banded_sum` gives None when no order makes a band
    narrower than :data:`MAX_BAND_FRACTION` of the size.
    """

    def __init__(self, parts: list, order: np.ndarray | None, width: int):
        self.n = parts[0].shape[0]
        self.width, self.order = width, order
        stacked = np.zeros((len(parts), 2 * width + 1, self.n))
        for j, part in enumerate(parts):
            coo = sp.coo_array(part if order is None else sp.csr_array(part)[order][:, order])
            np.add.at(stacked[j], (width + coo.row - coo.col, coo.col), coo.data.real)
        self._stacked = stacked.reshape(len(parts), -1)

    def lu(self, weights: np.ndarray) -> BandedLU:
        """The banded LU of :math:`\\sum_j w_j A_j` for the weights ``w`` (complex) in the order of the parts."""
        weights = np.asarray(weights)
        w = self.width
        band = np.zeros((3 * w + 1, self.n), np.result_type(weights.dtype, float))
        summed = weights.real @ self._stacked
        if np.iscomplexobj(weights):
            summed = summed + 1j * (weights.imag @ self._stacked)
        band[w:] = summed.reshape(2 * w + 1, self.n)  # the top w rows: room for the pivoting's fill
        return BandedLU(band, w, w, self.order)


def banded_sum(parts: list) -> BandedSum | None:
    """A :class:`BandedSum` of real sparse ``parts`` (one size, a symmetric pattern), or None when no band
    narrower than :data:`MAX_BAND_FRACTION` of the size exists (natural order, then reverse Cuthill-McKee)."""
    pattern = sp.csr_array(sum(abs(sp.csr_array(p)) for p in parts))
    if any(np.iscomplexobj(p.data) for p in parts):
        raise ValueError("parts must be real (the weights carry the complex moduli)")
    n = pattern.shape[0]
    limit = MAX_BAND_FRACTION * n
    coo = pattern.tocoo()
    width = int(np.abs(coo.row - coo.col).max(initial=0))
    order = None
    if width > limit:
        order = reverse_cuthill_mckee(pattern, symmetric_mode=True)
        reordered = pattern[order][:, order].tocoo()
        width = int(np.abs(reordered.row - reordered.col).max(initial=0))
        if width > limit:
            return None
    return BandedSum(parts, order, width)
