"""The banded Cholesky factor against a sparse LU, on a closed ring like the tire's."""

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from roadnoise_utils.tire.ring.banded import BandedCholesky


def closed_ring(n: int, width: int = 3) -> sp.csr_array:
    """SPD stiffness of ``n`` nodes on a ring, ``width`` DOF per node coupled to both neighbours."""
    rng = np.random.default_rng(0)
    blocks = {}
    for i in range(n):
        for j in (i, (i + 1) % n):
            block = rng.standard_normal((width, width))
            blocks[i, j] = blocks.get((i, j), 0) + block
    dense_rows, dense_cols, values = [], [], []
    for (i, j), block in blocks.items():
        for a in range(width):
            for b in range(width):
                dense_rows += [i * width + a, j * width + b]
                dense_cols += [j * width + b, i * width + a]
                values += [block[a, b], block[a, b]]
    coupling = sp.coo_array((values, (dense_rows, dense_cols)), shape=(n * width, n * width)).tocsr()
    shift = abs(coupling).sum(axis=1).max() + 1.0  # diagonally dominant: positive definite
    return (coupling + shift * sp.eye_array(n * width)).tocsr()


def test_solves_as_sparse_lu_one_and_many_right_hand_sides():
    matrix = closed_ring(400)
    factor = BandedCholesky(matrix)
    rhs = np.random.default_rng(1).standard_normal((matrix.shape[0], 5))
    reference = spla.splu(matrix.tocsc()).solve(rhs)
    np.testing.assert_allclose(factor.solve(rhs), reference, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(factor.solve(rhs[:, 0]), reference[:, 0], rtol=1e-12, atol=1e-14)


def test_the_closed_ring_becomes_a_narrow_band():
    # natural order: the closing elements couple DOF 0 and n - 1; reordered, about two nodes wide
    matrix = closed_ring(400)
    assert BandedCholesky(matrix).bandwidth <= 4 * 3


def test_refuses_an_asymmetric_matrix_and_an_indefinite_one():
    matrix = closed_ring(20).tolil()
    matrix[0, 5] += 1.0
    with pytest.raises(ValueError, match="symmetric"):
        BandedCholesky(matrix)
    with pytest.raises(np.linalg.LinAlgError):
        BandedCholesky(-closed_ring(20))
    with pytest.raises(ValueError, match="rows"):
        BandedCholesky(closed_ring(20)).solve(np.ones(7))
