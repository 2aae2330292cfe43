"""Fixtures of the RM-stage tests: a known rational system on the fitted band."""

from __future__ import annotations

import numpy as np
import pytest

#: The fitted band of the tests (Hz).
BAND_FREQS = np.arange(0.0, 251.0, 1.0)


@pytest.fixture
def known_system():
    """``known_system(seed, n_pairs) -> (poles, residues, frf)``: a random stable system on :data:`BAND_FREQS`."""

    def make(seed: int = 0, n_pairs: int = 4):
        """A random stable system: lightly damped pairs spread over the band, plus a constant."""
        rng = np.random.default_rng(seed)
        f = np.sort(rng.uniform(30, 240, n_pairs))
        omega = 2 * np.pi * f
        poles = -rng.uniform(0.01, 0.05, n_pairs) * omega + 1j * omega
        residues = (rng.uniform(0.5, 2, n_pairs) + 1j * rng.uniform(-0.5, 0.5, n_pairs)) * 1e6
        poles = np.concatenate([poles, poles.conj()])
        residues = np.concatenate([residues, residues.conj()])
        s = 2j * np.pi * BAND_FREQS
        frf = (residues[None, :] / (s[:, None] - poles[None, :])).sum(axis=1) + 2e3
        return poles, residues, frf

    return make
