"""Cleat test: road input, fast simulation and their properties (paper stage 8)."""

from __future__ import annotations

import control
import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.rm.simulation import foh_coefficients


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
