"""Mirror symmetry of the loaded tire, used to solve for the hub force four times faster.

The loaded tire on a flat road or a drum is symmetric fore-aft (x -> -x) and left-right
(y -> -y). The hub's vertical force only sees motions symmetric in both planes, so the
adjoint field :math:`y = D^{-T} K_{hf}^T` of :mod:`roadnoise_utils.tire.ring.frf` lies in the doubly symmetric
subspace. Projecting :math:`D(\\omega)` onto a basis ``T`` of that subspace,
``(T^T D T) y_s = T^T r`` and ``y = T y_s``, is exact (not an approximation) whenever ``D``
commutes with both mirrors; :func:`symmetric_basis` checks that and returns ``None`` when
it does not hold, and the callers then solve the full system.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from .mechanics import PHI, UX, UZ, BeltMesh

#: Relative tolerance of the commutation check.
SYMMETRY_TOLERANCE = 1e-9


def mirror(mesh: BeltMesh, fore_aft: bool) -> sp.csr_matrix:
    """Signed permutation of the belt DOF under x -> -x (``fore_aft``) or y -> -y."""
    ns, ne = mesh.n_strips, mesh.n_elements
    j, k = np.meshgrid(np.arange(ns), np.arange(ne), indexing="ij")
    j, k = j.ravel(), k.ravel()
    if fore_aft:
        j2, k2 = j, (ne - k) % ne
        signs = {UX: -1.0, UZ: 1.0, PHI: -1.0}  # in-plane rotation changes sense in the mirror
    else:
        j2, k2 = ns - 1 - j, k
        signs = {UX: 1.0, UZ: 1.0, PHI: 1.0}
    rows, cols, vals = [], [], []
    for c, s in signs.items():
        rows.append(mesh.dof(j2, k2, c))
        cols.append(mesh.dof(j, k, c))
        vals.append(np.full(j.size, s))
    n = mesh.n_belt_dof
    return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n, n))


def _commutes(mirror: sp.csr_matrix, matrix: sp.spmatrix) -> bool:
    diff = mirror @ matrix @ mirror.T - matrix
    scale = max(abs(matrix).max(), 1e-300)
    return diff.nnz == 0 or abs(diff).max() <= SYMMETRY_TOLERANCE * scale


def symmetric_basis(
    mesh: BeltMesh, matrices: list[sp.spmatrix], vectors: list[np.ndarray], fore_aft: bool = True
) -> sp.csr_matrix | None:
    """Basis (n_belt_dof, n_sym) of the doubly mirror-symmetric belt motions, or ``None``.

    ``matrices`` (belt DOF) must commute with both mirrors and ``vectors`` be invariant for
    the reduction to be exact; otherwise ``None`` is returned. With ``fore_aft=False`` only the
    left-right mirror is used (half the DOF, both fore-aft parities): the basis of a problem that
    is symmetric left-right only, as the tire whose cavity's air streams through the footprint.
    """
    mirrors = [mirror(mesh, False)] + ([mirror(mesh, True)] if fore_aft else [])
    for m in mirrors:
        if not all(_commutes(m, a) for a in matrices):
            return None
        for v in vectors:
            if np.max(np.abs(m @ v - v)) > SYMMETRY_TOLERANCE * max(np.max(np.abs(v)), 1e-300):
                return None
    eye = sp.identity(mesh.n_belt_dof, format="csr")
    projector = 0.5 * (eye + mirrors[0])
    if fore_aft:
        projector = 0.5 * projector @ (eye + mirrors[1])
    ns, ne = mesh.n_strips, mesh.n_elements
    j, k = np.meshgrid(np.arange((ns + 1) // 2), np.arange(ne // 2 + 1 if fore_aft else ne), indexing="ij")
    reps = np.concatenate([mesh.dof(j, k, c).ravel() for c in (UX, UZ, PHI)])
    basis = projector[:, np.sort(reps)].tocsc()
    keep = np.diff(basis.indptr) > 0
    basis = basis[:, np.nonzero(keep)[0]]
    basis.eliminate_zeros()
    keep = np.asarray(abs(basis).sum(axis=0)).ravel() > 0
    return basis[:, np.nonzero(keep)[0]].tocsr()
