"""Moving hub, road textures and the quarter car (paper stages 9-12)."""

from __future__ import annotations

import control
import numpy as np
import pytest

import roadnoise_utils as ru
from roadnoise_utils.vehicle.quarter_car import Element, QuarterCar

CAR = "midsize_195_65R15"


def test_transmissibility_has_the_character_of_fig_10():
    """Each of the paper's Fig. 10 bands (data/paper/claims.toml) meets its claim's test."""
    car = ru.vehicle.quarter_car.load_vehicle(CAR)
    bands = ru.claims.transmissibility_bands()
    assert set(bands) == {"fig10_low", "fig10_mid", "fig10_high"}
    statistics = ru.vehicle.quarter_car.transmissibility_statistics(car, bands)
    claims = {c["id"]: c for c in ru.claims.load_claims()}
    for claim_id, value in statistics.items():
        assert ru.claims.judge(claims[claim_id], value), (claim_id, value)


def test_transmissibility_statistics_are_those_of_the_band():
    """mean/min/max of |T| on the band, against a dense grid computed here; bad bands raise."""
    car = ru.vehicle.quarter_car.load_vehicle(CAR)
    f = np.linspace(100.0, 150.0, 5001)
    t = np.abs(ru.vehicle.quarter_car.transmissibility(car, f))
    bands = {k: ru.vehicle.quarter_car.FrequencyBand(100.0, 150.0, k) for k in ("mean", "min", "max")}
    statistics = ru.vehicle.quarter_car.transmissibility_statistics(car, bands)
    assert statistics["mean"] == pytest.approx(t.mean(), rel=1e-3)
    assert statistics["min"] == pytest.approx(t.min(), rel=1e-3)
    assert statistics["max"] == pytest.approx(t.max(), rel=1e-3)
    with pytest.raises(ValueError, match="statistic"):
        ru.vehicle.quarter_car.transmissibility_statistics(
            car, {"b": ru.vehicle.quarter_car.FrequencyBand(10.0, 20.0, "median")}
        )
    with pytest.raises(ValueError, match="f_low < f_high"):
        ru.vehicle.quarter_car.transmissibility_statistics(
            car, {"b": ru.vehicle.quarter_car.FrequencyBand(20.0, 10.0, "mean")}
        )


def test_two_mass_quarter_car_is_the_textbook_one():
    """Without tire dynamics (G_H = -k_t, F_F = k_t z_road) our corner is the textbook quarter car."""
    m_s, m_u, k_s, c_s, k_t = 350.0, 40.0, 25e3, 2000.0, 200e3
    car = QuarterCar(
        "two-mass",
        "none",
        {"body": m_s, "unsprung": m_u},
        (Element("spring", "unsprung", "body", stiffness=k_s), Element("damper", "unsprung", "body", damping=c_s)),
        hub="unsprung",
        upper_mount="body",
    )
    tire_spring = control.ss([], [], [], [[-k_t]])
    coupled = ru.vehicle.quarter_car.couple(ru.vehicle.quarter_car.vehicle_statespace(car), tire_spring)
    f = np.linspace(0.2, 40.0, 200)
    body_accel = np.asarray(coupled(2j * np.pi * f))[2, 0] * k_t  # per unit road displacement
    body_disp = body_accel / (-((2 * np.pi * f) ** 2))
    assert np.allclose(
        body_disp, ru.vehicle.quarter_car.two_mass_transmissibility(m_s, m_u, k_s, c_s, k_t, f), rtol=1e-9
    )


def test_bad_vehicle_files(tmp_path):
    good = (ru.repro.paths.data_dir() / "vehicles" / f"{CAR}.toml").read_text()
    bad_mass = tmp_path / "a.toml"
    bad_mass.write_text(good.replace("body = 350.0", "body = -350.0"))
    with pytest.raises(ValueError, match="mass 'body'.*valid range"):
        ru.vehicle.quarter_car.load_vehicle(bad_mass)
    bad_name = tmp_path / "b.toml"
    bad_name.write_text(good.replace('between = ["tower", "body"]', 'between = ["tower", "chassis"]', 1))
    with pytest.raises(ValueError, match="chassis"):
        ru.vehicle.quarter_car.load_vehicle(bad_name)
