"""The symmetric factor of a sparse symmetric matrix, and whether it is positive definite: the loaded tire's solver.

A symmetric matrix permuted symmetrically, :math:`P A P^T = L D L^T`, needs no pivoting when it is
positive definite, and then :math:`D > 0`; by Sylvester's law of inertia the signs of ``D`` are
those of ``A``'s eigenvalues, so the factor also says whether ``A`` is definite (a stable
equilibrium's tangent). SuperLU (:func:`scipy.sparse.linalg.splu`) computes it with the diagonal
pivots taken as they come (``diag_pivot_thresh=0``, ``SymmetricMode``) in a minimum-degree order of
:math:`A^T + A`: ``U = D L^T``. The loaded tire's stiffness is a closed ring of nodes, whose
reverse Cuthill-McKee band (:class:`~roadnoise_utils.tire.banded.BandedCholesky`) is two fronts
of rings wide; minimum degree cuts the ring instead. Measured on the production loaded tire's
tangent (19 020 free DOF, band 1703): factor 0.43 s against the band's 2.0-2.2 s, one solve
0.009 s against 0.026 s, the solutions within 1e-12; SuperLU in its default column order
(COLAMD) takes 4.1-4.6 s.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from .banded import require_symmetric

#: An indefinite matrix's solve ``x`` is accepted when its residual is below this fraction of
#: ``|A| |x| + |b|`` (its normwise backward error, infinity norms): a few times a stable solve's.
SOLVE_TOLERANCE = 1e-12
#: Steps of iterative refinement of an indefinite matrix's solve before it is factorised with pivoting.
REFINEMENTS = 2


class SymmetricFactor:
    """:math:`P A P^T = L D L^T` of a sparse symmetric ``matrix``; :meth:`solve` takes ``(n,)`` or ``(n, k)``.

    A complex symmetric matrix (:math:`A = A^T`: a damped dynamic stiffness) is factorised and
    solved as an indefinite real one (``require_definite=False``): never definite, no inertia.

    Attributes
    ----------
    definite : bool
        Whether ``matrix`` is positive definite: every pivot of ``D`` positive, each on the diagonal.
    negative_pivots : int or None
        The negative pivots of ``D``: by Sylvester's law of inertia the count of ``matrix``'s negative
        eigenvalues (in exact arithmetic; the unpivoted factor of an indefinite matrix may miss it by
        round-off); ``None`` where the factor had to pivot off the diagonal.

    Raises
    ------
    ValueError
        ``matrix`` is not square or not symmetric (beyond :data:`~roadnoise_utils.tire.banded.SYMMETRY_TOLERANCE`),
        or complex where it must be definite.
    numpy.linalg.LinAlgError
        ``require_definite`` and ``matrix`` is not positive definite, or ``matrix`` is singular.

    Notes
    -----
    Without pivoting the factor is stable for a definite matrix. An indefinite one
    (``require_definite=False``) keeps it as long as its solves are accurate: each solve is refined
    (:data:`REFINEMENTS` steps of iterative refinement at most) until its backward error is below
    :data:`SOLVE_TOLERANCE`, else the matrix is factorised again with
    SuperLU's partial pivoting, stable for any matrix.
    """

    def __init__(self, matrix: sp.spmatrix | sp.sparray, require_definite: bool = True):
        csc = sp.csc_matrix(matrix)
        require_symmetric(csc)
        self._complex = np.iscomplexobj(csc.data)
        if self._complex and require_definite:
            raise ValueError("matrix must be real to be positive definite (give require_definite=False)")
        self._matrix, self._pivoting = csc, False
        self.negative_pivots: int | None = None
        try:
            self._lu = spla.splu(
                csc, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True}
            )
        except RuntimeError:  # an exactly zero pivot: indefinite or singular
            self.definite = False
            if require_definite:
                raise np.linalg.LinAlgError("matrix is not positive definite") from None
            self._factor_with_pivoting()
            return
        if self._complex:  # a complex symmetric matrix (a damped dynamic stiffness) has no inertia
            self.definite = False
            return
        on_diagonal = np.array_equal(self._lu.perm_r, self._lu.perm_c)
        pivots = self._lu.U.diagonal()
        self.definite = bool(on_diagonal and np.all(pivots > 0.0))
        if on_diagonal:
            self.negative_pivots = int(np.count_nonzero(pivots < 0.0))
        if require_definite and not self.definite:
            raise np.linalg.LinAlgError("matrix is not positive definite")

    def _factor_with_pivoting(self) -> None:
        try:
            self._lu = spla.splu(self._matrix, permc_spec="MMD_AT_PLUS_A")
        except RuntimeError as error:
            raise np.linalg.LinAlgError(f"matrix is singular: {error}") from None
        self._pivoting = True

    @property
    def shape(self) -> tuple[int, int]:
        return self._lu.shape

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        """:math:`A^{-1}` ``rhs`` for ``rhs`` of shape (n,) or (n, k)."""
        rhs = np.asarray(rhs)
        if rhs.shape[0] != self.shape[0]:
            raise ValueError(f"rhs must have {self.shape[0]} rows, got shape {rhs.shape}")
        if self._complex:
            rhs = np.asarray(rhs, complex)
        elif np.iscomplexobj(rhs):
            return self.solve(np.ascontiguousarray(rhs.real)) + 1j * self.solve(np.ascontiguousarray(rhs.imag))
        else:
            rhs = np.asarray(rhs, float)
        x = self._lu.solve(rhs)
        if self.definite or self._pivoting:
            return x
        norm = float(abs(self._matrix).sum(axis=1).max())  # infinity norm; only an indefinite matrix's solves need it
        for _ in range(REFINEMENTS + 1):
            residual = rhs - self._matrix @ x
            bound = norm * np.abs(x).max(axis=0) + np.abs(rhs).max(axis=0)
            if np.all(np.abs(residual).max(axis=0) <= SOLVE_TOLERANCE * bound):
                return x
            x = x + self._lu.solve(residual)
        self._factor_with_pivoting()
        return self._lu.solve(rhs)
