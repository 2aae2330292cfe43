"""The tasselli's road kernels: averages in space, filters in wavenumber, the 5 cm resolution."""

from __future__ import annotations

import numpy as np

import roadnoise_utils as ru
from roadnoise_utils.road import kernels
from roadnoise_utils.road.input import profile_input


def test_road_kernels_average_correctly(flat):
    """A constant road lifts every tassello by the same amount; a ramp by its height at the centre."""
    const = profile_input(flat, lambda s: np.full_like(s, 2e-3), 5.0, (0.0, 0.01))
    assert np.allclose(const.u, 2e-3, rtol=1e-12)
    ramp = profile_input(flat, lambda s: 0.01 * s, 5.0, (0.0, 0.001))
    expected = 0.01 * flat.tasselli.centre_x
    assert np.allclose(ramp.u[:, 0], expected, rtol=0, atol=1e-4 * np.abs(expected).max())  # grid quadrature


def test_kernels_integrate_to_one_and_pass_long_waves(flat):
    k, _ = kernels.tassello_kernels(flat.tasselli, 1e-4)
    assert np.allclose(np.trapezoid(k, dx=1e-4, axis=1), 1.0, rtol=1e-12)
    gains = kernels.kernel_transforms(flat, np.array([0.0, 0.1, 50.0]))
    assert np.allclose(gains[:, 0], 1.0, rtol=1e-9)  # a constant road passes whole
    assert np.all(np.abs(gains[:, 1]) > 0.999)  # a 10 m wave too
    assert np.all(np.abs(gains[:, 2]) < np.abs(gains[:, 1]))  # 2 cm waves are averaged down


def test_tassellation_error_vanishes_for_long_waves(flat, fet):
    point_frf = ru.frf_visco(fet, flat, [100.0], progress=False).H_points[:, 0]
    errors = kernels.tassellation_error(flat, point_frf, np.array([20.0, 1.0, 0.05]))
    assert errors[0] < 1e-4 < errors[2] and errors[0] < errors[1] < errors[2]
