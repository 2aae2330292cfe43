"""The shared measures of analysis.py: the choice among equal candidates that round-off cannot make, the
tassello-by-tassello FRF errors, the damped components of a free decay."""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from roadnoise_utils.analysis import argmax_all, damped_components, local_frf_errors

finite = st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False)


@given(st.lists(finite, min_size=1, max_size=30), st.integers(0, 2**32 - 1))
def test_argmax_all_names_the_same_candidates_whatever_their_order_and_round_off(values, seed):
    """Every value within rtol of the largest, the largest included; the same set for the
    values reversed (a mirror image) and after a perturbation of one ulp (round-off)."""
    values = np.array(values)
    found = argmax_all(values)
    assert np.argmax(values) in found and np.all(np.diff(found) > 0)
    assert np.all(values[found] >= values.max() - 1e-6 * abs(values.max()))
    mirrored = values.size - 1 - argmax_all(values[::-1])
    np.testing.assert_array_equal(np.sort(mirrored), found)
    top = values.max()
    clear = np.abs(values - (top - 1e-6 * abs(top))) > 1e-9 * max(abs(top), 1e-300)  # none at the edge
    if clear.all():
        nudged = values * (1 + np.random.default_rng(seed).choice([-1, 1], values.size) * np.finfo(float).eps)
        np.testing.assert_array_equal(argmax_all(nudged), found)


def test_argmax_all_names_both_of_a_tie_and_one_of_distinct_values():
    assert argmax_all(np.array([0.3, 0.9181662, 0.2, 0.9181662 * (1 + 1e-15)])).tolist() == [1, 3]
    assert argmax_all(np.array([0.3, 0.9, 0.2, 0.91])).tolist() == [3]
    assert argmax_all(np.array([1.0, 0.999]), rtol=1e-2).tolist() == [0, 1]


@pytest.mark.parametrize(
    ("values", "rtol", "message"),
    [([], 1e-6, "values"), ([[1.0, 2.0]], 1e-6, "values"), ([1.0, np.nan], 1e-6, "values"), ([1.0], 1.0, "rtol")],
)
def test_argmax_all_refuses_bad_input(values, rtol, message):
    with pytest.raises(ValueError, match=message):
        argmax_all(np.array(values, dtype=float), rtol)


def test_local_frf_errors_of_a_known_perturbation():
    """Tasselli scaled by 1 + e_i give the relative error e_i at every frequency: max and median over them."""
    freqs = np.arange(0.0, 101.0, 1.0)
    rng = np.random.default_rng(3)
    reference = SimpleNamespace(freqs=freqs, H=rng.normal(size=(5, freqs.size)) + 1j * rng.normal(size=(5, freqs.size)))
    scale = np.array([0.01, -0.02, 0.03, 0.0, 0.05])
    models = {"same": reference, "scaled": SimpleNamespace(freqs=freqs, H=reference.H * (1 + scale[:, None]))}
    table = local_frf_errors(reference, models, 42.3)
    assert table.attrs["f"] == 42.0
    assert table.loc["same"].to_list() == [0.0, 0.0, 0.0]
    assert table.loc["scaled"].to_numpy() == pytest.approx([0.05, 0.02, 0.05], rel=1e-12)


def test_local_frf_errors_bad_input():
    freqs = np.arange(1.0, 11.0)
    reference = SimpleNamespace(freqs=freqs, H=np.ones((2, freqs.size)))
    with pytest.raises(ValueError, match="start at 0 Hz"):
        local_frf_errors(reference, {}, 5.0)
    reference.freqs = freqs - 1.0
    with pytest.raises(ValueError, match=r"frequency = 12.0 Hz: valid range is \[0, 9.0\]"):
        local_frf_errors(reference, {}, 12.0)


def test_damped_components_recover_a_decay_beside_a_spurious_growing_pole():
    """A decay of 300 N at 82 Hz, 6 % damping, with a tiny real growing term (the kind the matrix pencil
    fits to a contact's chatter: ~1e19 times larger at the end than at the start): the decay's own
    frequency, damping and amplitude come back (unscaled least squares returned ~1e-36 N)."""
    dt = 1 / 12000
    t = np.arange(0.0, 0.05, dt)
    y = 300.0 * np.exp(-0.06 * 2 * np.pi * 82.0 * t) * np.sin(2 * np.pi * 82.0 * t) + 1e-20 * np.exp(900.0 * t)
    table = damped_components(y, dt, n_components=2)
    first = table.iloc[0]
    zeta = 0.06 / np.sqrt(1 + 0.06**2)  # the decay rate over the pole's modulus
    assert abs(first["frequency (Hz)"] - 82.0) < 1e-3 and abs(first["damping ratio"] - zeta) < 1e-4
    assert abs(first["amplitude"] - 300.0) < 0.5
