"""Element matrices of the FET belt, vectorised over elements.

The belt rings are polygons of straight two-node frame elements in the wheel plane, with three
DOF per node (``ux``, ``uz`` and the rotation ``phi`` about the axle). All functions take
arrays over elements and return ``(n_elements, 6, 6)`` global-coordinate matrices, assembled
with :func:`assemble`.

References: Przemieniecki, *Theory of Matrix Structural Analysis* (1968), ch. 5 and 11
(frame stiffness, consistent mass, geometric stiffness); Hibbitt, "Some follower forces and
load stiffness", IJNME 14 (1979) (pressure load stiffness).
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp


def _rotation(cos: np.ndarray, sin: np.ndarray) -> np.ndarray:
    """Global-to-local transformation ``T`` (n, 6, 6) of 2D frame elements."""
    n = cos.size
    t = np.zeros((n, 6, 6))
    for off in (0, 3):
        t[:, off, off] = cos
        t[:, off, off + 1] = sin
        t[:, off + 1, off] = -sin
        t[:, off + 1, off + 1] = cos
        t[:, off + 2, off + 2] = 1.0
    return t


_BENDING_DOFS = np.array([1, 2, 4, 5])  # w1, phi1, w2, phi2 in the local element frame


def _embed_bending(target: np.ndarray, pattern: np.ndarray, factor: np.ndarray, length: np.ndarray) -> None:
    """Add ``factor * pattern`` scaled by [1, L, 1, L] on rows and columns to the bending DOFs."""
    scale = np.stack([np.ones_like(length), length, np.ones_like(length), length], axis=1)
    block = factor[:, None, None] * pattern[None] * scale[:, :, None] * scale[:, None, :]
    target[:, _BENDING_DOFS[:, None], _BENDING_DOFS[None, :]] += block


def _to_global(local: np.ndarray, cos: np.ndarray, sin: np.ndarray) -> np.ndarray:
    t = _rotation(cos, sin)
    return np.einsum("nji,njk,nkl->nil", t, local, t)


def frame_stiffness(length: np.ndarray, cos: np.ndarray, sin: np.ndarray, ea: np.ndarray, ei: np.ndarray) -> np.ndarray:
    """Euler-Bernoulli frame stiffness (axial ``ea`` in N, bending ``ei`` in N m^2)."""
    L = length
    k = np.zeros((L.size, 6, 6))
    a = ea / L
    k[:, 0, 0] = k[:, 3, 3] = a
    k[:, 0, 3] = k[:, 3, 0] = -a
    bend = np.array([[12, 6, -12, 6], [6, 4, -6, 2], [-12, -6, 12, -6], [6, 2, -6, 4]], dtype=float)
    _embed_bending(k, bend, ei / L**3, L)
    return _to_global(k, cos, sin)


def frame_mass(length: np.ndarray, cos: np.ndarray, sin: np.ndarray, mass_per_length: np.ndarray) -> np.ndarray:
    """Consistent mass of the frame element (``mass_per_length`` in kg/m)."""
    L = length
    m = np.zeros((L.size, 6, 6))
    ax = mass_per_length * L / 6.0
    m[:, 0, 0] = m[:, 3, 3] = 2 * ax
    m[:, 0, 3] = m[:, 3, 0] = ax
    bend = np.array([[156, 22, 54, -13], [22, 4, 13, -3], [54, 13, 156, -22], [-13, -3, -22, 4]], dtype=float)
    _embed_bending(m, bend, mass_per_length * L / 420.0, L)
    return _to_global(m, cos, sin)


def geometric_stiffness(length: np.ndarray, cos: np.ndarray, sin: np.ndarray, tension: np.ndarray) -> np.ndarray:
    """Geometric (pre-stress) stiffness of an element carrying axial ``tension`` (N, > 0 in tension)."""
    L = length
    k = np.zeros((L.size, 6, 6))
    g = np.array([[36, 3, -36, 3], [3, 4, -3, -1], [-36, -3, 36, -3], [3, -1, -3, 4]], dtype=float)
    _embed_bending(k, g, tension / (30.0 * L), L)
    return _to_global(k, cos, sin)


def pressure_load_stiffness(pressure_times_width: np.ndarray) -> np.ndarray:
    """Load stiffness of a follower pressure on the element chord (6x6, global).

    The pressure ``p`` on a strip of width ``b`` pushes each node of the chord ``x2 - x1``
    with ``p b / 2 * J (x2 - x1)``, ``J`` turning the chord (nodes ordered counter-clockwise)
    to its outward normal. The force follows the chord as it turns and stretches; its
    derivative, with a minus sign, is the load stiffness. It is not symmetric per element
    but sums to a symmetric matrix on a closed ring. Without it a tensioned ring is
    spuriously stiff in rigid rotation and in the n >= 2 modes.
    """
    n = pressure_times_width.size
    J = np.array([[0.0, 1.0], [-1.0, 0.0]])
    k = np.zeros((n, 6, 6))
    half = 0.5 * pressure_times_width[:, None, None]
    for row in (0, 3):
        k[:, row : row + 2, 0:2] = half * J  # dF/du1 = -pb/2 J  -> K = +pb/2 J
        k[:, row : row + 2, 3:5] = -half * J
    return k


def spring_matrix(direction: np.ndarray, stiffness: np.ndarray) -> np.ndarray:
    """``k a a^T`` for springs acting on the projections ``a`` (n, m) with stiffness ``k`` (n,)."""
    return stiffness[:, None, None] * direction[:, :, None] * direction[:, None, :]


def assemble(blocks: np.ndarray, dofs: np.ndarray, n_dof: int) -> sp.csr_matrix:
    """Sum element blocks (n, m, m) into a sparse (n_dof, n_dof) matrix at ``dofs`` (n, m)."""
    m = dofs.shape[1]
    rows = np.repeat(dofs, m, axis=1).ravel()
    cols = np.tile(dofs, (1, m)).ravel()
    return sp.coo_matrix((blocks.ravel(), (rows, cols)), shape=(n_dof, n_dof)).tocsr()
