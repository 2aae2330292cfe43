"""The sparse symmetric factor: solves as a dense solve, says whether the matrix is definite, refuses bad input."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp

from roadnoise_utils.tire.banded import BandedCholesky
from roadnoise_utils.tire.symmetric_factor import SymmetricFactor


def closed_ring(n: int, shift: float = 0.0) -> sp.csr_matrix:
    """A closed ring of springs to ground, 3 DOF per node coupled to the next two nodes: the loaded tire's pattern."""
    rng = np.random.default_rng(n)
    a = sp.lil_matrix((3 * n, 3 * n))
    for node in range(n):
        for other in (node + 1, node + 2):
            block = rng.normal(size=(3, 3))
            i, j = 3 * node, 3 * (other % n)
            a[i : i + 3, j : j + 3] = block
    a = a + a.T
    return (a + sp.identity(3 * n) * (abs(a).sum(axis=1).max() + 1.0 - shift)).tocsr()


def test_it_solves_as_the_dense_solve_and_the_banded_factor():
    matrix = closed_ring(40)
    rhs = np.random.default_rng(1).normal(size=(matrix.shape[0], 3))
    factor = SymmetricFactor(matrix)
    expected = np.linalg.solve(matrix.toarray(), rhs)
    np.testing.assert_allclose(factor.solve(rhs), expected, rtol=0, atol=1e-12 * np.abs(expected).max())
    np.testing.assert_allclose(factor.solve(rhs[:, 0]), BandedCholesky(matrix).solve(rhs[:, 0]), rtol=1e-12)
    complex_rhs = rhs[:, 0] + 2j * rhs[:, 1]
    np.testing.assert_allclose(factor.solve(complex_rhs), expected[:, 0] + 2j * expected[:, 1], atol=1e-11)
    assert factor.definite


def test_it_says_whether_the_matrix_is_definite_by_its_pivots():
    """Shifted past its least eigenvalue the ring is indefinite: refused as definite, solved all the same."""
    base = closed_ring(30)
    least = np.linalg.eigvalsh(base.toarray())[0]
    indefinite = base - sp.identity(base.shape[0]) * (least + 0.5 * abs(least))
    with pytest.raises(np.linalg.LinAlgError, match="not positive definite"):
        SymmetricFactor(indefinite)
    factor = SymmetricFactor(indefinite, require_definite=False)
    assert not factor.definite
    rhs = np.arange(base.shape[0], dtype=float)
    np.testing.assert_allclose(indefinite @ factor.solve(rhs), rhs, atol=1e-9 * np.abs(rhs).max())
    assert SymmetricFactor(base - sp.identity(base.shape[0]) * 0.5 * least).definite


@pytest.mark.parametrize("fraction", [0.1, 0.37, 0.8])
def test_its_negative_pivots_count_the_eigenvalues_below_a_shift(fraction):
    """Sylvester's law of inertia: the ring shifted into its spectrum has as many negative pivots as
    eigenvalues below the shift (the modes below a cut-off, counted by one factor)."""
    base = closed_ring(30)
    values = np.linalg.eigvalsh(base.toarray())
    shift = values[0] + fraction * (values[-1] - values[0])
    factor = SymmetricFactor(base - sp.identity(base.shape[0]) * shift, require_definite=False)
    assert factor.negative_pivots == np.count_nonzero(values < shift) > 0
    assert SymmetricFactor(base).negative_pivots == 0


def test_a_complex_symmetric_matrix_is_solved_as_the_dense_solve():
    """A damped dynamic stiffness (K (1 + i eta) - w^2 M: symmetric, not Hermitian, indefinite): solved to
    round-off, never called definite."""
    stiffness = closed_ring(30)
    least = np.linalg.eigvalsh(stiffness.toarray())[0]
    dynamic = (stiffness * (1 + 0.1j) - sp.identity(stiffness.shape[0]) * 1.5 * least).tocsc()
    factor = SymmetricFactor(dynamic, require_definite=False)
    rhs = np.random.default_rng(2).normal(size=(dynamic.shape[0], 2)) + 1j
    expected = np.linalg.solve(dynamic.toarray(), rhs)
    np.testing.assert_allclose(factor.solve(rhs), expected, rtol=0, atol=1e-11 * np.abs(expected).max())
    real = rhs.real[:, 0]  # a real right-hand side of a complex matrix: a complex solution
    np.testing.assert_allclose(factor.solve(real), np.linalg.solve(dynamic.toarray(), real), rtol=0, atol=1e-10)
    assert not factor.definite and factor.negative_pivots is None
    with pytest.raises(ValueError, match="real to be positive definite"):
        SymmetricFactor(dynamic)


def test_bad_input_is_refused_naming_it():
    with pytest.raises(ValueError, match="square"):
        SymmetricFactor(sp.csr_matrix(np.ones((3, 4))))
    with pytest.raises(ValueError, match="symmetric"):
        SymmetricFactor(sp.csr_matrix(np.array([[2.0, 1.0], [0.0, 2.0]])))
    with pytest.raises(np.linalg.LinAlgError, match="singular|definite"):
        SymmetricFactor(sp.csr_matrix(np.zeros((3, 3))), require_definite=False)
    with pytest.raises(ValueError, match="rhs must have 120 rows"):
        SymmetricFactor(closed_ring(40)).solve(np.ones(7))
