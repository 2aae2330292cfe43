"""The air cavity of the tire built from its cross-section (beyond the paper).

The cavity is the torus between the tire's inner surface (the mesh's inner face, bead to bead)
and the rim, here closed by the flanges' inner faces down to the bead seat and the rim's base
at the bead-seat radius (the drop centre left out). Below its first cross-sectional mode it is
the plane-wave waveguide of :mod:`~roadnoise_utils.tire.cavity`: Webster's equation along the centroid's circle,
:math:`s = R_c\\theta`, with the area

.. math:: A(\\theta) = \\frac{V'(\\theta)}{R_c}, \\qquad V' = \\int r\\,dA, \\quad R_c = \\frac{V'_0}{A_0},

:math:`V'` the section's volume per radian (Pappus: the torus is :math:`2\\pi R_c A_0`).

**The wall.** A wall point moving by ``u`` changes :math:`V'` at its angle by
:math:`\\oint r\\,(u\\cdot n)\\,dl` (Reynolds' transport theorem on the section: the Eulerian
change, at a fixed angle in space). Only the normal motion in the section's plane counts: a
circumferential displacement slides the wall along itself and moves no air. In both harmonic
sets ``u_r`` and ``u_y`` carry the same factor (``cos n theta`` symmetric, ``sin n theta``
antisymmetric), so one vector of the DOF, :func:`wall_volume`, gives the volume change of every
harmonic; by reciprocity the same vector times the pressure is the pressure's load.

**Loaded.** The loaded tire's static amplitudes (:func:`roadnoise_utils.tire.cross_section.static.loaded_amplitudes`,
every harmonic) give :math:`A(\\theta)` around the wheel (:func:`loaded_area`); the footprint's
dip and the bulges before and after it split the first doublet (:func:`loaded_split`), as on the
ring tire. Unlike the ring tire's, the sidewalls here bulge as the FE shell computes them, not
as assumed arcs.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..cavity import Cavity, air, webster_modes
from .static import SectionStaticState, SectionTire, loaded_amplitudes
from .waveguide import DOF_PER_NODE, R, Y, surface_points


def _contour(tire: SectionTire) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Gauss points of the inner face: nodes (q, 3), shape functions (q, 3), radius ``r`` (q,) and
    the section-plane vector ``n dl`` (q, 2; (r, y) components, Gauss weight included), outward
    from the cavity (into the tire)."""
    mesh = tire.mesh
    s = surface_points(mesh.face_lines(0))
    r = (s.shape * mesh.r[s.nodes]).sum(1)
    dr = (s.d_xi * mesh.r[s.nodes]).sum(1)
    dy = (s.d_xi * mesh.y[s.nodes]).sum(1)
    ndl = np.stack([dy, -dr], axis=1) * s.weight[:, None]  # the tangent (dr, dy) turned by -90 deg
    if np.sum(ndl[:, 0] * (r - tire.spec.geometry.rim_radius)) < 0:
        ndl = -ndl  # the line runs the other way round: outward is away from the axle on the crown
    return s.nodes, s.shape, r, ndl


def section_area(tire: SectionTire) -> tuple[float, float]:
    """Area (m^2) and volume per radian :math:`\\int r\\,dA` (m^3) of the unloaded cavity's section.

    By the divergence theorem in the section's plane, :math:`A = \\oint r\\,n_r\\,dl` and
    :math:`V' = \\oint \\tfrac12 r^2 n_r\\,dl`, on the inner face (Gauss points, exact for its
    quadratic lines) and on the rim's closing (flanges at the inner face's ends down to the bead
    seat, the base at the bead-seat radius).
    """
    _, _, r, ndl = _contour(tire)
    area = float(np.sum(r * ndl[:, 0]))
    volume = float(np.sum(0.5 * r**2 * ndl[:, 0]))
    base, width = _rim_base(tire)
    # the base faces the axle (n_r = -1) across the width; the flanges are radial (n_r = 0)
    return area - base * width, volume - 0.5 * base**2 * width


def _rim_base(tire: SectionTire) -> tuple[float, float]:
    """The rim's base closing the section: its radius (the bead seat's) and width (between the inner
    face's two ends), m."""
    mesh = tire.mesh
    ends = mesh.face_lines(0)[[0, -1], [0, -1]]
    return tire.spec.geometry.rim_radius, float(abs(mesh.y[ends[1]] - mesh.y[ends[0]]))


def wall_volume(tire: SectionTire) -> np.ndarray:
    """Change of the cavity's volume per radian per unit harmonic amplitude of each DOF (m^2), (n_dof,).

    :math:`\\oint r\\,(u_r n_r + u_y n_y)\\,dl` on the inner face: the same vector for every
    harmonic and both sets (the field's factor ``cos n theta`` or ``sin n theta`` apart); zero on
    the circumferential DOF. Bead DOF included (they move with the rim).
    """
    nodes, shape, r, ndl = _contour(tire)
    out = np.zeros(tire.mesh.n_dof)
    for component, axis in ((R, 0), (Y, 1)):
        np.add.at(out, DOF_PER_NODE * nodes + component, shape * (r * ndl[:, axis])[:, None])
    return out


@dataclass(frozen=True, eq=False)
class SectionCavity:
    """The cross-section tire's cavity as a waveguide.

    ``cavity``: the equivalent :class:`.cavity.Cavity` (its mean radius the centroid's
    :math:`R_c`, its area the section's, the air at the inflation pressure); ``wall`` the
    :func:`wall_volume` vector; ``rim_face`` the radial projection of the rim's base per radian
    (m^2): the pressure's force on the rim, and the rim's share of the volume change when it moves.
    """

    cavity: Cavity
    wall: np.ndarray
    rim_face: float


def section_cavity(tire: SectionTire, temperature: float | None = None) -> SectionCavity:
    """The cavity of a cross-section tire (``temperature`` in deg C; default the tire file's ``[cavity]``)."""
    spec = tire.spec
    area, volume = section_area(tire)
    if area <= 0 or volume <= 0:
        raise ValueError(f"the cavity's section has area {area:g} m^2: is the inner face's meridian closed by the rim?")
    centroid = volume / area
    sound, density = air(
        spec.cavity.temperature if temperature is None else temperature, spec.operating.inflation_pressure
    )
    base, width = _rim_base(tire)
    # a rectangle of the same area whose mid-radius is the centroid's: Cavity's mean radius and area
    height = 2.0 * (centroid - base)
    cavity = Cavity(base, base + height, area / height, sound, density)
    return SectionCavity(cavity=cavity, wall=wall_volume(tire), rim_face=base * width)


def loaded_areas(
    tire: SectionTire, states: list[SectionStaticState], n_nodes: int = 720, cavity: SectionCavity | None = None
) -> np.ndarray:
    """The loaded cavity's Webster area (m^2) at ``n_nodes`` equal angles from the footprint centre, per
    loaded state, (n_states, n_nodes).

    :math:`A_0 + \\sum_n (\\cos n\\theta\\, g\\cdot a^s_n + \\sin n\\theta\\, g\\cdot a^a_n)/R_c`,
    every harmonic of the static solve (:func:`roadnoise_utils.tire.cross_section.static.loaded_amplitudes`, one factorisation
    per harmonic for all states); linear in each state's contact forces, as the tire.
    """
    cavity = section_cavity(tire) if cavity is None else cavity
    theta = 2.0 * np.pi * np.arange(n_nodes) / n_nodes
    change = np.zeros((len(states), n_nodes))
    for n, symmetric, antisymmetric in loaded_amplitudes(tire, states):
        change += np.outer(cavity.wall @ symmetric, np.cos(n * theta))
        change += np.outer(cavity.wall @ antisymmetric, np.sin(n * theta))
    area = cavity.cavity.area + change / cavity.cavity.mean_radius
    if np.any(area <= 0.1 * cavity.cavity.area):
        raise ValueError("the tire's deflection closes more than 90 % of the cavity's section: a non-physical load")
    return area


def loaded_area(
    tire: SectionTire, state: SectionStaticState, n_nodes: int = 720, cavity: SectionCavity | None = None
) -> np.ndarray:
    """:func:`loaded_areas` of one loaded state, (n_nodes,)."""
    return loaded_areas(tire, [state], n_nodes, cavity)[0]


def loaded_split(tire: SectionTire, state: SectionStaticState, cavity: SectionCavity | None = None):
    """The loaded cavity's plane-wave modes (:func:`.cavity.webster_modes` on :func:`loaded_area`);
    ``.split()`` gives the first doublet's (fore-aft, vertical) frequencies (Hz)."""
    cavity = section_cavity(tire) if cavity is None else cavity
    return webster_modes(cavity.cavity, loaded_area(tire, state, cavity=cavity), tire.spec.cavity.modes)
