"""Threads inside one computation: the count is the setting or the cores, the results do not depend on it."""

from __future__ import annotations

import numpy as np
import pytest

from roadnoise_utils import parallel
from roadnoise_utils.rm import simulation


@pytest.mark.parametrize(("setting", "expected"), [("1", 1), (" 2 ", 2), ("", None)])
def test_the_thread_count_is_the_setting_or_the_cores(monkeypatch, setting, expected):
    monkeypatch.setenv("ROADNOISE_THREADS", setting)
    count = parallel.threads()
    assert count == expected if expected else 1 <= count <= parallel.MAX_THREADS


@pytest.mark.parametrize("setting", ["3", "two", "0"])
def test_a_thread_count_out_of_range_is_refused_by_name(monkeypatch, setting):
    monkeypatch.setenv("ROADNOISE_THREADS", setting)
    with pytest.raises(ValueError, match="ROADNOISE_THREADS"):
        parallel.threads()


def test_thread_map_keeps_the_order():
    items = list(range(25))
    assert list(parallel.thread_map(lambda k: k * k, items)) == [k * k for k in items]


def test_a_simulation_is_the_same_to_the_last_bit_on_one_thread_and_two(monkeypatch):
    """The sections are split into the same parts and summed in the same order whatever the thread count."""
    import control

    rng = np.random.default_rng(5)
    poles = -rng.uniform(5.0, 50.0, 6) + 1j * rng.uniform(100.0, 900.0, 6)
    a = np.zeros((12, 12))
    for k, p in enumerate(poles):
        a[2 * k : 2 * k + 2, 2 * k : 2 * k + 2] = [[p.real, p.imag], [-p.imag, p.real]]
    system = control.ss(a, rng.standard_normal((12, 3)), rng.standard_normal((1, 12)), np.zeros((1, 3)))
    t = np.arange(2000) / 5000.0
    u = rng.standard_normal((3, t.size))
    forces = []
    for setting in ("1", "2"):
        monkeypatch.setenv("ROADNOISE_THREADS", setting)
        forces.append(simulation.simulate(system, simulation.RoadInput(t, t, u, 1.0, "noise")).force)
    np.testing.assert_array_equal(forces[0], forces[1])
