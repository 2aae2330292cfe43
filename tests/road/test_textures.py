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
