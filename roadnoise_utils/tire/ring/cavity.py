"""The ring tire's air cavity: its geometry, loaded cross-section and coupling to the belt mesh."""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ... import guards
from ..cavity import DAMPING_RATIO, Cavity, CavityCoupling, air, webster_modes
from .mechanics import UX, UZ, build_mesh
from .spec import TireSpec


def ring_tire_cavity(spec: TireSpec, temperature: float | None = None) -> Cavity:
    """The cavity of a ring tire file: from the rim to the belt's inner surface (its centre line less
    half the belt, taken as a third of the tread thickness), as wide as the mean of the rim and the
    section widths, filled with air at the inflation pressure and at ``temperature`` (deg C; default
    the tire file's ``[cavity] temperature``)."""
    g = spec.geometry
    c, rho = air(spec.cavity.temperature if temperature is None else temperature, spec.operating.inflation_pressure)
    belt_inner = g.belt_radius - g.tread_thickness / 3.0
    width = 0.5 * (spec.operating.rim_width + g.section_width)
    return Cavity(g.rim_radius, belt_inner, width, c, rho)


def sidewall_gain(spec: TireSpec, cavity: Cavity) -> float:
    """Section area one sidewall gives the cavity per unit inward radial motion of the belt's edge (m^2/m).

    The sidewall is an inextensible circular arc (its cords do not stretch) through the bead
    (rim radius, half the rim width), the widest point (``max_width_radius``, half the section
    width) and the belt's edge (the cavity's outer radius, half the belt width): when the edge
    comes down, the chord shortens and the arc bulges out, enclosing more of the section
    (:math:`A_{seg} = \\rho^2(\\alpha - \\sin\\alpha\\cos\\alpha)` for an arc of radius
    :math:`\\rho` and half-angle :math:`\\alpha` at fixed length :math:`2\\rho\\alpha`).
    """
    from scipy.optimize import brentq

    g = spec.geometry
    bead = np.array([g.rim_radius, 0.5 * spec.operating.rim_width])
    widest = np.array([g.max_width_radius, 0.5 * g.section_width])
    edge = np.array([cavity.outer_radius, 0.5 * g.belt_width])
    lhs = 2.0 * np.array([widest - bead, edge - bead])
    centre = np.linalg.solve(lhs, [widest @ widest - bead @ bead, edge @ edge - bead @ bead])
    radius = float(np.linalg.norm(bead - centre))
    length = 2.0 * radius * np.arcsin(np.linalg.norm(edge - bead) / (2.0 * radius))

    def segment(chord: float) -> float:
        half_angle = brentq(lambda a: length / chord - a / np.sin(a), 1e-9, np.pi - 1e-9)
        return (length / (2.0 * half_angle)) ** 2 * (half_angle - np.sin(half_angle) * np.cos(half_angle))

    step = 1e-5 * cavity.outer_radius
    chord = lambda down: float(np.linalg.norm(edge - np.array([down, 0.0]) - bead))  # noqa: E731
    return (segment(chord(step)) - segment(chord(-step))) / (2.0 * step)


def loaded_area(cavity: Cavity, static, n_nodes: int | None = None) -> np.ndarray:
    """The cavity's cross-section (m^2) around a loaded ring tire, at its belt nodes' angles.

    The belt's inward radial displacement of each strip, times the strip's width, is the area the
    footprint takes out of the cavity; each sidewall gives some back as the belt's edge strip
    comes down (:func:`sidewall_gain`: about half on our tires, 0.059 of the 0.126 m lost per
    metre on the 165/65 R14, 0.081 of 0.150 m on the 195/65 R15). Linear in the displacement,
    as the tire.
    """
    spec = static.tire
    if spec is None or spec.model != "ring":
        raise ValueError("static must be a ring tire's loaded state (solve_static of a ring tire file)")
    mesh = build_mesh(spec)
    u = np.asarray(static.displacement)
    strips, nodes = np.meshgrid(np.arange(mesh.n_strips), np.arange(mesh.n_elements), indexing="ij")
    ux, uz = u[mesh.dof(strips, nodes, UX)], u[mesh.dof(strips, nodes, UZ)]
    inward = -(ux * np.sin(mesh.theta)[None, :] - uz * np.cos(mesh.theta)[None, :])  # (strips, nodes)
    lost = np.sum(inward * mesh.strip_width, axis=0) - sidewall_gain(spec, cavity) * (inward[0] + inward[-1])
    area = cavity.area - lost
    if np.any(area <= 0.1 * cavity.area):
        raise ValueError("the belt's deflection closes more than 90 % of the cavity section: a non-physical load")
    return area


def ring_cavity_coupling(
    fet, static, cavity: Cavity, n_modes: int = 41, damping_ratio: float = DAMPING_RATIO
) -> CavityCoupling:
    """The loaded cavity of a ring tire (:func:`webster_modes` on :func:`loaded_area`, one acoustic
    node per belt node) and its coupling with the belt's radial motion and the rim's.

    A belt node of strip ``s`` moving outward by :math:`u_r` grows the cavity by
    :math:`f_b (w_s/b) d\\theta\\, u_r`; the rim moving by :math:`(d_x, d_z)` shrinks it by
    :math:`(\\sin\\theta\\, d_x - \\cos\\theta\\, d_z)\\, f_r\\, d\\theta` at each angle. By
    reciprocity the same matrix gives the pressure's forces on the belt and on the rim.

    The faces :math:`f_b, f_r` (m^2 per radian) are the radial projections of the section's walls
    that move with the belt and with the rim: the belt's :math:`b R_{in}` and the rim's
    :math:`w_{rim} r_{rim}`, each with half the sidewalls' projection :math:`X`. The closed section
    fixes :math:`X`: :math:`\\oint (e_r \\cdot n)\\, r\\, dl = A` (the divergence theorem), so
    :math:`f_b - f_r = A` and a rigid translation of the whole tire sloshes the waveguide's air
    along the axis as the air's own mass requires (:math:`\\rho V / 2`, the axial half of it; the
    1-D model has no transverse flow). Without the sidewalls the faces overstate the coupling by
    18-30 % on our tires.
    """
    guards.integer("n_modes", n_modes, 1, fet.mesh.n_elements)
    guards.real("damping_ratio", damping_ratio, 0.0, 0.5, unit="-")
    mesh = fet.mesh
    area = loaded_area(cavity, static)
    modes = webster_modes(cavity, area, n_modes)
    n_nodes, dtheta = mesh.n_elements, 2.0 * np.pi / mesh.n_elements
    theta = mesh.theta
    # the area is on the belt's node angles: the waveguide's node k is belt node k
    nodes = np.arange(n_nodes)
    belt_face = mesh.n_strips * mesh.strip_width * cavity.outer_radius
    rim_face = cavity.inner_radius * static.tire.operating.rim_width
    sidewalls = cavity.area - (belt_face - rim_face)  # X: the sidewalls' radial projection
    face = (belt_face + 0.5 * sidewalls) / mesh.n_strips * dtheta  # per strip and node
    rim = (rim_face - 0.5 * sidewalls) * dtheta
    rows, cols, values = [], [], []
    for strip in range(mesh.n_strips):
        rows += [nodes, nodes]
        cols += [mesh.dof(strip, nodes, UX), mesh.dof(strip, nodes, UZ)]
        values += [face * np.sin(theta), -face * np.cos(theta)]
    hub_x, hub_z = mesh.hub_dofs[0], mesh.hub_dofs[1]
    rows += [nodes, nodes]
    cols += [np.full(n_nodes, hub_x), np.full(n_nodes, hub_z)]
    values += [-rim * np.sin(theta), rim * np.cos(theta)]
    wall = sp.csr_matrix(
        (np.concatenate(values), (np.concatenate(rows), np.concatenate(cols))), shape=(n_nodes, fet.n_dof)
    )
    volume = np.asarray(wall.T @ modes.shapes.T)  # (n_dof, modes); the shapes are normalised by the waveguide's mass
    omegas = 2.0 * np.pi * modes.freqs
    omegas[0] = 0.0
    return CavityCoupling(volume, omegas, cavity.density, cavity.sound_speed, damping_ratio, modes, wall, area)
