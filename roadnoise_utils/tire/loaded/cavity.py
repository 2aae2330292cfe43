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
"""

from __future__ import annotations

import numpy as np

from ..cavity import Cavity
from ..cross_section.cavity import section_cavity
from ..cross_section.spec import CrossSectionSpec
from ..cross_section.static import build_section_tire
from ..cross_section.waveguide import surface_points
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
    base = tire.spec.geometry.rim_radius
    outward = np.sign(np.sum(dy[0] * points.weight * (r[0] - base)))  # n_r along +dy points away from the axle
    volume = np.sum(0.5 * r**2 * outward * dy * points.weight, axis=1)
    ends = section.face_lines(0)[[0, -1], [0, -1]]
    width = np.abs(axial[:, ends[1]] - axial[:, ends[0]])
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
