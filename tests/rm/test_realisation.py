"""Realisation: the fits as real block-diagonal state space, alone and assembled (paper Eq. 2-4)."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.rm.fitting import vector_fit
from roadnoise_utils.rm.realisation import frequency_response
from tests.rm.conftest import BAND_FREQS


def test_realization_matches_pole_residue_form(known_system):
    _, _, frf = known_system(5)
    fit = vector_fit(BAND_FREQS, frf, n_poles=9)  # one real pole
    model = ru.realize(fit)
    assert model.nstates == 9
    response = frequency_response(model, BAND_FREQS)[0]
    assert np.max(np.abs(response - fit(BAND_FREQS))) <= 1e-12 * np.max(np.abs(frf))
    assert float(np.ravel(model.dcgain())[0]) == pytest.approx(fit.dc_gain, rel=1e-12)


def test_assembled_tire_is_the_sum_of_its_fits(paper_fits, flat):
    tire_F = ru.assemble_fixed_hub(paper_fits)
    assert tire_F.ninputs == flat.tasselli.n and tire_F.noutputs == 1
    assert tire_F.nstates == paper_fits.n_poles * flat.tasselli.n
    assert np.all(np.linalg.eigvals(tire_F.A).real < 0)
    check = np.array([0.0, 33.0, 80.0, 151.0, 249.0])
    assembled = frequency_response(tire_F, check)
    fitted = paper_fits.responses(check)
    assert np.max(np.abs(assembled - fitted)) <= 1e-10 * np.max(np.abs(fitted))
