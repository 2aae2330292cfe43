"""The FET model: our finite-element tire (paper section "The FET Model", Fig. 3).

The paper's FETvisco model (~8000 DOF, Mooney-Rivlin statics, viscoelastic dynamics, no
air cavity) is not available, so we build a physically sound substitute of the family
of flexible rings on an elastic foundation (Gong 1993; Kung, Soedel & Yang 1986; multi-ring
belts as in Kindt 2009):

* **Belt**: ``n_strips`` lateral strips, each a closed polygonal ring of ``n_elements``
  straight frame elements in the wheel plane (DOF per node: ``ux``, ``uz``, ``phi``), with
  membrane and bending stiffness, the geometric stiffness of the inflation pre-tension
  :math:`T = p\\,b\\,R` and the load stiffness of the follower inflation pressure.
* **Lateral coupling** of adjacent strips: in-plane shear (circumferential motion), the
  meridional membrane tension of the crown (radial motion) and lateral bending across the
  width (three-strip stencil), so the footprint has rows and columns.
* **Sidewalls + air**: a radial and a tangential foundation from every belt node to the rigid
  rim, part pneumatic (proportional to the inflation pressure, carried by the carcass plies:
  layer law ``carcass``) and part rubber (compound ``sidewall``), stiffer at the edge strips
  where the sidewalls attach. The steel-cord stiffness of the belt has its own layer law
  (``belt_plies``): damping comes from the layers that strain; only the gas pre-stress is lossless.
* **Tread**: a massless viscoelastic (compound ``tread``) foundation under each belt node, active
  where the node is in contact; its mass is carried by the belt. A crown drop lowers the
  tread surface towards the shoulders.
* **Rim/hub**: rigid, three DOF (``x``, ``z``, rotation) at the end of the DOF vector;
  fixed for the fixed-hub model.

The rubber moduli depend on frequency, so the stiffness is
``K(omega) = K_elastic + sum_c g_c(omega) K_c`` (:mod:`.rubber`) and a frequency costs
one sparse solve. Coordinates: ``x`` forward (direction of travel), ``z`` up, ``y`` lateral;
node angle ``theta`` measured from the bottom of the tire (centre of the footprint),
increasing counter-clockwise (towards +x first).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

from ..rubber import FractionalZener
from . import elements
from .spec import TireSpec

DOF_PER_NODE = 3
UX, UZ, PHI = 0, 1, 2


@dataclass(frozen=True, eq=False)
class BeltMesh:
    """Geometry and DOF numbering of the belt.

    Attributes
    ----------
    theta : ndarray (n_elements,)
        Node angles from the bottom of the tire (rad).
    y : ndarray (n_strips,)
        Lateral position of each strip centre (m).
    strip_width : float
        Width of one strip (m).
    belt_radius : float
        Radius of the belt centre line (m).
    tread_radius : ndarray (n_strips,)
        Radius of the undeformed tread surface of each strip, crown drop included (m).
    """

    theta: np.ndarray
    y: np.ndarray
    strip_width: float
    belt_radius: float
    tread_radius: np.ndarray

    @property
    def n_strips(self) -> int:
        return self.y.size

    @property
    def n_elements(self) -> int:
        return self.theta.size

    @property
    def n_belt_dof(self) -> int:
        return DOF_PER_NODE * self.n_strips * self.n_elements

    @property
    def n_dof(self) -> int:
        """All DOF: belt nodes plus the three hub DOF."""
        return self.n_belt_dof + 3

    @property
    def hub_dofs(self) -> np.ndarray:
        """Hub DOF indices ``[x, z, rotation]``."""
        return self.n_belt_dof + np.arange(3)

    @property
    def arc_length(self) -> float:
        """Arc length of belt per node (m)."""
        return 2.0 * np.pi * self.belt_radius / self.n_elements

    def dof(self, strip: np.ndarray | int, node: np.ndarray | int, component: int) -> np.ndarray:
        """Global DOF index of ``component`` (0 ux, 1 uz, 2 phi) at belt node (strip, node).

        Nodes are numbered circumference-major so that the matrices are banded.
        """
        return DOF_PER_NODE * (np.asarray(node) * self.n_strips + np.asarray(strip)) + component

    def belt_xz(self) -> tuple[np.ndarray, np.ndarray]:
        """Undeformed belt node coordinates ``x, z`` (m), each (n_strips, n_elements)."""
        x = self.belt_radius * np.sin(self.theta)
        z = -self.belt_radius * np.cos(self.theta)
        return np.broadcast_to(x, (self.n_strips, self.n_elements)), np.broadcast_to(
            z, (self.n_strips, self.n_elements)
        )

    def tread_xz(self) -> tuple[np.ndarray, np.ndarray]:
        """Undeformed tread-surface points under each belt node, ``x, z`` (m), (n_strips, n_elements)."""
        r = self.tread_radius[:, None]
        return r * np.sin(self.theta)[None, :], -r * np.cos(self.theta)[None, :]

    def tread_area(self) -> np.ndarray:
        """Gross tread-surface area represented by each node (m^2), (n_strips, n_elements)."""
        dtheta = 2.0 * np.pi / self.n_elements
        return np.broadcast_to(
            (self.tread_radius * dtheta * self.strip_width)[:, None], (self.n_strips, self.n_elements)
        )


def build_mesh(spec: TireSpec) -> BeltMesh:
    """Belt mesh of a tire: strips across the belt width, nodes around the circumference."""
    g = spec.geometry
    n_strips, n_el = spec.mesh.n_strips, spec.mesh.n_elements
    width = g.belt_width / n_strips
    y = -0.5 * g.belt_width + width * (np.arange(n_strips) + 0.5)
    theta = 2.0 * np.pi * np.arange(n_el) / n_el
    drop = g.crown_drop * np.abs(2.0 * y / g.belt_width) ** g.crown_exponent
    return BeltMesh(theta=theta, y=y, strip_width=width, belt_radius=g.belt_radius, tread_radius=g.outer_radius - drop)


@dataclass(frozen=True, eq=False)
class FETModel:
    """Mass and stiffness of the finite-element tire.

    Attributes
    ----------
    spec : TireSpec
        The parameters it was built from.
    mesh : BeltMesh
        Geometry and DOF numbering.
    M : scipy.sparse.csr_matrix
        Mass matrix (kg), all DOF; the hub DOF carry the rim-side sidewall mass only.
    K_elastic : scipy.sparse.csr_matrix
        Frequency-independent (lossless) stiffness of the gas pre-stress (N/m): inflation
        pre-tension, pressure load stiffness, meridional tension coupling.
    K_compound : dict of str to scipy.sparse.csr_matrix
        Stiffness of each rubber compound at its static modulus (N/m), scaled by
        :math:`g_c(\\omega)` in :meth:`K`. The tread has none here: it acts only in contact
        (see :attr:`tread_normal`).
    laws : dict of str to FractionalZener
        Modulus law of each compound.
    tread_normal, tread_shear : ndarray (n_strips, n_elements)
        Static normal and shear stiffness of the tread under each node (N/m).
    """

    spec: TireSpec
    mesh: BeltMesh
    M: sp.csr_matrix
    K_elastic: sp.csr_matrix
    K_compound: dict[str, sp.csr_matrix]
    laws: dict[str, FractionalZener]
    tread_normal: np.ndarray
    tread_shear: np.ndarray
    strip_foundation_share: np.ndarray = field(repr=False)

    @property
    def n_dof(self) -> int:
        return self.mesh.n_dof

    @property
    def hub_vertical_mass(self) -> float:
        """Rim-side sidewall mass carried by the hub's vertical DOF (kg).

        The moving-hub stages add it to the vehicle's unsprung mass (paper Eq. 5-7).
        """
        z = self.mesh.hub_dofs[1]
        return float(self.M[z, z])

    def modulus_ratio(self, compound: str, omega: float) -> complex:
        """:math:`g_c(\\omega)` of a compound at angular frequency ``omega`` (rad/s)."""
        return complex(self.laws[compound].ratio(omega))

    def K(self, omega: float = 0.0, storage_only: bool = False) -> sp.csr_matrix:
        """Stiffness at angular frequency ``omega`` (rad/s), complex unless ``storage_only``.

        ``K(omega) = K_elastic + sum_c g_c(omega) K_c``; with ``storage_only`` the real parts
        :math:`\\mathrm{Re}\\,g_c` are used (the frozen model FET70Hz of the paper).
        """
        total = self.K_elastic.astype(float if storage_only else complex)
        for name, kc in self.K_compound.items():
            g = self.modulus_ratio(name, omega)
            total = total + (g.real if storage_only else g) * kc
        return total.tocsr()


def _strip_share(spec: TireSpec) -> np.ndarray:
    """Share of the foundation (and sidewall mass) on each strip; edge strips weighted."""
    n = spec.mesh.n_strips
    w = np.ones(n)
    if n > 1:
        w[[0, -1]] = spec.foundation.edge_factor
    return w / w.sum()


def _ring_elements(mesh: BeltMesh):
    """Element connectivity (n_strips * n_el, 6) and chord geometry of all rings."""
    ns, ne = mesh.n_strips, mesh.n_elements
    strips = np.repeat(np.arange(ns), ne)
    k1 = np.tile(np.arange(ne), ns)
    k2 = (k1 + 1) % ne
    dofs = np.concatenate([np.stack([mesh.dof(strips, k, c) for c in range(3)], axis=1) for k in (k1, k2)], axis=1)
    th1, th2 = mesh.theta[k1], np.where(k2 == 0, 2 * np.pi, mesh.theta[k2])
    r = mesh.belt_radius
    dx = r * (np.sin(th2) - np.sin(th1))
    dz = -r * (np.cos(th2) - np.cos(th1))
    length = np.hypot(dx, dz)
    return strips, dofs, length, dx / length, dz / length


def _foundation(mesh: BeltMesh, share: np.ndarray, k_radial: float, k_tangential: float) -> sp.csr_matrix:
    """Radial and tangential springs from every belt node to the rigid rim (hub DOF)."""
    ns, ne = mesh.n_strips, mesh.n_elements
    j, k = np.meshgrid(np.arange(ns), np.arange(ne), indexing="ij")
    j, k = j.ravel(), k.ravel()
    th = mesh.theta[k]
    er = np.stack([np.sin(th), -np.cos(th)], axis=1)
    et = np.stack([np.cos(th), np.sin(th)], axis=1)
    hub = mesh.hub_dofs
    dofs = np.stack([mesh.dof(j, k, UX), mesh.dof(j, k, UZ), *[np.full(j.size, h) for h in hub]], axis=1)
    length = mesh.arc_length * share[j]
    zero = np.zeros(j.size)
    a_r = np.column_stack([er, -er, zero])
    # the rim turning by phi drags the foundation by R*phi at the belt (rigid rotation is free)
    a_t = np.column_stack([et, -et, np.full(j.size, -mesh.belt_radius)])
    blocks = elements.spring_matrix(a_r, k_radial * length) + elements.spring_matrix(a_t, k_tangential * length)
    return elements.assemble(blocks, dofs, mesh.n_dof)


def _strip_coupling(mesh: BeltMesh, k_radial: float, k_tangential: float) -> sp.csr_matrix:
    """Springs between the same node of adjacent strips, per unit circumferential length (N/m^2)."""
    ns, ne = mesh.n_strips, mesh.n_elements
    if ns < 2 or (k_radial == 0 and k_tangential == 0):
        return sp.csr_matrix((mesh.n_dof, mesh.n_dof))
    j, k = np.meshgrid(np.arange(ns - 1), np.arange(ne), indexing="ij")
    j, k = j.ravel(), k.ravel()
    th = mesh.theta[k]
    er = np.stack([np.sin(th), -np.cos(th)], axis=1)
    et = np.stack([np.cos(th), np.sin(th)], axis=1)
    dofs = np.stack([mesh.dof(j, k, UX), mesh.dof(j, k, UZ), mesh.dof(j + 1, k, UX), mesh.dof(j + 1, k, UZ)], axis=1)
    scale = mesh.arc_length / mesh.strip_width
    blocks = elements.spring_matrix(np.column_stack([er, -er]), np.full(j.size, k_radial * scale))
    blocks += elements.spring_matrix(np.column_stack([et, -et]), np.full(j.size, k_tangential * scale))
    return elements.assemble(blocks, dofs, mesh.n_dof)


def _lateral_bending(mesh: BeltMesh, d_bending: float) -> sp.csr_matrix:
    """Bending across the width: energy D/2 (w'')^2 with w'' from three adjacent strips."""
    ns, ne = mesh.n_strips, mesh.n_elements
    if ns < 3 or d_bending == 0:
        return sp.csr_matrix((mesh.n_dof, mesh.n_dof))
    j, k = np.meshgrid(np.arange(1, ns - 1), np.arange(ne), indexing="ij")
    j, k = j.ravel(), k.ravel()
    th = mesh.theta[k]
    er = np.stack([np.sin(th), -np.cos(th)], axis=1)
    dofs = np.stack([mesh.dof(jj, k, c) for jj in (j - 1, j, j + 1) for c in (UX, UZ)], axis=1)
    a = np.column_stack([er, -2 * er, er])
    stiffness = np.full(j.size, d_bending * mesh.arc_length / mesh.strip_width**3)
    return elements.assemble(elements.spring_matrix(a, stiffness), dofs, mesh.n_dof)


def build_fet(spec: TireSpec) -> FETModel:
    """Assemble the finite-element tire of a :class:`TireSpec`.

    Parameters
    ----------
    spec : TireSpec
        Validated tire parameters (:func:`load_tire`).

    Returns
    -------
    FETModel
        Sparse mass and stiffness matrices (all DOF, hub last), compound laws and tread
        stiffness per node, about the inflated, unloaded state.
    """
    if not isinstance(spec, TireSpec):
        raise TypeError(
            f'build_fet builds the ring model from a ring tire file ([tire] model = "ring"); got '
            f"{type(spec).__name__} ([tire] model = {getattr(spec, 'model', None)!r}: ask its tire model, ru.tire_model)"
        )
    mesh = build_mesh(spec)
    ns = mesh.n_strips
    p = spec.operating.inflation_pressure
    b, fnd = spec.belt, spec.foundation
    share = _strip_share(spec)

    strips, dofs, length, cos, sin = _ring_elements(mesh)
    per_strip = np.full(strips.size, 1.0 / ns)
    ei = b.bending_stiffness * per_strip
    rubber = b.bending_rubber_fraction
    tension = spec.hoop_tension * per_strip  # T = p b R, balanced exactly by the pressure on the chords
    # pre-stress of the gas: inflation pre-tension, follower-pressure load, meridional tension (lossless)
    k_gas = elements.assemble(
        elements.geometric_stiffness(length, cos, sin, tension)
        + elements.pressure_load_stiffness(p * mesh.strip_width * np.ones(strips.size)),
        dofs,
        mesh.n_dof,
    )
    k_gas = k_gas + _strip_coupling(mesh, spec.lateral_tension, 0.0)
    # steel-cord belt plies (membrane, cord bending, bending across the width): loss of the ply layers
    k_plies = elements.assemble(
        elements.frame_stiffness(length, cos, sin, b.axial_stiffness * per_strip, (1 - rubber) * ei), dofs, mesh.n_dof
    )
    k_plies = k_plies + _lateral_bending(mesh, (1 - rubber) * b.lateral_bending_stiffness)
    # belt skim rubber: bending share, inter-ply shear, lateral bending share
    k_belt_rubber = elements.assemble(elements.frame_stiffness(length, cos, sin, 0 * ei, rubber * ei), dofs, mesh.n_dof)
    k_belt_rubber = k_belt_rubber + _strip_coupling(mesh, 0.0, b.inplane_shear_stiffness)
    k_belt_rubber = k_belt_rubber + _lateral_bending(mesh, rubber * b.lateral_bending_stiffness)
    # sidewalls: the carcass plies tensioned by the pressure (pneumatic part) and the sidewall rubber
    k_carcass = _foundation(mesh, share, fnd.radial_pressure_factor * p, fnd.tangential_pressure_factor * p)
    k_sidewall = _foundation(mesh, share, fnd.radial_rubber, fnd.tangential_rubber)
    mass = elements.assemble(elements.frame_mass(length, cos, sin, b.mass_per_length * per_strip), dofs, mesh.n_dof)

    mass = mass + _sidewall_mass(mesh, spec, share)
    area = mesh.tread_area()
    return FETModel(
        spec=spec,
        mesh=mesh,
        M=mass.tocsr(),
        K_elastic=k_gas.tocsr(),
        K_compound={
            "belt": k_belt_rubber.tocsr(),
            "belt_plies": k_plies.tocsr(),
            "carcass": k_carcass.tocsr(),
            "sidewall": k_sidewall.tocsr(),
        },
        laws={name: c.law() for name, c in spec.compounds.items()},
        tread_normal=spec.tread.normal_stiffness_per_area * area,
        tread_shear=spec.tread.shear_stiffness_per_area * area,
        strip_foundation_share=share,
    )


def _sidewall_mass(mesh: BeltMesh, spec: TireSpec, share: np.ndarray) -> sp.csr_matrix:
    """Lumped sidewall mass: the crown share on the belt nodes (by strip share), the rest on the rim."""
    fnd = spec.foundation
    diag = np.zeros(mesh.n_dof)
    crown = fnd.crown_mass_share * fnd.sidewall_mass
    per_node = crown * share[:, None] / mesh.n_elements * np.ones((mesh.n_strips, mesh.n_elements))
    j, k = np.meshgrid(np.arange(mesh.n_strips), np.arange(mesh.n_elements), indexing="ij")
    for c in (UX, UZ):
        diag[mesh.dof(j, k, c).ravel()] += per_node.ravel()
    rim_mass = fnd.sidewall_mass - crown
    diag[mesh.hub_dofs[:2]] += rim_mass
    diag[mesh.hub_dofs[2]] += rim_mass * spec.geometry.rim_radius**2
    return sp.diags(diag).tocsr()
