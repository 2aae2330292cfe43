"""Moving hub, road textures and the quarter car (paper stages 9-12)."""

from __future__ import annotations

import numpy as np

import roadnoise_utils as ru

CAR = "midsize_195_65R15"


def test_moving_hub_model_structure(car_tire):
    _, _, _, fits, hub, _ = car_tire
    model = ru.rm.assemble_moving_hub(fits, hub)
    assert model.ninputs == len(fits) + 1 and model.nstates == fits.n_poles * len(fits) + hub.n_poles
    s = 2j * np.pi * np.array([50.0, 150.0])
    response = np.asarray(model(s, squeeze=False))[0]
    assert np.allclose(response[-1], hub[0](np.array([50.0, 150.0])), rtol=1e-10)
