"""The cross-section tire's modal reduction: loaded modes by component-mode synthesis (Fig. 4-5)."""

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.analysis import band_errors
from roadnoise_utils.repro import stages
from roadnoise_utils.tire.cross_section import modal as section_modal
from roadnoise_utils.tire.cross_section import stages as section_stages

TIRE = "165_65R14_cross_section"
FREQS = np.arange(0.0, 251.0, 10.0)  # notebook 09's check (section 7)


@pytest.fixture(scope="module")
def built():
    return section_stages.section_tire(TIRE), ru.stages.solve_static(TIRE)


def _rel_rms(approx, ref, axis=-1):
    return np.sqrt(np.mean(np.abs(approx - ref) ** 2, axis=axis) / np.mean(np.abs(ref) ** 2, axis=axis))


@pytest.mark.parametrize("name", [TIRE, "195_65R15_cross_section"])
def test_the_synthesis_equals_the_frozen_model_solved_directly(name):
    """Loaded modes from free modes + residual flexibility vs the footprint solve with the laws
    frozen at the reference mode: only the residual's inertia differs (it grows as (f / f_free)^2).
    The 165's inputs are notebook 09's (one cached computation for both)."""
    f_ref = stages.modal_reduction(TIRE).reference_frequency
    check = section_stages.frozen_check(name, f_ref, FREQS)
    reduced, direct = check.synthesis, check.direct
    assert np.all(check.eigenvalues.real > 0)  # the 195's few spurious Re < 0 modes are left to the anchors
    assert _rel_rms(reduced.H_tot, direct.H_tot) < 2e-3
    assert _rel_rms(reduced.G_H, direct.G_H) < 3e-3
    assert np.abs(reduced.H_points - direct.hub.T).max() < 5e-3 * np.abs(direct.hub).max()
    tasselli = direct.H_tasselli().T  # some nearly cancel inside: error against the largest
    assert np.abs(reduced.H - tasselli).max() < 5e-3 * np.abs(tasselli).max()
    assert np.abs(reduced.H_tot[0] - direct.H_tot[0]) < 1e-9 * np.abs(direct.H_tot[0])  # static anchor exact


def test_the_storage_frozen_model_has_real_loaded_modes():
    """The paper's FET70Hz has no loss: its loaded modes are real, and they are the complex
    model's modes but for the loss (the frequencies within 1 %)."""
    storage = stages.modal_reduction(TIRE, frozen="storage", damping="identified").frozen_eigenvalues
    lossy = stages.modal_reduction(TIRE).frozen_eigenvalues
    assert np.abs(storage.imag).max() < 1e-9 * np.abs(storage.real).max()
    low = storage.real < (2 * np.pi * 250.0) ** 2
    np.testing.assert_allclose(np.sqrt(storage.real[low]), np.sqrt(lossy.real[low]), rtol=1e-2)


def test_the_papers_procedure_follows_the_viscoelastic_tire(built):
    """Identified damping + complex frozen moduli + quasi-static anchors against the direct FRFs:
    exact at 0 Hz (to the Ritz bases), within 5 % below 100 Hz; the reference is the mode that carries H_tot(0)."""
    visco = stages.frf_visco(TIRE)
    reduced = stages.modal_reduction(TIRE)
    assert abs(reduced.reference_frequency - visco.freqs[np.argmax(np.abs(visco.H_tot[:251]))]) < 2.0
    np.testing.assert_allclose(reduced.frf.H[:, 0], visco.H[:, 0], rtol=1e-4)  # two Ritz bases: 2e-5 apart
    errors = band_errors(visco.freqs, visco.H_tot, reduced.frf.H_tot)["complex rel. RMS"]
    assert errors.iloc[0] < 0.05
    table = reduced.mode_table()
    assert (table["damping from"] == "identified").sum() == reduced.identification.freqs.size
    assert table["frequency (Hz)"].max() > 500.0  # loaded modes to at least 2 f_band


def test_section_modal_reduction_refuses_bad_options(built):
    tire, static = built
    visco = stages.frf_visco(TIRE)
    with pytest.raises(ValueError, match="frozen = 'liquid'"):
        section_modal.section_modal_reduction(tire, static, visco, frozen="liquid")
    with pytest.raises(ValueError, match="storage model has no loss"):
        section_modal.section_modal_reduction(tire, static, visco, frozen="storage", damping="model")
    with pytest.raises(ValueError, match="f_band"):
        section_modal.section_modal_reduction(tire, static, visco, f_band=0.0)
    with pytest.raises(ValueError, match="anchors must start at 0"):
        section_modal.section_modal_reduction(tire, static, visco, anchors=(0.1, 1.0))
    with pytest.raises(TypeError, match="FRFResult"):
        section_modal.section_modal_reduction(tire, static, "visco")


def test_loaded_modes_solved_by_left_right_parity_are_those_of_one_solve(built):
    """The symmetric and antisymmetric free modes solved apart, and the loaded-mode matrix's two
    parity blocks apart: the same eigenvalues as one solve of each; antisymmetric loaded modes
    move no hub force."""
    tire, static = built
    band = section_modal.reduction_band(250.0)  # (400, 1250) Hz: the modal stages' reductions, cached
    even = section_modal.EvenFootprint.build(tire, static, *band, section_stages.footprint_reductions(TIRE, *band))
    laws = section_modal.frozen_laws(tire.ops.laws, 2 * np.pi * 80.0)
    red = even.harmonics[3]
    k = red.projected.dynamic_stiffness(laws, np.zeros(1), inertia=False)[0]
    split, _, parity = section_modal._modes_by_parity(k, red.projected.mass, red.mirror)
    whole, _ = section_modal._eig_mass(k, red.projected.mass)
    assert set(parity) == {1, -1}
    np.testing.assert_allclose(np.sort_complex(split), np.sort_complex(whole), rtol=1e-9)
    modes = section_modal.section_loaded_modes(even, laws, 1250.0)
    free = section_modal.free_modes(even, laws, 1250.0)
    weight = even.pair_weight
    k_loaded = np.diag(free.eigenvalues) + free.shapes.T @ np.linalg.solve(
        next(even.receptances(np.zeros(1), laws, inertia=False))[1][0] / weight[None, :]
        - (free.shapes / free.eigenvalues) @ free.shapes.T,
        free.shapes,
    )
    one = np.sort_complex(np.linalg.eigvals(k_loaded))
    one = one[one.real > 0]
    np.testing.assert_allclose(np.sort_complex(modes.eigenvalues), one, rtol=1e-7)
    odd = np.isin(modes.harmonic * 1000 + modes.order, (free.harmonic * 1000 + free.order)[free.parity < 0])
    assert np.abs(modes.hub_gain[odd]).max() < 1e-9 * np.abs(modes.hub_gain).max()
