"""Direct FRFs: the symmetric reduction is exact, superposition holds, 0 Hz is the static stiffness, and the
cavity (at rest and rolling) equals the tire and the air solved as one system."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla

import roadnoise_utils as ru
from roadnoise_utils.tire import cavity
from roadnoise_utils.tire.ring import cavity as ring_cavity
from roadnoise_utils.tire.ring.frf import HubForceSolver
from roadnoise_utils.tire.ring.loaded import loaded_tire


def test_symmetric_reduction_equals_full_solve(fet, flat):
    freqs = np.array([0.0, 37.0, 80.0, 151.0, 333.0])
    reduced = ru.frf_visco(fet, flat, freqs, progress=False)
    full = ru.frf_visco(fet, flat, freqs, progress=False, use_symmetry=False)
    assert "symmetric" in reduced.method and "full" in full.method
    assert np.max(np.abs(reduced.H - full.H)) <= 1e-8 * np.max(np.abs(full.H))
    assert np.max(np.abs(reduced.G_H - full.G_H)) <= 1e-8 * np.max(np.abs(full.G_H))


def test_adjoint_equals_forward_solve_for_one_tassello(fet, flat):
    """Reciprocity: the hub force of a forward solve equals the adjoint FRF of that tassello."""
    lt = loaded_tire(fet, flat)
    solver = HubForceSolver(lt)
    omega = 2 * np.pi * 95.0
    t = flat.tasselli
    i = 5
    g = fet.modulus_ratio("tread", omega)
    rhs = g * (lt.road_input @ (t.node_tassello == i).astype(float))
    u = solver.solve_full(omega, rhs)
    forward = -(lt.hub_row(omega) @ u)
    adjoint = ru.frf_visco(fet, flat, [95.0], progress=False).H[i, 0]
    assert forward == pytest.approx(adjoint, rel=1e-9)


def test_superposition_direct(fet, flat):
    """Paper Eq. (i) for the direct model: sum of tassello FRFs = whole-footprint FRF (forward solve)."""
    r = ru.frf_visco(fet, flat, np.arange(0.0, 300.0, 7.0), progress=False)
    assert np.max(np.abs(r.H_sum - r.H_tot) / np.abs(r.H_tot)) < 1e-9


def test_zero_frequency_is_static_stiffness(fet, flat):
    """H_tot(0) = -G_H(0) = the tangent stiffness (sticking footprint: within 0.1 % of the frictionless one)."""
    r = ru.frf_visco(fet, flat, [0.0], progress=False)
    assert r.H_tot[0].imag == pytest.approx(0.0, abs=1e-6)
    assert r.H_tot[0].real == pytest.approx(-r.G_H[0].real, rel=1e-9)
    assert r.H_tot[0].real == pytest.approx(flat.vertical_stiffness, rel=1e-3)


def test_bad_frequencies(fet, flat):
    for freqs in ([], [-1.0], [np.nan], [[1.0, 2.0]]):
        with pytest.raises(ValueError, match="freqs"):
            ru.frf_visco(fet, flat, freqs, progress=False)


def _monolithic(fet, static, coupling, omega):
    """The tire and the whole waveguide (every acoustic node, no modes) solved as one sparse (u, p)
    system at ``omega``: H_tot and G_H, the independent reference of the cavity's Woodbury solve."""
    import scipy.sparse as sp
    import scipy.sparse.linalg as spla

    from roadnoise_utils.tire import cavity
    from roadnoise_utils.tire.ring import cavity as ring_cavity

    lt = loaded_tire(fet, static)
    free, hub = lt.free, fet.mesh.hub_dofs[1]
    cav = ring_cavity.ring_tire_cavity(static.tire)
    k_a, m_a = cavity.waveguide_matrices(cav, coupling.area)
    acoustic = (1.0 + 2j * coupling.damping_ratio) * k_a - (omega / cav.sound_speed) ** 2 * m_a
    wall, wall_hub = coupling.wall[:, free], np.asarray(coupling.wall[:, hub].toarray()).ravel()
    rho = cav.density
    system = sp.bmat([[lt.dynamic_stiffness(omega), -wall.T], [-rho * omega**2 * wall, acoustic]], format="csc")
    lu = spla.splu(system)
    row, g_tread = lt.hub_row(omega), fet.modulus_ratio("tread", omega)
    n = free.size
    footprint = g_tread * np.asarray(lt.road_input.sum(axis=1)).ravel()
    x = lu.solve(np.concatenate([footprint, np.zeros(wall.shape[0])]).astype(complex))
    h_tot = -(row @ x[:n]) + wall_hub @ x[n:]
    x = lu.solve(np.concatenate([-row, rho * omega**2 * wall_hub]).astype(complex))  # the hub moved up by 1
    g_h = -lt.hub_diagonal(omega) - row @ x[:n] + wall_hub @ x[n:]
    return h_tot, g_h


def test_cavity_coupling_equals_the_monolithic_tire_and_air_solve(fet, flat):
    """With every waveguide mode kept, the Woodbury solve of the cavity's low-rank term (symmetric
    reduction, pressure eliminated) equals the tire and the air solved as one (u, p) system (3e-10);
    with the 13 lowest modes (to ~1.3 kHz) the truncation is 9e-4 of the peak at 1-240 Hz; and the
    cavity changes H_tot most near its vertical mode."""
    from roadnoise_utils.tire.ring import cavity as ring_cavity

    cav = ring_cavity.ring_tire_cavity(flat.tire)
    full = ring_cavity.ring_cavity_coupling(fet, flat, cav, n_modes=fet.mesh.n_elements)
    few = ring_cavity.ring_cavity_coupling(fet, flat, cav)
    freqs = np.array([1.0, 60.0, 180.0, 215.0, 240.0])  # at 0 Hz the (u, p) system is singular (uniform p)
    exact = ru.tire.ring.frf.frf_visco(fet, flat, freqs, progress=False, cavity=full)
    truncated = ru.tire.ring.frf.frf_visco(fet, flat, freqs, progress=False, cavity=few)
    for k, f in enumerate(freqs):
        h_tot, g_h = _monolithic(fet, flat, full, 2 * np.pi * f)
        assert abs(exact.H_tot[k] - h_tot) < 1e-8 * abs(h_tot)
        assert abs(exact.G_H[k] - g_h) < 1e-8 * abs(g_h)
    assert np.abs(truncated.H_tot - exact.H_tot).max() < 2e-3 * np.abs(exact.H_tot).max()  # 9.1e-4
    plain = ru.tire.ring.frf.frf_visco(fet, flat, freqs, progress=False)
    change = np.abs(exact.H_tot / plain.H_tot - 1)
    assert change[0] < 0.05 and change.argmax() in (3, 4)  # near statics: the air's compressibility only


# The rolling cavity: the Woodbury solve of the convected waveguide equals the tire and every waveguide node
# solved as one convected (u, p) system, reduces to the cavity at rest, does not depend on the sense of
# rotation, and puts the waveguide's rolling doublet (an independent eigenproblem) into the hub force.

FLOW = 25.0  # m/s: the air of a ~95 km/h wheel


def _convected_monolithic(fet, static, coupling, omega, flow):
    """The tire and every waveguide node as one sparse (u, p) system of the convected Webster equation with the
    wall's motion convected (Myers): [[D, -G^T], [-rho c^2 S G, A(omega)]] at ``omega``; H_tot and G_H."""
    lt = loaded_tire(fet, static)
    cav = ring_cavity.ring_tire_cavity(static.tire)
    free, hub = lt.free, fet.mesh.hub_dofs[1]
    n = coupling.area.size
    spacing = 2.0 * np.pi * cav.mean_radius / n
    x, beta = omega / cav.sound_speed, flow / cav.sound_speed
    k_a, m_a = cavity.waveguide_matrices(cav, coupling.area)
    k_0, _ = cavity.waveguide_matrices(cav, np.ones(n))
    acoustic = (
        (1 - beta**2) * (1 + 2j * coupling.damping_ratio) * k_a
        - x**2 * m_a
        + 2j * x * beta * cavity.convection_matrix(cavity.flux_area(coupling.area))
    )
    source = (cav.density * cav.sound_speed**2) * (
        x**2 * sp.identity(n) - 2j * x * beta * cavity.convection_matrix(np.ones(n)) / spacing + beta**2 * k_0 / spacing
    )
    wall, wall_hub = coupling.wall[:, free], np.asarray(coupling.wall[:, hub].toarray()).ravel()
    lu = spla.splu(sp.bmat([[lt.dynamic_stiffness(omega), -wall.T], [-source @ wall, acoustic]], format="csc"))
    row, m = lt.hub_row(omega), free.size
    footprint = fet.modulus_ratio("tread", omega) * np.asarray(lt.road_input.sum(axis=1)).ravel()
    u = lu.solve(np.concatenate([footprint, np.zeros(n)]).astype(complex))
    h_tot = -(row @ u[:m]) + wall_hub @ u[m:]
    u = lu.solve(np.concatenate([-row, source @ wall_hub]).astype(complex))  # the hub moved up by 1
    return h_tot, -lt.hub_diagonal(omega) - row @ u[:m] + wall_hub @ u[m:]


@pytest.fixture(scope="module")
def couplings(coarse_fet, coarse_flat):
    cav = ring_cavity.ring_tire_cavity(coarse_flat.tire)
    every = ring_cavity.ring_cavity_coupling(coarse_fet, coarse_flat, cav, n_modes=coarse_fet.mesh.n_elements)
    return cav, every


def test_rolling_cavity_equals_the_convected_monolithic_solve(coarse_fet, coarse_flat, couplings):
    """Every waveguide mode kept: the left-right reduced Woodbury solve equals the one-system reference (2e-10) and
    the full solve; the flow breaks the fore-aft mirror (the solver drops it)."""
    cav, every = couplings
    rolling = cavity.rolling_coupling(every, cav, FLOW)
    freqs = np.array([1.0, 120.0, 228.0, 246.0])
    result = ru.frf_visco(coarse_fet, coarse_flat, freqs, progress=False, cavity=rolling)
    full = ru.frf_visco(coarse_fet, coarse_flat, freqs, progress=False, cavity=rolling, use_symmetry=False)
    assert "left-right" in result.method and "full" in full.method
    for k, f in enumerate(freqs):
        h_tot, g_h = _convected_monolithic(coarse_fet, coarse_flat, every, 2 * np.pi * f, FLOW)
        assert abs(result.H_tot[k] - h_tot) < 1e-8 * abs(h_tot)
        assert abs(result.G_H[k] - g_h) < 1e-8 * abs(g_h)
    assert np.abs(result.H - full.H).max() < 1e-8 * np.abs(full.H).max()


def test_rolling_cavity_reduces_to_rest_and_ignores_the_sense_of_rotation(coarse_fet, coarse_flat):
    """A vanishing flow gives the cavity at rest; the flow reversed (the tire rolling backwards: the mirror image
    of a fore-aft symmetric tire) gives the same vertical FRFs, though each alone is not symmetric."""
    cav = ring_cavity.ring_tire_cavity(coarse_flat.tire)
    rest = ring_cavity.ring_cavity_coupling(coarse_fet, coarse_flat, cav)
    freqs = np.array([30.0, 225.0, 240.0])
    at_rest = ru.frf_visco(coarse_fet, coarse_flat, freqs, progress=False, cavity=rest)
    creeping = ru.frf_visco(
        coarse_fet, coarse_flat, freqs, progress=False, cavity=cavity.rolling_coupling(rest, cav, 1e-7)
    )
    assert np.abs(creeping.H_tot - at_rest.H_tot).max() < 1e-9 * np.abs(at_rest.H_tot).max()
    forward = cavity.rolling_coupling(rest, cav, FLOW)
    backward = dataclasses.replace(forward, flow=dataclasses.replace(forward.flow, speed=-FLOW))
    ahead = ru.frf_visco(coarse_fet, coarse_flat, freqs, progress=False, cavity=forward)
    behind = ru.frf_visco(coarse_fet, coarse_flat, freqs, progress=False, cavity=backward)
    assert np.abs(ahead.H_tot - behind.H_tot).max() < 1e-9 * np.abs(ahead.H_tot).max()
    assert np.abs(ahead.G_H - behind.G_H).max() < 1e-9 * np.abs(ahead.G_H).max()
    assert np.abs(ahead.H_tot - at_rest.H_tot).max() > 0.05 * np.abs(at_rest.H_tot).max()
    # the tasselli ahead of and behind the centre trade places (the footprint's mirror image)
    assert np.abs(ahead.H - behind.H).max() > 1e-3 * np.abs(ahead.H).max()


def test_rolling_cavity_puts_both_waves_of_the_doublet_into_the_vertical_hub_force(coarse_fet, coarse_flat):
    """With the coupling weakened (1e-3) and light air damping, the cavity's share of the FRFs peaks on the
    waveguide's doublet (:func:`rolling_modes`, an eigenproblem of the air alone) within 0.1 Hz: at rest only the
    vertical mode reaches the hub; rolling, both waves do, with comparable strength."""
    cav = ring_cavity.ring_tire_cavity(coarse_flat.tire)
    base = ring_cavity.ring_cavity_coupling(coarse_fet, coarse_flat, cav, damping_ratio=1e-3)
    weak = dataclasses.replace(base, volume=1e-3 * base.volume, wall=1e-3 * base.wall)
    shares = {}
    for flow in (0.0, 20.0):
        doublet = cavity.rolling_modes(cav, base.area, flow)[1][:2]
        freqs = np.concatenate([np.arange(f - 0.5, f + 0.501, 0.1) for f in doublet])
        coupled = ru.frf_visco(
            coarse_fet, coarse_flat, freqs, progress=False, cavity=cavity.rolling_coupling(weak, cav, flow)
        )
        plain = ru.frf_visco(coarse_fet, coarse_flat, freqs, progress=False)
        share = np.abs(coupled.G_H - plain.G_H).reshape(2, -1)
        windows = freqs.reshape(2, -1)
        for k in range(2):
            assert abs(windows[k][share[k].argmax()] - doublet[k]) < 0.1 or flow == 0.0 and k == 0
        shares[flow] = share.max(axis=1)
    assert shares[0.0][0] < 0.05 * shares[0.0][1]  # at rest the fore-aft mode is (nearly) silent at the hub
    assert 0.2 < shares[20.0][0] / shares[20.0][1] < 5.0


def test_rolling_coupling_refuses_a_non_physical_flow(coarse_fet, coarse_flat):
    cav = ring_cavity.ring_tire_cavity(coarse_flat.tire)
    rest = ring_cavity.ring_cavity_coupling(coarse_fet, coarse_flat, cav, n_modes=5)
    for bad in (-1.0, 0.6 * cav.sound_speed, float("nan")):
        with pytest.raises(ValueError, match="flow_speed"):
            cavity.rolling_coupling(rest, cav, bad)
    assert cavity.rolling_coupling(rest, cav, 0.0).flow is None
