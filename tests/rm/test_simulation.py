"""Cleat test: road input, fast simulation and their properties (paper stage 8)."""

from __future__ import annotations

import control
import numpy as np
import pytest
import scipy.linalg as sla
from hypothesis import given, settings
from hypothesis import strategies as st

import roadnoise_utils as ru
from roadnoise_utils.repro import stages
from roadnoise_utils.rm import aggregated, simulation
from roadnoise_utils.rm.simulation import foh_coefficients
from roadnoise_utils.road.input import profile_input


def test_simulation_equals_python_control(drum_tire):
    static, system, sections = drum_tire
    road = ru.cleat_input(static, 30 / 3.6, distance=(-0.06, 0.0))
    reference = control.forced_response(system, T=road.t, U=road.u).outputs
    fast = ru.simulate(sections, road).force
    assert np.max(np.abs(fast - reference)) <= 1e-9 * np.max(np.abs(reference))


def test_simulation_handles_a_nonzero_first_sample(drum_tire):
    """The state starts at rest even when the input does not start at zero."""
    static, system, sections = drum_tire
    rng = np.random.default_rng(1)
    t = np.arange(300) / 5000.0
    u = 1e-3 * rng.standard_normal((system.ninputs, t.size))
    road = ru.RoadInput(t=t, distance=t, u=u, speed=1.0, description="noise")
    reference = control.forced_response(system, T=t, U=u).outputs
    assert np.allclose(ru.simulate(sections, road).force, reference, rtol=0, atol=1e-9 * np.abs(reference).max())


def test_many_input_many_output_response_equals_python_control():
    """``response`` (each mode stepped once for all inputs and outputs) equals ``forced_response`` on a
    random stable model with real poles, conjugate pairs, two independent blocks and a feedthrough."""
    from roadnoise_utils.rm.simulation import response

    rng = np.random.default_rng(4)
    blocks = []
    for n in (5, 3):
        q = rng.standard_normal((n, n))
        blocks.append(q - (np.abs(np.linalg.eigvals(q)).max() + 0.5) * np.eye(n))  # stable, mixed poles
    a = np.block([[blocks[0], np.zeros((5, 3))], [np.zeros((3, 5)), blocks[1]]]) * 200.0
    assert np.any(np.linalg.eigvals(a).imag != 0) and np.any(np.linalg.eigvals(a).imag == 0)
    system = control.ss(a, rng.standard_normal((8, 3)), rng.standard_normal((4, 8)), rng.standard_normal((4, 3)))
    t = np.arange(600) / 4000.0
    u = np.cumsum(rng.standard_normal((3, t.size)), axis=1) + 1.0  # nonzero at the first sample
    reference = control.forced_response(system, T=t, U=u).outputs
    fast = response(system, t, u)
    assert fast.shape == reference.shape
    assert np.abs(fast - reference).max() <= 1e-9 * np.abs(reference).max()


def test_foh_coefficients_series_and_closed_form_agree():
    dt = 1e-4
    for pole in (-1.0 + 0j, -50 + 2j * np.pi * 80, -0.01 + 2000j):
        e, g0, g1 = foh_coefficients(pole, dt)
        z = pole * dt
        # exact integrals: g0 + g1 = (e - 1)/p, g1 = (e - 1 - z)/(p^2 dt)
        assert g0 + g1 == pytest.approx((np.exp(z) - 1) / pole, rel=1e-9)
        assert e == pytest.approx(np.exp(z), rel=1e-14)


def test_linearity_in_cleat_height(drum_tire):
    static, _, sections = drum_tire
    one = ru.simulate(sections, ru.cleat_input(static, 8.0, height=0.010)).force
    two = ru.simulate(sections, ru.cleat_input(static, 8.0, height=0.020)).force
    assert np.allclose(two, 2 * one, rtol=1e-12, atol=1e-12 * np.abs(two).max())


def test_time_shift_invariance(drum_tire):
    """Starting the run earlier only delays the same response."""
    static, _, sections = drum_tire
    speed = 8.0
    late = ru.cleat_input(static, speed, distance=(-0.1, 0.3))
    shift = 37  # samples
    early = ru.cleat_input(static, speed, distance=(-0.1 - shift * speed / late.sample_rate, 0.3))
    f_late = ru.simulate(sections, late).force
    f_early = ru.simulate(sections, early).force
    assert np.allclose(f_early[shift : shift + f_late.size], f_late, rtol=0, atol=1e-9 * np.abs(f_late).max())


def test_causality_no_force_before_the_cleat_reaches_the_footprint(drum_tire):
    static, _, sections = drum_tire
    run = ru.simulate(sections, ru.cleat_input(static, 8.0, distance=(-0.2, 0.3)))
    before = run.distance < ru.experiments.cleat.footprint_entry(static) - 1e-3
    assert before.sum() > 10
    assert np.max(np.abs(run.force[before])) < 1e-9 * np.max(np.abs(run.force))


# --- Repeated and nearly repeated poles (defective state matrices) --------------------------------
# A transfer function with a double pole, a Jordan block, a closed loop or a rational fit with two
# poles a hair apart has eigenvectors that are (nearly) parallel: diagonalising it gives huge modal
# gains that cancel. Such blocks are stepped by their exact discretisation instead (ExactBlock). The
# reference is python-control's forced_response (which agrees with scipy.signal.lsim to ~1e-14).

DT = 1e-4
SAMPLES = 3000
#: Agreement asked of every model, relative to the peak of the response.
TOLERANCE = 1e-9


def _road(u: np.ndarray) -> ru.RoadInput:
    t = DT * np.arange(u.shape[1])
    return ru.RoadInput(t=t, distance=t, u=u, speed=1.0, description="test input")


def _inputs(n_inputs: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    t = DT * np.arange(SAMPLES)
    return np.sin(2 * np.pi * rng.uniform(5, 200, (n_inputs, 1)) * t) + 0.3 * rng.standard_normal((n_inputs, SAMPLES))


def _peak_error(system: control.StateSpace, u: np.ndarray) -> float:
    reference = control.forced_response(system, T=DT * np.arange(u.shape[1]), U=u).outputs
    ours = ru.simulate(system, _road(u)).force
    return float(np.abs(ours - reference).max() / np.abs(reference).max())


# the cases of the bug report, each wrong by a factor or more before: a triple real pole, a Jordan
# block, a double real pole with a double pair, a double real pole driven by a sine
CASES = {
    "triple real pole": control.ss(control.tf([1e6], np.poly([-200.0] * 3))),
    "Jordan block": control.ss([[-300.0, 1.0], [0.0, -300.0]], [[0.0], [1.0]], [[1.0, 0.0]], [[0.0]]),
    "double real pole, double pair": control.ss(
        control.tf([1e9], np.real(np.poly([-100, -100, -50 + 300j, -50 - 300j, -50 + 300j, -50 - 300j])))
    ),
    "double real pole, sine": control.ss(control.tf([1e4], np.poly([-100.0, -100.0]))),
}


@pytest.mark.parametrize("name", list(CASES))
def test_the_reported_defective_models_equal_forced_response(name):
    system = CASES[name]
    u = np.sin(2 * np.pi * 30 * DT * np.arange(SAMPLES))[None, :]
    assert len(simulation.modal_sections(system).blocks) == 1
    assert _peak_error(system, u) < TOLERANCE


def _jordan(pole: float, size: int) -> np.ndarray:
    return pole * np.eye(size) + np.diag(np.full(size - 1, abs(pole) * 0.3), 1)


def _repeated_pair(sigma: float, omega: float) -> np.ndarray:
    pair = np.array([[sigma, omega], [-omega, sigma]])
    return np.block([[pair, 0.5 * abs(sigma) * np.eye(2)], [np.zeros((2, 2)), pair]])


def _near_pair(pole: float, separation: float) -> np.ndarray:
    return np.array([[pole, abs(pole)], [0.0, pole * (1.0 + separation)]])


def _normal_pair(sigma: float, omega: float) -> np.ndarray:
    return np.array([[sigma, omega], [-omega, sigma]])


poles = st.floats(-2500.0, -40.0)
frequencies = st.floats(2 * np.pi * 20, 2 * np.pi * 300)
blocks = st.one_of(
    st.builds(_jordan, poles, st.integers(2, 3)),  # double and triple real poles, Jordan chains
    st.builds(_repeated_pair, st.floats(-300.0, -20.0), frequencies),  # a repeated complex pair
    st.builds(_near_pair, poles, st.floats(1e-8, 1e-3)),  # two real poles 1e-8 .. 1e-3 apart
    st.builds(_normal_pair, st.floats(-300.0, -20.0), frequencies),  # a normal block beside them
)


@settings(max_examples=25, deadline=None)
@given(parts=st.lists(blocks, min_size=1, max_size=3), n_inputs=st.integers(1, 2), seed=st.integers(0, 2**16))
def test_any_stable_model_with_repeated_poles_equals_forced_response(parts, n_inputs, seed):
    """Random block-diagonal models mixing Jordan chains, repeated pairs, near-repeated and normal
    blocks, each block in a random basis (a similarity transform): equal to ``forced_response``."""
    rng = np.random.default_rng(seed)
    mixed = []
    for block in parts:
        basis = np.eye(block.shape[0]) + 0.3 * rng.standard_normal(block.shape)
        mixed.append(basis @ block @ np.linalg.inv(basis))
    a = sla.block_diag(*mixed)
    system = control.ss(a, rng.standard_normal((a.shape[0], n_inputs)), rng.standard_normal((1, a.shape[0])), 0.0)
    assert _peak_error(system, _inputs(n_inputs, seed)) < TOLERANCE


def test_the_multi_output_response_steps_a_defective_block_exactly():
    triple, double = control.ss(CASES["triple real pole"]), control.ss(control.tf([2e3, 1e6], np.poly([-150.0] * 2)))
    a = sla.block_diag(np.asarray(triple.A), np.asarray(double.A))
    b = np.vstack([np.asarray(triple.B), np.asarray(double.B)])
    c = np.vstack(
        [np.hstack([np.asarray(triple.C), np.zeros((1, 2))]), np.hstack([np.zeros((1, 3)), np.asarray(double.C)])]
    )
    system = control.ss(a, b, c, np.zeros((2, 1)))  # two outputs, one per defective block
    u = _inputs(1, 7)
    t = DT * np.arange(SAMPLES)
    reference = control.forced_response(system, T=t, U=u).outputs
    ours = simulation.response(system, t, u)
    assert np.abs(ours - reference).max() < TOLERANCE * np.abs(reference).max()


def test_a_fitted_tire_has_no_exact_block_and_keeps_its_modal_sections():
    """The fast path stays for the models the collection fits: 1x1 and 2x2 blocks, one per pole."""
    sections = simulation.modal_sections(ru.assemble_fixed_hub(stages.fit_tasselli("165_65R14")))
    assert sections.blocks == () and len(sections.sections) > 0


def test_the_aggregated_road_path_gives_a_defective_tire_s_exact_force():
    """A tire whose tasselli share a Jordan block: the road path equals ``forced_response`` on the
    tasselli's inputs (it simulates the formed inputs: there are no sums of exponentials to aggregate)."""
    static = stages.solve_static("165_65R14")
    n = static.tasselli.n
    rng = np.random.default_rng(3)
    system = control.ss(_jordan(-400.0, 2), rng.standard_normal((2, n)) * 1e6, [[1.0, 0.5]], np.zeros((1, n)))
    x = np.linspace(-1.0, 5.0, 6001)
    z = 1e-5 * np.cumsum(rng.standard_normal(x.size))
    profile = lambda s: np.interp(s, x, z)  # noqa: E731
    road = profile_input(static, profile, 20.0, (0.0, 0.5), 9600.0)
    result = aggregated.road_hub_force(system, static, profile, 20.0, (0.0, 0.5), 9600.0)
    reference = control.forced_response(system, T=road.t - road.t[0], U=road.u).outputs
    np.testing.assert_array_equal(result.t, road.t)
    assert np.abs(result.force - reference).max() < TOLERANCE * np.abs(reference).max()


def test_an_exact_block_too_long_for_memory_is_refused_before_allocating(monkeypatch):
    from roadnoise_utils.guards import ResourceLimitError

    monkeypatch.setenv("ROADNOISE_MAX_BYTES", "1e6")
    block = simulation.ExactBlock.balanced(_jordan(-300.0, 3), np.ones((3, 1)), np.ones((1, 3)))
    with pytest.raises(ResourceLimitError, match="the inputs' length: the exact simulation of a 3-state block"):
        block.output(np.zeros((1, 10_000)), DT)
