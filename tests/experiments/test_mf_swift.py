"""The published MF-Swift 6.1 vertical model of the 205/60 R15 reference tire, checked by closed forms.

The tangent stiffness at the nominal load and pressure is the file's VERTICAL_STIFFNESS; the
deflection inverts the force; the tangent is the force's derivative; at a given deflection the force
scales with the pressure as (1 + PFZ1 dp). The values at 2, 4 and 6 kN are those worked by hand from
the published parameters: q_Fz1 = sqrt(16.431^2 - 4 x 15.416) = 14.433, rho(4 kN) = R0 x 0.0649 =
20.3 mm, K_v(2 kN)/K_v(4 kN) = sqrt((208.3 + 30.8)/270.0) = 0.941, K_v(6 kN)/K_v(4 kN) = 1.056, the
contact length at 4 kN 2 x 0.3135 x (0.7308 x 0.0649 + 0.6715 x 0.2548) = 137 mm.
"""

from __future__ import annotations

import numpy as np
import pytest

from roadnoise_utils.experiments import mf_swift
from roadnoise_utils.repro import paths
from roadnoise_utils.tire.model import tire_model


@pytest.fixture(scope="module")
def tire():
    return mf_swift.mf_swift_tire()


def test_the_tangent_at_the_nominal_load_is_the_file_s_vertical_stiffness(tire):
    assert tire.tangent_stiffness(tire.nominal_load) == pytest.approx(209651.0, rel=1e-12)
    assert tire.q_fz1 == pytest.approx(14.433, abs=1e-3)
    assert tire.force(tire.deflection(tire.nominal_load)) == pytest.approx(tire.nominal_load, rel=1e-12)


def test_the_tangent_is_the_force_s_derivative_and_the_pressure_scales_the_force(tire):
    for load, pressure in ((1500.0, None), (4000.0, 1.8e5), (7000.0, 2.8e5)):
        rho = tire.deflection(load, pressure)
        h = 1e-7
        slope = (tire.force(rho + h, pressure) - tire.force(rho - h, pressure)) / (2 * h)
        assert tire.tangent_stiffness(load, pressure) == pytest.approx(slope, rel=1e-7)
        assert tire.force(rho, pressure) == pytest.approx(load, rel=1e-12)
    rho = 0.02
    dp = (2.8e5 - tire.nominal_pressure) / tire.nominal_pressure
    assert tire.force(rho, 2.8e5) == pytest.approx(tire.force(rho) * (1 + tire.p_fz1 * dp), rel=1e-12)


def test_the_values_worked_by_hand_from_the_published_parameters(tire):
    table = mf_swift.mf_swift_table(tire).set_index("load (N)")
    assert table.loc[4000.0, "deflection (mm)"] == pytest.approx(20.3, abs=0.05)
    assert table.loc[2000.0, "K_v / K_v(FNOMIN)"] == pytest.approx(0.941, abs=5e-4)
    assert table.loc[6000.0, "K_v / K_v(FNOMIN)"] == pytest.approx(1.056, abs=5e-4)
    assert table.loc[4000.0, "contact length (mm)"] == pytest.approx(137.0, abs=0.5)
    assert np.all(np.diff(table["contact length (mm)"]) > 0)


def test_bad_input_and_bad_files_are_refused_naming_them(tire, tmp_path, monkeypatch):
    for call, name in (
        (lambda: tire.deflection(-1.0), "load"),
        (lambda: tire.tangent_stiffness(np.nan), "load"),
        (lambda: tire.force(-0.01), "deflection"),
        (lambda: tire.contact_length(4000.0, pressure=1.0), "pressure"),
        (lambda: mf_swift.mf_swift_tire("no_such_tire"), "no_such_tire"),
    ):
        with pytest.raises(ValueError, match=name):
            call()
    original = (paths.data_dir() / "published" / "205_60R15_mf_swift.toml").read_text()
    (tmp_path / "published").mkdir()
    monkeypatch.setattr(mf_swift, "data_dir", lambda: tmp_path)
    for edit, message in (
        (("Q_FZ2 = 15.416", "Q_FZ2 = 15.416\nQ_FZ3 = 1.0"), r"unknown \['Q_FZ3'\]"),
        (("PFZ1 = 0.7097", "PFZ_1 = 0.7097"), r"missing \['PFZ1'\]"),
        (("FNOMIN = 4000.0", "FNOMIN = -4000.0"), "FNOMIN"),
        (("VERTICAL_STIFFNESS = 209651.0", "VERTICAL_STIFFNESS = 9651.0"), "no real Q_FZ1"),
    ):
        (tmp_path / "published" / "bad.toml").write_text(original.replace(*edit))
        with pytest.raises(ValueError, match=message):
            mf_swift.mf_swift_tire("bad")


def test_the_comparison_puts_each_model_beside_the_published_tire(tire):
    """The published row is the published model's own values; a model's row its own footprints' at the
    same three loads (the 205/60 R15 ring tire: its file at the published tire's size and pressure)."""
    ring = tire_model("205_60R15")
    table = mf_swift.published_comparison(tire, [ring])
    assert list(table.index) == [tire.name, ring.name]
    own = mf_swift.mf_swift_table(tire).set_index("load (N)")
    published = table.loc[tire.name]
    assert published["K_v at the nominal load (N/mm)"] == pytest.approx(tire.vertical_stiffness / 1e3, rel=1e-12)
    assert published["K_v(light) / K_v(nominal)"] == pytest.approx(own.loc[2000.0, "K_v / K_v(FNOMIN)"], rel=1e-12)
    assert published["contact length (mm)"] == pytest.approx(own.loc[4000.0, "contact length (mm)"], rel=1e-12)
    footprints = [ring.load(ring.case("flat", load)) for load in (2000.0, 4000.0, 6000.0)]
    row = table.loc[ring.name]
    assert row["inflation (bar)"] == published["inflation (bar)"] == 2.2
    assert row["K_v(heavy) / K_v(nominal)"] == pytest.approx(
        footprints[2].vertical_stiffness / footprints[1].vertical_stiffness, rel=1e-12
    )
    assert row["contact length (mm)"] == pytest.approx(footprints[1].footprint_length * 1e3, rel=1e-12)
    softer = ring.replace(**{"operating.inflation_pressure": 0.78 * 2.2e5}).load(ring.case("flat", 4000.0))
    assert row["K_v(pressure - 22 %) / K_v"] == pytest.approx(
        softer.vertical_stiffness / footprints[1].vertical_stiffness, rel=1e-12
    )
    stiffer = tire.tangent_stiffness(4000.0, 1.22 * tire.nominal_pressure) / tire.vertical_stiffness
    assert published["K_v(pressure + 22 %) / K_v"] == pytest.approx(stiffer, rel=1e-12)
    assert row["K_v(pressure - 22 %) / K_v"] < 1.0 < row["K_v(pressure + 22 %) / K_v"]
    files = ("205_60R15_cross_section", "205_60R15_loaded")  # each model's inflation from its own files
    assert [mf_swift._inflation(tire_model(name)) for name in files] == [tire.nominal_pressure] * 2
    for loads in ((2000.0, 3000.0, 6000.0), (6000.0, 4000.0, 2000.0), (2000.0, 4000.0)):
        with pytest.raises(ValueError, match="loads"):
            mf_swift.published_comparison(tire, [], loads)
    with pytest.raises(ValueError, match="pressure_change"):
        mf_swift.published_comparison(tire, [], pressure_change=0.5)
