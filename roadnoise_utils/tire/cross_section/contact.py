"""Contact of the cross-section tire: Green's functions from the harmonic sum, one-sided contact.

The tread surface meets the road on a grid of contact points: the tread-surface nodes across
the crown (columns, <= 5 mm apart) times points along the circumference every
``[mesh] contact_spacing`` (rows, <= 3 mm). Each point stands for an arc of one spacing, so a
contact force is spread over it and a displacement is its mean over it; the flexibility between
two points is the harmonic sum (Kropp 1992; Wullens & Kropp, Acta Acustica 90, 2004)

.. math:: G(\\theta_a - \\theta_b) = \\sum_{n=0}^{N} s_n\\, F_n \\circ P(n\\,\\Delta\\theta),
          \\qquad s_n = \\mathrm{sinc}^2(n\\,\\Delta\\theta_p / 2),

with :math:`F_n = K_n^{-1}` restricted to the contact nodes' ``r, theta`` DOF and ``P`` the
trigonometric pattern of the symmetric and antisymmetric sets: ``cos`` for ``rr`` and
``tt``, ``-sin`` for ``rt`` (radial response to a tangential force) and ``+sin`` for ``tr``.
The vertical compliance of the points follows by projecting on ``e_z``. Contact is vertical and
frictionless while loading, solved with the same primal active set as the ring model
(:func:`.active_set.active_set`); the tire is linear about its inflated state.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
import scipy.sparse.linalg as spla

from .geometry import Meridian
from .mesh import SectionMesh
from .operators import HarmonicOperators
from .waveguide import lagrange3

#: Candidate contact points lie within this arc of the bottom of the tire (m along the tread).
CANDIDATE_HALF_LENGTH = 0.11


@dataclass(frozen=True, eq=False)
class ContactGrid:
    """Contact points of the tread surface: ``columns`` across by ``rows`` along.

    Attributes
    ----------
    nodes : ndarray of int (n_cols,)
        Tread-surface nodes of the crown (outer node row), left to right.
    y, radius : ndarray (n_cols,)
        Lateral position and radius of each column (m).
    width : ndarray (n_cols,)
        Consistent tributary width of each node, :math:`\\int N_a\\,ds` over the face (m).
    theta : ndarray (n_rows,)
        Angles of the rows from the bottom of the tire (rad), symmetric about 0.
    dtheta : float
        Angular spacing of the rows (rad).
    """

    nodes: np.ndarray
    y: np.ndarray
    radius: np.ndarray
    width: np.ndarray
    theta: np.ndarray
    dtheta: float

    @property
    def n_cols(self) -> int:
        return self.nodes.size

    @property
    def n_rows(self) -> int:
        return self.theta.size

    @property
    def dofs(self) -> np.ndarray:
        """``r`` DOF of the columns then their ``theta`` DOF (2 n_cols,)."""
        return np.concatenate([3 * self.nodes, 3 * self.nodes + 1])

    def xz(self) -> tuple[np.ndarray, np.ndarray]:
        """Undeformed point coordinates ``x, z`` (m), each (n_cols, n_rows)."""
        r = self.radius[:, None]
        return r * np.sin(self.theta)[None, :], -r * np.cos(self.theta)[None, :]

    def area(self) -> np.ndarray:
        """Tread-surface area of each point (m^2), (n_cols, n_rows)."""
        return np.broadcast_to((self.width * self.radius * self.dtheta)[:, None], (self.n_cols, self.n_rows))


def contact_grid(mesh: SectionMesh, line: Meridian, spacing: float, outer_radius: float) -> ContactGrid:
    """The contact grid of a meshed tire (see the module notes)."""
    top = mesh.n_rows - 1
    stations = np.nonzero(line.crown)[0]
    nodes = mesh.node(stations, top)
    # consistent tributary width: integral of each quadratic face shape function along the face
    width = np.zeros(mesh.n_nodes)
    xg, wg = np.polynomial.legendre.leggauss(3)
    shape, d_xi = lagrange3(xg)
    for line_nodes in mesh.face_lines(top):
        ds = np.hypot(d_xi.T @ mesh.r[line_nodes], d_xi.T @ mesh.y[line_nodes])
        width[line_nodes] += shape @ (wg * ds)
    # the edge nodes of the crown also carry the shoulder side of their element: keep the crown side
    crown_width = width[nodes].copy()
    for end, inner in ((0, 1), (-1, -2)):
        crown_width[end] = 0.5 * crown_width[inner] * 0.5  # a corner node's crown share: L/6 = (2L/3) / 4
    dtheta = spacing / outer_radius
    m = int(np.ceil(CANDIDATE_HALF_LENGTH / spacing))
    return ContactGrid(
        nodes=nodes,
        y=mesh.y[nodes],
        radius=mesh.r[nodes],
        width=crown_width,
        theta=dtheta * np.arange(-m, m + 1),
        dtheta=dtheta,
    )


def extended_grid(grid: ContactGrid, half_length: float) -> tuple[ContactGrid, int]:
    """The grid with rows out to ``half_length`` (m along the tread) each side, and how many rows it adds per side.

    The static footprint needs rows to :data:`CANDIDATE_HALF_LENGTH`; a cleat on a drum meets the
    tread farther ahead (a 15 mm cleat on the 1.25 m drum about 105 mm ahead of the axle).
    """
    m = (grid.n_rows - 1) // 2
    wanted = int(np.ceil(half_length / (grid.dtheta * grid.radius.max())))
    if wanted <= m:
        return grid, 0
    theta = grid.dtheta * np.arange(-wanted, wanted + 1)
    return replace(grid, theta=theta), wanted - m


def harmonic_flexibility(
    ops: HarmonicOperators, dofs: np.ndarray, harmonics: int, omega: float = 0.0, storage_only: bool = True
) -> np.ndarray:
    """:math:`F_n = K_n(\\omega)^{-1}` at ``dofs`` for ``n = 0..harmonics``, beads clamped, (N + 1, d, d)."""
    free = ops.free
    position = np.searchsorted(free, dofs)
    if not np.array_equal(free[position], dofs):
        raise ValueError("contact DOF must not be clamped")
    rhs = np.zeros((free.size, dofs.size))
    rhs[position, np.arange(dofs.size)] = 1.0
    out = np.empty((harmonics + 1, dofs.size, dofs.size), dtype=float if storage_only else complex)
    for n in range(harmonics + 1):
        k = ops.free_stiffness(n, omega, storage_only=storage_only)
        out[n] = spla.splu(k).solve(rhs.astype(k.dtype))[position]
    return out


def patch_factor(n: np.ndarray, dtheta: float) -> np.ndarray:
    """:math:`\\mathrm{sinc}^2(n\\,\\Delta\\theta/2)`: a force spread over one arc, a displacement averaged over one."""
    return np.sinc(np.asarray(n) * dtheta / (2 * np.pi)) ** 2


def angular_sums(flex: np.ndarray, offsets: np.ndarray, dtheta: float) -> np.ndarray:
    """Flexibility between columns at angular offsets, (n_offsets, 2 c, 2 c) in ``(r, theta)`` blocks.

    ``offsets`` are angles ``theta_response - theta_force`` (rad).
    """
    n = np.arange(flex.shape[0])
    weight = patch_factor(n, dtheta)[None, :]
    cos = np.cos(np.outer(offsets, n)) * weight
    sin = np.sin(np.outer(offsets, n)) * weight
    c = flex.shape[1] // 2
    flat = flex.reshape(flex.shape[0], -1)
    even = (cos @ flat).reshape(-1, 2 * c, 2 * c)
    odd = (sin @ flat).reshape(-1, 2 * c, 2 * c)
    out = even.copy()
    out[:, :c, c:] = -odd[:, :c, c:]  # radial response to a tangential force
    out[:, c:, :c] = odd[:, c:, :c]
    return out


def vertical_compliance(grid: ContactGrid, flex: np.ndarray) -> np.ndarray:
    """Vertical compliance between all contact points (m/N), (P, P) with P = n_cols * n_rows, column-major.

    Point ``(j, a)`` (column ``j``, row ``a``) has flat index ``j * n_rows + a``.
    """
    rows = grid.n_rows
    offsets = grid.dtheta * np.arange(-(rows - 1), rows)
    sums = angular_sums(flex, offsets, grid.dtheta)
    c = grid.n_cols
    a = np.arange(rows)
    k = a[:, None] - a[None, :] + rows - 1  # offset index of (response a, force b)
    block = sums[k]  # (rows, rows, 2c, 2c)
    th = grid.theta
    ca, sa = np.cos(th)[:, None], np.sin(th)[:, None]
    cb, sb = np.cos(th)[None, :], np.sin(th)[None, :]
    # u_z = -cos(a) u_r + sin(a) u_t; force F_z: f_r = -cos(b) F, f_t = sin(b) F
    rr, rt = block[:, :, :c, :c], block[:, :, :c, c:]
    tr, tt = block[:, :, c:, :c], block[:, :, c:, c:]
    comp = (
        (ca * cb)[:, :, None, None] * rr
        - (ca * sb)[:, :, None, None] * rt
        - (sa * cb)[:, :, None, None] * tr
        + (sa * sb)[:, :, None, None] * tt
    )  # (a, b, j, k)
    return np.transpose(comp, (2, 0, 3, 1)).reshape(c * rows, c * rows)
