"""Vector fitting and the state-space tire (paper Eq. 1-4, Fig. 6)."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.analysis import relative_rms_error
from roadnoise_utils.rm.fitting import vector_fit
from tests.rm.conftest import BAND_FREQS


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_recovers_known_8_pole_system(seed, known_system):
    poles, _, frf = known_system(seed)
    fit = vector_fit(BAND_FREQS, frf, n_poles=8)
    assert np.sort_complex(fit.poles) == pytest.approx(np.sort_complex(poles), rel=1e-8)
    assert fit.rms_error < 1e-10
    assert fit.direct == pytest.approx(2e3, rel=1e-8)


def test_bounded_error_with_noise(known_system):
    poles, _, frf = known_system(3)
    rng = np.random.default_rng(42)
    noise = 0.01 * np.abs(frf).mean() * (rng.standard_normal(frf.size) + 1j * rng.standard_normal(frf.size))
    fit = vector_fit(BAND_FREQS, frf + noise, n_poles=8)
    clean_error = np.linalg.norm(fit(BAND_FREQS) - frf) / np.linalg.norm(frf)
    assert fit.rms_error < 0.03  # the noise itself is ~1.4 % of the mean modulus
    assert clean_error < 0.01  # the fit averages the noise out
    assert np.sort_complex(fit.poles).imag == pytest.approx(np.sort_complex(poles).imag, rel=0.02)


@pytest.mark.parametrize("n_poles", [5, 8, 11])
def test_models_are_real_and_stable(flat, fet, n_poles):
    visco = ru.frf_visco(fet, flat, BAND_FREQS, progress=False)
    rows = visco.H[::9]
    fits = ru.fit_tasselli(BAND_FREQS, rows, n_poles=n_poles)
    s = 2j * np.pi * BAND_FREQS
    for fit, data in zip(fits, rows):
        assert fit.order == n_poles
        assert np.all(fit.poles.real < 0)
        # conjugate symmetry: G(-jw) = conj(G(jw)), i.e. a real impulse response
        neg = (fit.residues[None, :] / (-s[:, None] - fit.poles[None, :])).sum(axis=1) + fit.direct
        assert np.allclose(neg, np.conj(fit(BAND_FREQS)), rtol=1e-12, atol=1e-9 * np.abs(fit(BAND_FREQS)).max())
        assert fit.dc_gain == pytest.approx(data[0].real, rel=1e-10)


def test_bad_data_is_refused(known_system):
    _, _, frf = known_system()
    with pytest.raises(ValueError, match="NaN"):
        vector_fit(BAND_FREQS, np.where(BAND_FREQS > 100, np.nan, frf))
    with pytest.raises(ValueError, match="fewer than"):
        vector_fit(BAND_FREQS[:8], frf[:8], n_poles=8)
    with pytest.raises(ValueError, match="strictly increasing"):
        vector_fit(BAND_FREQS[::-1], frf)
    with pytest.raises(ValueError, match="n_poles"):
        vector_fit(BAND_FREQS, frf, n_poles=0)
    with pytest.raises(ValueError, match="weight"):
        vector_fit(BAND_FREQS, frf, weight="loud")


def test_every_tassello_within_one_percent(paper_fits):
    assert paper_fits.rms_errors.max() < 0.01


def test_dc_gains_are_the_static_influences(paper_fits, fet, flat):
    static_influence = ru.frf_visco(fet, flat, [0.0], progress=False).H[:, 0].real
    dc = np.ravel(ru.assemble_fixed_hub(paper_fits).dcgain())
    assert np.allclose(dc, static_influence, rtol=1e-9)


def test_keeps_the_best_iteration_not_the_last(tire):
    """A tassello whose error rises again after the second relocation (18 poles on the paper tire's
    tassello 9): the fit keeps the earlier poles, and their error is the one a run capped at that
    iteration (where it is the last) returns."""
    visco = ru.stages.frf_visco(tire)
    band = visco.freqs <= 250.0
    f, h = visco.freqs[band], visco.H[8, band]
    fit = vector_fit(f, h, n_poles=18, iterations=30, tolerance=1e-12)
    assert fit.iterations == 30 and len(fit.errors) == 31
    assert fit.rms_error == min(fit.errors) == fit.errors[fit.best_iteration]
    assert fit.best_iteration < fit.iterations and fit.errors[-1] > 1.1 * fit.rms_error
    assert relative_rms_error(fit(f), h) == pytest.approx(fit.rms_error, rel=1e-9)
    capped = vector_fit(f, h, n_poles=18, iterations=fit.best_iteration, tolerance=1e-12)
    assert capped.best_iteration == capped.iterations == fit.best_iteration
    assert capped.rms_error == pytest.approx(fit.rms_error, rel=1e-12)
    assert np.allclose(capped.poles, fit.poles, rtol=1e-12)


def test_raising_the_iteration_cap_never_worsens_a_fit(tire):
    visco = ru.stages.frf_visco(tire)
    rows = visco.H[::8]
    errors = [
        ru.fit_tasselli(visco.freqs, rows, n_poles=18, f_max=250.0, iterations=cap, tolerance=1e-12).rms_errors
        for cap in (2, 6, 20)
    ]
    assert np.all(errors[1] <= errors[0]) and np.all(errors[2] <= errors[1])


def test_fits_the_data_band_unless_told(known_system):
    _, _, frf = known_system(1)
    wide = np.arange(0.0, 400.0)
    h = np.concatenate([frf, frf[-1] * np.ones(wide.size - frf.size)])  # any data beyond 250 Hz
    assert ru.fit_tasselli(wide, h).band == (0.0, 399.0)
    assert ru.fit_tasselli(wide, h, f_max=250.0).band == (0.0, 250.0)


def test_automatic_order_is_the_lowest_even_order_reaching_the_target(known_system):
    poles, _, frf = known_system(2, n_pairs=4)  # exactly 8 poles and a constant
    fits = ru.fit_tasselli(BAND_FREQS, np.array([frf, 0.5 * frf]), n_poles="auto", target_error=1e-8)
    assert fits.n_poles == 8 and fits.rms_errors.max() <= 1e-8
    assert ru.fit_tasselli(BAND_FREQS, frf, n_poles=6).rms_errors.max() > 1e-8  # the order below does not
    with pytest.warns(ru.guards.RoadnoiseWarning, match="no even order up to 6 reaches target_error"):
        capped = ru.fit_tasselli(BAND_FREQS, frf, n_poles="auto", target_error=1e-8, max_poles=6)
    assert capped.n_poles == 6


def test_bad_automatic_order_options(known_system):
    _, _, frf = known_system()
    with pytest.raises(ValueError, match="'auto'"):
        ru.fit_tasselli(BAND_FREQS, frf, n_poles="many")
    with pytest.raises(ValueError, match="target_error .* only with n_poles='auto'"):
        ru.fit_tasselli(BAND_FREQS, frf, n_poles=8, target_error=0.01)
    with pytest.raises(ValueError, match="target_error = -1"):
        ru.fit_tasselli(BAND_FREQS, frf, n_poles="auto", target_error=-1)
    with pytest.raises(ValueError, match="max_poles = 1"):
        ru.fit_tasselli(BAND_FREQS, frf, n_poles="auto", max_poles=1)


def test_a_band_beyond_the_frfs_is_fitted_as_far_as_they_go_with_a_warning(known_system):
    from roadnoise_utils.guards import RoadnoiseWarning

    _, _, frf = known_system(seed=2)
    with pytest.warns(RoadnoiseWarning, match="f_max = 400 Hz is beyond the FRFs' last frequency 250 Hz"):
        fits = ru.fit_tasselli(BAND_FREQS, frf[None, :], n_poles=8, f_max=400.0)
    assert fits.band == (0.0, 250.0)


def test_a_weight_that_is_zero_everywhere_is_refused_naming_the_row(known_system):
    _, _, frf = known_system(seed=3)
    weight = np.ones((2, BAND_FREQS.size))
    weight[1] = 0.0
    with pytest.raises(ValueError, match=r"weight is zero at every frequency of FRF row\(s\) \[1\]"):
        ru.fit_tasselli(BAND_FREQS, np.vstack([frf, frf]), n_poles=8, weight=weight)


def test_frfs_too_large_to_fit_and_ragged_rows_are_refused_with_a_message(known_system):
    _, _, frf = known_system(seed=4)
    with pytest.raises(ValueError, match=r"H: values up to [0-9.]+e\+30[0-9], valid range is \|H\| <= 1e\+150"):
        ru.fit_tasselli(BAND_FREQS, frf[None, :] * 1e295, n_poles=8)  # was a raw overflow warning
    with pytest.raises(ValueError, match="every row as long as freqs"):
        ru.fit_tasselli(BAND_FREQS, [frf, frf[:-3]], n_poles=8)


def test_confine_moves_poles_onto_the_limits():
    """Closed form: a pole above the band gets damping ratio OUT_OF_BAND_DAMPING, a pole slower than
    SLOWEST_DECAY x omega_low that decay; the imaginary parts and every other pole stay."""
    from roadnoise_utils.rm import vf_kernels

    poles = np.array([-1e-6 + 2j, -1e-6 - 2j, -1e-6 + 0.5j, -0.3 + 0.5j, -1e-9 + 0j, -0.2 + 3j])
    confined = vf_kernels.confine(poles, omega_low=0.01)
    floor, zeta = vf_kernels.SLOWEST_DECAY * 0.01, vf_kernels.OUT_OF_BAND_DAMPING
    expected = np.array(
        [
            -zeta * 2 / np.sqrt(1 - zeta**2) + 2j,
            -zeta * 2 / np.sqrt(1 - zeta**2) - 2j,
            -floor + 0.5j,
            poles[3],
            -floor + 0j,
            poles[5],  # above the band but damped 6.7 %: left alone
        ]
    )
    assert confined == pytest.approx(expected, rel=1e-12)
    assert -confined[0].real / abs(confined[0]) == pytest.approx(zeta, rel=1e-12)


def test_fitted_poles_stay_within_what_the_band_supports(paper_fits):
    """No pole of the pipeline's fits is nearly undamped above the band or slower than the grid resolves."""
    from roadnoise_utils.rm import vf_kernels

    top, low = 2 * np.pi * paper_fits.band[1], 2 * np.pi * paper_fits.freqs[paper_fits.freqs > 0][0]
    for fit in paper_fits:
        above = np.abs(fit.poles.imag) > top
        assert np.all(-fit.poles.real[above] >= vf_kernels.OUT_OF_BAND_DAMPING * np.abs(fit.poles[above]) * (1 - 1e-9))
        assert np.all(-fit.poles.real >= vf_kernels.SLOWEST_DECAY * low * (1 - 1e-9))


def test_a_relocation_with_coinciding_poles_is_that_of_one_pole_plus_the_unmovable_twin():
    """Two identical poles give identical columns: the least squares are rank deficient and their
    minimum-norm solution splits the coefficient between the twins. Sigma is then the one-pole
    sigma, and its zeros are that sigma's zero plus the twin pole itself (a mode sigma cannot
    see). Householder QR leaves the deficient factor at ~1e-16, not 0: solved as if regular, the
    zeros of one row came out near -9e5."""
    from roadnoise_utils.rm import vf_kernels

    s = 1j * np.linspace(0.0, 1.0, 200)
    h = (1.0 / (s + 0.3) + 0.2)[None, :] * np.array([[1.0], [2.0 - 0.5j]])
    w = np.ones(h.shape)
    upper = np.zeros((2, 0), complex)
    pole = -0.05
    twins = vf_kernels.relocate(s, h, w, np.full((2, 2), pole), upper)
    single = vf_kernels.relocate(s, h, w, np.full((2, 1), pole), upper)
    for found, alone in zip(twins, single):
        expected = np.sort_complex(np.array([pole, alone[0]]))
        np.testing.assert_allclose(np.sort_complex(found), expected, rtol=1e-8, atol=1e-10)
