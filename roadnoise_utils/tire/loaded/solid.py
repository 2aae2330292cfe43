"""Total Lagrangian 27-node layered solids: internal forces, consistent tangent and mass.

The displacement ``u`` (global Cartesian components at the nodes) gives at every integration
point the deformation gradient :math:`F = I + \\partial u / \\partial X`, the Green-Lagrange
strain :math:`E = \\tfrac12 (F^T F - I)` and, from the layer's law
(:mod:`~roadnoise_utils.tire.loaded.material`), the second Piola-Kirchhoff stress ``S``. With
:math:`\\delta E = B\\,\\delta u` (``B`` depends on ``F``), the internal force and its exact
derivative are (Bathe, *Finite Element Procedures*, 2014, sec. 6.3; Wriggers, *Nonlinear Finite
Element Methods*, 2008, ch. 4)

.. math:: f = \\int B^T S\\,dV_0,\\qquad
          K = \\int \\big(B^T D B + G^T \\hat S G\\big)\\,dV_0,

the material and the geometric (initial-stress) parts. Each element's integration points are
those of its section element (ply by ply through the thickness, three along the meridian) times
three Gauss points over its arc. Elements swept from one section element share their point
count, so they are evaluated together (:class:`ElementGroup`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp

from ..cross_section.laminate import VOIGT, rotate
from ..cross_section.mesh import SectionMesh, meridian_tangent
from ..cross_section.spec import CrossSectionSpec
from ..cross_section.waveguide import lagrange3
from .material import (
    PointMaterials,
    green_strain,
    half_sphere,
    least_acoustic_eigenvalue,
    rubber_lame,
    stress_and_tangent,
)
from .mesh import Scatter, SolidMesh

#: ``PAIRS[a, j, k] = 1`` where the Voigt strain ``a`` holds ``F_ij dN/dX_k`` (shears: both orders).
#: Gauss points around each arc for the stiffness: three, exact for the quadratic arcs. Measured on
#: a small tire (4 crown and 2 x 2 sidewall section elements, beads clamped, no inflation): with
#: 48 arcs of 7.5 degrees its frequencies are the waveguide tire's to 0.04 % at n = 2, 0.9 % at
#: n = 4 and 2.5 % at n = 6; with 24 arcs of 15 degrees the bending of the thin belt over curved
#: quadratic arcs locks (membrane locking: the midsurface cannot bend without stretching), up to
#: 14 % high. Two points (reduced integration around the arc) unlock it, within 0.25 % at n = 6
#: on 24 arcs, but admit a spurious mode on coarse arcs (3 Hz on 6 arcs of 60 degrees), so they
#: are an option, not the default, until an assumed-strain treatment of the circumferential
#: membrane strain removes the locking without it.
ARC_POINTS = 3

PAIRS = np.zeros((6, 3, 3))
for _row, (_i, _j) in enumerate(VOIGT):
    PAIRS[_row, _i, _j] = 1.0
    PAIRS[_row, _j, _i] = 1.0


def shape_functions(xi: np.ndarray, eta: np.ndarray, zeta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """27-node shape functions (q, 27) and their parent derivatives (q, 27, 3) at points ``(xi, eta, zeta)``.

    Local node ``9 c + 3 a + b``: ``a`` along the meridian (``xi``), ``b`` through the thickness
    (``eta``), ``c`` around the arc (``zeta``), each at parent coordinates -1, 0, 1.
    """
    ni, di = lagrange3(xi)
    nj, dj = lagrange3(eta)
    nk, dk = lagrange3(zeta)
    shape = np.einsum("cq,aq,bq->qcab", nk, ni, nj).reshape(-1, 27)
    d = np.stack(
        [
            np.einsum("cq,aq,bq->qcab", nk, di, nj).reshape(-1, 27),
            np.einsum("cq,aq,bq->qcab", nk, ni, dj).reshape(-1, 27),
            np.einsum("cq,aq,bq->qcab", dk, ni, nj).reshape(-1, 27),
        ],
        axis=-1,
    )
    return shape, d


@dataclass(frozen=True, eq=False)
class ElementGroup:
    """The elements swept from one section element, with everything their points need.

    Attributes
    ----------
    elements : ndarray of int (m,)
    dofs : ndarray of int (m, 81)
        Global DOF of each element, column ``3 a + i`` for local node ``a``, component ``i``.
    shape : ndarray (q, 27)
        Shape functions at the points (the same in every element of the group).
    grad : ndarray (m, q, 27, 3)
        Reference gradients :math:`\\partial N_a / \\partial X_j` (1/m).
    volume : ndarray (m, q)
        Reference volume of each point (m^3): weight times Jacobian.
    density : ndarray (q,)
        kg/m^3.
    compound : ndarray of int (q,)
        Index into the section's compounds.
    materials : PointMaterials
        Over ``(m, q)``, in the global axes.
    arc_points : int
        Gauss points around each arc.
    scatter : Scatter
        The mesh's sparse pattern, shared by its groups (:attr:`.mesh.SolidMesh.scatter`).
    """

    elements: np.ndarray
    dofs: np.ndarray
    shape: np.ndarray
    grad: np.ndarray
    volume: np.ndarray
    density: np.ndarray
    compound: np.ndarray
    materials: PointMaterials
    arc_points: int
    scatter: Scatter

    @cached_property
    def voigt_gradients(self) -> np.ndarray:
        r"""``G`` (m, q, 6 * 27, 3): :math:`G_{(r,a),j} = \sum_k P_{rjk} N_{a,k}` with :data:`PAIRS` ``P``, the
        reference gradients arranged by Voigt strain (:func:`strain_operator`); built on first use."""
        m, q = self.volume.shape
        return np.einsum("rjk,mqak->mqraj", PAIRS, self.grad).reshape(m, q, 6 * 27, 3)


def element_groups(mesh: SolidMesh, spec: CrossSectionSpec, arc_points: int = ARC_POINTS) -> list[ElementGroup]:
    """The mesh's elements grouped by section element, reference geometry and materials at their points.

    ``arc_points`` Gauss points around each arc: :data:`ARC_POINTS` for the stiffness, 3 for the
    mass (:func:`mass_matrix`, whose integrand needs them).
    """
    if arc_points not in (2, 3):
        raise ValueError(f"arc_points = {arc_points!r}: give 2 (the stiffness) or 3 (the mass)")
    pts = mesh.section.points
    lame = np.array([rubber_lame(spec.layers[name]) for name in pts.layers])  # (n_layers, 2)
    section_cords = cord_directions(mesh.section, spec)
    zeta, zeta_weight = np.polynomial.legendre.leggauss(arc_points)
    groups = []
    for e in range(mesh.section.elements.shape[0]):
        sel = np.nonzero(pts.element == e)[0]
        xi = np.repeat(pts.xi[sel], arc_points)
        eta = np.repeat(pts.eta[sel], arc_points)
        zz = np.tile(zeta, sel.size)
        weight = np.repeat(pts.weight[sel], arc_points) * np.tile(zeta_weight, sel.size)
        shape, d_parent = shape_functions(xi, eta, zz)
        elements = np.nonzero(mesh.section_element == e)[0]
        nodes = mesh.coordinates[mesh.elements[elements]]  # (m, 27, 3)
        jac = np.einsum("maj,qak->mqjk", nodes, d_parent)  # dX_j / dparent_k
        det = np.linalg.det(jac)  # one sign throughout (the parent axes' handedness), never zero
        if not (np.all(det > 0.0) or np.all(det < 0.0)):
            raise ValueError(f"section element {e}: an element swept from it is inverted or degenerate")
        grad = np.einsum("qak,mqkj->mqaj", d_parent, np.linalg.inv(jac))
        position = np.einsum("qa,maj->mqj", shape, nodes)
        theta = np.arctan2(position[..., 0], -position[..., 2])
        stiffness = rotate(np.repeat(pts.stiffness[sel], arc_points, axis=0)[None], _model_to_global(theta))
        layer = np.repeat(pts.layer[sel], arc_points)
        cords = np.einsum("mqij,qfj->mqfi", _model_to_global(theta), np.repeat(section_cords[sel], arc_points, axis=0))
        try:
            materials = PointMaterials.from_stiffness(
                stiffness,
                np.broadcast_to(lame[layer, 0], theta.shape),
                np.broadcast_to(lame[layer, 1], theta.shape),
                cords,
            )
        except ValueError as error:
            names = ", ".join(sorted({pts.layers[i] for i in layer}))
            raise ValueError(f"[layers] {names} (section element {e}): {error}") from error
        groups.append(
            ElementGroup(
                elements=elements,
                dofs=(3 * mesh.elements[elements][:, :, None] + np.arange(3)).reshape(-1, 81),
                shape=shape,
                grad=grad,
                volume=np.abs(det) * weight[None, :],
                density=np.repeat(pts.density[sel], arc_points),
                compound=np.repeat(pts.compound[sel], arc_points),
                materials=materials,
                arc_points=arc_points,
                scatter=mesh.scatter,
            )
        )
    return groups


def cord_directions(section: SectionMesh, spec: CrossSectionSpec) -> np.ndarray:
    r"""Unit directions (q, 2, 3) of the two cord families at the section's points, in its axes ``(r, theta, y)``.

    A ply at ``beta`` from the circumferential direction has cords along
    :math:`\cos\beta\, e_\theta \pm \sin\beta\, s` (``s`` the meridian tangent, as the laminate
    rotates its stiffness); zero vectors at points outside cord plies.
    """
    pts = section.points
    s_r, s_y = meridian_tangent(section.r, section.y, section.elements[pts.element], pts.xi, pts.eta)
    angle = np.array([np.radians(getattr(spec.layers[name], "cord_angle", np.nan)) for name in pts.layers])[pts.layer]
    has_cords = np.isfinite(angle)
    cos, sin = np.where(has_cords, np.cos(angle), 0.0), np.where(has_cords, np.sin(angle), 0.0)
    out = np.zeros((pts.element.size, 2, 3))
    for family, sign in enumerate((1.0, -1.0)):
        out[:, family] = np.stack([sign * sin * s_r, cos, sign * sin * s_y], axis=-1)
    return out


def _model_to_global(theta: np.ndarray) -> np.ndarray:
    """Rotations (..., 3, 3) from the section's axes ``(r, theta, y)`` to ``(x, y, z)``: ``[new, old]`` cosines."""
    s, c = np.sin(theta), np.cos(theta)
    z = np.zeros_like(theta)
    o = np.ones_like(theta)
    # e_r = (sin, 0, -cos), e_theta = (cos, 0, sin), e_y = (0, 1, 0) as the columns
    return np.stack([np.stack([s, c, z], -1), np.stack([z, z, o], -1), np.stack([-c, s, z], -1)], -2)


def deformation_gradient(group: ElementGroup, u: np.ndarray) -> np.ndarray:
    """``F`` (m, q, 3, 3) of the group's elements for nodal displacements ``u`` (n_dof,).

    Raises
    ------
    FloatingPointError
        A point is inverted (``det F <= 0``): no physical state, the step that led there too long.
    """
    u_e = u[group.dofs].reshape(-1, 27, 3)
    f = np.eye(3) + np.matmul(np.swapaxes(u_e, 1, 2)[:, None], group.grad)
    if not np.all(np.linalg.det(f) > 0.0):
        raise FloatingPointError("a point of the mesh is inverted (det F <= 0): the load step is too large")
    return f


def strain_operator(f: np.ndarray, group: ElementGroup) -> np.ndarray:
    r"""``B`` (m, q, 6, 81) with :math:`\delta E = B\,\delta u_e` (Voigt, engineering shears) at the group's points.

    Row ``(j, k)``, column ``3 a + i``: :math:`F_{ij} N_{a,k}`, plus :math:`F_{ik} N_{a,j}` for a shear;
    that is :math:`B_{(r,a),i} = \sum_j G_{(r,a),j} F_{ij}` with the group's fixed
    :attr:`ElementGroup.voigt_gradients` ``G``: one batched product per evaluation.
    """
    b = np.matmul(group.voigt_gradients, np.swapaxes(f, -1, -2))  # (m, q, 6 * 27, 3)
    return b.reshape(*f.shape[:2], 6, 81)


def group_force_and_tangent(
    group: ElementGroup, u: np.ndarray, tangent: bool = True
) -> tuple[np.ndarray, np.ndarray | None]:
    """Element internal forces (m, 81) and, with ``tangent``, stiffness matrices (m, 81, 81) at ``u``."""
    f = deformation_gradient(group, u)
    stress, d = stress_and_tangent(green_strain(f), group.materials)
    b = strain_operator(f, group)
    m, q = group.volume.shape
    flat_b = b.reshape(m, q * 6, 81)
    force = np.matmul((stress * group.volume[..., None]).reshape(m, 1, q * 6), flat_b)[:, 0]
    return force, (element_tangent(group, b, d, stress) if tangent else None)


def element_tangent(group: ElementGroup, b: np.ndarray, d: np.ndarray, stress: np.ndarray) -> np.ndarray:
    """Element stiffness (m, 81, 81): material part from ``B`` and ``D``, geometric part from the stress ``S``."""
    m, q = group.volume.shape
    flat_b = b.reshape(m, q * 6, 81)
    db = np.matmul(d * group.volume[..., None, None], b).reshape(m, q * 6, 81)
    k = np.matmul(np.swapaxes(flat_b, 1, 2), db)
    s = np.zeros((m, q, 3, 3))
    for col, (i, j) in enumerate(VOIGT):
        s[..., i, j] = s[..., j, i] = stress[..., col] * group.volume
    gs = np.swapaxes(np.matmul(group.grad, s), 1, 2).reshape(m, 27, q * 3)  # [a, (q, l)]
    geo = np.matmul(gs, np.swapaxes(group.grad, 1, 2).reshape(m, 27, q * 3).swapaxes(1, 2))
    view = k.reshape(m, 27, 3, 27, 3)
    for i in range(3):
        view[:, :, i, :, i] += geo
    return k


def assemble_blocks(groups: list[ElementGroup], blocks: list[np.ndarray], n_dof: int) -> sp.csr_matrix:
    """Global sparse matrix of the element matrices ``blocks`` (one array per group), on the mesh's pattern."""
    scatter = groups[0].scatter
    if scatter.n_dof != n_dof or any(group.scatter is not scatter for group in groups):
        raise ValueError(f"groups: give groups of one mesh of n_dof = {n_dof} DOF (solid.element_groups)")
    return scatter.matrix([group.elements for group in groups], blocks)


def assemble(groups: list[ElementGroup], u: np.ndarray, n_dof: int) -> tuple[np.ndarray, sp.csr_matrix]:
    """Global internal force (n_dof,) and tangent stiffness (sparse) at displacements ``u``."""
    force = np.zeros(n_dof)
    blocks = []
    for group in groups:
        f_e, k_e = group_force_and_tangent(group, u)
        np.add.at(force, group.dofs, f_e)
        blocks.append(k_e)
    return force, assemble_blocks(groups, blocks, n_dof)


def prestressed_tangent(groups: list[ElementGroup], u: np.ndarray, n_dof: int) -> sp.csr_matrix:
    r"""Stiffness of the undeformed solids carrying the linear-elastic stress of the small displacement ``u`` (N/m).

    :math:`K = \int (B_0^T D_0 B_0 + G^T \hat\sigma G)\,dV_0` with :math:`\sigma = D_0 B_0 u`: the
    initial-stress linearisation of a pre-stressed structure about its unstressed geometry, as the
    waveguide tire takes its inflation. It is not the consistent first-order tangent: the
    initial-displacement terms (``B`` at the displaced state) and the pressure stiffness's change
    with the geometry, of the same order in ``u`` as the stress kept, are left out.
    :func:`assemble` at the inflated state is the exact tangent instead.
    """
    blocks = []
    for group in groups:
        f = np.broadcast_to(np.eye(3), group.grad.shape[:2] + (3, 3))
        b = strain_operator(f, group)
        _, d = stress_and_tangent(np.zeros(group.volume.shape + (6,)), group.materials)
        u_e = u[group.dofs].reshape(-1, 1, 81, 1)
        stress = np.matmul(d, np.matmul(b, u_e))[..., 0]
        blocks.append(element_tangent(group, b, d, stress))
    return assemble_blocks(groups, blocks, n_dof)


def internal_force(groups: list[ElementGroup], u: np.ndarray, n_dof: int) -> np.ndarray:
    """Global internal force (n_dof,) at displacements ``u``, without the tangent."""
    force = np.zeros(n_dof)
    for group in groups:
        np.add.at(force, group.dofs, group_force_and_tangent(group, u, tangent=False)[0])
    return force


def ellipticity(groups: list[ElementGroup], u: np.ndarray, directions: int = 200) -> list[np.ndarray]:
    """Per group, the least acoustic eigenvalue (Pa, (m, q)) at displacements ``u`` over ``directions``
    directions (:func:`~roadnoise_utils.tire.loaded.material.least_acoustic_eigenvalue`): negative where
    the law has lost strong ellipticity."""
    normals = half_sphere(directions)
    return [least_acoustic_eigenvalue(deformation_gradient(g, u), g.materials, normals) for g in groups]


def mass_matrix(groups: list[ElementGroup], n_dof: int) -> sp.csr_matrix:
    """Consistent mass (kg), sparse, from groups with 3 points around each arc (exact for the quadratic arcs)."""
    if any(group.arc_points < 3 for group in groups):
        raise ValueError("the mass needs 3 Gauss points around each arc: element_groups(..., arc_points=3)")
    blocks = []
    for group in groups:
        nn = np.einsum("qa,qb,q,mq->mab", group.shape, group.shape, group.density, group.volume)
        blocks.append(np.einsum("mab,ij->maibj", nn, np.eye(3)).reshape(-1, 81, 81))
    return assemble_blocks(groups, blocks, n_dof)
