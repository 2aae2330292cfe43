"""Damping identification and modal reduction (paper stages 3-5) against the direct viscoelastic model."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.response.modal_reduction import identify_modes


@pytest.fixture(scope="module")
def visco(fet, flat):
    return ru.frf_visco(fet, flat, np.arange(0.0, 301.0, 1.0), progress=False)


@pytest.fixture(scope="module")
def reduced(fet, flat, visco):
    return ru.modal_reduction(fet, flat, visco=visco)


def test_identification_recovers_a_known_system():
    """Noise-free FRF of three hysteretic modes plus a residual: poles recovered to 1e-6."""
    f = np.arange(0.0, 301.0, 1.0)
    w = 2 * np.pi * f
    wr = 2 * np.pi * np.array([62.0, 118.0, 201.0])
    eta = np.array([0.05, 0.03, 0.02])
    residues = np.array([3.0e9, 2.0e9 + 5e8j, 4.0e9])
    frf = (residues[None, :] / (wr**2 * (1 + 1j * eta) - w[:, None] ** 2)).sum(axis=1) + 1.0e4 - 0.01 * w**2
    ident = identify_modes(f, frf, f_max=250.0)
    assert ident.freqs == pytest.approx(wr / (2 * np.pi), rel=1e-6)
    assert ident.loss_factor == pytest.approx(eta, rel=1e-5)
    assert ident.rms_error < 1e-8


def test_identification_bad_input():
    f = np.arange(0.0, 10.0)
    with pytest.raises(ValueError, match="frf contains NaN or inf"):
        identify_modes(f, np.full(10, np.nan + 0j))
    with pytest.raises(ValueError, match="same length"):
        identify_modes(f, np.ones(9, complex))
    with pytest.raises(ValueError, match="no resonance peak"):
        identify_modes(f, np.ones(10, complex))


def test_identified_damping_positive_and_consistent(reduced):
    ident = reduced.identification
    assert ident.freqs.size >= 4  # the first four vertical modes at least (paper Fig. 14)
    assert np.all(ident.damping > 0)
    measured = np.isfinite(ident.damping_half_power)
    assert np.all(np.abs(ident.damping[measured] / ident.damping_half_power[measured] - 1) < 0.2)


def test_reference_frequency_is_the_first_vertical_mode(reduced):
    assert reduced.reference_frequency == pytest.approx(reduced.identification.freqs[0])
    assert 75 < reduced.reference_frequency < 85


def test_modes_reach_twice_the_band(reduced):
    assert reduced.model.freqs.max() >= 500.0


def test_modal_local_frfs_match_direct(reduced, visco):
    """Every tassello within 5 % at the freezing frequency and 0.5 % at 0 Hz."""
    frf = reduced.frf
    k = int(np.argmin(np.abs(visco.freqs - reduced.reference_frequency)))
    assert np.all(np.abs(frf.H[:, k] - visco.H[:, k]) <= 0.05 * np.abs(visco.H[:, k]))
    assert np.all(np.abs(frf.H[:, 0] - visco.H[:, 0]) <= 0.005 * np.abs(visco.H[:, 0]))


def test_the_tassello_table_is_the_direct_comparison(reduced, visco):
    """local_frf_errors gives the largest and median tassello error the assertion above bounds."""
    table = ru.analysis.local_frf_errors(visco, {"modal": reduced.frf}, reduced.reference_frequency)
    k = int(np.argmin(np.abs(visco.freqs - reduced.reference_frequency)))
    at_f = np.abs(reduced.frf.H[:, k] / visco.H[:, k] - 1)
    assert table.loc["modal", "max at f"] == pytest.approx(at_f.max(), rel=1e-9)
    assert table.loc["modal", "median at f"] == pytest.approx(np.median(at_f), rel=1e-9)
    assert table.attrs["f"] == visco.freqs[k]


def test_damping_comparison_names_the_identified_modes(reduced):
    """One row per identified mode, in order, the identified loss factor over the frozen model's own."""
    comparison = reduced.damping_comparison()
    ident = reduced.identification
    assert len(comparison) == ident.freqs.size
    assert comparison["eta identified"].to_numpy() == pytest.approx(ident.loss_factor, rel=1e-12)
    eta_frozen = (reduced.frozen_eigenvalues.imag / reduced.frozen_eigenvalues.real)[comparison.index - 1]
    assert comparison["ratio"].to_numpy() == pytest.approx(ident.loss_factor / eta_frozen, rel=1e-12)


def test_paper_variant_sums_well_below_100_hz(fet, flat, visco):
    """The paper's FET-frozen model with identified damping: Fig. 5 accuracy, decreasing with frequency."""
    paper = ru.modal_reduction(fet, flat, visco=visco, frozen="storage", damping="identified")
    errors = ru.analysis.band_errors(visco.freqs, visco.H_tot, paper.frf.H_sum)["complex rel. RMS"].to_numpy()
    assert errors[0] < 0.1
    assert np.all(np.diff(errors) > 0)


def test_frozen_model_underestimates_frequencies_above_freezing(reduced, visco):
    """Paper's approximation (a)."""
    peaks = ru.analysis.peak_comparison(visco.freqs, visco.H_tot, reduced.frf.H_tot, f_max=260)
    above = peaks["reference (Hz)"] > reduced.reference_frequency + 5
    assert above.sum() >= 3 and np.all(peaks.loc[above, "shift (%)"] < 0)


def test_hub_frf_static_value(reduced, visco, flat):
    """|G_H(0)| is the vertical stiffness of the loaded tire (sign: a rising hub is pulled down)."""
    assert visco.G_H[0].real < 0
    assert abs(visco.G_H[0]) == pytest.approx(flat.vertical_stiffness, rel=0.01)
    assert reduced.frf.G_H[0] == pytest.approx(visco.G_H[0], rel=1e-9)
    k = int(np.argmin(np.abs(visco.freqs - reduced.reference_frequency)))
    assert abs(reduced.frf.G_H[k] / visco.G_H[k] - 1) < 0.05


def test_only_doubly_symmetric_modes_load_the_hub(fet, flat):
    """The reduction to the symmetric class is exact: every other mode has zero hub gain."""
    modes = ru.loaded_modes(fet, flat, n_modes=40)
    scale = np.abs(modes.hub_gain).max()
    assert np.all(np.abs(modes.hub_gain[~modes.vertical]) < 1e-8 * scale)
    assert np.all(np.abs(modes.hub_gain[modes.vertical][:5]) > 1e-2 * scale)


def test_bad_options(fet, flat, visco):
    with pytest.raises(ValueError, match="frozen"):
        ru.modal_reduction(fet, flat, visco=visco, frozen="liquid")
    with pytest.raises(ValueError, match="storage model has no loss"):
        ru.modal_reduction(fet, flat, visco=visco, frozen="storage", damping="model")
    with pytest.raises(ValueError, match="anchors"):
        ru.modal_reduction(fet, flat, visco=visco, anchors=(10.0, 100.0))


def test_the_mode_shapes_sign_does_not_depend_on_round_off(fet, flat):
    """Each shape's sign is fixed by a generic projection, not by its largest entry (which, on a mirror-symmetric
    tire, ties between mirrored nodes and is chosen by round-off): a flipped or slightly perturbed shape gets the
    same sign back, for every mode."""
    from roadnoise_utils.tire.ring.modes import _shape_signs

    shapes = ru.loaded_modes(fet, flat, n_modes=40).shapes
    assert np.all(_shape_signs(shapes) == 1.0)
    assert np.all(_shape_signs(-shapes) == -1.0)
    perturbed = shapes * (1.0 + 1e-12 * np.random.default_rng(1).standard_normal(shapes.shape))
    assert np.all(_shape_signs(perturbed) == 1.0)
    pair = np.zeros((shapes.shape[0], 1))
    pair[[3, 7]] = [[1.0], [-1.0]]  # an antisymmetric pair of equal magnitude: argmax of |v| is a tie
    assert _shape_signs(pair)[0] == -_shape_signs(-pair)[0]


def test_identified_damping_goes_to_the_nearest_visible_mode():
    """Modes visible at the hub at 82, 121 and 244 Hz; H_tot's fit resolves 80 and 242 Hz (the 121 Hz mode
    too weak in it, the air's resonance strong): the identified loss factors go to 82 and 244 Hz, the
    121 Hz mode keeps the frozen model's own; an invisible mode keeps its own too."""
    from roadnoise_utils.response.modal_reduction import ModeIdentification, apply_identified_damping

    freqs = np.array([40.0, 82.0, 121.0, 244.0])
    eigenvalues = (2 * np.pi * freqs) ** 2 * (1 + 0.1j)
    hub_gain = np.array([1e-6, 1.0, 0.5, 0.8])
    ident = ModeIdentification(
        np.array([80.0, 242.0]), np.array([0.2, 0.02]), np.full(2, np.nan), np.ones(2), (0j, 0j), (0.0, 250.0), 0.0
    )
    damped, source = apply_identified_damping(eigenvalues, hub_gain, ident, "complex", 250.0)
    assert list(source) == ["frozen model", "identified", "frozen model", "identified"]
    assert damped.imag / damped.real == pytest.approx([0.1, 0.2, 0.1, 0.02])


def test_identified_and_visible_modes_are_matched_in_order_with_the_least_distance():
    """Closed cases: matched greedily, 100 Hz would take 106 Hz and leave 110 Hz the 90 Hz mode (26 Hz
    in all); in order the two cost 14 Hz. The longer list's extra entries are left out, either side."""
    from roadnoise_utils.response.modal_reduction import matched_in_order

    assert matched_in_order(np.array([100.0, 110.0]), np.array([90.0, 106.0])) == [(0, 0), (1, 1)]
    assert matched_in_order(np.array([80.0, 242.0]), np.array([82.0, 121.0, 244.0])) == [(0, 0), (1, 2)]
    assert matched_in_order(np.array([80.0, 100.0, 120.0]), np.array([79.0, 119.0])) == [(0, 0), (2, 1)]
    assert matched_in_order(np.array([]), np.array([81.0])) == []
