"""The moving-hub check (paper Eq. 5-7): the RM moving-hub tire against the FE tire with its hub free."""

from __future__ import annotations

import numpy as np
import pytest

import roadnoise_utils as ru


@pytest.mark.parametrize("tire", ["195_65R15", "195_65R15_cross_section"])
@pytest.mark.filterwarnings(
    "ignore:no order in"
)  # the 195 cross-section's shoulder tasselli: documented (the book's reference, "The finite-element tire")
def test_moving_hub_matches_fe_with_a_free_hub(tire):
    """The fitted RM moving hub (Eq. 5-7) against the FE tire with its hub free: for the ring a
    solve with every belt DOF, for the cross-section tire the exact two-port of its direct
    H_tot and G_H."""
    check = ru.experiments.moving_hub_check(tire, freqs=np.arange(2.0, 251.0, 4.0))
    assert check.suspension == ru.experiments.suspension_conditions()
    errors = check.errors()
    assert errors["hub acceleration"] < 0.02 and errors["hub force F_M"] < 0.02
    # the two errors are the relative RMS of what they name
    w2 = (2 * np.pi * check.freqs) ** 2
    manual = np.linalg.norm(w2 * (check.rm_hub - check.fe_hub)) / np.linalg.norm(w2 * check.fe_hub)
    assert errors["hub acceleration"] == pytest.approx(manual, rel=1e-12)


def test_a_stiffer_suspension_moves_the_hub_less():
    """Physical sense of the check: quasi-static hub motion per road displacement falls as k grows."""
    f = np.array([2.0])
    soft = ru.experiments.moving_hub_check(freqs=f, suspension=ru.experiments.Suspension(30.0, 2e4, 3000.0))
    stiff = ru.experiments.moving_hub_check(freqs=f, suspension=ru.experiments.Suspension(30.0, 2e5, 3000.0))
    assert abs(stiff.fe_hub[0]) < abs(soft.fe_hub[0]) < 1.0
