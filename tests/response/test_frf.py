"""Direct FRFs: the symmetric reduction is exact, superposition holds, and 0 Hz is the static stiffness."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.response.frf import HubForceSolver
from roadnoise_utils.response.loaded import loaded_tire


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

    lt = loaded_tire(fet, static)
    free, hub = lt.free, fet.mesh.hub_dofs[1]
    cav = cavity.ring_tire_cavity(static.tire)
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
    from roadnoise_utils.tire import cavity

    cav = cavity.ring_tire_cavity(flat.tire)
    full = cavity.ring_cavity_coupling(fet, flat, cav, n_modes=fet.mesh.n_elements)
    few = cavity.ring_cavity_coupling(fet, flat, cav)
    freqs = np.array([1.0, 60.0, 180.0, 215.0, 240.0])  # at 0 Hz the (u, p) system is singular (uniform p)
    exact = ru.response.frf.frf_visco(fet, flat, freqs, progress=False, cavity=full)
    truncated = ru.response.frf.frf_visco(fet, flat, freqs, progress=False, cavity=few)
    for k, f in enumerate(freqs):
        h_tot, g_h = _monolithic(fet, flat, full, 2 * np.pi * f)
        assert abs(exact.H_tot[k] - h_tot) < 1e-8 * abs(h_tot)
        assert abs(exact.G_H[k] - g_h) < 1e-8 * abs(g_h)
    assert np.abs(truncated.H_tot - exact.H_tot).max() < 2e-3 * np.abs(exact.H_tot).max()  # 9.1e-4
    plain = ru.response.frf.frf_visco(fet, flat, freqs, progress=False)
    change = np.abs(exact.H_tot / plain.H_tot - 1)
    assert change[0] < 0.05 and change.argmax() in (3, 4)  # near statics: the air's compressibility only
