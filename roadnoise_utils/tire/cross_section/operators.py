"""The cross-section FE tire: harmonic matrices about the inflated state.

:func:`harmonic_operators` integrates the element matrices of a :class:`.SectionMesh` once, as
polynomials in the harmonic number ``n`` (:mod:`roadnoise_utils.tire.cross_section.waveguide`), solves the inflation (``n = 0``,
beads clamped, linear) for the pre-stress and returns a :class:`HarmonicOperators` from which
any harmonic's stiffness and mass cost a few sparse additions:

.. math:: K_n(\\omega) = w_n\\Big[\\sum_c g_c(\\omega)\\,K_c(n) + g_p(\\omega)\\,K_{pn}(n)\\Big],
          \\qquad K_{pn} = K_\\sigma - p\\,H,\\qquad M_n = w_n M.

``K_pn`` is the *pneumatic* stiffness: the geometric stiffness of the inflation pre-stress
``K_sigma`` and the follower-pressure load stiffness ``-p H``, always together (each alone
resists rigid rotations; together they do not). Its law ``g_p`` is the modelling choice of the
tire file's ``[pneumatic] compound``: ``"none"`` keeps it lossless (``g_p = 1``), a compound
name (the carcass) gives it that law — the ring model's pneumatic foundation: the
cord plies that carry the pressure flex as the tire deforms and their rubber matrix shears
between the cords. It is a model of a loss the linear layers do not produce, not a material
property; notebook 09 shows both.

The inflation pre-stress comes from a *linear* solve of the layered solid under the pressure,
about the given (inflated) geometry: it carries the membrane forces of the cord layers (the
membrane solution of the inflated torus, checked in the tests) without the geometric
nonlinearity of inflating from the moulded shape.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ..rubber import FractionalZener
from .mesh import SectionMesh
from .waveguide import (
    assemble_points,
    element_dofs,
    gradient_operators,
    harmonic_weight,
    point_geometry,
    pressure_operators,
    strain_operators,
)


@dataclass(frozen=True, eq=False)
class HarmonicOperators:
    """Harmonic stiffness and mass of a cross-section tire, per radian, as polynomials in ``n``.

    Attributes
    ----------
    mesh : SectionMesh
    elastic : dict of str to tuple of 3 csr_matrix
        ``(K0, K1, K2)`` of each compound at its static modulus (N/m per radian).
    geometric : tuple of 3 csr_matrix
        Geometric stiffness of the inflation pre-stress, same form.
    pressure : tuple of 2 csr_matrix
        Load stiffness of the follower pressure, ``-p (H0 + n H1)``.
    mass : csr_matrix
        Consistent mass per radian (kg).
    fixed : ndarray of int
        DOF clamped to the rim (all DOF of the bead stations).
    laws : dict of str to FractionalZener
    pressure_value : float
        Inflation pressure (Pa).
    inflation : ndarray (n_dof,)
        Displacement of the inflation solve (m), ``n = 0``.
    stress : ndarray (q, 6)
        Inflation pre-stress at the quadrature points (Pa), Voigt ``[rr, tt, yy, ty, ry, rt]``.
    pneumatic_law : str or None
        Compound whose law scales the pneumatic stiffness; ``None``: lossless.
    """

    mesh: SectionMesh
    elastic: dict[str, tuple[sp.csr_matrix, sp.csr_matrix, sp.csr_matrix]]
    geometric: tuple[sp.csr_matrix, sp.csr_matrix, sp.csr_matrix]
    pressure: tuple[sp.csr_matrix, sp.csr_matrix]
    mass: sp.csr_matrix
    fixed: np.ndarray
    laws: dict[str, FractionalZener]
    pressure_value: float
    inflation: np.ndarray
    stress: np.ndarray
    pneumatic_law: str | None = None

    @property
    def n_dof(self) -> int:
        return self.mesh.n_dof

    @property
    def free(self) -> np.ndarray:
        """DOF not clamped to the rim."""
        return np.setdiff1d(np.arange(self.n_dof), self.fixed)

    @cached_property
    def _pattern(self) -> _SharedPattern:
        """Every operator's entries on one sparsity pattern (see :class:`_SharedPattern`)."""
        bases = {("mass",): self.mass}
        for name, blocks in self.elastic.items():
            bases.update({("elastic", name, p): block for p, block in enumerate(blocks)})
        bases.update({("geometric", p): block for p, block in enumerate(self.geometric)})
        bases.update({("pressure", p): block for p, block in enumerate(self.pressure)})
        return _SharedPattern(bases, self.free)

    def _pneumatic_data(self, n: int) -> np.ndarray:
        d = self._pattern.data
        k0, k1, k2 = (d["geometric", p] for p in range(3))
        return k0 + d["pressure", 0] + n * (k1 + d["pressure", 1]) + n * n * k2

    def _gas_data(self, n: int) -> np.ndarray:
        return self._pneumatic_data(n) if self.pneumatic_law is None else np.zeros(self._pattern.nnz)

    def _compound_data(self, name: str, n: int) -> np.ndarray:
        d = self._pattern.data
        total = (
            (d["elastic", name, 0] + n * d["elastic", name, 1] + n * n * d["elastic", name, 2])
            if (name in self.elastic)
            else np.zeros(self._pattern.nnz)
        )
        return total + self._pneumatic_data(n) if name == self.pneumatic_law else total

    def _stiffness_data(self, n: int, omega: float, storage_only: bool) -> np.ndarray:
        total = self._gas_data(n).astype(float if storage_only else complex)
        for name in self.scaled:
            g = complex(self.laws[name].ratio(omega))
            total = total + (g.real if storage_only else g) * self._compound_data(name, n)
        return harmonic_weight(n) * total

    def pneumatic(self, n: int) -> sp.csr_matrix:
        """Pneumatic stiffness at harmonic ``n``, pre-stress and pressure load together (without ``w_n``)."""
        return self._pattern.matrix(self._pneumatic_data(n))

    def gas(self, n: int) -> sp.csr_matrix:
        """Lossless stiffness at harmonic ``n`` (without ``w_n``): the pneumatic stiffness unless a law scales it."""
        return self._pattern.matrix(self._gas_data(n))

    @property
    def scaled(self) -> tuple[str, ...]:
        """Compounds whose laws scale a part of the stiffness (the layers', and the pneumatic law)."""
        names = tuple(self.elastic)
        return names if self.pneumatic_law in (None, *names) else (*names, self.pneumatic_law)

    def layers(self, name: str, n: int) -> sp.csr_matrix:
        """Elastic stiffness of one compound's layers at harmonic ``n`` (without ``w_n``); zero if it has none."""
        if name not in self.elastic:
            return sp.csr_matrix(self.mass.shape)
        d = self._pattern.data
        return self._pattern.matrix(d["elastic", name, 0] + n * d["elastic", name, 1] + n * n * d["elastic", name, 2])

    def compound(self, name: str, n: int) -> sp.csr_matrix:
        """Static stiffness scaled by one compound's law at harmonic ``n`` (without ``w_n``)."""
        return self._pattern.matrix(self._compound_data(name, n))

    def stiffness(self, n: int, omega: float = 0.0, storage_only: bool = False) -> sp.csr_matrix:
        """``K_n(omega)`` (N/m), all DOF, weight ``w_n`` included; complex unless ``storage_only``."""
        return self._pattern.matrix(self._stiffness_data(n, omega, storage_only))

    def mass_matrix(self, n: int) -> sp.csr_matrix:
        """``M_n`` (kg), weight ``w_n`` included."""
        return self._pattern.matrix(harmonic_weight(n) * self._pattern.data["mass",])

    # the same on the free DOF (rim clamped), without slicing a sparse matrix each time

    def free_stiffness(self, n: int, omega: float = 0.0, storage_only: bool = False) -> sp.csc_matrix:
        """``K_n(omega)`` on the free DOF (:attr:`free`), CSC."""
        return self._pattern.free_matrix(self._stiffness_data(n, omega, storage_only))

    def free_mass(self, n: int) -> sp.csc_matrix:
        """``M_n`` on the free DOF, CSC."""
        return self._pattern.free_matrix(harmonic_weight(n) * self._pattern.data["mass",])

    def free_compound(self, name: str, n: int) -> sp.csc_matrix:
        """:meth:`compound` on the free DOF, CSC (without ``w_n``)."""
        return self._pattern.free_matrix(self._compound_data(name, n))

    def free_gas(self, n: int) -> sp.csc_matrix:
        """:meth:`gas` on the free DOF, CSC (without ``w_n``)."""
        return self._pattern.free_matrix(self._gas_data(n))


class _SharedPattern:
    """Sparse operators of one mesh on the union of their sparsity patterns (CSR, sorted).

    Every operator's entries are stored aligned to the union, so a harmonic's stiffness is a
    weighted sum of a few dense vectors and one matrix construction, instead of a dozen sparse
    additions; the free-DOF block (rim clamped) keeps its own row and column index once found.
    """

    def __init__(self, bases: dict[tuple, sp.spmatrix], free: np.ndarray):
        shape = next(iter(bases.values())).shape
        union = sum((abs(sp.csr_matrix(b)) for b in bases.values()), sp.csr_matrix(shape)).tocsr()
        union.sort_indices()
        rows = np.repeat(np.arange(shape[0]), np.diff(union.indptr))
        keys = rows.astype(np.int64) * shape[1] + union.indices
        self.shape, self.indptr, self.indices, self.nnz = shape, union.indptr, union.indices, union.nnz
        self.data = {}
        for name, base in bases.items():
            coo = sp.coo_matrix(base)
            stored = coo.data != 0  # explicitly stored zeros are not in the union (a sum drops them)
            row, col, value = coo.row[stored], coo.col[stored], coo.data[stored]
            aligned = np.zeros(union.nnz, np.result_type(coo.data, float))
            np.add.at(aligned, np.searchsorted(keys, row.astype(np.int64) * shape[1] + col), value)
            self.data[name] = aligned
        position = np.full(shape[0], -1)
        position[free] = np.arange(free.size)
        keep = np.nonzero((position[rows] >= 0) & (position[union.indices] >= 0))[0]
        self.free_take = keep
        free_rows, free_cols = position[rows[keep]], position[union.indices[keep]]
        self.free_shape = (free.size, free.size)
        self.free_indptr = np.concatenate([[0], np.cumsum(np.bincount(free_rows, minlength=free.size))])
        self.free_indices = free_cols

    def matrix(self, data: np.ndarray) -> sp.csr_matrix:
        """The operator with entries ``data`` (aligned to the union), all DOF."""
        return sp.csr_matrix((data, self.indices, self.indptr), shape=self.shape)

    def free_matrix(self, data: np.ndarray) -> sp.csc_matrix:
        """Its free-DOF block, CSC."""
        block = sp.csr_matrix((data[self.free_take], self.free_indices, self.free_indptr), shape=self.free_shape)
        return block.tocsc()


def _polynomial_blocks(b0: np.ndarray, b1: np.ndarray, weight: np.ndarray, middle: np.ndarray) -> tuple:
    """Per-point ``(B0' D B0, B0' D B1 + B1' D B0, B1' D B1) * weight`` for operators (q, m, 27)."""
    d_b0 = np.einsum("qij,qjb->qib", middle, b0)
    d_b1 = np.einsum("qij,qjb->qib", middle, b1)
    k0 = np.einsum("qia,qib->qab", b0, d_b0)
    k1 = np.einsum("qia,qib->qab", b0, d_b1)
    k2 = np.einsum("qia,qib->qab", b1, d_b1)
    w = weight[:, None, None]
    return k0 * w, (k1 + np.transpose(k1, (0, 2, 1))) * w, k2 * w


def harmonic_operators(
    mesh: SectionMesh,
    laws: dict[str, FractionalZener],
    inflation_pressure: float,
    fixed: np.ndarray | None = None,
    prestress: np.ndarray | None = None,
    pneumatic_law: str | None = None,
) -> HarmonicOperators:
    """Integrate the harmonic matrices and the inflation pre-stress of a cross-section mesh.

    Parameters
    ----------
    mesh : SectionMesh
    laws : dict of str to FractionalZener
        Modulus law of every compound named by the mesh's plies.
    inflation_pressure : float
        Pa, on the inner face (node row 0).
    fixed : ndarray of int, optional
        DOF clamped to the rim; default every DOF of the two bead stations.
    prestress : ndarray (q, 6), optional
        A given pre-stress (Pa) instead of the inflation solve (verification of thin rings).
    pneumatic_law : str, optional
        Compound whose law scales the pneumatic stiffness (see the module notes); lossless if None.
    """
    missing = sorted((set(mesh.points.compounds) | ({pneumatic_law} - {None})) - set(laws))
    if missing:
        raise ValueError(f"no modulus law for compound(s) {missing}")
    pts = mesh.points
    geo = point_geometry(mesh.r, mesh.y, mesh.elements, pts)
    dofs = element_dofs(mesh.elements)
    n_dof = mesh.n_dof
    bc, bn = strain_operators(geo)
    elastic = {}
    for index, name in enumerate(pts.compounds):
        sel = pts.compound == index
        blocks = _polynomial_blocks(bc[sel], bn[sel], geo.volume[sel], pts.stiffness[sel])
        elastic[name] = tuple(assemble_points(b, pts.element[sel], dofs, n_dof) for b in blocks)
    shape = np.zeros((geo.shape.shape[0], 3, 27))
    for c in range(3):
        shape[:, c, c::3] = geo.shape
    mass = assemble_points(
        np.einsum("qia,qib->qab", shape, shape) * (pts.density * geo.volume)[:, None, None], pts.element, dofs, n_dof
    )
    if fixed is None:
        fixed = (3 * mesh.bead_nodes[:, None] + np.arange(3)).ravel()
    fixed = np.unique(np.asarray(fixed, int))
    dv, h0, h1 = pressure_operators(mesh.r, mesh.y, mesh.face_lines(0), n_dof)
    if prestress is None:
        inflation, stress = _inflate(elastic, dv, fixed, bc, dofs, pts, inflation_pressure, n_dof)
    else:
        inflation, stress = np.zeros(n_dof), np.asarray(prestress, float)
    geometric = _geometric_stiffness(geo, stress, pts.element, dofs, n_dof)
    p = inflation_pressure
    return HarmonicOperators(
        mesh=mesh,
        elastic=elastic,
        geometric=geometric,
        pressure=(-p * h0, -p * h1),
        mass=mass,
        fixed=fixed,
        laws=dict(laws),
        pressure_value=p,
        inflation=inflation,
        stress=stress,
        pneumatic_law=pneumatic_law,
    )


def _inflate(elastic, dv, fixed, bc, dofs, pts, pressure, n_dof):
    """Linear inflation solve at ``n = 0`` (beads clamped); displacement and point stresses."""
    k = sum(parts[0] for parts in elastic.values()) * harmonic_weight(0)
    free = np.setdiff1d(np.arange(n_dof), fixed)
    load = pressure * harmonic_weight(0) * dv
    u = np.zeros(n_dof)
    u[free] = spla.spsolve(k[free][:, free].tocsc(), load[free])
    strain = np.einsum("qib,qb->qi", bc, u[dofs[pts.element]])
    return u, np.einsum("qij,qj->qi", pts.stiffness, strain)


def _geometric_stiffness(geo, stress, element, dofs, n_dof):
    """``(K0, K1, K2)`` of the initial-stress energy 1/2 sigma_ij u_k,i u_k,j (per radian)."""
    s = np.zeros((stress.shape[0], 3, 3))
    voigt = ((0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1))
    for col, (i, j) in enumerate(voigt):
        s[:, i, j] = s[:, j, i] = stress[:, col]
    gc, gn = gradient_operators(geo)
    parts = [np.zeros((stress.shape[0], 27, 27)) for _ in range(3)]
    for k in range(3):
        blocks = _polynomial_blocks(gc[:, k], gn[:, k], geo.volume, s)
        for part, block in zip(parts, blocks):
            part += block
    return tuple(assemble_points(part, element, dofs, n_dof) for part in parts)
