"""The air cavity in the cross-section tire's footprint FRFs, against the tire and the air solved as one.

On the 165/65 R14 on a coarse grid (``coarse_section``): the reference solves every harmonic directly."""

import numpy as np
import pytest
import scipy.sparse.linalg as spla

import roadnoise_utils as ru
from roadnoise_utils.tire.cavity import waveguide_matrices
from roadnoise_utils.tire.cross_section import cavity_frf
from roadnoise_utils.tire.cross_section import stages as section_stages
from roadnoise_utils.tire.cross_section.dynamics import rim_transfer, rim_vector
from roadnoise_utils.tire.cross_section.footprint import contact_receptance, footprint_frf, footprint_reductions


@pytest.fixture(scope="module")
def setting(coarse_section):
    tire = section_stages.section_tire(coarse_section)
    static = ru.stages.solve_static(coarse_section, "flat")
    coupling = cavity_frf.section_cavity_coupling(tire, static)
    return tire, static, coupling


@pytest.fixture(scope="module")
def with_wall(setting):
    """The harmonics reduced with the cavity wall's static shapes (as the stages reduce a cavity tire)."""
    tire, _, coupling = setting
    return footprint_reductions(tire, 400.0, 1000.0, coupling.cavity.wall)


def _one_system(tire, static, coupling, frequency):
    """H_tot and G_H with the air as the waveguide's nodal pressures (every node, no modes) and the tire's
    harmonics solved directly (contact receptance of every harmonic; the wall's load in every harmonic the
    nodes resolve): the contact forces and the pressures of one dense system."""
    ops, grid = tire.ops, tire.grid
    free, fixed = ops.free, ops.fixed
    omega = 2 * np.pi * frequency
    air = coupling.cavity.cavity
    wall = coupling.cavity.wall
    col, row = static.points
    th = grid.theta[row]
    c = grid.n_cols
    nodes = coupling.area.size
    dtheta = 2 * np.pi / nodes
    theta = dtheta * np.arange(nodes)
    compliance = contact_receptance(tire, static, frequency)
    rim = rim_transfer(ops, grid.dofs, np.array([omega]))
    spread = np.sinc(grid.dtheta / (2 * np.pi))
    transfer = (-(np.cos(th) ** 2) * rim.contact[0, col] + np.sin(th) ** 2 * rim.contact[0, c + col]) * spread
    position = np.searchsorted(free, grid.dofs)
    shift = np.zeros((col.size, nodes), complex)  # point displacement per unit nodal pressure
    volume = np.zeros((nodes, nodes), complex)
    rim_force = np.zeros(nodes, complex)
    for n in range(min(tire.harmonics, nodes // 2) + 1):
        d = (ops.stiffness(n, omega) - omega**2 * ops.mass_matrix(n)).tocsr()
        z = spla.splu(d[free][:, free].tocsc()).solve(wall[free].astype(complex))
        weight = np.cos(n * theta) * dtheta
        moved = np.sinc(n * grid.dtheta / (2 * np.pi)) * (
            -np.cos(th) * np.cos(n * th) * z[position][col] + np.sin(th) * np.sin(n * th) * z[position][c + col]
        )
        shift += np.outer(moved, weight)
        volume += (wall[free] @ z) * np.outer(weight, weight)
        if n == 1:
            rim_b = rim_vector(ops)[fixed]
            reaction = -(z @ (d[free][:, fixed] @ rim_b)) + wall[fixed] @ rim_b + coupling.cavity.rim_face
            rim_force = reaction * weight
    stiffness, mass = waveguide_matrices(air, coupling.area)
    k2 = (omega / air.sound_speed) ** 2
    acoustic = (stiffness * (1 + 2j * coupling.damping_ratio) - k2 * mass).toarray()
    rho_w2 = air.density * omega**2
    system = np.block([[compliance, shift], [-rho_w2 * shift.T, acoustic - rho_w2 * volume]])
    p = col.size
    held = np.linalg.solve(system, np.concatenate([np.ones(p), np.zeros(nodes)]))
    h_tot = transfer @ held[:p] + rim_force @ held[p:]
    moving = np.linalg.solve(system, np.concatenate([-transfer, rho_w2 * rim_force]))
    g_h = transfer @ moving[:p] + rim_force @ moving[p:] - rim.free_rim[0]
    bare = np.linalg.solve(compliance, transfer)  # the same tire without the air
    return (h_tot, g_h), (bare.sum(), -(rim.free_rim[0] + transfer @ bare))


@pytest.mark.parametrize("frequency", [120.0, 248.0, 400.0])
def test_the_coupled_footprint_equals_the_tire_and_air_solved_as_one(setting, with_wall, frequency, coarse_section):
    """The even modes, their harmonic content truncated, the Woodbury update of the reduced footprint
    solve (mirror splits, Ritz-reduced harmonics) against every waveguide node and every harmonic in
    one dense solve; at 120 Hz, on the loaded vertical cavity mode (~248 Hz, where the cavity triples
    |H_tot|) and at the band's top. What the cavity adds is compared apart from the Ritz reduction's
    own error, the coupled FRFs less the plain ones on both sides. (Next to the fore-aft mode's
    frequency H_tot has a deep dip, where a relative comparison means little.)"""
    tire, static, coupling = setting
    freqs = np.array([frequency]) if frequency == 400.0 else np.array([frequency, 400.0])
    coupled = footprint_frf(tire, static, freqs, reductions=with_wall, cavity=coupling)
    plain = footprint_frf(
        tire, static, freqs, reductions=section_stages.footprint_reductions(coarse_section, 400.0, 1000.0)
    )
    (h_tot, g_h), (h_bare, g_bare) = _one_system(tire, static, coupling, frequency)
    added_h, added_g = coupled.H_tot[0] - plain.H_tot[0], coupled.G_H[0] - plain.G_H[0]
    assert abs(added_h) > 1e-2 * abs(plain.H_tot[0])  # the cavity matters here: not a vanishing term
    assert abs(coupled.H_tot[0] / h_tot - 1) < 1e-3
    assert abs(coupled.G_H[0] / g_h - 1) < 1e-4
    assert abs(added_h - (h_tot - h_bare)) < 2e-3 * abs(h_tot - h_bare)
    assert abs(added_g - (g_h - g_bare)) < 1e-3 * abs(g_h - g_bare)


def test_a_rigid_translation_and_the_pressure_on_a_free_body(setting):
    """Independent of the coupling's algebra: a rigid upward translation of the whole wheel (the wall's
    DOF and the rim's base) changes the section's volume per radian by -A cos(theta) (the divergence
    theorem), and at rest a cos(theta) pressure in the closed cavity puts -pi A on the hub, the
    tire's reaction and the rim's face together (for every non-uniform even mode, per unit of its
    cos(theta) content); a rim motion changes the volume by the hub force's own vector (reciprocity)."""
    from roadnoise_utils.tire.cross_section.dynamics import rigid_vertical

    tire, static, coupling = setting
    cav = coupling.cavity
    assert cav.wall @ rigid_vertical(tire.ops) + cav.rim_face == pytest.approx(-cav.cavity.area, rel=1e-12)
    terms = cavity_frf.cavity_terms(tire, static, coupling, np.array([2 * np.pi * 0.01, 2 * np.pi * 250.0]))
    per_content = terms.rim[0, 1:] / coupling.content[1:, 1]
    np.testing.assert_allclose(per_content, -cav.cavity.area, rtol=1e-6)
    ops, omega = tire.ops, 2 * np.pi * 250.0
    free, fixed = ops.free, ops.fixed
    d = (ops.stiffness(1, omega) - omega**2 * ops.mass_matrix(1)).tocsr()
    rim_b = rim_vector(ops)[fixed]
    moved = -spla.splu(d[free][:, free].tocsc()).solve(np.asarray(d[free][:, fixed] @ rim_b, complex))
    volume = cav.wall[free] @ moved + cav.wall[fixed] @ rim_b + cav.rim_face  # per unit rim motion
    np.testing.assert_allclose(terms.rim[1, 1:] / coupling.content[1:, 1], volume, rtol=1e-10)


def test_the_cavity_adds_the_air_s_stiffness_at_rest_and_a_resonance_at_its_vertical_mode(setting, coarse_section):
    """At rest only the uniform mode acts, and the air's compressibility can only stiffen the tire; the
    coupled H_tot peaks next to the loaded cavity's vertical (even) mode, the fore-aft one absent."""
    tire, static, coupling = setting
    reductions = section_stages.footprint_reductions(coarse_section, 400.0, 1000.0)
    freqs = np.concatenate([[0.01], np.arange(200.0, 281.0, 2.0), [400.0]])
    coupled = footprint_frf(tire, static, freqs, reductions=reductions, cavity=coupling)
    plain = footprint_frf(tire, static, freqs, reductions=reductions)
    assert abs(coupled.G_H[0]) > abs(plain.G_H[0])
    assert abs(coupled.H_tot[0]) > abs(plain.H_tot[0])
    band = slice(1, -1)
    gain = np.abs(coupled.H_tot[band] / plain.H_tot[band])
    vertical = coupling.omegas[1] / (2 * np.pi)
    assert abs(freqs[band][gain.argmax()] - vertical) < 5.0
    assert gain.max() > 1.5


def test_the_cavity_needs_the_tire_s_own_laws(setting):
    tire, static, coupling = setting
    with pytest.raises(ValueError, match="cavity"):
        footprint_frf(tire, static, np.array([0.0, 100.0]), inertia=False, cavity=coupling)


def test_the_reduced_harmonics_carry_the_wall_s_load(setting, with_wall, coarse_section):
    """The cavity's terms from the Ritz-reduced harmonics (the wall's static shapes in their bases)
    against every harmonic solved directly, across the band."""
    tire, static, coupling = setting
    assert len(with_wall.dynamic) == len(section_stages.footprint_reductions(coarse_section, 400.0, 1000.0).dynamic)
    omegas = 2 * np.pi * np.array([5.0, 90.0, 250.0, 390.0])
    reduced = cavity_frf.cavity_terms(tire, static, coupling, omegas, with_wall.dynamic)
    exact = cavity_frf.cavity_terms(tire, static, coupling, omegas)
    for name in ("points", "volume", "rim"):
        a, b = getattr(reduced, name), getattr(exact, name)
        assert np.abs(a - b).max() < 1e-3 * np.abs(b).max(), name
