"""The shared measures of analysis.py: the choice among equal candidates that round-off cannot make."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from roadnoise_utils.analysis import argmax_all

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
