"""The banded Cholesky factor and the banded LU of a weighted sum against a sparse LU, on a closed ring like the tire's."""

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from roadnoise_utils.tire.banded import BandedCholesky, banded_sum


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


def _open_chain(n: int) -> sp.csr_array:
    """A tridiagonal matrix: a band in its natural order."""
    return sp.diags_array([np.full(n - 1, -1.0), np.full(n, 3.0), np.full(n - 1, -1.5)], offsets=[-1, 0, 1]).tocsr()


@pytest.mark.parametrize(
    "parts", [[closed_ring(300), sp.eye_array(900).tocsr()], [_open_chain(500), sp.eye_array(500)]]
)
def test_the_banded_lu_of_a_weighted_sum_solves_as_sparse_lu_both_ways(parts):
    """A complex weighted sum (a dynamic stiffness: K g - omega^2 M), reordered (the closed ring) or not (a chain):
    A x = b and A^T x = b (not conjugated) as SuperLU's, one and several right-hand sides."""
    weights = np.array([1.0 + 0.2j, -0.7])
    summed = banded_sum(parts)
    assert (summed.order is None) == (parts[0].shape[0] == 500)  # the chain is a band already
    matrix = (weights[0] * parts[0] + weights[1] * parts[1]).tocsc()
    rhs = np.random.default_rng(2).standard_normal((matrix.shape[0], 3)) + 1j
    lu, reference = summed.lu(weights), spla.splu(matrix)
    for trans in ("N", "T"):
        np.testing.assert_allclose(lu.solve(rhs, trans), reference.solve(rhs, trans=trans), rtol=1e-11, atol=1e-13)
        np.testing.assert_allclose(lu.solve(rhs[:, 0], trans), reference.solve(rhs[:, 0], trans=trans), rtol=1e-11)


def test_a_matrix_with_no_narrow_band_is_left_to_the_sparse_lu():
    rng = np.random.default_rng(3)
    dense = sp.random_array((200, 200), density=0.2, random_state=rng)
    assert banded_sum([(dense + dense.T).tocsr() + 50 * sp.eye_array(200)]) is None
