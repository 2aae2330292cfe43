"""Moving hub, road textures and the quarter car (paper stages 9-12)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.signal import coherence as estimated_coherence

import roadnoise_utils as ru
from roadnoise_utils.road import profile_input, texture_input

CAR = "midsize_195_65R15"


@pytest.mark.parametrize("name", ["rough", "smooth"])
def test_profile_psd_matches_target(name):
    """Averaged over 8 seeds, every octave within 10 % of the target (one seed: 30 %)."""
    spectrum = ru.textures.load_texture(name)
    bands = [(0.25, 0.5), (0.5, 1), (1, 2), (2, 4), (4, 8), (8, 16)]
    ratios = []
    for seed in range(8):
        n, g = ru.textures.profile_psd(ru.textures.generate_profile(spectrum, 200.0, 0.004, seed=seed))
        ratios.append(
            [np.mean(g[(n >= lo) & (n < hi)]) / np.mean(spectrum.psd(n[(n >= lo) & (n < hi)])) for lo, hi in bands]
        )
    ratios = np.array(ratios)
    assert np.all((ratios > 0.7) & (ratios < 1.3))
    assert np.all(np.abs(ratios.mean(axis=0) - 1) < 0.1)


def test_seed_reproduces_the_road():
    spectrum = ru.textures.load_texture("rough")
    a = ru.textures.generate_profile(spectrum, 50.0, 0.004, seed=7)
    b = ru.textures.generate_profile(spectrum, 50.0, 0.004, seed=7)
    c = ru.textures.generate_profile(spectrum, 50.0, 0.004, seed=8)
    assert np.array_equal(a.z, b.z) and not np.allclose(a.z, c.z)
    y = np.array([0.0, 0.02, 0.05])
    assert np.array_equal(
        ru.textures.generate_field(spectrum, 50.0, 0.004, y, 3).z,
        ru.textures.generate_field(spectrum, 50.0, 0.004, y, 3).z,
    )


def test_3d_tracks_have_the_target_coherence():
    spectrum = ru.textures.load_texture("rough")
    y = np.array([0.0, 0.1])
    field = ru.textures.generate_field(spectrum, 400.0, 0.004, y, seed=11)
    n, gamma2 = estimated_coherence(field.z[0], field.z[1], fs=250.0, nperseg=4096)
    band = (n > 1.0) & (n < 6.0)
    model = ru.textures.coherence(spectrum, n[band], 0.1) ** 2
    assert np.mean(np.abs(gamma2[band] - model)) < 0.1
    assert ru.textures.coherence(spectrum, np.array([0.0]), 0.1)[0] == pytest.approx(1.0)


def test_field_factored_by_blocks_and_groups_equals_the_whole_factor(monkeypatch):
    """Two wheels' tracks 1.5 m apart, factored block by block of wavenumbers and apart once they
    decouple, equal the field from one coherence matrix over all tracks and wavenumbers (1e-12)."""
    from scipy.special import gamma as gamma_fn
    from scipy.special import kv

    from roadnoise_utils.road import textures

    spectrum = ru.textures.load_texture("rough")
    y = np.array([-0.78, -0.75, -0.72, 0.72, 0.75, 0.78])
    monkeypatch.setattr(textures, "FIELD_BLOCK", 500)  # several blocks, the first ones coupled
    field = ru.textures.generate_field(spectrum, 60.0, 0.004, y, seed=5)
    # the reference: the formula of the module docstring, no cut-off, one Cholesky per wavenumber
    n, freqs = textures._grid(60.0, 0.004, y.size)
    rng = np.random.default_rng(5)
    white = (rng.standard_normal((freqs.size, y.size)) + 1j * rng.standard_normal((freqs.size, y.size))) / np.sqrt(2)
    nu = spectrum.local_exponent(freqs)[:, None, None] / 2.0
    x = 2 * np.pi * freqs[:, None, None] * np.abs(y[:, None] - y[None, :])[None]
    with np.errstate(invalid="ignore", over="ignore"):
        gamma = np.nan_to_num(x**nu * kv(nu, x) / (2 ** (nu - 1) * gamma_fn(nu)), nan=0.0)
    gamma[x == 0] = 1.0
    factor = np.linalg.cholesky(gamma + 1e-10 * np.eye(y.size))
    coeff = np.einsum("fij,fj->fi", factor, white) * np.sqrt(2.0 * spectrum.psd(freqs) / (n * 0.004))[:, None]
    reference = np.fft.irfft(0.5 * n * coeff.T, n, axis=1)
    assert np.abs(field.z - reference).max() < 1e-12 * np.abs(reference).max()
    # both paths were taken: the wheels are coupled in the first block and apart in the later ones
    assert textures.coherence(spectrum, freqs[:500], 1.44).max() > textures.INDEPENDENT
    assert textures.coherence(spectrum, freqs[500:], 1.44).max() < textures.INDEPENDENT


def test_bad_road_inputs(flat):
    with pytest.raises(ValueError, match="reference_psd"):
        ru.textures.RoadSpectrum("bad", -1e-6, 2.0, 2.0, 1.5, 0.05, 50.0)
    with pytest.raises(ValueError, match="min_wavelength.*5 cm"):
        ru.textures.RoadSpectrum("fine", 256e-6, 2.0, 2.0, 1.5, 0.03, 50.0)
    with pytest.raises(ValueError, match="step"):
        ru.textures.generate_profile(ru.textures.load_texture("rough"), 10.0, 0.02, seed=1)
    with pytest.raises(ValueError, match="speed"):
        profile_input(flat, lambda s: 0 * s, 0.0, (0.0, 1.0))
    with pytest.raises(ValueError, match="duration"):
        texture_input(flat, ru.textures.load_texture("rough"), 20.0, 0.0, seed=1)
