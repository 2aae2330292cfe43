"""The air cavity as a waveguide: the rigid torus, Webster's equation, the split under load."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.repro import stages
from roadnoise_utils.tire import cavity
from roadnoise_utils.tire.ring import cavity as ring_cavity

TIRE = "195_65R15"


@pytest.fixture(scope="module")
def spec():
    return stages.load_tire(TIRE)


def test_air_and_the_rigid_torus(spec):
    """Air at 20 deg C: c = 343.2 m/s; at 2.3 bar gauge 3.9 kg/m^3 (ideal gas). The 195/65 R15's
    cavity: 27.5 L, its first mode at c / (2 pi R) = 222 Hz, inside the 200-230 Hz of passenger tires."""
    c, rho = cavity.air(20.0, 2.3e5)
    assert c == pytest.approx(343.2, abs=0.1) and rho == pytest.approx((2.3e5 + 101325) / (287.05 * 293.15))
    cav = ring_cavity.ring_tire_cavity(spec)
    f = cavity.rigid_torus_frequencies(cav, [1, 2])
    assert f[1] == pytest.approx(2 * f[0]) and 200.0 < f[0] < 230.0
    assert 0.02 < cav.volume < 0.035


def test_webster_modes_of_a_uniform_torus_are_the_closed_form(spec):
    """Uniform section: the doublets n = 1..3 at n c / (2 pi R) within the elements' (n dtheta)^2 / 12,
    one even and one odd mode each, and the uniform pressure at 0 Hz."""
    cav = ring_cavity.ring_tire_cavity(spec)
    modes = cavity.webster_modes(cav, n_modes=7)
    exact = cavity.rigid_torus_frequencies(cav, [1, 1, 2, 2, 3, 3])
    assert modes.freqs[0] < 1e-2
    np.testing.assert_allclose(modes.freqs[1:], exact, rtol=(3 * 2 * np.pi / 720) ** 2 / 12 * 1.5)
    assert sorted(modes.parity[1:3]) == [-1, 1]


def test_loaded_doublet_splits_fore_aft_below_vertical_as_measured(spec):
    """Loaded, the odd (fore-aft) mode falls and the even (vertical) one rises, as measured (Choi &
    Bolton 2020, 2026); light load: the split is the first-order formula's (2 %); at the tire
    file's 4000 N it lies in the measured 2-14 Hz at rated load; a linear tire makes it linear in load."""
    cav = ring_cavity.ring_tire_cavity(spec)
    f1 = cavity.rigid_torus_frequencies(cav, 1)[0]
    splits = {}
    for load in (500.0, 2000.0, 4000.0):
        area = ring_cavity.loaded_area(cav, stages.solve_static(spec, load=load))
        fore_aft, vertical = cavity.webster_modes(cav, area).split()
        assert fore_aft < f1 < vertical
        splits[load] = vertical - fore_aft
        if load == 500.0:
            theta = 2 * np.pi * np.arange(area.size) / area.size
            ds = 2 * np.pi * cav.mean_radius / area.size
            first_order = np.sum((cav.area - area) * np.cos(2 * theta)) * ds / (np.pi * cav.mean_radius * cav.area) * f1
            assert splits[load] == pytest.approx(first_order, rel=0.02)
    assert 2.0 < splits[4000.0] < 14.0
    assert splits[4000.0] / splits[2000.0] == pytest.approx(2.0, rel=0.1)


def test_bad_cavity_input_is_refused(spec):
    cav = ring_cavity.ring_tire_cavity(spec)
    with pytest.raises(ValueError, match="outer_radius"):
        cavity.Cavity(0.2, 0.15, 0.15, 343.0, 3.9)
    with pytest.raises(ValueError, match="area must be positive"):
        cavity.webster_modes(cav, np.full(100, -1.0))
    with pytest.raises(ValueError, match="temperature"):
        cavity.air(400.0)


def test_a_rigid_translation_carries_the_air_it_holds(spec):
    """The whole tire (belt and rim) moved up rigidly: no uniform volume change, and at low frequency the
    waveguide's pressure on the walls is the inertia of the axially sloshing air, rho V / 2 (the 1-D
    model's share of the air's mass; within 3 % on the loaded section, whose footprint the faces,
    drawn for the unloaded section, do not follow)."""
    from roadnoise_utils.tire.ring.mechanics import UZ

    fet = ru.build_fet(spec)
    static = stages.solve_static(spec)
    cav = ring_cavity.ring_tire_cavity(spec)
    coupling = ring_cavity.ring_cavity_coupling(fet, static, cav, n_modes=fet.mesh.n_elements)
    mesh = fet.mesh
    up = np.zeros(fet.n_dof)
    strips, nodes = np.meshgrid(np.arange(mesh.n_strips), np.arange(mesh.n_elements), indexing="ij")
    up[mesh.dof(strips, nodes, UZ)] = 1.0
    up[mesh.hub_dofs[1]] = 1.0
    volume = coupling.volume.T @ up  # each mode's volume change
    assert abs(volume[0]) < 1e-10 * np.abs(volume).max()  # 1.4e-11: the sum of cos over the nodes
    omega = 2 * np.pi * 1.0
    gains = coupling.gains(omega)
    force = up @ (coupling.volume @ (gains * volume))  # the walls' pressure force along the motion
    mass = force.real / omega**2  # an inertia force, in phase with the displacement: + m omega^2 u
    loaded_volume = np.sum(coupling.area) * 2 * np.pi * cav.mean_radius / coupling.area.size
    assert mass == pytest.approx(0.5 * cav.density * loaded_volume, rel=0.03)  # 2.2 %: the loaded section


def test_sidewall_gain_is_the_bulging_arcs_area_by_a_second_method(spec):
    """The area an inextensible sidewall arc encloses as the belt edge comes down, computed here by
    sampling the arc and the shoelace formula (the arc's radius found by bisection on its length),
    equals :func:`roadnoise_utils.tire.ring.cavity.sidewall_gain` (1 %); it gives back about half the belt's loss."""
    g = spec.geometry
    cav = ring_cavity.ring_tire_cavity(spec)
    bead = np.array([g.rim_radius, 0.5 * spec.operating.rim_width])
    widest = np.array([g.max_width_radius, 0.5 * g.section_width])
    edge = np.array([cav.outer_radius, 0.5 * g.belt_width])
    # the unloaded arc's length: the circle through the three points, sampled
    a, b = widest - bead, edge - bead
    d = 2 * (a[0] * b[1] - a[1] * b[0])
    centre = bead + np.array([b[1] * (a @ a) - a[1] * (b @ b), a[0] * (b @ b) - b[0] * (a @ a)]) / d
    radius = np.linalg.norm(bead - centre)
    half = np.arcsin(np.linalg.norm(edge - bead) / (2 * radius))
    length = 2 * radius * half

    def enclosed(end: np.ndarray) -> float:
        chord = np.linalg.norm(end - bead)
        lo, hi = chord / 2 + 1e-12, 10.0  # bisection on the arc radius: 2 r asin(c / 2r) = length
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if 2 * mid * np.arcsin(chord / (2 * mid)) > length else (lo, mid)
        r = 0.5 * (lo + hi)
        t = np.linspace(-np.arcsin(chord / (2 * r)), np.arcsin(chord / (2 * r)), 4001)
        sag = np.sqrt(r**2 - (chord / 2) ** 2)
        x, y = r * np.sin(t), r * np.cos(t) - sag  # the arc over its chord, the chord on y = 0
        return 0.5 * abs(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))

    step = 1e-4
    gain = (enclosed(edge - [step, 0.0]) - enclosed(edge + [step, 0.0])) / (2 * step)
    assert ring_cavity.sidewall_gain(spec, cav) == pytest.approx(gain, rel=0.01)
    assert 0.3 < 2 * gain / g.belt_width < 0.7


def test_rolling_splits_each_doublet_by_the_wheels_rotation(spec):
    """The air streaming through the fixed footprint: on a uniform torus the first doublet goes to
    f1 (1 -/+ U/c) (1e-5); at rest the loaded split is the standing waves'; rolling, the loaded doublet
    sits at f_mean -/+ sqrt((split/2)^2 + f_rot^2) with f_rot = U / (2 pi R) the rotation frequency (2 %)."""
    cav = ring_cavity.ring_tire_cavity(spec)
    f1 = cavity.rigid_torus_frequencies(cav, 1)[0]
    beta = 20.0 / cav.sound_speed
    _, uniform = cavity.rolling_modes(cav, np.full(720, cav.area), 20.0)
    np.testing.assert_allclose(uniform[:2], [f1 * (1 - beta), f1 * (1 + beta)], rtol=1e-5)
    area = ring_cavity.loaded_area(cav, stages.solve_static(spec))
    fore_aft, vertical = cavity.webster_modes(cav, area).split()
    _, still = cavity.rolling_modes(cav, area, 0.0)
    np.testing.assert_allclose(still[:2], [fore_aft, vertical], rtol=1e-6)
    flow = 15.0
    f_rot = flow / (2 * np.pi * cav.mean_radius)
    _, rolling = cavity.rolling_modes(cav, area, flow)
    half = np.sqrt((0.5 * (vertical - fore_aft)) ** 2 + f_rot**2)
    mean = 0.5 * (vertical + fore_aft)
    np.testing.assert_allclose(rolling[:2], [mean - half, mean + half], rtol=0.02 * half / mean)
    with pytest.raises(ValueError, match="flow_speed"):
        cavity.rolling_modes(cav, area, 400.0)


@pytest.mark.parametrize("flow", [25.0, -25.0])
def test_the_rolling_pressure_of_a_travelling_wall_wave_is_doppler_shifted(flow):
    """On a uniform torus a wall wave q = e^{i(w t - n theta)} drives, seen by the streaming air, the pressure
    of the torus at rest at the Doppler-shifted frequency w_r = w - n U/R (Galilean invariance):
    p = rho c^2 w_r^2 q / (A ((c n/R)^2 - w_r^2)). Checks the convection's sign, the (1 - beta^2) and the
    convected source together; a source without the flow (d_t^2 q) is 16-66 % off here."""
    import dataclasses

    import scipy.sparse as sp

    cav = cavity.Cavity(0.18, 0.26, 0.14, 343.0, 3.9)
    n_nodes, radius = 720, cav.mean_radius
    area = np.full(n_nodes, cav.area)
    modes = cavity.webster_modes(cav, area, 41)
    wall = sp.identity(n_nodes, format="csr")  # one "DOF" per node: its volume change
    omegas = 2 * np.pi * modes.freqs
    omegas[0] = 0.0
    rest = cavity.CavityCoupling(
        np.asarray(wall.T @ modes.shapes.T), omegas, cav.density, cav.sound_speed, 0.0, modes, wall, area
    )
    rolling = cavity.rolling_coupling(rest, cav, abs(flow))
    rolling = dataclasses.replace(rolling, flow=dataclasses.replace(rolling.flow, speed=flow))
    spacing = 2 * np.pi * radius / n_nodes
    for order in (1, 2):
        for f in (150.0, 260.0):
            omega = 2 * np.pi * f
            q = np.exp(-1j * order * modes.theta)
            c, w = rolling.terms(omega)
            p = modes.shapes.T @ (c @ (w.T @ (q * spacing)))
            shifted = omega - flow * order / radius
            rc2 = cav.density * cav.sound_speed**2
            exact = rc2 * shifted**2 * q / (cav.area * ((cav.sound_speed * order / radius) ** 2 - shifted**2))
            assert np.abs(p / exact - 1).max() < 1e-3


# ---------------------------------------------------------------- the air's modes as coordinates of their own


def _coupling(damping_ratio: float = 0.01) -> cavity.CavityCoupling:
    """A random coupling: 7 coordinates, the uniform pressure and three resonant modes."""
    volume = np.random.default_rng(3).standard_normal((7, 4)) * 1e-3
    omegas = 2 * np.pi * np.array([0.0, 240.0, 246.0, 480.0])
    return cavity.CavityCoupling(volume, omegas, 3.8, 345.0, damping_ratio, None, None, None)


def _eliminated(coupling: cavity.CavityCoupling, air: cavity.AirCoordinates, omega: float) -> np.ndarray:
    """The air's term on the model's coordinates, its own condensed out at ``omega`` (rad/s)."""
    r = coupling.volume.shape[0]
    d = air.stiffness.astype(complex)
    d[r:, r:] -= omega**2 * np.diag(air.mass)
    if air.damping is not None:
        d = d + 1j * omega * air.damping
    return d[:r, :r] - d[:r, r:] @ np.linalg.solve(d[r:, r:], d[r:, :r])


@pytest.mark.parametrize("omega", [0.0, 2 * np.pi * 80.0, 2 * np.pi * 240.0, 2 * np.pi * 400.0, 2 * np.pi * 3000.0])
def test_the_air_s_coordinates_eliminated_give_the_hysteretic_term_exactly(omega):
    """Second method: the coupling's own term :math:`-V C(\\omega) V^T` (:meth:`CavityCoupling.terms`), to round-off."""
    coupling = _coupling()
    air = cavity.air_coordinates(coupling)
    gains, volume = coupling.terms(omega)
    expected = -coupling.volume @ gains @ volume.T
    assert np.abs(_eliminated(coupling, air, omega) - expected).max() < 1e-12 * np.abs(expected).max()
    assert air.damping is None and air.size == 3


def test_the_causal_air_is_passive_and_has_the_hysteretic_gain_at_each_mode_s_own_frequency():
    """Closed forms: eliminated, the causal coordinates give the gain of the docstring; at each resonant
    mode's frequency (one mode alone) it equals the hysteretic gain; well below it, the air's inertia
    :math:`\\rho c^2 \\omega^2/\\omega_m^2`. Its dashpots are positive semi-definite, its springs too."""
    coupling = _coupling()
    air = cavity.air_coordinates(coupling, causal=True)
    assert np.linalg.eigvalsh(air.damping).min() > -1e-12 * np.abs(air.damping).max()
    assert np.linalg.eigvalsh(air.stiffness).min() > -1e-9 * np.abs(air.stiffness).max()
    rc2, zeta = coupling.density * coupling.sound_speed**2, coupling.damping_ratio
    for m in (1, 2, 3):
        alone = cavity.CavityCoupling(coupling.volume[:, [m]], coupling.omegas[[m]], 3.8, 345.0, zeta, None, None, None)
        single = cavity.air_coordinates(alone, causal=True)
        v, w_m = alone.volume, alone.omegas[0]
        for omega in (0.3 * w_m, w_m, 1.7 * w_m):
            gain = rc2 * (omega**2 - 1j * zeta * omega * (w_m**2 - omega**2) / (2 * w_m))
            gain /= w_m**2 + 2j * zeta * w_m * omega - omega**2
            assert np.allclose(_eliminated(alone, single, omega), -gain * v @ v.T, rtol=1e-12, atol=0)
        hysteretic = -alone.volume @ np.diag(alone.gains(w_m)) @ alone.volume.T
        assert np.allclose(_eliminated(alone, single, w_m), hysteretic, rtol=1e-12, atol=0)
    low = 0.1 * coupling.omegas[1]  # the air's inertia, to (omega / omega_m)^2 = 1 %
    inertia = -rc2 * low**2 * (coupling.volume[:, 1:] / coupling.omegas[1:] ** 2) @ coupling.volume[:, 1:].T
    uniform = rc2 * np.outer(coupling.volume[:, 0], coupling.volume[:, 0])
    dynamic = _eliminated(coupling, air, low).real - uniform
    assert np.abs(dynamic - inertia).max() < 0.02 * np.abs(inertia).max()


def test_the_air_s_pressures_push_the_model_as_its_stiffness_and_dashpots_do():
    """Reciprocity: the force of the pressures on the model's coordinates, :math:`V a`, is minus the air's
    stiffness and dashpots acting on any motion (the rows of the model's coordinates)."""
    coupling = _coupling()
    r = coupling.volume.shape[0]
    air = cavity.air_coordinates(coupling, causal=True)
    x, v = np.random.default_rng(4).standard_normal((2, r + air.size))
    force = coupling.volume @ (air.pressure @ x + air.pressure_rate @ v)
    assert np.allclose(force, -(air.stiffness @ x + air.damping @ v)[:r], rtol=1e-12, atol=1e-12 * np.abs(force).max())
    hysteretic = cavity.air_coordinates(coupling)
    assert np.allclose(coupling.volume @ (hysteretic.pressure @ x), -(hysteretic.stiffness @ x)[:r])
    assert not hysteretic.pressure_rate.any()


def test_lossless_air_and_streaming_air():
    coupling = _coupling()
    assert np.isrealobj(cavity.air_coordinates(coupling, lossless=True).stiffness.real)
    assert np.abs(cavity.air_coordinates(coupling, lossless=True).stiffness.imag).max() == 0.0
    assert not cavity.air_coordinates(coupling, causal=True, lossless=True).damping.any()
    flow = cavity.RollingFlow(1.0, np.zeros((4, 4)), np.zeros((7, 4)), np.zeros((7, 4)))
    from dataclasses import replace

    with pytest.raises(ValueError, match="no flow"):
        cavity.air_coordinates(replace(coupling, flow=flow))
