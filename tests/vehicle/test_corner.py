"""Moving hub, road textures and the quarter car (paper stages 9-12)."""

from __future__ import annotations

import numpy as np

import roadnoise_utils as ru
from roadnoise_utils.rm.simulation import modal_sections
from roadnoise_utils.road import profile_input, texture_input

CAR = "midsize_195_65R15"


def test_linearity_of_the_corner(car_tire):
    car, _, static, fits, hub, rim_side = car_tire
    model = ru.vehicle.corner.corner_model(car, hub, rim_side)
    sections = modal_sections(ru.assemble_fixed_hub(fits))
    profile = ru.textures.generate_profile(ru.textures.load_texture("smooth"), 60.0, 0.004, seed=5)
    one = profile_input(static, profile.as_2d(), 20.0, (0.0, 10.0), oversample=1)
    two = profile_input(static, lambda s: 2 * profile.height(s), 20.0, (0.0, 10.0), oversample=1)
    a = ru.vehicle.corner.run_corner(sections, model, one).outputs["a_mount"]
    b = ru.vehicle.corner.run_corner(sections, model, two).outputs["a_mount"]
    assert np.allclose(b, 2 * a, rtol=1e-10, atol=1e-10 * np.abs(b).max())


def test_time_and_frequency_domain_spectra_agree(car_tire):
    car, _, static, fits, hub, rim_side = car_tire
    model = ru.vehicle.corner.corner_model(car, hub, rim_side)
    sections = modal_sections(ru.assemble_fixed_hub(fits))
    spectrum = ru.textures.load_texture("rough")
    speed = 30.0
    run = ru.vehicle.corner.run_corner(
        sections, model, texture_input(static, spectrum, speed, 8.0, seed=4, lateral=False)
    )
    fc = np.arange(2.0, 251.0)
    predicted = ru.vehicle.corner.predicted_psd(fc, fits.responses(fc), static, spectrum, speed, model)["a_hub"]
    ratios = ru.vehicle.spectra.band_power_ratios(
        ru.vehicle.corner.spectra(run)["a_hub"], fc, predicted, [(20, 40), (40, 80), (80, 160), (160, 250)]
    )
    assert np.all((ratios > 0.8) & (ratios < 1.2))
