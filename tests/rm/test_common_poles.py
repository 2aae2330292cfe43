"""One pole set for all tasselli: fast relaxed vector fitting and its shared state space (Eq. 1-3)."""

from __future__ import annotations

import control
import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.rm.realisation import frequency_response, shared_realisation
from tests.rm.conftest import BAND_FREQS


def _common_system(n_responses: int = 6, seed: int = 7):
    """Responses sharing four lightly damped pole pairs, each with its own residues and constant."""
    rng = np.random.default_rng(seed)
    omega = 2 * np.pi * np.array([45.0, 92.0, 150.0, 215.0])
    upper = -rng.uniform(0.01, 0.05, omega.size) * omega + 1j * omega
    poles = np.concatenate([upper, upper.conj()])
    s = 2j * np.pi * BAND_FREQS
    rows = []
    for _ in range(n_responses):
        r = (rng.uniform(0.2, 2, omega.size) + 1j * rng.uniform(-0.5, 0.5, omega.size)) * 1e6
        r = np.concatenate([r, r.conj()])
        rows.append((r[None, :] / (s[:, None] - poles[None, :])).sum(axis=1) + rng.uniform(1e3, 3e3))
    return poles, np.array(rows)


def test_recovers_known_common_poles():
    poles, H = _common_system()
    fits = ru.fit_tasselli(BAND_FREQS, H, n_poles=8, common_poles=True)
    assert fits.common_poles and fits.n_states == 8
    for fit in fits:
        assert np.array_equal(fit.poles, fits[0].poles)
        assert fit.rms_error < 1e-10
    assert np.sort_complex(fits[0].poles) == pytest.approx(np.sort_complex(poles), rel=1e-8)


def test_common_poles_keep_the_best_iteration():
    _, H = _common_system(seed=3)
    fits = ru.fit_tasselli(BAND_FREQS, H, n_poles=8, common_poles=True, iterations=12, tolerance=1e-12)
    worst = np.max([fit.errors for fit in fits], axis=0)  # worst row's error after each relocation
    assert fits[0].best_iteration == int(np.argmin(worst))
    assert fits.rms_errors.max() == pytest.approx(worst.min(), rel=1e-9)


def test_common_pole_tire_fits_every_tassello_with_few_states(tire, paper_fits):
    """The paper tire's 73 local FRFs with one set of 18 poles: 18 states against 13 per tassello,
    every tassello within 1 %, and the fits' sum following the direct H_tot within the bound the
    tasselli's own errors set (triangle inequality)."""
    visco = ru.stages.frf_visco(tire)
    fits = ru.fit_tasselli(visco.freqs, visco.H, n_poles=18, f_max=250.0, common_poles=True)
    assert fits.n_states == 18 < paper_fits.n_states == 13 * len(paper_fits)
    assert fits.rms_errors.max() < 0.01
    band = visco.freqs <= 250.0
    total = fits.responses(visco.freqs[band]).sum(axis=0)
    h_tot = visco.H_tot[band]
    bound = np.sum(fits.rms_errors * np.linalg.norm(visco.H[:, band], axis=1)) / np.linalg.norm(h_tot)
    assert np.linalg.norm(total - h_tot) / np.linalg.norm(h_tot) <= bound + 1e-10
    tire_F = ru.assemble_fixed_hub(fits)
    assert tire_F.nstates == 18 and tire_F.ninputs == len(fits)
    check = np.array([0.0, 33.0, 80.0, 151.0, 249.0])
    fitted = fits.responses(check)
    assert np.max(np.abs(frequency_response(tire_F, check) - fitted)) <= 1e-10 * np.max(np.abs(fitted))


def test_simulated_common_pole_tire_equals_python_control():
    """The simulation runs a mode driven by many inputs as one mixed input: the same force as
    python-control's forced_response (same FOH assumption)."""
    _, H = _common_system(n_responses=5, seed=11)
    H[2] = H[2] + np.real(H[2, 0]) * 0.3 / (1 + 1j * BAND_FREQS / 60.0)  # a response that needs the real pole
    fits = ru.fit_tasselli(BAND_FREQS, H, n_poles=9, common_poles=True)
    system = ru.assemble_fixed_hub(fits)
    assert system.nstates == 9
    rng = np.random.default_rng(5)
    t = np.arange(400) / 4000.0
    u = 1e-3 * rng.standard_normal((system.ninputs, t.size))
    road = ru.RoadInput(t=t, distance=t, u=u, speed=1.0, description="noise")
    reference = control.forced_response(system, T=t, U=u).outputs
    assert np.allclose(ru.simulate(system, road).force, reference, rtol=0, atol=1e-9 * np.abs(reference).max())


def test_shared_realisation_needs_common_poles(paper_fits):
    with pytest.raises(ValueError, match="same poles"):
        shared_realisation(paper_fits.fits[:2])
    with pytest.raises(ValueError, match="common_poles = 'yes'"):
        ru.fit_tasselli(BAND_FREQS, _common_system()[1], common_poles="yes")
