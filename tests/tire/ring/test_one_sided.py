"""One-sided contact of the FE tire on the drum: Prony form, contact conditions, frozen = linear, slow = static."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.road.cleat import cleat_profile, point_heights
from roadnoise_utils.tire.ring import one_sided
from roadnoise_utils.tire.rubber import FractionalZener, prony_series

TIRE = "165_65R14"
DRUM = 1.25
CLEAT = cleat_profile(0.015, 0.015)


@pytest.fixture(scope="module")
def drum_tire():
    spec = ru.load_tire(TIRE)
    fet = ru.build_fet(spec)
    return fet, ru.stages.solve_static(spec, "drum", drum_radius=DRUM)


def test_prony_series_matches_the_fractional_law_and_keeps_the_static_modulus():
    law = FractionalZener(2.6, 5e-5, 0.45)
    series = prony_series(law)
    omega = 2 * np.pi * np.linspace(1.0, 1000.0, 500)
    assert series.ratio(0.0) == 1.0
    assert np.max(np.abs(series.ratio(omega) / law.ratio(omega) - 1)) < 2e-3
    assert np.all(series.weights >= 0)


def test_prony_step_update_is_exact_for_a_ramp():
    """tau v' + v = u with u = t (ramp): v(t) = t - tau (1 - exp(-t/tau)) from v(0) = 0."""
    series = prony_series(FractionalZener(1.6, 5e-4, 0.7))
    tau, dt = series.times[3], 1.3e-4
    decay, gain, _ = series.step_constants(dt)
    v = 0.0
    for step in range(10):
        v = decay[3] * v + gain[3] * (step + 1) * dt + (1 - decay[3] - gain[3]) * step * dt
    t = 10 * dt
    assert v == pytest.approx(t - tau * (1 - np.exp(-t / tau)), rel=1e-12)


def test_point_heights_average_a_linear_road_to_the_quadrature_error():
    heights = point_heights(
        np.array([0.0, 0.02]), np.array([0.004, 0.006]), np.array([0.005, 0.003]), lambda s: 2 * s, [0.1]
    )
    # hat centroid: x + (dx_plus - dx_minus) / 3
    assert np.allclose(heights[:, 0], 2 * (np.array([0.0, 0.02]) + 0.1 + np.array([0.001, -0.003]) / 3), rtol=1e-4)


def test_quasi_static_run_balances_forces_and_never_penetrates(drum_tire):
    fet, static = drum_tire
    run = one_sided.quasi_static_run(fet, static, CLEAT, (-0.2, 0.15), step=0.002)
    assert run.force_balance < 1e-9
    assert run.max_penetration == 0.0
    before = run.distance < -0.12  # the cleat has not reached the tread
    assert np.allclose(run.hub_force[before], 0.0, atol=1e-6)
    assert np.all(run.contact_points[before] == static.contact.sum())
    assert run.contact_points.min() < 0.3 * static.contact.sum()  # the tread lifts off next to the cleat


def test_frozen_contact_equals_the_linear_fe_model(drum_tire):
    check = ru.experiments.frozen_check(TIRE)
    assert abs(check.peak_difference) < 0.02 and check.rms_difference < 0.02
    assert np.all(check.run.contact_points == drum_tire[1].contact.sum())


def test_frozen_run_is_linear_in_the_cleat_height(drum_tire):
    fet, static = drum_tire
    runs = [
        one_sided.dynamic_run(fet, static, cleat_profile(h, 0.015), 30 / 3.6, (-0.15, 0.0), frozen=True)
        for h in (0.005, 0.010)
    ]
    assert np.allclose(runs[1].hub_force, 2 * runs[0].hub_force, rtol=0, atol=1e-8 * np.abs(runs[1].hub_force).max())


def test_one_sided_run_lifts_off_and_keeps_contact_compressive(drum_tire):
    fet, static = drum_tire
    run = one_sided.dynamic_run(fet, static, CLEAT, 30 / 3.6, (-0.15, 0.15))
    assert run.max_penetration < 1e-12
    assert run.contact_points.min() < 0.3 * static.contact.sum()
    frozen = one_sided.dynamic_run(fet, static, CLEAT, 30 / 3.6, (-0.15, 0.15), frozen=True)
    assert run.peak_force > 1.5 * frozen.peak_force  # contact loss raises the peak


def test_a_slow_dynamic_run_tends_to_the_quasi_static_one(drum_tire):
    """The excess over the exact quasi-static peak shrinks with speed (the rubber's rate effect, ~ speed^alpha)."""
    fet, static = drum_tire
    quasi = one_sided.quasi_static_run(fet, static, CLEAT, (-0.12, 0.13))
    excess = [
        one_sided.dynamic_run(fet, static, CLEAT, speed, (-0.12, 0.13), dt=dt).peak_force / quasi.peak_force - 1
        for speed, dt in ((0.1, 5e-3), (0.03, 1e-2))
    ]
    assert 0 < excess[1] < excess[0] < 0.06 and excess[1] < 0.03


def test_bad_input_names_the_parameter(drum_tire):
    from roadnoise_utils.tire.ring.model import check_cleat_height

    fet, static = drum_tire
    with pytest.raises(ValueError, match="dt = .* too coarse for the contact"):
        one_sided.dynamic_run(fet, static, CLEAT, 30 / 3.6, (-0.15, 0.0), dt=1e-3)
    with pytest.raises(ValueError, match="speed = .* valid range is speed >="):
        one_sided.dynamic_run(fet, static, CLEAT, 0.01, (-0.15, 0.15), dt=1e-4)
    with pytest.raises(ValueError, match="cleat height = 60.0 mm: valid range is <="):
        check_cleat_height(static, 0.06)
    with pytest.warns(ru.guards.RoadnoiseWarning, match="exceeds the static deflection"):
        check_cleat_height(static, 0.03)
    with pytest.raises(RuntimeError, match="margin"):
        one_sided.dynamic_run(fet, static, CLEAT, 30 / 3.6, (-0.15, 0.0), margin=0.01)


def test_a_run_starting_on_the_cleat_and_a_bad_margin_are_refused(drum_tire):
    fet, static = drum_tire
    with pytest.raises(ValueError, match="already touches the tread at the first travel"):
        one_sided.dynamic_run(fet, static, CLEAT, 30 / 3.6, (-0.05, 0.0))
    with pytest.raises(ValueError, match="margin = nan"):
        one_sided.dynamic_run(fet, static, CLEAT, 30 / 3.6, (-0.15, 0.0), margin=float("nan"))


def test_the_convergence_study_runs_each_mesh_step_and_speed_it_reports(monkeypatch):
    """Each number of :func:`convergence` comes from the run it names: a stand-in stage whose peak
    encodes its arguments (mesh, speed, step, travel) shows which run each entry read."""
    from roadnoise_utils.experiments import one_sided_cleat

    class Run:
        def __init__(self, n, speed, distance, dt):
            self.dt = 1e-4 if dt is None else dt
            self.peak_force = n + 1e3 * speed + 1e6 * self.dt + 10 * distance[1]

    def stage(tire, speed, height, base, shape, drum, distance, dt=None, **_):
        return Run(tire.mesh.n_elements, speed, distance, dt)

    class Test:
        dynamic = Run(999, 0.0, (0.0, 0.0), 1.0)

    conditions = one_sided_cleat.one_sided_conditions(n_elements=400)
    monkeypatch.setattr(one_sided_cleat.stages, "one_sided_run", stage)
    monkeypatch.setattr(one_sided_cleat, "one_sided_cleat_test", lambda tire, conditions: Test)
    study = one_sided_cleat.convergence(TIRE, conditions=conditions, slow_runs=((0.1, 5e-3),))
    coarse = ru.load_tire(TIRE).mesh.n_elements
    c, d, sweep = conditions.cleat, conditions.distance[1], conditions.sweep_distance[1]
    assert study.quasi_static_peaks == {coarse: coarse + 100 + 10 * d, 400: 400 + 100 + 10 * d}
    assert study.dynamic_peaks == {coarse: coarse + 1e3 * c.dynamic_speed + 100 + 10 * d, 400: Test.dynamic.peak_force}
    assert list(study.step_peaks) == [1e-4, 5e-5]
    assert study.slow_peaks == {0.1: coarse + 100 + 5e3 + 10 * sweep}
    assert study.slow_quasi_static == coarse + 100 + 10 * sweep
