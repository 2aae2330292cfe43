"""Vector fitting and the state-space tire (paper Eq. 1-4, Fig. 6)."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.fitting import vector_fit
from roadnoise_utils.statespace import frequency_response

FREQS = np.arange(0.0, 251.0, 1.0)


def _system(seed: int = 0, n_pairs: int = 4):
    """A random stable system: lightly damped pairs spread over the band, plus a constant."""
    rng = np.random.default_rng(seed)
    f = np.sort(rng.uniform(30, 240, n_pairs))
    omega = 2 * np.pi * f
    poles = -rng.uniform(0.01, 0.05, n_pairs) * omega + 1j * omega
    residues = (rng.uniform(0.5, 2, n_pairs) + 1j * rng.uniform(-0.5, 0.5, n_pairs)) * 1e6
    poles = np.concatenate([poles, poles.conj()])
    residues = np.concatenate([residues, residues.conj()])
    s = 2j * np.pi * FREQS
    frf = (residues[None, :] / (s[:, None] - poles[None, :])).sum(axis=1) + 2e3
    return poles, residues, frf


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_recovers_known_8_pole_system(seed):
    poles, _, frf = _system(seed)
    fit = vector_fit(FREQS, frf, n_poles=8)
    assert np.sort_complex(fit.poles) == pytest.approx(np.sort_complex(poles), rel=1e-8)
    assert fit.rms_error < 1e-10
    assert fit.direct == pytest.approx(2e3, rel=1e-8)


def test_bounded_error_with_noise():
    poles, _, frf = _system(3)
    rng = np.random.default_rng(42)
    noise = 0.01 * np.abs(frf).mean() * (rng.standard_normal(frf.size) + 1j * rng.standard_normal(frf.size))
    fit = vector_fit(FREQS, frf + noise, n_poles=8)
    clean_error = np.linalg.norm(fit(FREQS) - frf) / np.linalg.norm(frf)
    assert fit.rms_error < 0.03  # the noise itself is ~1.4 % of the mean modulus
    assert clean_error < 0.01  # the fit averages the noise out
    assert np.sort_complex(fit.poles).imag == pytest.approx(np.sort_complex(poles).imag, rel=0.02)


@pytest.mark.parametrize("n_poles", [5, 8, 11])
def test_models_are_real_and_stable(flat, fet, n_poles):
    visco = ru.frf_visco(fet, flat, FREQS, progress=False)
    rows = visco.H[::9]
    fits = ru.fit_tasselli(FREQS, rows, n_poles=n_poles)
    s = 2j * np.pi * FREQS
    for fit, data in zip(fits, rows):
        assert fit.order == n_poles
        assert np.all(fit.poles.real < 0)
        # conjugate symmetry: G(-jw) = conj(G(jw)), i.e. a real impulse response
        neg = (fit.residues[None, :] / (-s[:, None] - fit.poles[None, :])).sum(axis=1) + fit.direct
        assert np.allclose(neg, np.conj(fit(FREQS)), rtol=1e-12, atol=1e-9 * np.abs(fit(FREQS)).max())
        assert fit.dc_gain == pytest.approx(data[0].real, rel=1e-10)


def test_bad_data_is_refused():
    _, _, frf = _system()
    with pytest.raises(ValueError, match="NaN"):
        vector_fit(FREQS, np.where(FREQS > 100, np.nan, frf))
    with pytest.raises(ValueError, match="fewer than"):
        vector_fit(FREQS[:8], frf[:8], n_poles=8)
    with pytest.raises(ValueError, match="strictly increasing"):
        vector_fit(FREQS[::-1], frf)
    with pytest.raises(ValueError, match="n_poles"):
        vector_fit(FREQS, frf, n_poles=0)
    with pytest.raises(ValueError, match="weight"):
        vector_fit(FREQS, frf, weight="loud")


def test_realization_matches_pole_residue_form():
    _, _, frf = _system(5)
    fit = vector_fit(FREQS, frf, n_poles=9)  # one real pole
    model = ru.realize(fit)
    assert model.nstates == 9
    response = frequency_response(model, FREQS)[0]
    assert np.max(np.abs(response - fit(FREQS))) <= 1e-12 * np.max(np.abs(frf))
    assert float(np.ravel(model.dcgain())[0]) == pytest.approx(fit.dc_gain, rel=1e-12)


@pytest.fixture(scope="module")
def pipeline_fits(tire):
    return ru.pipeline.tassello_fits(tire)


def test_every_tassello_within_one_percent(pipeline_fits):
    assert pipeline_fits.rms_errors.max() < 0.01


def test_assembled_tire_is_the_sum_of_its_fits(pipeline_fits, flat):
    tire_F = ru.assemble_fixed_hub(pipeline_fits)
    assert tire_F.ninputs == flat.tasselli.n and tire_F.noutputs == 1
    assert tire_F.nstates == pipeline_fits.n_poles * flat.tasselli.n
    assert np.all(np.linalg.eigvals(tire_F.A).real < 0)
    check = np.array([0.0, 33.0, 80.0, 151.0, 249.0])
    assembled = frequency_response(tire_F, check)
    fitted = pipeline_fits.responses(check)
    assert np.max(np.abs(assembled - fitted)) <= 1e-10 * np.max(np.abs(fitted))


def test_dc_gains_are_the_static_influences(pipeline_fits, fet, flat):
    static_influence = ru.frf_visco(fet, flat, [0.0], progress=False).H[:, 0].real
    dc = np.ravel(ru.assemble_fixed_hub(pipeline_fits).dcgain())
    assert np.allclose(dc, static_influence, rtol=1e-9)


def test_at_least_as_good_as_scikit_rf(pipeline_fits, tire):
    visco = ru.pipeline.visco_frf(tire, progress=False)
    rows = slice(0, None, 6)
    peer_errors, _ = ru.peers.skrf_vector_fit(visco.freqs, visco.H[rows], pipeline_fits.n_poles)
    assert np.all(pipeline_fits.rms_errors[rows] <= peer_errors)
