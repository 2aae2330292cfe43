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


def _symmetric_ring(spacing: float, count: int, shift: float = 0.0) -> dict:
    """One column of contact nodes at ``spacing`` symmetric about x = 0, numbered from the leading
    edge, its centre node moved by ``shift`` (m) as round-off of a loaded state moves a node."""
    x = spacing * np.arange(count // 2, -(count // 2) - 1, -1.0)
    x[count // 2] += shift
    n = x.size
    return dict(
        node_strip=np.zeros(n, int),
        node_index=np.arange(n),
        node_x=x,
        node_y=np.zeros(n),
        node_dx_minus=np.full(n, spacing),
        node_dx_plus=np.full(n, spacing),
        strip_width=0.02,
        strips_per_column=1,
    )


@pytest.mark.parametrize("shift", [0.0, 3e-15, -3e-15, 2e-12, -2e-12])
def test_a_node_on_the_footprint_middle_joins_the_leading_row_whatever_the_round_off(shift):
    """Eleven nodes 9.5 mm apart span 104.5 mm: six rows of 17.4 mm, the middle edge through the
    centre node. It joins the leading row of the two (the 195/65 R15 ring on the drum sits 6e-15 of
    a row from that edge, the 165/65 R14 cross-section exactly on it), whatever the round-off."""
    tasselli = tassellate(**_symmetric_ring(0.0095, 10, shift), target_length=0.02)
    rows = tasselli.row[tasselli.node_tassello]
    assert tasselli.n == 6 and rows[5] == 2  # node_x runs from the leading edge: node 5 is the centre
    np.testing.assert_array_equal(np.delete(rows, 5), np.delete(rows.max() - rows[::-1], 5))  # the rest mirrored


@pytest.mark.parametrize("target", [0.0125, 0.015, 0.02, 0.025])
def test_rows_mirror_a_symmetric_footprint_and_round_off_cannot_move_them(target):
    """Every node's row but the centre node's mirrors its partner's across the centre, and a shift
    of the centre node by round-off changes no row, at target lengths that put nodes on edges and not."""
    base = tassellate(**_symmetric_ring(0.0095, 10), target_length=target)
    rows = base.row[base.node_tassello]
    np.testing.assert_array_equal(np.delete(rows, 5), np.delete(rows.max() - rows[::-1], 5))
    assert rows.max() + 1 == int(np.ceil(0.1045 / target))  # the fewest rows no longer than the target
    for shift in (3e-15, -3e-15, 1e-12, -1e-12):
        moved = tassellate(**_symmetric_ring(0.0095, 10, shift), target_length=target)
        np.testing.assert_array_equal(moved.row[moved.node_tassello], rows)
