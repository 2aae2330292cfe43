"""Tasselli: a partition of the contact points with shape-function weights (paper Fig. 2)."""

from __future__ import annotations

import numpy as np
import pytest

from roadnoise_utils.tire.tasselli import MAX_TASSELLO_SIZE, tassellate


@pytest.mark.parametrize("road", ["flat", "drum"])
def test_partition_covers_every_contact_point_once(road, flat, drum):
    st = flat if road == "flat" else drum
    t = st.tasselli
    contact = set(zip(*np.nonzero(st.contact)))
    listed = list(zip(t.node_strip, t.node_index))
    assert len(listed) == len(set(listed)) == len(contact)
    assert set(listed) == contact
    assert np.all((t.node_tassello >= 0) & (t.node_tassello < t.n))
    assert np.array_equal(t.membership().sum(axis=0), np.ones(len(listed)))


def test_weights_sum_to_one(flat):
    t = flat.tasselli
    assert np.allclose(np.bincount(t.node_tassello, weights=t.node_weight), 1.0, rtol=0, atol=1e-12)
    assert np.all(t.node_weight > 0)


def test_sizes_and_count(flat):
    t = flat.tasselli
    assert t.length.max() <= MAX_TASSELLO_SIZE and t.width.max() <= MAX_TASSELLO_SIZE
    assert 60 <= t.n <= 85  # paper Fig. 2: 71


def test_numbering_from_leading_edge(flat):
    t = flat.tasselli
    assert np.all(np.diff(t.row) >= 0)  # row by row
    assert t.centre_x[0] > 0 > t.centre_x[-1]  # first at the leading edge (+x), last at the trailing edge
    same_row = t.row[1:] == t.row[:-1]
    assert np.all(np.diff(t.centre_y)[same_row] > 0)  # left to right within a row


def test_road_averages(flat):
    """Constant field -> constant; linear field -> value at the centre; quadratic -> bounded."""
    t = flat.tasselli
    assert np.allclose(t.average(lambda x, y: np.full_like(x, 3e-3)), 3e-3, rtol=1e-12)
    a, b, c = 1e-3, 0.05, -0.02
    assert np.allclose(t.average(lambda x, y: a + b * x + c * y), a + b * t.centre_x + c * t.centre_y, rtol=1e-10)
    sq = t.average(lambda x, y: x**2)
    assert np.all(sq >= (t.centre_x**2) - 1e-15)  # Jensen: the average of a convex field exceeds its value


def test_nan_road_is_refused(flat):
    with pytest.raises(ValueError, match="NaN"):
        flat.tasselli.average(lambda x, y: np.where(x > 0, np.nan, 0.0))


def test_too_large_tasselli_are_refused():
    x = np.array([0.0, 0.01])
    kwargs = dict(
        node_strip=np.array([0, 0]),
        node_index=np.array([0, 1]),
        node_x=x,
        node_y=np.zeros(2),
        node_dx_minus=np.full(2, 0.01),
        node_dx_plus=np.full(2, 0.01),
        strip_width=0.014,
    )
    with pytest.raises(ValueError, match="25 mm"):
        tassellate(**kwargs, target_length=0.03, strips_per_column=1)
    with pytest.raises(ValueError, match="strips_per_column"):
        tassellate(**kwargs, target_length=0.015, strips_per_column=2)
