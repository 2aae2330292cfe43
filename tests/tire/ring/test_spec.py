"""Tire files: both load, and every kind of bad input is refused with a message naming the field."""

from __future__ import annotations

import tomllib

import pytest

import roadnoise_utils as ru
from roadnoise_utils.repro.paths import data_dir
from roadnoise_utils.tire.ring.spec import from_dict, to_dict


@pytest.mark.parametrize("name", ["165_65R14", "195_65R15"])
def test_tire_files_load(name):
    spec = ru.load_tire(name)
    assert spec.operating.inflation_pressure == pytest.approx(2.3e5)  # paper: 2.3 bar for both tires
    assert spec.geometry.outer_radius > spec.geometry.belt_radius > spec.geometry.rim_radius


def test_paper_operating_point(tire):
    assert tire.operating.vertical_load == 4512.0
    assert tire.operating.rim_width == pytest.approx(4 * 0.0254)  # 4J rim


def _raw(name="165_65R14"):
    with open(data_dir() / "tires" / f"{name}.toml", "rb") as fh:
        return tomllib.load(fh)


def test_missing_field_is_named_with_its_range():
    data = _raw()
    del data["belt"]["bending_stiffness"]
    with pytest.raises(ValueError, match=r"\[belt\] is missing 'bending_stiffness'.*N m\^2, valid range \[0.01, 200\]"):
        from_dict(data, "t.toml")


def test_out_of_range_value_is_named_with_its_range():
    data = _raw()
    data["operating"]["inflation_pressure"] = -2.3e5
    with pytest.raises(
        ValueError, match=r"inflation_pressure = -230000 Pa is outside its valid range \[50000, 500000\] Pa"
    ):
        from_dict(data, "t.toml")


@pytest.mark.parametrize("value", [float("nan"), float("inf"), "2.3 bar", True])
def test_non_numbers_are_refused(value):
    data = _raw()
    data["operating"]["inflation_pressure"] = value
    with pytest.raises(ValueError, match="inflation_pressure"):
        from_dict(data, "t.toml")


def test_unknown_field_and_missing_section():
    data = _raw()
    data["belt"]["bending_stifness"] = 5.0
    with pytest.raises(ValueError, match="unknown parameter.*bending_stifness"):
        from_dict(data, "t.toml")
    data = _raw()
    del data["tread"]
    with pytest.raises(ValueError, match=r"missing section.*\[tread\]"):
        from_dict(data, "t.toml")
    data = _raw()
    del data["compounds"]["tread"]
    with pytest.raises(ValueError, match=r"compounds.tread"):
        from_dict(data, "t.toml")


def test_integer_fields_and_cross_checks():
    data = _raw()
    data["mesh"]["n_elements"] = 300.5
    with pytest.raises(ValueError, match="n_elements = 300.5 must be an integer"):
        from_dict(data, "t.toml")
    data = _raw()
    data["geometry"]["belt_width"] = 0.2
    with pytest.raises(ValueError, match="belt_width = 0.2 m must not exceed section_width"):
        from_dict(data, "t.toml")


def test_round_trip_and_replace(tire):
    assert to_dict(from_dict(to_dict(tire))) == to_dict(tire)
    stiffer = tire.replace(**{"belt.bending_stiffness": 9.0})
    assert stiffer.belt.bending_stiffness == 9.0 and tire.belt.bending_stiffness != 9.0
    with pytest.raises(ValueError, match="bending_stiffness"):
        tire.replace(**{"belt.bending_stiffness": 0.0})
    with pytest.raises(KeyError):
        tire.replace(**{"belt.no_such_parameter": 1.0})


def test_unknown_tire_name_lists_the_available_ones():
    with pytest.raises(FileNotFoundError, match="165_65R14"):
        ru.load_tire("no_such_tire")
