"""Moving hub, road textures and the quarter car (paper stages 9-12)."""

from __future__ import annotations

import numpy as np

import roadnoise_utils as ru

CAR = "midsize_195_65R15"


def test_eq5_superposition_holds_in_the_fe_model(car_tire):
    """F_M = F_F + G_H u_H with all three from the FE model (no fits): exact for a linear model."""
    _, fet, static, _, _, _ = car_tire
    f = np.array([30.0, 90.0, 170.0])
    u_hub, f_hub = ru.tire.ring.fe_reference.fe_moving_hub(fet, static, f, 20.0, 40e3, 500.0)
    direct = ru.frf_visco(fet, static, f, progress=False)
    assert np.allclose(f_hub, direct.H_tot + direct.G_H * u_hub, rtol=1e-8)
