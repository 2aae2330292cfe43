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
