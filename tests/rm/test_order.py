"""Model order: the error falls with the number of poles and the lowest order within tolerance is chosen."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.rm.order import lowest_order, order_scan
from tests.rm.conftest import BAND_FREQS


def test_order_scan_and_lowest_order_on_a_known_system(known_system):
    _, _, frf = known_system(4, n_pairs=3)  # six poles
    scan = order_scan(BAND_FREQS, frf, orders=[2, 4, 6, 8])
    assert scan.loc[6, "max rms error"] < 1e-8 < scan.loc[2, "max rms error"]
    assert lowest_order(BAND_FREQS, frf, tolerance=1e-6, orders=range(2, 12)).n_poles == 6
    with pytest.raises(ValueError, match="no order in \\[2, 3\\] fits every FRF within"):
        lowest_order(BAND_FREQS, frf, tolerance=1e-6, orders=range(2, 4))
    assert np.isfinite(scan["median rms error"]).all()
    # not strict: the order with the smallest worst error, and a warning that says so
    worst = order_scan(BAND_FREQS, frf, orders=[2, 3])["max rms error"]
    with pytest.warns(ru.guards.RoadnoiseWarning, match=f"no order in \\[2, 3\\].*using {worst.idxmin()} poles"):
        best = lowest_order(BAND_FREQS, frf, tolerance=1e-6, orders=range(2, 4), strict=False)
    assert best.n_poles == worst.idxmin() and best.rms_errors.max() == worst.min()
