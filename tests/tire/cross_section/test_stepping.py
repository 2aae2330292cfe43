"""Time stepping of the cross-section tire: the scheme's constants, passivity, rest, linearity, decay."""

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.tire.cross_section import stages as section_stages
from roadnoise_utils.tire.cross_section.dynamics import Projected
from roadnoise_utils.tire.cross_section.stepping import SPECTRAL_RADIUS, GeneralizedAlpha, HarmonicStepper, passive_part

TIRE = "165_65R14_cross_section"
DT = 1.0 / 12000.0


def _amplification(scheme: GeneralizedAlpha, omega_dt: float) -> np.ndarray:
    """Amplification matrix of (u, dt v, dt^2 a) for an undamped oscillator, from the scheme's equations."""
    am, af, b, g = scheme.alpha_m, scheme.alpha_f, scheme.beta, scheme.gamma
    w2 = omega_dt**2
    # (1-am) a1 + am a0 + (1-af) w2 u1 + af w2 u0 = 0;  u1 = u0 + v0 + (1/2-b) a0 + b a1;  v1 = v0 + (1-g) a0 + g a1
    lhs = np.array([[(1 - af) * w2, 0.0, 1 - am], [1.0, 0.0, -b], [0.0, 1.0, -g]])
    rhs = np.array([[-af * w2, 0.0, -am], [1.0, 1.0, 0.5 - b], [0.0, 1.0, 1 - g]])
    return np.linalg.solve(lhs, rhs)


def test_generalized_alpha_constants_and_spectral_radius():
    """rho = 1 is the trapezoidal rule; the amplification's spectral radius is 1 at low frequency and
    rho at infinite frequency (Chung & Hulbert 1993), computed here from the scheme's own equations."""
    trapezoid = GeneralizedAlpha(1.0)
    assert (trapezoid.alpha_m, trapezoid.alpha_f, trapezoid.gamma, trapezoid.beta) == (0.5, 0.5, 0.5, 0.25)
    scheme = GeneralizedAlpha(SPECTRAL_RADIUS)
    high = np.abs(np.linalg.eigvals(_amplification(scheme, 1e5))).max()
    low = np.abs(np.linalg.eigvals(_amplification(scheme, 1e-3))).max()
    assert high == pytest.approx(SPECTRAL_RADIUS, abs=1e-3)
    assert low == pytest.approx(1.0, abs=1e-6)
    # in the band: 250 Hz at the runs' step loses under 0.1 % of amplitude per period (0.03 %)
    omega_dt = 2 * np.pi * 250.0 * DT
    per_period = np.abs(np.linalg.eigvals(_amplification(scheme, omega_dt))).max() ** (2 * np.pi / omega_dt)
    assert per_period > 0.999


def test_passive_part_drops_unstable_directions_and_keeps_the_laws_on_positive_parts():
    """A harmonic with a negative static stiffness direction and an indefinite compound: the kept
    subspace is mass-orthonormal, every compound that carries a law is positive semi-definite,
    and the static stiffness on the kept subspace is unchanged."""
    rng = np.random.default_rng(1)
    k = 6
    basis = np.linalg.qr(rng.normal(size=(k, k)))[0]
    mass = np.diag(rng.uniform(1.0, 2.0, k))
    positive = basis @ np.diag(rng.uniform(1.0, 3.0, k)) @ basis.T
    indefinite = basis @ np.diag([-5.0, -0.5, 0.2, 0.3, 0.4, 0.5]) @ basis.T  # makes one direction unstable
    projected = Projected(
        compounds={"rubber": positive, "carcass": indefinite},
        gas=np.zeros((k, k)),
        mass=mass,
        contact=rng.normal(size=(k, 3)),
        momentum=rng.normal(size=k),
    )
    kept, dropped = passive_part(projected, ["rubber", "carcass"])
    assert dropped == 1
    assert np.allclose(kept.mass, np.eye(k - 1), atol=1e-12)
    for matrix in kept.compounds.values():
        assert np.linalg.eigvalsh(matrix).min() > -1e-12
    static = kept.gas + sum(kept.compounds.values())
    assert np.linalg.eigvalsh(static).min() > 0


@pytest.fixture(scope="module")
def stepper_and_static(coarse_section):
    """The coarse tire on the drum (rest, linearity and decay hold on any grid; a sixth of the steps' cost)."""
    tire = section_stages.section_tire(coarse_section)
    static = ru.stages.solve_static(coarse_section, "drum", drum_radius=1.25)
    return HarmonicStepper(tire, DT, section_stages.harmonic_reductions(coarse_section)), static


def test_the_static_state_stays_at_rest(stepper_and_static):
    """Started at rest under the static contact forces and held by them, nothing moves: the hub
    carries the load times the spread factor sinc(dtheta/2) (the momentum balance; 1 - 2e-5 on the
    coarse grid's 6 mm rows)."""
    stepper, static = stepper_and_static
    start = stepper.start(static.contact_force)
    for _ in range(30):
        stepper.predict()
        hub = stepper.advance(static.contact_force)
    assert np.abs(stepper.displacement() - start).max() < 1e-9 * static.deflection
    assert hub == pytest.approx(stepper.spread * static.load, rel=1e-9)
    assert stepper.spread == pytest.approx(1.0, abs=3e-5) and stepper.spread < 1.0


def test_response_is_linear_and_decays(stepper_and_static):
    """At rest the hub force stays at the load (less 5e-6 for the spread factor) but for round-off; a force
    pulse at one tread point: twice the pulse, twice the response through the pulse and the first
    ringing (superposition); the free response after it decays (every Maxwell branch dissipates, the
    scheme is stable)."""
    stepper, static = stepper_and_static
    grid = static.grid
    pulse = np.zeros((grid.n_cols, grid.n_rows))
    pulse[grid.n_cols // 2, grid.n_rows // 2] = 50.0

    def hub_force(scale: float, steps: int) -> np.ndarray:
        stepper.start(static.contact_force)
        hub = []
        for step in range(steps):
            stepper.predict()
            hub.append(stepper.advance(static.contact_force + (scale * pulse if step < 12 else 0.0)))
        return np.array(hub)

    rest = hub_force(0.0, 100)
    assert np.ptp(rest) < 1e-10 * static.load  # round-off of the steps (1e-14 - 1e-12, with the BLAS threads)
    single, double = hub_force(1.0, 600) - rest[0], hub_force(2.0, 100) - rest[0]
    assert np.abs(double - 2 * single[:100]).max() < 1e-7 * np.abs(double).max()
    early, late = np.abs(single[50:200]).max(), np.abs(single[450:600]).max()
    assert late < 0.5 * early


def test_effective_compliance_is_symmetric_positive_definite(stepper_and_static):
    stepper, static = stepper_and_static
    compliance = stepper.effective_compliance()
    contact = static.contact.ravel()
    block = compliance[np.ix_(contact, contact)]
    assert np.abs(compliance - compliance.T).max() < 1e-12 * np.abs(compliance).max()
    assert np.linalg.eigvalsh(block).min() > 0


def test_step_compliance_is_the_harmonic_path_of_a_load(stepper_and_static):
    """The grid's step compliance (harmonic sums of C A^-1 C^T) equals loading every harmonic with
    the spread forces and summing the motion back: the contact solve and the stepping agree."""
    stepper, static = stepper_and_static
    grid = static.grid
    forces = np.zeros((grid.n_cols, grid.n_rows))
    col, row = grid.n_cols // 2, grid.n_rows // 2
    forces[col - 2 : col + 3, row - 5 : row + 5] = np.random.default_rng(0).uniform(0.0, 5.0, (5, 10))
    loads = stepper.loads(forces)  # per harmonic; each of its halves (entries of a group) sees the same loads
    values = [np.matmul(group.contact, np.matmul(group.load, loads[group.n])) for group in stepper.groups]
    motion = stepper.vertical(stepper._per_harmonic(values)).ravel()
    assert np.abs(motion - stepper.effective_compliance() @ forces.ravel()).max() < 1e-12 * np.abs(motion).max()


def test_bad_input_is_refused(stepper_and_static):
    tire = section_stages.section_tire(TIRE)
    with pytest.raises(ValueError, match="dt"):
        HarmonicStepper(tire, 0.0, [])
    with pytest.raises(ValueError, match="harmonics 0"):
        HarmonicStepper(tire, DT, section_stages.harmonic_reductions(TIRE)[:-1])
    with pytest.raises(ValueError, match="spectral_radius"):
        HarmonicStepper(tire, DT, section_stages.harmonic_reductions(TIRE), spectral_radius=1.5)


def test_the_stepping_reuses_the_footprints_modal_harmonics():
    """The stage's harmonics, built from the footprint's reductions of its modal harmonics (the same
    band and cutoff), are those reduce_all computes alone: each harmonic's halves reduced afresh have
    the same modes, dropped directions and static compliance at the contact DOF (1e-9; ARPACK's start
    vectors rotate the bases, not the spaces). The footprint refuses reductions of another band."""
    from roadnoise_utils.tire.cross_section.dynamics import lateral_mirror, reduce_harmonic
    from roadnoise_utils.tire.cross_section.footprint import EvenFootprint, FootprintReductions
    from roadnoise_utils.tire.cross_section.stepping import CUTOFF_FACTOR, parity_halves

    tire = section_stages.section_tire(TIRE)
    reduced = section_stages.harmonic_reductions(TIRE, 400.0)
    names, mirror = list(tire.ops.scaled), lateral_mirror(tire.ops)

    def compliance(p):
        return p.contact.T @ np.linalg.solve(p.gas + sum(p.compounds.values()), p.contact)

    for n in (0, 1, 9):
        red = reduce_harmonic(tire.ops, tire.grid.dofs, n, 400.0, CUTOFF_FACTOR * 400.0, mirror=mirror)
        expected = [passive_part(half, names) for _, half in parity_halves(red)]
        got = [h for h in reduced if h.n == n]
        assert [h.n_modes for h in got] == [red.n_modes] * len(expected) and red.n_modes > 0
        assert [h.dropped for h in got] == [dropped for _, dropped in expected]
        for h, (projected, _) in zip(got, expected):
            reference = compliance(projected)
            assert np.abs(compliance(h.projected) - reference).max() < 1e-9 * np.abs(reference).max()
    static = ru.stages.solve_static(TIRE, "flat")
    other = FootprintReductions(60.0, 150.0, [], np.zeros(0, int), np.zeros((0, 0)), [])
    with pytest.raises(ValueError, match="reductions are for 60 Hz"):
        EvenFootprint.build(tire, static, 80.0, CUTOFF_FACTOR * 80.0, other)


def test_a_viscous_part_is_stepped_to_second_order():
    """A damped oscillator (80 Hz, 5 %; its one compound's matrix zero) driven by
    :math:`F = k \\sin^3(2\\pi 60 t)` from rest, against scipy's DOP853 at 1e-11: the error falls by
    4 per halving of the step (second order, as without the dashpot: Chung & Hulbert 1993), and a
    dashpot left out of the balance would miss by the damping force's share."""
    from scipy.integrate import solve_ivp

    from roadnoise_utils.tire.cross_section.stepping import StepGroup, SteppedHarmonic
    from roadnoise_utils.tire.rubber import PronyBranches, prony_series
    from roadnoise_utils.tire.schema import Compound

    k, c = (2 * np.pi * 80.0) ** 2, 2 * 0.05 * 2 * np.pi * 80.0
    law = Compound(2.0, 1e-3, 0.5).law()
    scheme = GeneralizedAlpha(SPECTRAL_RADIUS)

    def force(t):
        return k * np.sin(2 * np.pi * 60.0 * t) ** 3

    def error(dt: float, damped: bool = True) -> float:
        damping = np.array([[c]]) if damped else None
        projected = Projected({"rubber": np.zeros((1, 1))}, np.array([[k]]), np.eye(1), np.eye(1), np.zeros(1),
                              damping=damping)  # fmt: skip
        group = StepGroup([SteppedHarmonic(1, projected, 1, 0)], dt, {"rubber": PronyBranches(prony_series(law), dt)},
                          scheme, 1)  # fmt: skip
        t = np.arange(int(round(0.1 / dt))) * dt
        q = np.zeros(t.size)
        for i in range(1, t.size):
            free = group.predict(dt, scheme)
            group.advance(free, np.full((1, 1, 1), force(t[i])), dt, scheme)
            q[i] = group.q[0, 0, 0]
        exact = solve_ivp(lambda s, y: [y[1], force(s) - k * y[0] - c * y[1]], (0.0, t[-1]), [0.0, 0.0], t_eval=t,
                          rtol=1e-11, atol=1e-13, method="DOP853").y[0]  # fmt: skip
        return float(np.abs(q - exact).max() / np.abs(exact).max())

    errors = [error(dt) for dt in (2e-4, 1e-4, 5e-5)]
    assert errors[-1] < 2e-3
    assert 3.5 < errors[0] / errors[1] < 4.5 and 3.5 < errors[1] / errors[2] < 4.5
    assert error(5e-5, damped=False) > 50 * errors[-1]
