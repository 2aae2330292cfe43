"""Moving hub, road textures and the quarter car (paper stages 9-12)."""

from __future__ import annotations

import control
import numpy as np
import pytest
from scipy.signal import coherence as estimated_coherence

import roadnoise_utils as ru
from roadnoise_utils import corner, movinghub, textures, vehicle
from roadnoise_utils.road import contact_tracks, profile_input, texture_input
from roadnoise_utils.simulation import modal_sections
from roadnoise_utils.vehicle import Element, QuarterCar

CAR = "midsize_195_65R15"


@pytest.fixture(scope="module")
def car_tire():
    car = vehicle.load_vehicle(CAR)
    tire = ru.load_tire(car.tire)
    fet = ru.build_fet(tire)
    static = ru.pipeline.static_state(tire)
    fits = ru.pipeline.tassello_fits(tire)
    hub = ru.pipeline.hub_fit(tire)
    rim_side = fet.hub_vertical_mass
    return car, fet, static, fits, hub, rim_side


def test_moving_hub_matches_fe_with_a_free_hub(car_tire):
    _, fet, static, fits, hub, rim_side = car_tire
    check = ru.conditions.load_conditions("moving_hub_check")["hub"]
    suspension = (check["mass"], check["stiffness"], check["damping"])
    f = np.arange(2.0, 251.0, 4.0)
    u_fe, f_fe = movinghub.fe_moving_hub(fet, static, f, *suspension)
    u_rm, f_rm = movinghub.rm_moving_hub(fits, hub, f, *suspension, tire_hub_mass=rim_side)
    w2 = (2 * np.pi * f) ** 2
    assert np.linalg.norm(w2 * (u_rm - u_fe)) / np.linalg.norm(w2 * u_fe) < 0.02
    assert np.linalg.norm(f_rm - f_fe) / np.linalg.norm(f_fe) < 0.02


def test_eq5_superposition_holds_in_the_fe_model(car_tire):
    """F_M = F_F + G_H u_H with all three from the FE model (no fits): exact for a linear model."""
    _, fet, static, _, _, _ = car_tire
    f = np.array([30.0, 90.0, 170.0])
    u_hub, f_hub = movinghub.fe_moving_hub(fet, static, f, 20.0, 40e3, 500.0)
    direct = ru.frf_visco(fet, static, f, progress=False)
    assert np.allclose(f_hub, direct.H_tot + direct.G_H * u_hub, rtol=1e-8)


def test_moving_hub_model_structure(car_tire):
    _, _, _, fits, hub, _ = car_tire
    model = movinghub.assemble_moving_hub(fits, hub)
    assert model.ninputs == len(fits) + 1 and model.nstates == fits.n_poles * len(fits) + hub.n_poles
    s = 2j * np.pi * np.array([50.0, 150.0])
    response = np.asarray(model(s, squeeze=False))[0]
    assert np.allclose(response[-1], hub[0](np.array([50.0, 150.0])), rtol=1e-10)


@pytest.mark.parametrize("name", ["rough", "smooth"])
def test_profile_psd_matches_target(name):
    """Averaged over 8 seeds, every octave within 10 % of the target (one seed: 30 %)."""
    spectrum = textures.load_texture(name)
    bands = [(0.25, 0.5), (0.5, 1), (1, 2), (2, 4), (4, 8), (8, 16)]
    ratios = []
    for seed in range(8):
        n, g = textures.profile_psd(textures.generate_profile(spectrum, 200.0, 0.004, seed=seed))
        ratios.append(
            [np.mean(g[(n >= lo) & (n < hi)]) / np.mean(spectrum.psd(n[(n >= lo) & (n < hi)])) for lo, hi in bands]
        )
    ratios = np.array(ratios)
    assert np.all((ratios > 0.7) & (ratios < 1.3))
    assert np.all(np.abs(ratios.mean(axis=0) - 1) < 0.1)


def test_seed_reproduces_the_road():
    spectrum = textures.load_texture("rough")
    a = textures.generate_profile(spectrum, 50.0, 0.004, seed=7)
    b = textures.generate_profile(spectrum, 50.0, 0.004, seed=7)
    c = textures.generate_profile(spectrum, 50.0, 0.004, seed=8)
    assert np.array_equal(a.z, b.z) and not np.allclose(a.z, c.z)
    y = np.array([0.0, 0.02, 0.05])
    assert np.array_equal(
        textures.generate_field(spectrum, 50.0, 0.004, y, 3).z, textures.generate_field(spectrum, 50.0, 0.004, y, 3).z
    )


def test_3d_tracks_have_the_target_coherence():
    spectrum = textures.load_texture("rough")
    y = np.array([0.0, 0.1])
    field = textures.generate_field(spectrum, 400.0, 0.004, y, seed=11)
    n, gamma2 = estimated_coherence(field.z[0], field.z[1], fs=250.0, nperseg=4096)
    band = (n > 1.0) & (n < 6.0)
    model = textures.coherence(spectrum, n[band], 0.1) ** 2
    assert np.mean(np.abs(gamma2[band] - model)) < 0.1
    assert textures.coherence(spectrum, np.array([0.0]), 0.1)[0] == pytest.approx(1.0)


def test_bad_road_inputs(flat):
    with pytest.raises(ValueError, match="reference_psd"):
        textures.RoadSpectrum("bad", -1e-6, 2.0, 2.0, 1.5, 0.05, 50.0)
    with pytest.raises(ValueError, match="min_wavelength.*5 cm"):
        textures.RoadSpectrum("fine", 256e-6, 2.0, 2.0, 1.5, 0.03, 50.0)
    with pytest.raises(ValueError, match="step"):
        textures.generate_profile(textures.load_texture("rough"), 10.0, 0.02, seed=1)
    with pytest.raises(ValueError, match="speed"):
        profile_input(flat, lambda s: 0 * s, 0.0, (0.0, 1.0))
    with pytest.raises(ValueError, match="duration"):
        texture_input(flat, textures.load_texture("rough"), 20.0, 0.0, seed=1)


def test_texture_input_tracks_and_seed(flat):
    """One track per belt strip in contact; the seed fixes the road, another seed changes it."""
    assert np.array_equal(contact_tracks(flat), np.unique(flat.tasselli.node_y))
    spectrum = textures.load_texture("rough")
    a = texture_input(flat, spectrum, 20.0, 0.2, seed=3)
    b = texture_input(flat, spectrum, 20.0, 0.2, seed=3)
    c = texture_input(flat, spectrum, 20.0, 0.2, seed=4)
    assert a.u.shape == (flat.tasselli.n, a.t.size)
    assert np.array_equal(a.u, b.u) and not np.allclose(a.u, c.u)


def test_linearity_of_the_corner(car_tire):
    car, _, static, fits, hub, rim_side = car_tire
    model = corner.corner_model(car, hub, rim_side)
    sections = modal_sections(ru.assemble_fixed_hub(fits))
    profile = textures.generate_profile(textures.load_texture("smooth"), 40.0, 0.004, seed=5)
    one = profile_input(static, profile.as_2d(), 20.0, (0.0, 10.0), oversample=1)
    two = profile_input(static, lambda s: 2 * profile.height(s), 20.0, (0.0, 10.0), oversample=1)
    a = corner.run_corner(sections, model, one).outputs["a_mount"]
    b = corner.run_corner(sections, model, two).outputs["a_mount"]
    assert np.allclose(b, 2 * a, rtol=1e-10, atol=1e-10 * np.abs(b).max())


def test_time_and_frequency_domain_spectra_agree(car_tire):
    car, _, static, fits, hub, rim_side = car_tire
    model = corner.corner_model(car, hub, rim_side)
    sections = modal_sections(ru.assemble_fixed_hub(fits))
    spectrum = textures.load_texture("rough")
    speed = 30.0
    run = corner.run_corner(sections, model, texture_input(static, spectrum, speed, 8.0, seed=4, lateral=False))
    fc = np.arange(2.0, 251.0)
    predicted = corner.predicted_psd(fc, fits.responses(fc), static, spectrum, speed, model)["a_hub"]
    ratios = corner.band_power_ratios(
        corner.spectra(run)["a_hub"], fc, predicted, [(20, 40), (40, 80), (80, 160), (160, 250)]
    )
    assert np.all((ratios > 0.8) & (ratios < 1.2))


def test_transmissibility_has_the_character_of_fig_10():
    """Each of the paper's Fig. 10 bands (data/paper/claims.toml) meets its claim's test."""
    car = vehicle.load_vehicle(CAR)
    bands = ru.claims.transmissibility_bands()
    assert set(bands) == {"fig10_low", "fig10_mid", "fig10_high"}
    statistics = vehicle.transmissibility_statistics(car, bands)
    claims = {c["id"]: c for c in ru.claims.load_claims()}
    for claim_id, value in statistics.items():
        assert ru.claims.judge(claims[claim_id], value), (claim_id, value)


def test_transmissibility_statistics_are_those_of_the_band():
    """mean/min/max of |T| on the band, against a dense grid computed here; bad bands raise."""
    car = vehicle.load_vehicle(CAR)
    f = np.linspace(100.0, 150.0, 5001)
    t = np.abs(vehicle.transmissibility(car, f))
    bands = {k: vehicle.FrequencyBand(100.0, 150.0, k) for k in ("mean", "min", "max")}
    statistics = vehicle.transmissibility_statistics(car, bands)
    assert statistics["mean"] == pytest.approx(t.mean(), rel=1e-3)
    assert statistics["min"] == pytest.approx(t.min(), rel=1e-3)
    assert statistics["max"] == pytest.approx(t.max(), rel=1e-3)
    with pytest.raises(ValueError, match="statistic"):
        vehicle.transmissibility_statistics(car, {"b": vehicle.FrequencyBand(10.0, 20.0, "median")})
    with pytest.raises(ValueError, match="f_low < f_high"):
        vehicle.transmissibility_statistics(car, {"b": vehicle.FrequencyBand(20.0, 10.0, "mean")})


def test_band_power_helpers_on_a_flat_spectrum():
    """A white PSD: power shares are bandwidth ratios, the RMS is sqrt(level x bandwidth)."""
    f = np.arange(0.0, 501.0, 0.5)
    p = np.full(f.size, 4.0)
    assert corner.power_share((f, p), 0.0, 50.0, band=(2.0, 250.0)) == pytest.approx(48 / 248, rel=0.02)
    assert corner.band_rms((f, p), band=(2.0, 250.0)) == pytest.approx(np.sqrt(4.0 * 248.0), rel=0.01)
    ratios = corner.band_power_ratios((f, p), np.arange(0.0, 501.0), np.full(501, 2.0), [(10, 20), (100, 200)])
    assert np.allclose(ratios, 2.0)


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
    coupled = vehicle.couple(vehicle.vehicle_statespace(car), tire_spring)
    f = np.linspace(0.2, 40.0, 200)
    body_accel = np.asarray(coupled(2j * np.pi * f))[2, 0] * k_t  # per unit road displacement
    body_disp = body_accel / (-((2 * np.pi * f) ** 2))
    assert np.allclose(body_disp, vehicle.two_mass_transmissibility(m_s, m_u, k_s, c_s, k_t, f), rtol=1e-9)


def test_bad_vehicle_files(tmp_path):
    good = (ru.paths.data_dir() / "vehicles" / f"{CAR}.toml").read_text()
    bad_mass = tmp_path / "a.toml"
    bad_mass.write_text(good.replace("body = 350.0", "body = -350.0"))
    with pytest.raises(ValueError, match="mass 'body'.*valid range"):
        vehicle.load_vehicle(bad_mass)
    bad_name = tmp_path / "b.toml"
    bad_name.write_text(good.replace('between = ["tower", "body"]', 'between = ["tower", "chassis"]', 1))
    with pytest.raises(ValueError, match="chassis"):
        vehicle.load_vehicle(bad_name)
