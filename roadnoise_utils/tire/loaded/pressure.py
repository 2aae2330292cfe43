"""The inflation pressure on the loaded tire's inner surface: an exact follower load.

The pressure ``p`` acts on the current inner surface, normal to it: on node ``a``,

.. math:: f_a = p\\int N_a\\,(x_{,\\xi}\\times x_{,\\zeta})\\,d\\xi\\,d\\zeta,

with ``x = X + u`` the current position on each 9-node face (quadratic along the meridian ``xi``
and around the arc ``zeta``). Its derivative, the load stiffness (Hibbitt, *Int. J. Numer. Meth.
Eng.* 14, 1979; Schweizerhof & Ramm, *J. Eng. Mech.* 110, 1984), is

.. math:: \\frac{\\partial f_a}{\\partial u_b} = p\\int N_a\\,\\big(N_{b,\\zeta}[x_{,\\xi}]_\\times
          - N_{b,\\xi}[x_{,\\zeta}]_\\times\\big)\\,d\\xi\\,d\\zeta.

With the beads held on the rim the load is conservative: ``f = p dV/du`` for the volume ``V``
enclosed by the inner surface, the rim and the axle,
:math:`V = \\tfrac12\\int Px\\cdot(x_{,\\xi}\\times x_{,\\zeta})\\,d\\xi\\,d\\zeta` (``P`` the
projection normal to the axle, as the waveguide tire's cavity: its flanks at the beads are
planes normal to the axle, on which ``Px . n = 0``), and the load stiffness is symmetric.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

from ..cross_section.waveguide import lagrange3
from .mesh import SolidMesh

_GAUSS3 = np.polynomial.legendre.leggauss(3)


@dataclass(frozen=True, eq=False)
class InnerSurface:
    """The inner surface as 9-node faces with their integration points.

    Attributes
    ----------
    faces : ndarray of int (n_f, 9)
        Nodes, local ``3 c + a``: ``a`` along the meridian, ``c`` around the arc.
    shape, d_xi, d_zeta : ndarray (q, 9)
        Shape functions and parent derivatives at the 3 x 3 Gauss points of a face.
    weight : ndarray (q,)
    sign : float
        +1 or -1: the orientation that points ``x_xi x x_zeta`` out of the cavity.
    """

    faces: np.ndarray
    shape: np.ndarray
    d_xi: np.ndarray
    d_zeta: np.ndarray
    weight: np.ndarray
    sign: float

    @property
    def dofs(self) -> np.ndarray:
        """Global DOF (n_f, 27) of each face, column ``3 a + i``."""
        return (3 * self.faces[:, :, None] + np.arange(3)).reshape(-1, 27)


def inner_surface(mesh: SolidMesh) -> InnerSurface:
    """The faces of the section's inner node row swept around every arc, oriented out of the cavity."""
    lines = mesh.section.face_lines(0)  # (E, 3) section nodes along the inner face
    n_rings = mesh.theta.size
    arcs = np.arange(mesh.n_arcs)
    rings = (2 * arcs[:, None] + np.arange(3)) % n_rings  # (n_arcs, 3)
    faces = (rings[:, None, :, None] * mesh.section.n_nodes + lines[None, :, None, :]).reshape(-1, 9)
    x, wx = _GAUSS3
    n, d = lagrange3(x)  # (3 nodes, 3 points)
    # point 3 i + k (i along xi, k along zeta), node 3 c + a (c around the arc, a along the meridian)
    shape = np.einsum("ai,ck->ikca", n, n).reshape(9, 9)
    d_xi = np.einsum("ai,ck->ikca", d, n).reshape(9, 9)
    d_zeta = np.einsum("ai,ck->ikca", n, d).reshape(9, 9)
    weight = np.outer(wx, wx).ravel()
    surface = InnerSurface(faces=faces, shape=shape, d_xi=d_xi, d_zeta=d_zeta, weight=weight, sign=1.0)
    radial = mesh.coordinates * np.array([1.0, 0.0, 1.0])
    outward = pressure_load(mesh, surface, np.zeros(mesh.n_dof), 1.0) @ radial.ravel()
    return InnerSurface(faces=faces, shape=shape, d_xi=d_xi, d_zeta=d_zeta, weight=weight, sign=np.sign(outward))


def _tangents(mesh: SolidMesh, surface: InnerSurface, u: np.ndarray):
    x = mesh.coordinates[surface.faces] + u[surface.dofs].reshape(-1, 9, 3)  # (n_f, 9, 3)
    return (
        x,
        np.einsum("qa,fai->fqi", surface.d_xi, x),
        np.einsum("qa,fai->fqi", surface.d_zeta, x),
    )


def pressure_load(mesh: SolidMesh, surface: InnerSurface, u: np.ndarray, pressure: float) -> np.ndarray:
    """Nodal forces (n_dof,) of ``pressure`` (Pa) on the inner surface displaced by ``u``."""
    _, x_xi, x_zeta = _tangents(mesh, surface, u)
    normal = np.cross(x_xi, x_zeta) * (surface.sign * pressure * surface.weight)[None, :, None]
    force = np.zeros(mesh.n_dof)
    np.add.at(force, surface.dofs, np.einsum("qa,fqi->fai", surface.shape, normal).reshape(-1, 27))
    return force


def face_points(mesh: SolidMesh, surface: InnerSurface, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The inner surface displaced by ``u`` at its faces' integration points: their positions (n_f, q, 3)
    and their area vectors out of the cavity times the points' weights (n_f, q, 3; m^2): a pressure
    field ``p`` puts :math:`\\sum_q p_q N_a(q)\\,a_q` on node ``a`` (:func:`pressure_load` for a uniform one)."""
    x, x_xi, x_zeta = _tangents(mesh, surface, u)
    position = np.einsum("qa,fai->fqi", surface.shape, x)
    return position, np.cross(x_xi, x_zeta) * (surface.sign * surface.weight)[None, :, None]


def _skew(v: np.ndarray) -> np.ndarray:
    """``[v]x`` (..., 3, 3): ``[v]x w = v x w``."""
    z = np.zeros(v.shape[:-1])
    return np.stack(
        [
            np.stack([z, -v[..., 2], v[..., 1]], -1),
            np.stack([v[..., 2], z, -v[..., 0]], -1),
            np.stack([-v[..., 1], v[..., 0], z], -1),
        ],
        -2,
    )


def pressure_stiffness(mesh: SolidMesh, surface: InnerSurface, u: np.ndarray, pressure: float) -> sp.csr_matrix:
    """:math:`\\partial f / \\partial u` (sparse, N/m) of :func:`pressure_load`: the load stiffness with its sign."""
    _, x_xi, x_zeta = _tangents(mesh, surface, u)
    scale = surface.sign * pressure * surface.weight
    blocks = np.einsum("qa,qb,fqij,q->faibj", surface.shape, surface.d_zeta, _skew(x_xi), scale) - np.einsum(
        "qa,qb,fqij,q->faibj", surface.shape, surface.d_xi, _skew(x_zeta), scale
    )
    blocks = blocks.reshape(-1, 27, 27)
    dofs = surface.dofs
    rows = np.broadcast_to(dofs[:, :, None], blocks.shape).ravel()
    cols = np.broadcast_to(dofs[:, None, :], blocks.shape).ravel()
    return sp.csr_matrix((blocks.ravel(), (rows, cols)), shape=(mesh.n_dof, mesh.n_dof))


def cavity_volume(mesh: SolidMesh, surface: InnerSurface, u: np.ndarray) -> float:
    """Volume (m^3) enclosed by the inner surface displaced by ``u``, the rim and the axle (beads held)."""
    x, x_xi, x_zeta = _tangents(mesh, surface, u)
    position = np.einsum("qa,fai->fqi", surface.shape, x) * np.array([1.0, 0.0, 1.0])
    return float(0.5 * surface.sign * np.einsum("fqi,fqi,q->", position, np.cross(x_xi, x_zeta), surface.weight))
