"""The air cavity of the loaded FE tire: its section round the wheel, from the loaded solids' inner surface.

The cavity is the cross-section tire's (:mod:`roadnoise_utils.tire.cross_section.cavity`): the torus
between the inner surface, bead to bead, and the rim, a plane-wave waveguide along the centroid's
circle of radius :math:`R_c` with Webster's area :math:`A(\\phi) = A_0 + (V'(\\phi) - V'_0)/R_c`,
:math:`V'` the section's volume per radian. The waveguide tire gets :math:`V'` from its linear
static amplitudes; here each ring of the solid mesh's nodes gives it from the nodes' loaded
positions: the ring's inner-face line drawn in one half-plane (radius from the axle and axial
position of each node; a loaded ring's nodes leave their half-plane by their small
circumferential displacements), closed by the rim's base, and

.. math:: V' = \\oint \\tfrac12 r^2\\,n_r\\,dl

by the divergence theorem (three Gauss points on each quadratic line, as the waveguide's).
:math:`V'_0` is the round, uninflated tire's, so the area includes the inflation's growth, where the
waveguide tires add the load's change only; the split, from the area's variation round the wheel,
hardly feels the uniform part. The ring's section stands at its loaded angle
:math:`\\phi` round the axle (its nodes' mean), so :math:`A(\\phi)` is the Eulerian area the air
sees at a fixed angle in space, as the waveguide's; interpolated periodically between the rings
onto equal angles from the footprint centre. Its frequencies come from
:func:`roadnoise_utils.tire.cavity.webster_modes`, as the other models'.

**Coupled to the tire** (:func:`loaded_coupling`, beyond the paper): a pressure field
:math:`p(\\phi)` of the waveguide acts on the loaded inner surface, normal to it, and on the
rim's base. Its work on a small motion ``u`` is :math:`\\int p\\,n\\cdot u\\,dA`, so the wall
matrix's row of waveguide node ``j`` (:func:`wall_matrix`, m^3/m) is
:math:`\\int N_j(\\phi(x))\\,N_a\\,n\\,dA` over the inner surface at the loaded positions
(:math:`N_j` the waveguide's linear elements, :math:`\\phi(x)` a point's angle round the axle from
the footprint centre, as the areas'), plus the rim's base, which moves with the hub: a vertical
rim motion ``w`` grows the cavity by :math:`r_b b\\,w\\cos\\phi` per radian (:math:`r_b` the
rim's radius, ``b`` the beads' axial distance). The same matrix gives, by reciprocity, the
volume change the motion ``u`` makes at each node, and the modes' volume changes
:math:`V = G^T \\Phi^T` couple the air to the tire as the ring tire's
(:class:`roadnoise_utils.tire.cavity.CavityCoupling`). A rigid vertical translation of the whole
wheel leaves the cavity's volume unchanged (the surface's and the rim's shares each vanish); seen
from the fixed angles it shifts the section, by :math:`-(A\\cos\\phi + A'\\sin\\phi)` per radian
(the divergence theorem), and the first even mode's share of that shift weighs the rim's term
against the surface's (tested: without the rim it would be 2.5 times off on the test mesh).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import scipy.sparse as sp

from ..cavity import AirCoordinates, Cavity, CavityCoupling, air_coordinates, webster_modes
from ..cross_section.cavity import section_cavity
from ..cross_section.spec import CrossSectionSpec
from ..cross_section.static import build_section_tire
from ..cross_section.waveguide import surface_points
from . import pressure
from .dynamics import ReducedFootprint
from .statics import LoadedTire, StaticState

#: Equal angles round the wheel the Webster area is given at (as the cross-section tire's).
N_ANGLES = 720


def air_cavity(construction: CrossSectionSpec, temperature: float | None = None) -> Cavity:
    """The unloaded cavity of the construction the solids sweep (its section mesh, the air at its pressure;
    ``temperature`` in deg C, default the tire file's ``[cavity]``): no solid mesh needed."""
    return section_cavity(build_section_tire(construction), temperature).cavity


def ring_volumes(tire: LoadedTire, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The angle round the axle (rad, from the bottom) and the cavity's volume per radian :math:`V'` (m^3)
    of every ring of nodes displaced by ``u``, rings in their order round the wheel."""
    mesh = tire.mesh
    section = mesh.section
    points = surface_points(section.face_lines(0))
    rings = np.argsort(mesh.theta)
    position = (mesh.coordinates + u.reshape(-1, 3))[mesh.node(rings[:, None], np.arange(section.n_nodes)[None, :])]
    radius = np.hypot(position[..., 0], position[..., 2])  # (rings, section nodes): distance from the axle
    axial = position[..., 1]
    r = np.einsum("qk,jqk->jq", points.shape, radius[:, points.nodes])
    dy = np.einsum("qk,jqk->jq", points.d_xi, axial[:, points.nodes])
    base, width = rim_base(tire)  # the beads are held on the rim: the same at every ring and in every state
    outward = np.sign(np.sum(dy[0] * points.weight * (r[0] - base)))  # n_r along +dy points away from the axle
    volume = np.sum(0.5 * r**2 * outward * dy * points.weight, axis=1)
    volume -= 0.5 * base**2 * width  # the rim's base faces the axle across the beads' width
    angle = np.arctan2(position[..., 0].mean(axis=1), -position[..., 2].mean(axis=1))
    return angle, volume


def webster_area(tire: LoadedTire, state: StaticState, cavity: Cavity | None = None) -> np.ndarray:
    """The loaded cavity's Webster area (m^2) at :data:`N_ANGLES` equal angles from the footprint centre:
    :math:`A_0 + (V'(\\phi) - V'_0)/R_c` (module notes), :math:`V'_0` the round tire's."""
    cavity = air_cavity(tire.spec) if cavity is None else cavity
    _, round_volume = ring_volumes(tire, np.zeros(tire.n_dof))
    angle, volume = ring_volumes(tire, state.u)
    phi = 2.0 * np.pi * np.arange(N_ANGLES) / N_ANGLES
    change = np.interp(phi, angle, volume - round_volume, period=2.0 * np.pi)
    area = cavity.area + change / cavity.mean_radius
    if np.any(area <= 0.1 * cavity.area):
        raise ValueError("the tire's deflection closes more than 90 % of the cavity's section: a non-physical load")
    return area


def rim_base(tire: LoadedTire) -> tuple[float, float]:
    """The rim's base closing the cavity: its radius (the construction's rim radius, m) and width (the
    axial distance between the inner surface's ends at the beads, which the rim holds; m)."""
    section = tire.mesh.section
    ends = section.face_lines(0)[[0, -1], [0, -1]]
    return float(tire.spec.geometry.rim_radius), float(abs(section.y[ends[1]] - section.y[ends[0]]))


def wall_matrix(tire: LoadedTire, state: StaticState, n_nodes: int = N_ANGLES) -> sp.csr_matrix:
    """The volume change (m^3 per m) at each of ``n_nodes`` waveguide nodes (equal angles from the
    footprint centre) per unit displacement of each DOF, about the loaded ``state`` (module notes):
    the inner surface's integration points shared between the two nodes either side of their angle
    (the waveguide's linear elements), the rim's base spread evenly over the rim nodes' vertical DOF
    (they move together with the hub)."""
    position, area = pressure.face_points(tire.mesh, tire.surface, state.u)
    step = 2.0 * np.pi / n_nodes
    at = np.mod(np.arctan2(position[..., 0], -position[..., 2]), 2.0 * np.pi) / step  # (n_f, q)
    left = np.floor(at).astype(int)
    share = at - left
    nodes = np.stack([left % n_nodes, (left + 1) % n_nodes], axis=-1)  # (n_f, q, 2)
    hats = np.stack([1.0 - share, share], axis=-1)
    # face f, point q, side s, node a of the face, component i
    values = np.einsum("fqs,qa,fqi->fqsai", hats, tire.surface.shape, area)
    rows = np.broadcast_to(nodes[..., None, None], values.shape)
    dofs = tire.surface.dofs.reshape(-1, 9, 3)  # (n_f, a, i)
    cols = np.broadcast_to(dofs[:, None, None, :, :], values.shape)
    wall = sp.coo_matrix((values.ravel(), (rows.ravel(), cols.ravel())), shape=(n_nodes, tire.n_dof)).tocsr()
    radius, width = rim_base(tire)
    hub = tire.rim_vertical
    phi = step * np.arange(n_nodes)
    base = radius * width * np.cos(phi) * step / hub.size  # (n_nodes,) per rim node
    rim = sp.csr_matrix(
        (np.repeat(base, hub.size), (np.repeat(np.arange(n_nodes), hub.size), np.tile(hub, n_nodes))),
        shape=(n_nodes, tire.n_dof),
    )
    return (wall + rim).tocsr()


def loaded_coupling(tire: LoadedTire, state: StaticState, temperature: float | None = None) -> CavityCoupling:
    """The air cavity of the loaded ``state`` coupled to the tire's DOF: the tire file's ``[cavity]``
    modes (``modes``, both parities, the uniform one included) of Webster's equation on
    :func:`webster_area`, their damping ratio, and :func:`wall_matrix` (``temperature`` in deg C,
    default the file's)."""
    settings = tire.spec.cavity
    air = air_cavity(tire.spec, temperature)
    area = webster_area(tire, state, air)
    modes = webster_modes(air, area, settings.modes)
    wall = wall_matrix(tire, state, area.size)
    volume = np.asarray(wall.T @ modes.shapes.T)  # (n_dof, modes), in the shapes' normalisation
    omegas = 2.0 * np.pi * modes.freqs
    omegas[0] = 0.0  # the uniform pressure
    return CavityCoupling(volume, omegas, air.density, air.sound_speed, settings.damping_ratio, modes, wall, area)


def with_air_coordinates(reduced: ReducedFootprint, lossless: bool = False) -> tuple[ReducedFootprint, AirCoordinates]:
    """The reduced tire with its air cavity's resonant modes as interior coordinates of their own, appended
    last (:func:`roadnoise_utils.tire.cavity.air_coordinates`, the FRFs' hysteretic air: exactly the
    reduced tire with the air's term :math:`-V C(\\omega) V^T`; ``lossless``: undamped air, for the
    modal reduction's storage moduli): their masses join ``mass``, their stiffness ``air``."""
    if reduced.cavity is None:
        raise ValueError("reduced: give a reduction with its air cavity coupled (dynamics.reduce(..., cavity=))")
    air = air_coordinates(reduced.cavity, causal=False, lossless=lossless)
    r = reduced.mass.shape[0]

    def padded(matrix: np.ndarray) -> np.ndarray:
        return np.pad(matrix, ((0, air.size), (0, air.size)))

    mass = padded(reduced.mass)
    mass[r:, r:] = np.diag(air.mass)
    augmented = replace(
        reduced,
        compounds={name: padded(part) for name, part in reduced.compounds.items()},
        pneumatic=padded(reduced.pneumatic),
        mass=mass,
        curvature=padded(reduced.curvature),
        basis=None if reduced.basis is None else np.pad(reduced.basis, ((0, 0), (0, air.size))),
        cavity=None,
        air=air.stiffness,
        n_air=air.size,
    )
    return augmented, air
