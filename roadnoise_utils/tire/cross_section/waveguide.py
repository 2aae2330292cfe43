"""Waveguide (2.5-D) finite elements: the cross-section in 9-node solids, Fourier harmonics around.

The tire is a solid of revolution about the axle (axis ``y``). Its cross-section (the meridian
plane ``r, y``) is meshed with 9-node Lagrange quadrilaterals; around the circumference the
displacement is a Fourier series, each harmonic ``n`` decoupled from the others because the
structure does not change with ``theta`` (Zienkiewicz & Taylor, *The Finite Element Method*,
vol. 1, ch. 9 "semi-analytical"; for tires Nilsson 2006, Fraggstedt 2006, Waki, Mace & Brennan
JSV 327 (2009)). With ``theta`` measured from the bottom of the tire, the symmetric set is

.. math:: u_r = a_r \\cos n\\theta,\\quad u_\\theta = a_\\theta \\sin n\\theta,\\quad u_y = a_y \\cos n\\theta

and the antisymmetric set (``sin``, ``-cos``, ``sin``) has the same matrices when every layer is
orthotropic in ``(r, theta, y)`` (:mod:`roadnoise_utils.tire.cross_section.laminate`). Strains (engineering, Voigt
``[rr, tt, yy, ty, ry, rt]``) are ``B = B_c + n B_n`` with the trigonometric factors dropped;
each row carries a single factor (``cos`` or ``sin``), so the circumferential integral is
``w_n = 2 pi`` for ``n = 0`` and ``pi`` otherwise, and every matrix is a polynomial in ``n``:

.. math:: K_n = w_n (K^{(0)} + n K^{(1)} + n^2 K^{(2)}).

Three kinds of stiffness: elastic (per compound, scaled by :math:`g_c(\\omega)`); geometric,
from the inflation pre-stress :math:`\\sigma^0`, energy
:math:`\\tfrac12 \\int \\sigma^0_{ij} u_{k,i} u_{k,j}\\,dV`; and the load stiffness of the
follower inflation pressure, :math:`-p\\,\\partial^2 V/\\partial u^2` with ``V`` the volume enclosed
by the inner surface and the rim (Hibbitt 1979; Schweizerhof & Ramm 1984).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp

DOF_PER_NODE = 3
R, T, Y = 0, 1, 2  # displacement components u_r, u_theta, u_y

_GAUSS3 = np.polynomial.legendre.leggauss(3)


def lagrange3(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Quadratic Lagrange shape functions on ``[-1, 1]`` (nodes -1, 0, 1) and derivatives, (3, m)."""
    x = np.asarray(x, float)
    n = np.stack([0.5 * x * (x - 1), 1 - x**2, 0.5 * x * (x + 1)])
    d = np.stack([x - 0.5, -2 * x, x + 0.5])
    return n, d


@dataclass(frozen=True, eq=False)
class QuadraturePoints:
    """Integration points of all elements, each with its material.

    Attributes
    ----------
    element : ndarray of int (q,)
    xi, eta : ndarray (q,)
        Parent coordinates: ``xi`` along the meridian, ``eta`` through the thickness.
    weight : ndarray (q,)
        Parent-domain weight (Jacobian and radius not included).
    stiffness : ndarray (q, 6, 6)
        Static stiffness in the model axes (Pa).
    density : ndarray (q,)
        kg/m^3.
    compound : ndarray of int (q,)
        Index into ``compounds``.
    compounds : tuple of str
        Compound (modulus law) names.
    layer : ndarray of int (q,)
        Index into ``layers`` (the construction layer the point lies in).
    layers : tuple of str
    """

    element: np.ndarray
    xi: np.ndarray
    eta: np.ndarray
    weight: np.ndarray
    stiffness: np.ndarray
    density: np.ndarray
    compound: np.ndarray
    compounds: tuple[str, ...]
    layer: np.ndarray
    layers: tuple[str, ...]


@dataclass(frozen=True, eq=False)
class PointGeometry:
    """Shape functions and geometry at the quadrature points (all arrays over points ``q``)."""

    shape: np.ndarray  # (q, 9)
    d_r: np.ndarray  # (q, 9) dN/dr
    d_y: np.ndarray  # (q, 9) dN/dy
    radius: np.ndarray  # (q,)
    volume: np.ndarray  # (q,) weight * detJ * r : the volume per radian of circumference


def point_geometry(
    node_r: np.ndarray, node_y: np.ndarray, elements: np.ndarray, points: QuadraturePoints
) -> PointGeometry:
    """Shape functions, Cartesian derivatives and volume weights at every quadrature point."""
    ni, di = lagrange3(points.xi)
    nj, dj = lagrange3(points.eta)
    # node k = 3 * a + b : a along xi, b along eta
    shape = (ni[:, None, :] * nj[None, :, :]).reshape(9, -1).T
    d_xi = (di[:, None, :] * nj[None, :, :]).reshape(9, -1).T
    d_eta = (ni[:, None, :] * dj[None, :, :]).reshape(9, -1).T
    er, ey = node_r[elements[points.element]], node_y[elements[points.element]]
    j11, j12 = (d_xi * er).sum(1), (d_xi * ey).sum(1)  # dr/dxi, dy/dxi
    j21, j22 = (d_eta * er).sum(1), (d_eta * ey).sum(1)
    det = j11 * j22 - j12 * j21
    if not (np.all(det > 0) or np.all(det < 0)):
        raise ValueError("cross-section mesh has an inverted or degenerate element (check the layer thicknesses)")
    d_r = (j22[:, None] * d_xi - j12[:, None] * d_eta) / det[:, None]
    d_y = (-j21[:, None] * d_xi + j11[:, None] * d_eta) / det[:, None]
    radius = (shape * er).sum(1)
    return PointGeometry(shape=shape, d_r=d_r, d_y=d_y, radius=radius, volume=points.weight * np.abs(det) * radius)


def strain_operators(g: PointGeometry) -> tuple[np.ndarray, np.ndarray]:
    """``B_c`` and ``B_n`` (q, 6, 27) of the symmetric set, trigonometric factors dropped.

    Voigt rows ``[rr, tt, yy, ty, ry, rt]``; columns ``3 a + c`` for node ``a``, component ``c``.
    """
    q = g.shape.shape[0]
    n_over_r = g.shape / g.radius[:, None]
    bc = np.zeros((q, 6, 9, 3))
    bn = np.zeros((q, 6, 9, 3))
    bc[:, 0, :, R] = g.d_r  # e_rr = du_r/dr
    bc[:, 1, :, R] = n_over_r  # e_tt = (u_r + du_t/dtheta)/r
    bn[:, 1, :, T] = n_over_r
    bc[:, 2, :, Y] = g.d_y  # e_yy
    bc[:, 3, :, T] = g.d_y  # g_ty = du_t/dy + du_y/(r dtheta)
    bn[:, 3, :, Y] = -n_over_r
    bc[:, 4, :, R] = g.d_y  # g_ry
    bc[:, 4, :, Y] = g.d_r
    bc[:, 5, :, T] = g.d_r - n_over_r  # g_rt = du_r/(r dtheta) + du_t/dr - u_t/r
    bn[:, 5, :, R] = -n_over_r
    return bc.reshape(q, 6, 27), bn.reshape(q, 6, 27)


def gradient_operators(g: PointGeometry) -> tuple[np.ndarray, np.ndarray]:
    """Displacement gradient ``(grad u)_{kj}`` as ``G_c + n G_n`` (q, 3, 3, 27): [component k, direction j].

    Physical components in the local frame ``(r, theta, y)``; the trigonometric factor of each
    entry is dropped (``u_k``'s own factor for ``j = r, y``; the other one for ``j = theta``).
    """
    q = g.shape.shape[0]
    n_over_r = g.shape / g.radius[:, None]
    gc = np.zeros((q, 3, 3, 9, 3))
    gn = np.zeros((q, 3, 3, 9, 3))
    for k in (R, T, Y):
        gc[:, k, R, :, k] = g.d_r
        gc[:, k, Y, :, k] = g.d_y
    gn[:, R, T, :, R] = -n_over_r  # (du_r/dtheta - u_t)/r
    gc[:, R, T, :, T] = -n_over_r
    gn[:, T, T, :, T] = n_over_r  # (du_t/dtheta + u_r)/r
    gc[:, T, T, :, R] = n_over_r
    gn[:, Y, T, :, Y] = -n_over_r  # du_y/(r dtheta)
    return gc.reshape(q, 3, 3, 27), gn.reshape(q, 3, 3, 27)


def element_dofs(elements: np.ndarray) -> np.ndarray:
    """Global DOF (n_el, 27) of each element, columns ``3 a + c``."""
    return (DOF_PER_NODE * elements[:, :, None] + np.arange(DOF_PER_NODE)).reshape(elements.shape[0], 27)


def assemble_points(blocks: np.ndarray, element: np.ndarray, dofs: np.ndarray, n_dof: int) -> sp.csr_matrix:
    """Sum per-point (q, 27, 27) blocks into a sparse (n_dof, n_dof) matrix."""
    rows = np.broadcast_to(dofs[element][:, :, None], blocks.shape)
    cols = np.broadcast_to(dofs[element][:, None, :], blocks.shape)
    return sp.csr_matrix((blocks.ravel(), (rows.ravel(), cols.ravel())), shape=(n_dof, n_dof))


@dataclass(frozen=True, eq=False)
class SurfacePoints:
    """Integration points on a face line of the cross-section (the inner surface).

    ``shape`` and ``d_xi`` are the three-node line shape functions (q, 3) on the face nodes
    ``nodes`` (q, 3); ``weight`` the Gauss weights; ``r, y`` and ``dr, dy`` the position and
    its derivative along the line.
    """

    nodes: np.ndarray
    shape: np.ndarray
    d_xi: np.ndarray
    weight: np.ndarray


def surface_points(lines: np.ndarray) -> SurfacePoints:
    """Three Gauss points on each three-node face line (n_lines, 3)."""
    xg, wg = _GAUSS3
    n, d = lagrange3(xg)
    nl = lines.shape[0]
    return SurfacePoints(
        nodes=np.repeat(lines, 3, axis=0),
        shape=np.tile(n.T, (nl, 1)),
        d_xi=np.tile(d.T, (nl, 1)),
        weight=np.tile(wg, nl),
    )


def _surface_vectors(node_r, node_y, s: SurfacePoints):
    """Position x, tangent x_xi (q, 3) in (r, theta, y) and operators u, u_xi, u_theta (q, 3, 9)."""
    r = (s.shape * node_r[s.nodes]).sum(1)
    y = (s.shape * node_y[s.nodes]).sum(1)
    dr = (s.d_xi * node_r[s.nodes]).sum(1)
    dy = (s.d_xi * node_y[s.nodes]).sum(1)
    q = r.size
    x = np.stack([r, np.zeros(q), y], axis=1)
    x_xi = np.stack([dr, np.zeros(q), dy], axis=1)
    x_th = np.stack([np.zeros(q), r, np.zeros(q)], axis=1)
    u = np.zeros((q, 3, 3, 3))  # [point, vector component, line node, dof component]
    u_xi = np.zeros((q, 3, 3, 3))
    uth_c = np.zeros((q, 3, 3, 3))
    uth_n = np.zeros((q, 3, 3, 3))
    for c in (R, T, Y):
        u[:, c, :, c] = s.shape
        u_xi[:, c, :, c] = s.d_xi
    # d u / d theta = (du_r/dth - u_t) e_r + (du_t/dth + u_r) e_t + du_y/dth e_y
    uth_n[:, R, :, R] = -s.shape
    uth_c[:, R, :, T] = -s.shape
    uth_n[:, T, :, T] = s.shape
    uth_c[:, T, :, R] = s.shape
    uth_n[:, Y, :, Y] = -s.shape
    shape = (q, 3, 9)
    return x, x_xi, x_th, u.reshape(shape), u_xi.reshape(shape), uth_c.reshape(shape), uth_n.reshape(shape)


def _eps() -> np.ndarray:
    """Levi-Civita symbol (3, 3, 3)."""
    eps = np.zeros((3, 3, 3))
    eps[0, 1, 2] = eps[1, 2, 0] = eps[2, 0, 1] = 1.0
    eps[0, 2, 1] = eps[2, 1, 0] = eps[1, 0, 2] = -1.0
    return eps


def _triple(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Triple products ``a . (b x c)`` per point; each argument a vector (q, 3) or an operator (q, 3, m).

    Operators become the axes of the result in argument order: two operators give (q, m, m).
    """
    subs = []
    out = ""
    for arg, letter, idx in ((a, "a", "i"), (b, "b", "j"), (c, "c", "k")):
        if arg.ndim == 3:
            subs.append(f"q{letter}{idx}")
            out += idx
        else:
            subs.append(f"q{letter}")
    return np.einsum(f"abc,{','.join(subs)}->q{out}", _eps(), a, b, c)


def pressure_operators(
    node_r: np.ndarray, node_y: np.ndarray, lines: np.ndarray, n_dof: int
) -> tuple[np.ndarray, sp.csr_matrix, sp.csr_matrix]:
    """Volume of the cavity to first and second order in the symmetric-set amplitudes.

    The cavity is the volume between the face ``lines`` (the inner surface, three-node lines
    from one bead to the other) and the axle, closed by the rigid rim (which does not move) or
    by planes normal to the axle. With ``P`` the projection normal to the axle,
    :math:`V = \\tfrac12\\int Px\\cdot(x_\\xi\\times x_\\theta)\\,d\\xi\\,d\\theta`
    (divergence theorem with :math:`\\nabla\\cdot Px/2 = 1`), and the terms of first and second
    order in the displacement are, per radian,

    .. math:: V_1 = \\tfrac12[Pu\\cdot(x_\\xi\\times x_\\theta) + Px\\cdot(u_\\xi\\times x_\\theta)
              + Px\\cdot(x_\\xi\\times u_\\theta)],\\quad
              V_2 = \\tfrac12[Px\\cdot(u_\\xi\\times u_\\theta) + Pu\\cdot(x_\\xi\\times u_\\theta)
              + Pu\\cdot(u_\\xi\\times x_\\theta)].

    The sign is fixed so that a uniform outward radial motion increases ``V``.

    Returns
    -------
    dv : ndarray (n_dof,)
        :math:`\\partial V_1 / \\partial a` per radian for ``n = 0`` (times ``w_0`` and ``p``:
        the inflation load).
    h0, h1 : scipy.sparse.csr_matrix
        Hessian of ``V2`` per radian, ``H = H^(0) + n H^(1)`` (times ``-p w_n``: the load stiffness).
    """
    s = surface_points(lines)
    x, x_xi, x_th, u, u_xi, uth_c, uth_n = _surface_vectors(node_r, node_y, s)
    w = s.weight
    # the volume between the surface and the axle: the divergence of x_perp / 2 (x_perp the part of
    # x normal to the axle) is 1, and x_perp . n = 0 on the planes y = const that close the cavity
    px, pu = x.copy(), u.copy()
    px[:, Y] = 0.0
    pu[:, Y] = 0.0
    first = (_triple(pu, x_xi, x_th) + _triple(px, u_xi, x_th) + _triple(px, x_xi, uth_c)) / 2.0
    dofs = (DOF_PER_NODE * s.nodes[:, :, None] + np.arange(3)).reshape(-1, 9)
    dv = np.zeros(n_dof)
    np.add.at(dv, dofs, first * w[:, None])
    outward = np.zeros(n_dof)
    outward[R::DOF_PER_NODE] = 1.0
    sign = 1.0 if dv @ outward > 0 else -1.0
    a0 = (_triple(px, u_xi, uth_c) + _triple(pu, x_xi, uth_c) + _triple(pu, u_xi, x_th)) / 2.0
    a1 = (_triple(px, u_xi, uth_n) + _triple(pu, x_xi, uth_n)) / 2.0
    hessians = []
    for a in (a0, a1):
        blocks = sign * (a + np.transpose(a, (0, 2, 1))) * w[:, None, None]
        rows = np.broadcast_to(dofs[:, :, None], blocks.shape)
        cols = np.broadcast_to(dofs[:, None, :], blocks.shape)
        hessians.append(sp.csr_matrix((blocks.ravel(), (rows.ravel(), cols.ravel())), shape=(n_dof, n_dof)))
    return sign * dv, hessians[0], hessians[1]


def harmonic_weight(n: int) -> float:
    """Circumferential integral of ``cos^2 n theta`` (or ``sin^2``; both rows at ``n = 0``)."""
    return 2.0 * np.pi if n == 0 else np.pi


def face_springs(
    node_r: np.ndarray, node_y: np.ndarray, lines: np.ndarray, k_r: float, k_t: float, n_dof: int
) -> sp.csr_matrix:
    """Distributed springs to ground on a face (N/m^3 radial ``k_r`` and tangential ``k_t``), per radian.

    The same for every harmonic (times ``w_n``); used to put a ring on an elastic foundation for
    the check against the closed-form ring frequencies of :mod:`roadnoise_utils.tire.ring.closed_form` (Gong 1993).
    """
    s = surface_points(lines)
    r = (s.shape * node_r[s.nodes]).sum(1)
    ds = np.hypot((s.d_xi * node_r[s.nodes]).sum(1), (s.d_xi * node_y[s.nodes]).sum(1))
    w = s.weight * ds * r
    blocks = np.zeros((r.size, 9, 9))
    for c, k in ((R, k_r), (T, k_t)):
        blocks[:, c::3, c::3] = k * w[:, None, None] * s.shape[:, :, None] * s.shape[:, None, :]
    dofs = (DOF_PER_NODE * s.nodes[:, :, None] + np.arange(3)).reshape(-1, 9)
    rows = np.broadcast_to(dofs[:, :, None], blocks.shape)
    cols = np.broadcast_to(dofs[:, None, :], blocks.shape)
    return sp.csr_matrix((blocks.ravel(), (rows.ravel(), cols.ravel())), shape=(n_dof, n_dof))
